#pragma once

#include "raylab/core/Ray.h"
#include "raylab/core/Scene.h"

namespace raylab {

/**
 * \brief Generates camera rays from a CameraSpec: a pinhole, or a thin lens with an
 * aperture and a focus distance (depth of field, Cook 1984 / PBR book 5.2.3).
 *
 * Film coordinates are in pixels: (0, 0) is the top-left corner of the image, x grows
 * right, y grows down; the centre of pixel (i, j) is (i + 0.5, j + 0.5). The camera looks
 * down its local -z; the image plane spans the vertical field of view.
 */
class Camera {
 public:
  explicit Camera(const CameraSpec& spec);

  /// The ray through film position `film` (pixels); `lens` in [0,1)^2 picks the point on
  /// the lens (ignored by a pinhole); `time` in [0, 1] is the shutter time. World space,
  /// unit direction.
  Ray generateRay(const Vec2& film, const Vec2& lens, double time) const;

  const CameraSpec& spec() const { return m_spec; }
  /// Unit viewing direction, world space.
  Vec3 forward() const { return m_forward; }

 private:
  /// The ray from `eye` along `direction` (whose forward component is `forward`), started at
  /// the near clip (world space).
  Ray nearStart(const Point3& eye, const Vec3& direction, double forward, double time) const;

  CameraSpec m_spec;
  Vec3 m_forward, m_right, m_up;  ///< Orthonormal camera frame, world space.
  double m_tanHalfFov;            ///< tan(vertical fov / 2).
  double m_focusDistance;         ///< Resolved focus distance, world units.
};

}  // namespace raylab
