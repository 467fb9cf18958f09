#include "raylab/vis/ViewCamera.h"

#include "raylab/core/Camera.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Shape.h"
#include "raylab/core/Sphere.h"

#include "ShapeGeometry.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace raylab::vis {

namespace {

/// Turn of the default view about the world up axis, away from straight behind the
/// scene camera, so the camera body does not sit in front of the room's centre.
constexpr double kAzimuthDegrees = 25.0;
/// How far the default view looks down.
constexpr double kElevationDegrees = 28.0;
/// Fraction of the half-picture kept free around the framed box.
constexpr double kMargin = 0.05;

/// Unit "up" of the scene camera, falling back to +y when it is degenerate.
Vec3 worldUp(const CameraSpec& camera) {
  const double length = glm::length(camera.up);
  return length > 0.0 ? camera.up / length : Vec3(0.0, 1.0, 0.0);
}

/// Unit viewing direction of the scene camera (its local -z), falling back to -z.
Vec3 cameraForward(const CameraSpec& camera) {
  const Vec3 d = camera.lookAt - camera.position;
  const double length = glm::length(d);
  return length > 0.0 ? d / length : Vec3(0.0, 0.0, -1.0);
}

/// A unit vector perpendicular to n.
Vec3 anyPerpendicular(const Vec3& n) {
  const Vec3 a = std::abs(n.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  return glm::normalize(glm::cross(n, a));
}

Bounds3 boundedShapes(const Scene& scene) {
  const std::vector<bool> walls = enclosingWalls(scene);
  // With walls around it, the room is what the camera sees of it.
  if (std::find(walls.begin(), walls.end(), true) != walls.end()) {
    const Bounds3 room = roomBounds(scene);
    if (!room.empty()) return room;
  }
  Bounds3 box;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    if (!object.shape || walls[i]) continue;
    const Bounds3 b = object.shape->bounds();
    if (b.empty()) continue;
    const Vec3 e = b.extent();
    if (!std::isfinite(e.x) || !std::isfinite(e.y) || !std::isfinite(e.z)) continue;
    box.extend(b);
  }
  return box;
}

}  // namespace

std::vector<bool> enclosingWalls(const Scene& scene) {
  std::vector<bool> walls(scene.objects.size(), false);
  bool anyHuge = false;
  for (const SceneObject& o : scene.objects)
    anyHuge |= o.shape && o.shape->kind() == ShapeKind::Sphere &&
               static_cast<const Sphere&>(*o.shape).radius() > 1e3;
  if (!anyHuge) return walls;
  // The viewing distance: to what the camera's central ray meets (else to the look-at).
  const Camera camera(scene.camera);
  const Ray central =
      camera.generateRay(Vec2(scene.camera.width / 2.0, scene.camera.height / 2.0), Vec2(0.5), 0.0);
  const std::optional<SceneHit> hit = SceneIntersector(scene).intersect(central);
  const double viewing = hit ? glm::length(hit->si.p - scene.camera.position)
                             : glm::length(scene.camera.lookAt - scene.camera.position);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Shape* shape = scene.objects[i].shape.get();
    if (shape && shape->kind() == ShapeKind::Sphere)
      walls[i] = static_cast<const Sphere&>(*shape).radius() > 100.0 * std::max(viewing, 1e-9);
  }
  return walls;
}

Bounds3 roomBounds(const Scene& scene) {
  // The first hits of a 9 x 9 grid of camera rays, edges included.
  const Camera camera(scene.camera);
  const SceneIntersector intersector(scene);
  Bounds3 box;
  constexpr int kGrid = 9;
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      const Vec2 film(scene.camera.width * double(i) / (kGrid - 1),
                      scene.camera.height * double(j) / (kGrid - 1));
      if (const std::optional<SceneHit> hit =
              intersector.intersect(camera.generateRay(film, Vec2(0.5), 0.0)))
        box.extend(hit->si.p);
    }
  return box;
}

Vec3 ViewCamera::direction() const {
  const Vec3 d = focalPoint - eye;
  const double length = glm::length(d);
  return length > 0.0 ? d / length : Vec3(0.0, 0.0, -1.0);
}

std::string ViewCamera::toString() const {
  std::ostringstream out;
  out << "ViewCamera(eye " << raylab::toString(eye) << ", focal point "
      << raylab::toString(focalPoint) << ", up " << raylab::toString(up) << ", view angle "
      << viewAngle << ")";
  return out.str();
}

double cameraGlyphSize(const Scene& scene) {
  Bounds3 box = boundedShapes(scene);
  if (box.empty()) box = Bounds3(scene.camera.lookAt - Vec3(1.0), scene.camera.lookAt + Vec3(1.0));
  return std::max(0.06 * glm::length(box.extent()), 1e-3);
}

