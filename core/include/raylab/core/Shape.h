#pragma once

#include "raylab/core/Bounds3.h"
#include "raylab/core/Exception.h"
#include "raylab/core/Ray.h"
#include "raylab/core/Types.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

/// First phase of an intersection: where along the ray, and which primitive.
/// Cheap to produce; `Shape::surfaceAt` turns the nearest one into geometry.
struct Hit {
  double t = kInfinity;  ///< Ray parameter of the hit (world units along a unit ray).
  int primitive = -1;    ///< Face / triangle index inside the shape, -1 when not meaningful.
  Vec2 uv{0.0};          ///< Surface parameters; barycentrics (b1, b2) for triangles.
};

/// Second phase: the local geometry at the nearest hit, computed once.
struct SurfaceInteraction {
  double t = kInfinity;   ///< Ray parameter of the hit.
  Point3 p{0.0};          ///< Hit point, world space.
  Normal3 n{0.0};         ///< Unit geometric normal, world space, pointing outward.
  Normal3 ns{0.0};        ///< Unit shading normal, world space, on n's side (dot(ns, n) > 0):
                          ///< a smooth mesh's vertex normals interpolated at the hit. Zero
                          ///< for flat surfaces, which shade with n (see shadingNormal()).
  Vec3 pError{0.0};       ///< Bound on the rounding error of p, per axis (world units): the
                          ///< exact surface point lies within p +- pError. Filled by every
                          ///< shape's surfaceAt; secondary rays leave from outside that box
                          ///< (RayOffset.h).
  bool frontFace = true;  ///< True when the ray arrives from the side `n` points to.
  Vec2 uv{0.0};           ///< Surface parameters; barycentrics (b1, b2) for triangles.
  int primitive = -1;     ///< Face / triangle index, -1 when not meaningful.

  /// The geometric normal turned against the ray: the side tests, the ray offsets
  /// (RayOffset.h) and the side a new ray leaves from use it.
  Normal3 facingNormal() const { return frontFace ? n : -n; }
  /// The shading normal, outward: ns on a smooth surface, else n.
  Normal3 shadingNormal() const { return isZero(ns) ? n : ns; }
  /// The shading normal turned to the side the ray arrived from (the geometric side,
  /// frontFace): what BSDFs, local shading and their cosines use.
  Normal3 facingShadingNormal() const { return frontFace ? shadingNormal() : -shadingNormal(); }
  /**
   * \brief Whether the direction w (world space, leaving the hit) lies on the same side of
   * the geometric surface as of the shading surface: dot(w, n) > 0 exactly when
   * dot(w, ns) > 0. Always true on flat surfaces. A direction where the two disagree lies
   * in the wedge between them; the engine absorbs every ray a hit spawns there (Tracer.cpp,
   * engineStep): a reflected or sampled direction below the geometric surface, and a light
   * below it, carry nothing, so no light leaks through a shading normal.
   */
  bool sidesAgree(const Vec3& w) const {
    return isZero(ns) || (glm::dot(w, n) > 0.0) == (glm::dot(w, ns) > 0.0);
  }
  std::string toString() const;
};

/// One boundary crossing along a ray, for inside/outside teaching.
struct Crossing {
  double t = 0.0;        ///< Ray parameter.
  bool entering = true;  ///< True when the ray goes from outside to inside here
                         ///< (for open surfaces: arrives on the front side).
  int primitive = -1;    ///< Face / triangle index.
};

/// A point sampled on a shape's surface (area lights).
struct ShapeSample {
  Point3 p{0.0};       ///< World space.
  Normal3 n{0.0};      ///< Outward unit normal, world space.
  double pdfArea = 0;  ///< Density per unit world area.
};

/// What a shape is, for drawing and for files.
enum class ShapeKind { Sphere, Box, Plane, Quad, Triangle, TriangleMesh };
const char* toString(ShapeKind kind);

