#include "ShapeGeometry.h"

#include "raylab/core/Box.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Triangle.h"
#include "raylab/core/TriangleMesh.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataNormals.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab::vis {

namespace {

/// Collects polygons with per-point normals (each polygon gets its own points, so a
/// normal per polygon gives flat shading).
class FlatPolygons {
 public:
  FlatPolygons() {
    m_normals->SetNumberOfComponents(3);
    m_normals->SetName("Normals");
  }

  /// Adds a planar polygon with the given unit normal, all world space.
  void add(const std::vector<Point3>& corners, const Normal3& normal) {
    m_polys->InsertNextCell(static_cast<vtkIdType>(corners.size()));
    for (const Point3& p : corners) {
      m_polys->InsertCellPoint(m_points->InsertNextPoint(p.x, p.y, p.z));
      m_normals->InsertNextTuple3(normal.x, normal.y, normal.z);
    }
  }

  vtkSmartPointer<vtkPolyData> polyData() const {
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(m_points);
    data->SetPolys(m_polys);
    data->GetPointData()->SetNormals(m_normals);
    return data;
  }

 private:
  vtkNew<vtkPoints> m_points;
  vtkNew<vtkCellArray> m_polys;
  vtkNew<vtkDoubleArray> m_normals;
};

/// Adds a one-sided polygon turned so that its normal faces `inside` (when not on it).
void addFacing(FlatPolygons& polygons, std::vector<Point3> corners, Normal3 normal,
               const Point3& inside) {
  if (glm::dot(inside - corners.front(), normal) < 0.0) {
    std::reverse(corners.begin(), corners.end());
    normal = -normal;
  }
  polygons.add(corners, normal);
}

vtkSmartPointer<vtkMatrix4x4> toVtk(const Mat4& m) {
  auto out = vtkSmartPointer<vtkMatrix4x4>::New();
  // GLM is column-major (m[column][row]); VTK's Element is [row][column].
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) out->SetElement(row, column, m[column][row]);
  }
  return out;
}

vtkSmartPointer<vtkPolyData> sphereGeometry(const Sphere& sphere) {
  // Step 1: the round sphere in object space; VTK's theta runs around the z axis (n
  // slices) and phi from pole to pole (m slices), as the original course program's m, n.
  vtkNew<vtkSphereSource> source;
  source->SetCenter(sphere.centre().x, sphere.centre().y, sphere.centre().z);
  source->SetRadius(sphere.radius());
  source->SetThetaResolution(std::max(sphere.n(), 3));
  source->SetPhiResolution(std::max(sphere.m(), 3));
  source->Update();
  if (sphere.worldFromObject().isIdentity()) return source->GetOutput();

  // Step 2: map to world space; normals go through the inverse transpose.
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(toVtk(sphere.worldFromObject().matrix()));
  vtkNew<vtkTransformPolyDataFilter> mapped;
  mapped->SetTransform(transform);
  mapped->SetInputConnection(source->GetOutputPort());
  mapped->Update();
  return mapped->GetOutput();
}

