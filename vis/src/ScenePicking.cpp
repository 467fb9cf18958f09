// SceneView's picking: the object and the ray under a point of the picture.
#include "SceneViewImpl.h"

#include "raylab/core/SceneIntersector.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>

namespace raylab::vis {

int SceneView::objectAt(double x, double y, int width, int height) const {
  if (width <= 0 || height <= 0 || m_scene.objects.empty()) return -1;
  // The view ray through (x, y): a pinhole at the eye with the view's vertical angle.
  const ViewCamera view = viewCamera();
  const Vec3 forward = glm::normalize(view.focalPoint - view.eye);
  const Vec3 right = glm::normalize(glm::cross(forward, view.up));
  const Vec3 up = glm::cross(right, forward);
  const double tanHalf = std::tan(radians(view.viewAngle) / 2.0);
  const double px = (2.0 * x / width - 1.0) * tanHalf * double(width) / height;
  const double py = (1.0 - 2.0 * y / height) * tanHalf;
  Ray ray = Ray::make(view.eye, forward + px * right + py * up);
  // The first surface drawn there: one-sided surfaces (walls, quads, planes, triangles)
  // are invisible from their back, so the ray passes through them.
  const SceneIntersector intersector(m_scene);
  for (int pass = 0; pass < 64; ++pass) {
    const std::optional<SceneHit> hit = intersector.intersect(ray);
    if (!hit) return -1;
    const std::size_t i = std::size_t(hit->object);
    const bool oneSided = m_impl->oneSided.size() == m_scene.objects.size() && m_impl->oneSided[i];
    Vec3 n = hit->si.n;
    if (glm::dot(m_impl->inside - hit->si.p, n) < 0.0) n = -n;  // the face drawn
    if (!oneSided || glm::dot(ray.direction, n) < 0.0) return hit->object;
    ray.tMin = glm::length(hit->si.p - ray.origin) * (1.0 + 1e-9) + 1e-9;
  }
  return -1;
}

int SceneView::segmentAt(double x, double y, int width, int height, double tolerance) const {
  m_impl->rays.ensureBuilt();
  const RayTreeActors& rays = m_impl->rays;
  if (!rays.shown || width <= 0 || height <= 0) return -1;
  // Project with the view camera's matrix once, then test every drawn line in 2D.
  vtkCamera* camera = m_impl->renderer->GetActiveCamera();
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(double(width) / height, -1, 1);
  double e[16];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) e[4 * r + c] = m->GetElement(r, c);
  // SrgbImage coordinates (y down) of a world point; w <= 0 when behind the eye.
  auto project = [&](const float* p, double& px, double& py) {
    const double w = e[12] * p[0] + e[13] * p[1] + e[14] * p[2] + e[15];
    if (w <= 1e-12) return false;
    px = ((e[0] * p[0] + e[1] * p[1] + e[2] * p[2] + e[3]) / w + 1.0) * width / 2.0;
    py = height - ((e[4] * p[0] + e[5] * p[1] + e[6] * p[2] + e[7]) / w + 1.0) * height / 2.0;
    return true;
  };
  int best = -1;
  double bestDistance = tolerance;
  for (int k = 0; k < kRayWidthClasses; ++k) {
    vtkPolyData* lines = rays.geometry.lines[std::size_t(k)];
    if (!lines || lines->GetNumberOfPoints() == 0) continue;
    const auto* points = static_cast<const float*>(lines->GetPoints()->GetVoidPointer(0));
    const std::vector<int>& ids = rays.geometry.cellSegment[std::size_t(k)];
    for (std::size_t c = 0; c < ids.size(); ++c) {
      double ax, ay, bx, by;
      if (!project(points + 6 * c, ax, ay) || !project(points + 6 * c + 3, bx, by)) continue;
      // Distance from (x, y) to the projected segment.
      const double dx = bx - ax, dy = by - ay;
      const double len2 = dx * dx + dy * dy;
      const double t =
          len2 > 0.0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / len2, 0.0, 1.0) : 0.0;
      const double d = std::hypot(x - (ax + t * dx), y - (ay + t * dy));
      if (d < bestDistance) {
        bestDistance = d;
        best = ids[c];
      }
    }
  }
  return best;
}

}  // namespace raylab::vis
