#include "raylab/core/Shape.h"

namespace raylab {

const char* toString(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::Sphere:
      return "sphere";
    case ShapeKind::Box:
      return "box";
    case ShapeKind::Plane:
      return "plane";
    case ShapeKind::Quad:
      return "quad";
    case ShapeKind::Triangle:
      return "triangle";
    case ShapeKind::TriangleMesh:
      return "mesh";
  }
  return "unknown";
}

std::optional<SurfaceInteraction> Shape::closestHit(const Ray& ray) const {
  const std::optional<Hit> hit = intersect(ray);
  if (!hit) return std::nullopt;
  return surfaceAt(ray, *hit);
}

std::string SurfaceInteraction::toString() const {
  return "SurfaceInteraction[t=" + std::to_string(t) + ", p=" + raylab::toString(p) +
         ", n=" + raylab::toString(n) +
         (isZero(ns) ? std::string() : ", ns=" + raylab::toString(ns)) +
         (frontFace ? ", front" : ", back") + ", primitive=" + std::to_string(primitive) + "]";
}

}  // namespace raylab