vtkSmartPointer<vtkPolyData> planeGeometry(const Plane& plane, const DrawingFrame& frame) {
  // Step 1: centre the square on the point of the plane nearest the room.
  const Normal3 n = glm::normalize(plane.planeNormal());
  const Point3 centre = frame.inside - glm::dot(frame.inside - plane.point(), n) * n;
  const Vec3 a = std::abs(n.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  const Vec3 u = glm::normalize(glm::cross(n, a)) * frame.planeHalfSize;
  const Vec3 v = glm::cross(n, glm::normalize(u)) * frame.planeHalfSize;

  // Step 2: u x v = n, so this order is counter-clockwise seen from the front.
  FlatPolygons polygons;
  addFacing(polygons, {centre - u - v, centre + u - v, centre + u + v, centre - u + v}, n,
            frame.inside);
  return polygons.polyData();
}

vtkSmartPointer<vtkPolyData> quadGeometry(const Quad& quad, const DrawingFrame& frame) {
  const Point3 c = quad.corner();
  const Vec3 u = quad.edgeU();
  const Vec3 v = quad.edgeV();
  FlatPolygons polygons;
  addFacing(polygons, {c, c + u, c + u + v, c + v}, glm::normalize(glm::cross(u, v)), frame.inside);
  return polygons.polyData();
}

vtkSmartPointer<vtkPolyData> triangleGeometry(const Triangle& triangle, const DrawingFrame& frame) {
  const Point3 p0 = triangle.vertex(0);
  const Point3 p1 = triangle.vertex(1);
  const Point3 p2 = triangle.vertex(2);
  FlatPolygons polygons;
  addFacing(polygons, {p0, p1, p2}, glm::normalize(glm::cross(p1 - p0, p2 - p0)), frame.inside);
  return polygons.polyData();
}

vtkSmartPointer<vtkPolyData> meshGeometry(const TriangleMesh& mesh) {
  // A mesh with corner normals is drawn with them, as the ray tracer shades it: a point
  // per corner, each with its normal turned to its triangle's side.
  if (mesh.hasNormals()) {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> triangles;
    vtkNew<vtkDoubleArray> normals;
    normals->SetNumberOfComponents(3);
    normals->SetName("Normals");
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      const TriangleMesh::Index3& tri = mesh.triangles()[t];
      vtkIdType ids[3];
      for (int k = 0; k < 3; ++k) {
        const Point3& p = mesh.vertices()[std::size_t(tri[k])];
        ids[k] = points->InsertNextPoint(p.x, p.y, p.z);
        const Normal3 n = mesh.shadingNormal(int(t), k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0);
        normals->InsertNextTuple3(n.x, n.y, n.z);
      }
      triangles->InsertNextCell(3, ids);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(triangles);
    data->GetPointData()->SetNormals(normals);
    return data;
  }
  vtkNew<vtkPoints> points;
  for (const Point3& p : mesh.vertices()) points->InsertNextPoint(p.x, p.y, p.z);
  vtkNew<vtkCellArray> triangles;
  for (const TriangleMesh::Index3& t : mesh.triangles()) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    triangles->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> raw;
  raw->SetPoints(points);
  raw->SetPolys(triangles);

  // Smooth normals within a surface, sharp edges kept above 30 degrees; the file's
  // winding is trusted (no reorientation), as the ray tracer trusts it.
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(raw);
  normals->SetFeatureAngle(30.0);
  normals->SplittingOn();
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  normals->Update();
  return normals->GetOutput();
}

}  // namespace

vtkSmartPointer<vtkPolyData> hexahedronGeometry(const std::array<Point3, 8>& corners) {
  Point3 centroid(0.0);
  for (const Point3& p : corners) centroid += p / 8.0;

  FlatPolygons polygons;
  for (int axis = 0; axis < 3; ++axis) {
    // The two other axes in cyclic order, so that (b, c) walks the face counter-clockwise
    // seen from the positive side of `axis` in box coordinates.
    const int b = (axis + 1) % 3;
    const int c = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      std::vector<Point3> face;
      const int walk[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (const auto& step : walk) {
        const int k = (side << axis) | (step[0] << b) | (step[1] << c);
        face.push_back(corners[static_cast<std::size_t>(k)]);
      }
      // Turn the face outward, whatever the handedness of the corners' map.
      Normal3 n = glm::cross(face[1] - face[0], face[3] - face[0]);
      const double length = glm::length(n);
      if (length == 0.0) continue;
      n /= length;
      Point3 faceCentre(0.0);
      for (const Point3& p : face) faceCentre += p / 4.0;
      if (glm::dot(n, faceCentre - centroid) < 0.0) {
        std::reverse(face.begin(), face.end());
        n = -n;
      }
      polygons.add(face, n);
    }
  }
  return polygons.polyData();
}

vtkSmartPointer<vtkPolyData> shapeGeometry(const Shape& shape, const DrawingFrame& frame) {
  switch (shape.kind()) {
    case ShapeKind::Sphere:
      return sphereGeometry(static_cast<const Sphere&>(shape));
    case ShapeKind::Box:
      return hexahedronGeometry(static_cast<const Box&>(shape).vertices());
    case ShapeKind::Plane:
      return planeGeometry(static_cast<const Plane&>(shape), frame);
    case ShapeKind::Quad:
      return quadGeometry(static_cast<const Quad&>(shape), frame);
    case ShapeKind::Triangle:
      return triangleGeometry(static_cast<const Triangle&>(shape), frame);
    case ShapeKind::TriangleMesh:
      return meshGeometry(static_cast<const TriangleMesh&>(shape));
  }
  return vtkSmartPointer<vtkPolyData>::New();
}

