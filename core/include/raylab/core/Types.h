#pragma once

#include <glm/glm.hpp>

#include <limits>
#include <string>

/// \file Types.h
/// Geometric vocabulary of the core. Everything is double precision (glm::dvec3).
///
/// GLM is column-major: `M * v` transforms a column vector, and `T * R * S` applies S
/// first, then R, then T. Keep that in mind when composing transforms (the seed's authors
/// lost time on it). The world is right-handed with y up; cameras look down their local -z.

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

}  // namespace raylab
