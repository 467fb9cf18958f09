#include "raylab/core/Camera.h"

#include "raylab/core/Exception.h"
#include "raylab/core/Sampling.h"

#include <cmath>

namespace raylab {

Camera::Camera(const CameraSpec& spec) : m_spec(spec) {
  // Reject cameras that cannot form an image; these come from scene files and the UI.
  const Vec3 view = spec.lookAt - spec.position;
  const double distance = glm::length(view);
  if (!(distance > 0.0) || !std::isfinite(distance))
    throw Exception("camera: position and lookAt must be different finite points, got " +
                    raylab::toString(spec.position) + " and " + raylab::toString(spec.lookAt));
  if (!(spec.verticalFov > 0.0 && spec.verticalFov < 180.0))
    throw Exception("camera: verticalFov must be in (0, 180) degrees, got " +
                    std::to_string(spec.verticalFov));
  if (spec.width <= 0 || spec.height <= 0)
    throw Exception("camera: width and height must be positive, got " + std::to_string(spec.width) +
                    " x " + std::to_string(spec.height));
  if (!(spec.aperture >= 0.0) || !(spec.focusDistance >= 0.0) || !(spec.nearClip >= 0.0))
    throw Exception("camera: aperture, focusDistance and nearClip must be >= 0");

  // Build the orthonormal frame: forward towards lookAt, right = forward x up, and the
  // true up perpendicular to both (the camera looks down its local -z).
  m_forward = view / distance;
  const Vec3 right = glm::cross(m_forward, spec.up);
  const double rightLength = glm::length(right);
  if (!(rightLength > 1e-12 * glm::length(spec.up)))
    throw Exception("camera: up " + raylab::toString(spec.up) +
                    " must not be zero or parallel to the viewing direction");
  m_right = right / rightLength;
  m_up = glm::cross(m_right, m_forward);

  m_tanHalfFov = std::tan(0.5 * radians(spec.verticalFov));
  m_focusDistance = spec.focusDistance > 0.0 ? spec.focusDistance : distance;
}

Ray Camera::generateRay(const Vec2& film, const Vec2& lens, double time) const {
  // Film position (pixels, y down) to screen coordinates on the plane one unit in front
  // of the eye: [-aspect tan(fov/2), aspect tan(fov/2)] across, [tan, -tan] down.
  const double aspect = double(m_spec.width) / double(m_spec.height);
  const double sx = (2.0 * film.x / m_spec.width - 1.0) * aspect * m_tanHalfFov;
  const double sy = (1.0 - 2.0 * film.y / m_spec.height) * m_tanHalfFov;
  const Vec3 direction = m_forward + sx * m_right + sy * m_up;
  if (m_spec.aperture <= 0.0) return nearStart(m_spec.position, direction, 1.0, time);

  // Thin lens: every ray through this film point meets the pinhole ray on the plane in
  // focus (perpendicular to forward, m_focusDistance away); start it from a uniform point
  // on the lens disk of radius `aperture` (PBR book 5.2.3).
  const Point3 focus = m_spec.position + m_focusDistance * direction;
  const Vec2 disk = m_spec.aperture * sampleUniformDisk(lens);
  const Point3 origin = m_spec.position + disk.x * m_right + disk.y * m_up;
  const Vec3 toFocus = focus - origin;  // forward component m_focusDistance
  return nearStart(origin, toFocus, m_focusDistance, time);
}

Ray Camera::nearStart(const Point3& eye, const Vec3& direction, double forward, double time) const {
  // On the near plane, nearClip in front of the eye along the viewing direction:
  // `direction` scaled to a forward component of nearClip. On the near sphere, nearClip
  // along the unit direction, as smallpt's Ray(cam.o + d * 140, d.norm()) does once g++
  // has normalised d (it evaluates the arguments right to left).
  if (m_spec.nearClip == 0.0) return Ray::make(eye, direction, 0.0, kInfinity, time);
  const Vec3 offset = m_spec.nearClipShape == NearClipShape::Sphere
                          ? m_spec.nearClip * glm::normalize(direction)
                          : (m_spec.nearClip / forward) * direction;
  return Ray::make(eye + offset, direction, 0.0, kInfinity, time);
}

}  // namespace raylab