namespace {

/// Right, up and backward unit axes of the scene camera (it looks down its -z).
struct CameraFrame {
  Vec3 right, up, back;
};

CameraFrame cameraFrame(const CameraSpec& camera) {
  Vec3 forward = camera.lookAt - camera.position;
  forward = glm::length(forward) > 0.0 ? glm::normalize(forward) : Vec3(0.0, 0.0, -1.0);
  Vec3 right = glm::cross(forward, camera.up);
  if (glm::length(right) < 1e-12) right = glm::cross(forward, Vec3(1.0, 0.0, 0.0));
  right = glm::normalize(right);
  return {right, glm::cross(right, forward), -forward};
}

}  // namespace

vtkSmartPointer<vtkPolyData> cameraBodyGeometry(const CameraSpec& camera, double size) {
  const CameraFrame f = cameraFrame(camera);
  // A body wider than tall, deeper than wide, with its front face at the eye.
  const Vec3 half(0.5 * size, 0.35 * size, 0.6 * size);
  const Point3 centre = camera.position + half.z * f.back;
  std::array<Point3, 8> corners;
  for (int k = 0; k < 8; ++k) {
    const Point3 b = Box::canonicalVertex(k);
    corners[static_cast<std::size_t>(k)] =
        centre + b.x * half.x * f.right + b.y * half.y * f.up + b.z * half.z * f.back;
  }
  return hexahedronGeometry(corners);
}

vtkSmartPointer<vtkPolyData> cameraFrustumGeometry(const CameraSpec& camera, double length) {
  const CameraFrame f = cameraFrame(camera);
  const double distance = length > 0.0 ? length : 1.0;
  const double aspect = camera.height > 0 ? static_cast<double>(camera.width) / camera.height : 1.0;
  const double halfHeight = distance * std::tan(radians(camera.verticalFov) / 2.0);
  const double halfWidth = halfHeight * aspect;
  const Point3 centre = camera.position - distance * f.back;

  vtkNew<vtkPoints> points;
  points->InsertNextPoint(camera.position.x, camera.position.y, camera.position.z);
  const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (const auto& s : signs) {
    const Point3 p = centre + s[0] * halfWidth * f.right + s[1] * halfHeight * f.up;
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> lines;
  for (vtkIdType corner = 1; corner <= 4; ++corner) {
    const vtkIdType edge[2] = {0, corner};
    lines->InsertNextCell(2, edge);
  }
  const vtkIdType rectangle[5] = {1, 2, 3, 4, 1};
  lines->InsertNextCell(5, rectangle);

  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  return data;
}

vtkSmartPointer<vtkPolyData> wallPatchGeometry(const Sphere& sphere, const DrawingFrame& frame,
                                               double halfSize) {
  // Step 1: the point of the sphere nearest the room, and its tangent plane's axes.
  const Point3 c = sphere.centre();
  const double r = sphere.radius();
  Vec3 toRoom = frame.inside - c;
  toRoom = glm::length(toRoom) > 0.0 ? glm::normalize(toRoom) : Vec3(0.0, 1.0, 0.0);
  const Point3 nearest = c + r * toRoom;
  const Vec3 a = std::abs(toRoom.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  const Vec3 u = glm::normalize(glm::cross(toRoom, a));
  const Vec3 v = glm::cross(toRoom, u);

  // Step 2: a grid on the tangent plane, each vertex moved onto the sphere.
  constexpr int kCells = 32;
  vtkNew<vtkPoints> points;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      const double s = halfSize * (2.0 * i / kCells - 1.0), t = halfSize * (2.0 * j / kCells - 1.0);
      const Point3 onPlane = nearest + s * u + t * v;
      const Point3 p = c + r * glm::normalize(onPlane - c);
      points->InsertNextPoint(p.x, p.y, p.z);
    }

  // Step 3: two triangles per cell, wound so that their normal faces the room.
  const bool roomInside = glm::length(frame.inside - c) < r;
  vtkNew<vtkCellArray> cells;
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const vtkIdType p00 = j * (kCells + 1) + i, p10 = p00 + 1, p01 = p00 + kCells + 1,
                      p11 = p01 + 1;
      // u x v = toRoom: counter-clockwise in (u, v) faces away from the centre.
      const vtkIdType outward[2][3] = {{p00, p10, p11}, {p00, p11, p01}};
      const vtkIdType inward[2][3] = {{p00, p11, p10}, {p00, p01, p11}};
      for (const auto& tri : roomInside ? inward : outward) cells->InsertNextCell(3, tri);
    }
  auto patch = vtkSmartPointer<vtkPolyData>::New();
  patch->SetPoints(points);
  patch->SetPolys(cells);
  return patch;
}

}  // namespace raylab::vis