Bounds3 drawnBounds(const Scene& scene) {
  Bounds3 box = boundedShapes(scene);
  if (box.empty()) box = Bounds3(scene.camera.lookAt - Vec3(1.0), scene.camera.lookAt + Vec3(1.0));
  // The camera glyph: its body behind the eye and its frustum in front.
  const double size = cameraGlyphSize(scene);
  const vtkSmartPointer<vtkPolyData> glyphs[2] = {
      cameraBodyGeometry(scene.camera, size),
      cameraFrustumGeometry(scene.camera, kFrustumLengthInGlyphs * size)};
  for (const vtkSmartPointer<vtkPolyData>& glyph : glyphs) {
    double b[6];
    glyph->GetBounds(b);
    box.extend(Bounds3(Point3(b[0], b[2], b[4]), Point3(b[1], b[3], b[5])));
  }
  return box;
}

ViewCamera defaultViewCamera(const Scene& scene, double aspect) {
  ViewCamera view;
  const Bounds3 box = drawnBounds(scene);
  const Vec3 up = worldUp(scene.camera);

  // Step 1: the scene camera's forward direction, flattened onto the ground.
  Vec3 ahead = cameraForward(scene.camera);
  ahead -= glm::dot(ahead, up) * up;
  ahead = glm::length(ahead) > 1e-9 ? glm::normalize(ahead) : anyPerpendicular(up);

  // Step 2: turn it about the up axis and tilt it down: the view direction.
  const Mat4 turn = glm::rotate(Mat4(1.0), radians(kAzimuthDegrees), up);
  ahead = glm::normalize(Vec3(turn * glm::dvec4(ahead, 0.0)));
  const double elevation = radians(kElevationDegrees);
  const Vec3 d = std::cos(elevation) * ahead - std::sin(elevation) * up;
  const Vec3 right = glm::normalize(glm::cross(d, up));
  const Vec3 viewUp = glm::cross(right, d);

  // Step 3: back off from the box centre until every corner fits the frustum:
  //   |x| <= (D + z) tan(h/2) (1 - margin) and the same for y, with z the corner's
  //   offset along the view direction and D the eye's distance to the centre.
  const Point3 centre = box.centre();
  const double tanV = std::tan(radians(view.viewAngle) / 2.0) * (1.0 - kMargin);
  const double tanH = tanV * std::max(aspect, 1e-3);
  double distance = 0.0;
  for (int k = 0; k < 8; ++k) {
    const Point3 corner((k & 1) ? box.upper.x : box.lower.x, (k & 2) ? box.upper.y : box.lower.y,
                        (k & 4) ? box.upper.z : box.lower.z);
    const Vec3 q = corner - centre;
    const double z = glm::dot(q, d);
    distance = std::max(distance, std::abs(glm::dot(q, right)) / tanH - z);
    distance = std::max(distance, std::abs(glm::dot(q, viewUp)) / tanV - z);
  }
  distance = std::max(distance, 1e-3);

  view.focalPoint = centre;
  view.eye = centre - distance * d;
  view.up = viewUp;
  return view;
}

std::optional<Vec2> projectToImage(const ViewCamera& camera, const Point3& world, int width,
                                   int height) {
  if (width <= 0 || height <= 0) return std::nullopt;
  if (glm::dot(world - camera.eye, camera.direction()) <= 0.0) return std::nullopt;

  // Step 1: world -> normalised view coordinates in [-1, 1], with VTK's own matrices.
  vtkNew<vtkCamera> vtk;
  vtk->SetPosition(camera.eye.x, camera.eye.y, camera.eye.z);
  vtk->SetFocalPoint(camera.focalPoint.x, camera.focalPoint.y, camera.focalPoint.z);
  vtk->SetViewUp(camera.up.x, camera.up.y, camera.up.z);
  vtk->SetViewAngle(camera.viewAngle);
  vtkMatrix4x4* m =
      vtk->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1.0, 1.0);
  const double in[4] = {world.x, world.y, world.z, 1.0};
  double out[4];
  m->MultiplyPoint(in, out);
  if (out[3] == 0.0) return std::nullopt;
  const double vx = out[0] / out[3];
  const double vy = out[1] / out[3];

  // Step 2: view -> display (origin bottom-left, as vtkViewport::ViewToDisplay), then
  // flip y so that rows count from the top.
  const double dx = (vx + 1.0) * width / 2.0;
  const double dy = (vy + 1.0) * height / 2.0;
  return Vec2(dx, height - dy);
}