/**
 * \brief A geometric primitive a ray can hit: the interface every shape implements.
 *
 * Intersection has two phases (pbrt's `BasicIntersect` / `InteractionFromIntersection`):
 * `intersect` finds the nearest t in [ray.tMin, ray.tMax] and returns ids only;
 * `surfaceAt` computes point, normal and parameters for that one hit. `intersectAll`
 * returns every crossing along the ray, sorted by t, to show entering and leaving.
 *
 * All positions, directions and normals in this interface are in world space.
 * `apply(M)` transforms the shape by an affine matrix M in world space
 * (rotate / translate / uniform and non-uniform scale), i.e. new = M * old.
 */
class Shape {
 public:
  /// Thrown by constructors and apply() for geometry that cannot exist: a negative or
  /// NaN radius, a zero-length axis or edge, a singular matrix.
  class InvalidGeometry : public Exception {
   public:
    using Exception::Exception;
  };

  virtual ~Shape() = default;

  virtual ShapeKind kind() const = 0;
  /// Whether the surface bounds a region of space, so that a ray crossing it enters or leaves
  /// a solid: sphere, box, mesh (read as closed and oriented outward), and a plane (the
  /// half-space behind it). A quad or a triangle is an open surface.
  virtual bool isClosed() const = 0;
  /// Whether the surface is flat (one normal everywhere): plane, quad, triangle.
  virtual bool isFlat() const = 0;

  /// Nearest hit with t in [ray.tMin, ray.tMax], or nothing.
  virtual std::optional<Hit> intersect(const Ray& ray) const = 0;
  /// Geometry of a hit returned by `intersect` for the same ray.
  virtual SurfaceInteraction surfaceAt(const Ray& ray, const Hit& hit) const = 0;
  /// Every crossing of the surface with t in [ray.tMin, ray.tMax], sorted by t.
  virtual std::vector<Crossing> intersectAll(const Ray& ray) const = 0;

  /// Outward unit normal at a point known to be on the surface (world space).
  virtual Normal3 normal(const Point3& p) const = 0;
  /// Whether a point is inside the solid. Plane: the half-space behind the normal.
  /// Open surfaces (Quad, Triangle) have no inside and answer false.
  virtual bool inside(const Point3& p) const = 0;
  /// Transforms the shape in world space: new = M * old. M must be affine and invertible.
  virtual void apply(const Mat4& m) = 0;
  /// World-space bounding box. Infinite for a plane.
  virtual Bounds3 bounds() const = 0;

  virtual std::unique_ptr<Shape> clone() const = 0;
  virtual std::string toString() const = 0;

  /// Surface area, world units squared (infinite for a plane).
  virtual double area() const = 0;
  /// A point on the surface for u in [0,1)^2, for area lights (world space). Throws
  /// InvalidGeometry for shapes that cannot be sampled (a plane, a mesh without area).
  virtual ShapeSample sampleArea(const Vec2& u) const = 0;
  /// Density per unit world area with which sampleArea picks the surface point p (p must
  /// lie on the surface; world space).
  virtual double pdfArea(const Point3& p) const = 0;

  /// Both phases at once: nearest hit and its geometry.
  std::optional<SurfaceInteraction> closestHit(const Ray& ray) const;
};

/// Declares, inside a concrete shape, the part of Shape's interface that every shape
/// defines in its own source: intersect, surfaceAt, intersectAll, normal, inside, apply,
/// bounds, toString, area, sampleArea and pdfArea (documented on Shape above). What the
/// shape is (kind, isClosed, isFlat) and clone stay written out in its header.
#define RAYLAB_SHAPE_INTERFACE                                                 \
  std::optional<Hit> intersect(const Ray& ray) const override;                 \
  SurfaceInteraction surfaceAt(const Ray& ray, const Hit& hit) const override; \
  std::vector<Crossing> intersectAll(const Ray& ray) const override;           \
  Normal3 normal(const Point3& p) const override;                              \
  bool inside(const Point3& p) const override;                                 \
  void apply(const Mat4& m) override;                                          \
  Bounds3 bounds() const override;                                             \
  std::string toString() const override;                                       \
  double area() const override;                                                \
  ShapeSample sampleArea(const Vec2& u) const override;                        \
  double pdfArea(const Point3& p) const override

}  // namespace raylab
