// Rays, shapes, their double-precision intersections and the exact oracle (CGAL), so a
// notebook can hold the floating-point hit next to the exact one.

#include "Bindings.h"

#include "raylab/core/Box.h"
#include "raylab/core/ExactOracle.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Ray.h"
#include "raylab/core/Shape.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Triangle.h"
#include "raylab/core/TriangleMesh.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace raylab::python {
namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// A 4 x 4 matrix written row by row (as in scene files) as a column-major glm matrix.
Mat4 toMat4(const DoubleArray& rows) {
  if (rows.ndim() != 2 || rows.shape(0) != 4 || rows.shape(1) != 4)
    throw py::value_error("matrix must be 4 x 4 (rows of 4 numbers)");
  Mat4 m(1.0);
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) m[col][row] = rows.at(row, col);
  return m;
}

/// A ray's point or vector with finite components; ValueError naming it otherwise (the
/// exact oracle cannot take NaN or an infinity, issue 38).
const Vec3& requireFinite(const Vec3& v, const char* what) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    throw py::value_error(std::string(what) + " must be finite, got " + toString(v));
  return v;
}

/// A ray parameter that is a number (an infinite t_max is no bound); ValueError for NaN.
double requireNotNan(double t, const char* what) {
  if (std::isnan(t)) throw py::value_error(std::string(what) + " must be a number, not NaN");
  return t;
}

}  // namespace

