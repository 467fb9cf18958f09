#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <string>

/// \file Types.h
/// Geometric vocabulary of the core. Everything is double precision (glm::dvec3).
///
/// GLM is column-major: `M * v` transforms a column vector, and `T * R * S` applies S
/// first, then R, then T. Keep that in mind when composing transforms (the authors of the
/// original course program lost time on it). The world is right-handed with y up; cameras
/// look down their local -z.

namespace raylab {

using Point3 = glm::dvec3;   ///< A position (transforms with translation).
using Vec3 = glm::dvec3;     ///< A direction or offset (ignores translation).
using Normal3 = glm::dvec3;  ///< A surface normal (transforms with the inverse transpose).
using Vec2 = glm::dvec2;     ///< Surface parameters (u, v) or barycentrics.
using Mat4 = glm::dmat4;     ///< Affine 4x4 matrix, column-major.
using Mat3 = glm::dmat3;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

/// Degrees (as in scene files) to radians (as in code).
constexpr double radians(double degrees) { return degrees * (kPi / 180.0); }

/// "(x, y, z)" with full round-trip precision, for messages and toString().
std::string toString(const Vec3& v);

/// Luminance of a linear RGB colour with the Rec. 709 weights: how bright it looks. The one
/// place these weights are written (lobe and light choice, ray energy, text contrast).
constexpr double luminance(const Vec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

/// True when no component is NaN or infinite (inline: the engine asks it of every ray).
inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// |v| per component, without branches: glm::abs compiles to a compare and a jump per
/// component, which mispredict where signs vary from hit to hit (error bounds of hits).
inline Vec3 absolute(const Vec3& v) { return {std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}; }

/// True when every component is exactly 0 (a lobe or light that carries nothing).
constexpr bool isZero(const Vec3& v) { return v.x == 0.0 && v.y == 0.0 && v.z == 0.0; }

/// True when no component is positive (nothing to deliver: zero or negative weights).
constexpr bool isNonPositive(const Vec3& v) { return v.x <= 0.0 && v.y <= 0.0 && v.z <= 0.0; }

}  // namespace raylab