ViewCamera closeUpView(const Scene& scene, int index, double aspect) {
  if (index < 0 || index >= static_cast<int>(scene.objects.size()))
    return defaultViewCamera(scene, aspect);
  const Bounds3 box = scene.objects[static_cast<std::size_t>(index)].shape->bounds();
  const Vec3 extent = box.extent();
  if (box.empty() || !std::isfinite(extent.x) || !std::isfinite(extent.y) ||
      !std::isfinite(extent.z))
    return defaultViewCamera(scene, aspect);
  const Point3 centre = box.centre();
  const double radius = std::max(0.5 * glm::length(extent), 1e-6);
  const Vec3 up =
      glm::length(scene.camera.up) > 0.0 ? glm::normalize(scene.camera.up) : Vec3(0.0, 1.0, 0.0);
  // From the scene camera's side, raised by a quarter of the way.
  Vec3 back = scene.camera.position - centre;
  if (!(glm::length(back) > 0.0)) back = Vec3(0.0, 0.0, 1.0);
  back = glm::normalize(glm::normalize(back) + 0.25 * up);
  ViewCamera view;
  view.viewAngle = 30.0;
  // The sphere around the box spans 80% of the narrower side of the picture.
  const double halfV = radians(view.viewAngle) / 2.0;
  const double halfNarrow = aspect >= 1.0 ? halfV : std::atan(std::tan(halfV) * aspect);
  const double distance = radius / std::sin(0.8 * halfNarrow);
  view.eye = centre + distance * back;
  view.focalPoint = centre;
  view.up = up;
  return view;
}

ViewCamera closeUpOnRay(const Scene& scene, const RayTree& tree, int id, double aspect) {
  if (id < 0 || id >= static_cast<int>(tree.segments.size()))
    return defaultViewCamera(scene, aspect);
  // The hit: where ray `id` starts, or for the camera ray where it ends.
  const RaySegment& ray = tree.segments[static_cast<std::size_t>(id)];
  const RaySegment* in =
      ray.parent >= 0 ? &tree.segments[static_cast<std::size_t>(ray.parent)] : &ray;
  const RaySegment* out = ray.parent >= 0 ? &ray : nullptr;
  if (!out && ray.firstChild >= 0) out = &tree.segments[static_cast<std::size_t>(ray.firstChild)];
  if (!in->hit || in->object < 0 || in->object >= static_cast<int>(scene.objects.size()))
    return defaultViewCamera(scene, aspect);
  const Point3 point = in->endPoint;
  // Square to the plane of the incoming and the outgoing ray (or the normal).
  Vec3 across = glm::cross(in->direction, out ? out->direction : Vec3(in->normal));
  if (!(glm::length(across) > 1e-9)) across = glm::cross(in->direction, Vec3(in->normal));
  if (!(glm::length(across) > 1e-9)) across = glm::cross(in->direction, scene.camera.up);
  if (!(glm::length(across) > 1e-9)) return closeUpView(scene, in->object, aspect);
  across = glm::normalize(across);
  // From the side the scene camera looks from (its own rays lie in the plane, so its
  // position cannot choose).
  if (glm::dot(across, scene.camera.position - scene.camera.lookAt) < 0.0) across = -across;
  // Up: the world's up, square to the view; the incoming ray where they are parallel.
  Vec3 up = scene.camera.up - glm::dot(scene.camera.up, across) * across;
  if (!(glm::length(up) > 1e-9)) up = in->direction;
  const Bounds3 box = scene.objects[static_cast<std::size_t>(in->object)].shape->bounds();
  const Vec3 extent = box.extent();
  double radius = 0.5 * glm::length(extent);
  if (box.empty() || !std::isfinite(radius) || !(radius > 0.0)) radius = 1.0;
  ViewCamera view;
  view.viewAngle = 30.0;
  const double halfV = radians(view.viewAngle) / 2.0;
  const double halfNarrow = aspect >= 1.0 ? halfV : std::atan(std::tan(halfV) * aspect);
  view.eye = point + radius / std::sin(0.8 * halfNarrow) * across;
  view.focalPoint = point;
  view.up = glm::normalize(up);
  return view;
}

ViewCamera behindCameraView(const Scene& scene, double aspect) {
  const CameraSpec& camera = scene.camera;
  const Vec3 toTarget = camera.lookAt - camera.position;
  const double distance = glm::length(toTarget);
  const Vec3 forward = distance > 0.0 ? toTarget / distance : Vec3(0.0, 0.0, -1.0);
  const Vec3 up = glm::length(camera.up) > 0.0 ? glm::normalize(camera.up) : Vec3(0, 1, 0);
  // Back along the view direction and up a little, by a share of the glyph scale, so the
  // camera's body and frustum show at the bottom of the picture.
  const double step = 4.0 * vis::cameraGlyphSize(scene);
  vis::ViewCamera view;
  view.eye = camera.position - step * forward + 1.2 * step * up;
  view.focalPoint = camera.lookAt;
  view.up = up;
  // A wider angle than the scene camera's, wider still for a narrow picture.
  view.viewAngle = std::min(120.0, camera.verticalFov * 1.25 * std::max(1.0, 1.2 / aspect));
  return view;
}

}  // namespace raylab::vis