namespace {

/// raylab.Ray, Hit, SurfaceInteraction and Crossing: what rays and hits are.
void bindRays(py::module_& m) {
  py::class_<Ray>(m, "Ray", "A half-line origin + t direction, t in [t_min, t_max] (world space).")
      .def(py::init([](const Point3& origin, const Vec3& direction, double tMin, double tMax,
                       double time) {
             requireFinite(origin, "origin");
             requireFinite(direction, "direction");
             requireNotNan(tMin, "t_min");
             requireNotNan(tMax, "t_max");
             requireNotNan(time, "time");
             // Divided by its largest component first: a direction of 1e300 has an infinite
             // length and one of 1e-320 a zero one.
             const double big =
                 std::max({std::abs(direction.x), std::abs(direction.y), std::abs(direction.z)});
             if (big == 0.0) throw py::value_error("direction must not be zero");
             return Ray::make(origin, direction / big, tMin, tMax, time);
           }),
           py::arg("origin"), py::arg("direction"), py::arg("t_min") = 0.0,
           py::arg("t_max") = kInfinity, py::arg("time") = 0.0,
           "The direction is normalised (Ray::make).")
      .def_property(
          "origin", [](const Ray& r) { return r.origin; },
          [](Ray& r, const Point3& p) { r.origin = requireFinite(p, "origin"); })
      .def_property(
          "direction", [](const Ray& r) { return r.direction; },
          [](Ray& r, const Vec3& d) {
            requireFinite(d, "direction");
            if (glm::length(d) == 0.0) throw py::value_error("direction must not be zero");
            r.direction = d;
          })
      .def_property(
          "t_min", [](const Ray& r) { return r.tMin; },
          [](Ray& r, double t) { r.tMin = requireNotNan(t, "t_min"); })
      .def_property(
          "t_max", [](const Ray& r) { return r.tMax; },
          [](Ray& r, double t) { r.tMax = requireNotNan(t, "t_max"); })
      .def_property(
          "time", [](const Ray& r) { return r.time; },
          [](Ray& r, double t) { r.time = requireNotNan(t, "time"); })
      .def("at", &Ray::at, py::arg("t"), "The point at parameter t.")
      .def("__repr__", &Ray::toString);

  py::class_<Hit>(m, "Hit", "First phase of an intersection: where along the ray, which primitive.")
      .def_readonly("t", &Hit::t)
      .def_readonly("primitive", &Hit::primitive)
      .def_readonly("uv", &Hit::uv)
      .def("__repr__", [](const Hit& h) {
        return "Hit(t=" + std::to_string(h.t) + ", primitive=" + std::to_string(h.primitive) + ")";
      });

  py::class_<SurfaceInteraction>(m, "SurfaceInteraction", "The geometry at a hit (world space).")
      .def_readonly("t", &SurfaceInteraction::t)
      .def_readonly("point", &SurfaceInteraction::p)
      .def_readonly("normal", &SurfaceInteraction::n, "Unit geometric normal, pointing outward.")
      .def_readonly("front_face", &SurfaceInteraction::frontFace)
      .def_readonly("uv", &SurfaceInteraction::uv)
      .def_readonly("primitive", &SurfaceInteraction::primitive)
      .def_property_readonly("facing_normal", &SurfaceInteraction::facingNormal)
      .def_property_readonly("shading_normal", &SurfaceInteraction::shadingNormal,
                             "Unit shading normal, outward: a smooth mesh's interpolated vertex "
                             "normals, else the geometric normal.")
      .def("__repr__", &SurfaceInteraction::toString);

  py::class_<Crossing>(m, "Crossing", "One crossing of a surface along a ray.")
      .def_readonly("t", &Crossing::t)
      .def_readonly("entering", &Crossing::entering)
      .def_readonly("primitive", &Crossing::primitive)
      .def("__repr__", [](const Crossing& c) {
        return std::string("Crossing(t=") + std::to_string(c.t) +
               (c.entering ? ", entering)" : ", leaving)");
      });
}

/// raylab.Shape and the primitives a Python program can make.
void bindShapes(py::module_& m) {
  py::class_<Shape, std::shared_ptr<Shape>>(m, "Shape", R"(A primitive a ray can hit (world space).
Made with Sphere, Box, Plane, Quad, Triangle, TriangleMesh or Scene.shape(name).)")
      .def_property_readonly("kind", [](const Shape& s) { return std::string(toString(s.kind())); })
      .def("intersect", &Shape::intersect, py::arg("ray"),
           "Nearest hit in [t_min, t_max] in doubles (a Hit), or None.")
      .def("closest_hit", &Shape::closestHit, py::arg("ray"),
           "Nearest hit with its geometry (a SurfaceInteraction), or None.")
      .def("surface_at", &Shape::surfaceAt, py::arg("ray"), py::arg("hit"))
      .def("intersect_all", &Shape::intersectAll, py::arg("ray"),
           "Every crossing in [t_min, t_max], sorted by t (entering / leaving).")
      .def("normal", &Shape::normal, py::arg("point"))
      .def("inside", &Shape::inside, py::arg("point"))
      .def("bounds",
           [](const Shape& s) {
             const Bounds3 b = s.bounds();
             return py::make_tuple(toTuple(b.lower), toTuple(b.upper));
           })
      .def("area", &Shape::area)
      .def(
          "apply", [](Shape& s, const DoubleArray& matrix) { s.apply(toMat4(matrix)); },
          py::arg("matrix"), "Transforms the shape in world space by a 4 x 4 matrix (new = M old).")
      .def("__repr__", &Shape::toString);

  py::class_<Sphere, Shape, std::shared_ptr<Sphere>>(m, "Sphere")
      .def(py::init<const Point3&, double, int, int>(), py::arg("centre"), py::arg("radius"),
           py::arg("m") = 24, py::arg("n") = 24);
  py::class_<Box, Shape, std::shared_ptr<Box>>(m, "Box").def(py::init<const Point3&, const Vec3&>(),
                                                             py::arg("centre"), py::arg("size"));
  py::class_<Plane, Shape, std::shared_ptr<Plane>>(m, "Plane")
      .def(py::init<const Point3&, const Normal3&>(), py::arg("point"), py::arg("normal"));
  py::class_<Quad, Shape, std::shared_ptr<Quad>>(m, "Quad").def(
      py::init<const Point3&, const Vec3&, const Vec3&>(), py::arg("corner"), py::arg("u"),
      py::arg("v"));
  py::class_<Triangle, Shape, std::shared_ptr<Triangle>>(m, "Triangle")
      .def(py::init<const Point3&, const Point3&, const Point3&>(), py::arg("p0"), py::arg("p1"),
           py::arg("p2"));
  py::class_<TriangleMesh, Shape, std::shared_ptr<TriangleMesh>>(m, "TriangleMesh")
      .def(py::init([](const std::vector<Point3>& vertices,
                       const std::vector<std::array<int, 3>>& triangles) {
             return std::make_shared<TriangleMesh>(vertices, triangles);
           }),
           py::arg("vertices"), py::arg("triangles"))
      .def(
          "compute_crease_normals",
          [](TriangleMesh& mesh, double degrees) { mesh.computeCreaseNormals(radians(degrees)); },
          py::arg("crease_angle"),
          "Smooth shading: vertex normals averaged over the faces within crease_angle degrees.")
      .def_property_readonly("has_normals", &TriangleMesh::hasNormals);
}

/// The exact (CGAL) oracle: its answer, the comparison with the double one.
void bindExactOracle(py::module_& m) {
  py::class_<ExactResult>(m, "ExactResult", "The exact (CGAL) answer for one ray and one shape.")
      .def_property_readonly(
          "classification",
          [](const ExactResult& r) { return std::string(toString(r.classification)); })
      .def_property_readonly("hit", &ExactResult::hit)
      .def_readonly("t", &ExactResult::t, "Exact t, correctly rounded to a double.")
      .def_readonly("t_lower", &ExactResult::tLower)
      .def_readonly("t_upper", &ExactResult::tUpper)
      .def_readonly("primitive", &ExactResult::primitive)
      .def_readonly("margin", &ExactResult::margin)
      .def_readonly("cosine", &ExactResult::cosine)
      .def_readonly("line_crossings", &ExactResult::lineCrossings)
      .def("__repr__", &ExactResult::toString);

  py::class_<OracleComparison>(m, "OracleComparison", "The exact answer next to the double one.")
      .def_readonly("exact", &OracleComparison::exact)
      .def_readonly("floating", &OracleComparison::floating)
      .def_readonly("agree", &OracleComparison::agree)
      .def_readonly("t_error", &OracleComparison::tError)
      .def_readonly("t_error_ulps", &OracleComparison::tErrorUlps)
      .def("__repr__", &OracleComparison::toString);

  m.def("exact_classify", &ExactOracle::classify, py::arg("shape"), py::arg("ray"),
        "The exact oracle's classification: miss, hit, tangent, through edge or vertex.");
  m.def("oracle_compare", &ExactOracle::compare, py::arg("shape"), py::arg("ray"),
        "The exact answer next to shape.intersect(ray) in doubles.");
}

}  // namespace

void bindGeometry(py::module_& m) {
  bindRays(m);
  bindShapes(m);
  bindExactOracle(m);
}

}  // namespace raylab::python
