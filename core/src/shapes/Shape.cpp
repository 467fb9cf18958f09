#include "raylab/core/Shape.h"

#include "raylab/core/Check.h"
#include "shapes/ShapeFormat.h"

#include <algorithm>

namespace raylab {

namespace detail {
// Each defined beside its shape (core/src/shapes/<Shape>.cpp).
const ShapeFormat& sphereFormat();
const ShapeFormat& boxFormat();
const ShapeFormat& planeFormat();
const ShapeFormat& quadFormat();
const ShapeFormat& triangleFormat();
const ShapeFormat& meshFormat();
}  // namespace detail

const std::vector<const ShapeFormat*>& shapeFormats() {
  // The one list of the built-in shapes, in the order of ShapeKind.
  static const std::vector<const ShapeFormat*> all = {
      &detail::sphereFormat(), &detail::boxFormat(),      &detail::planeFormat(),
      &detail::quadFormat(),   &detail::triangleFormat(), &detail::meshFormat()};
  return all;
}

const ShapeFormat* shapeFormat(std::string_view word) {
  for (const ShapeFormat* format : shapeFormats())
    if (word == format->word) return format;
  return nullptr;
}

const ShapeFormat& shapeFormat(ShapeKind kind) {
  const std::vector<const ShapeFormat*>& all = shapeFormats();
  const auto found =
      std::find_if(all.begin(), all.end(), [&](const ShapeFormat* f) { return f->kind == kind; });
  RAYLAB_CHECK(found != all.end());  // every ShapeKind has its row
  return **found;
}

std::string shapeWordList() {
  const std::vector<const ShapeFormat*>& all = shapeFormats();
  std::string list;
  for (std::size_t i = 0; i < all.size(); ++i)
    list += (i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + std::string(all[i]->word);
  return list;
}

const char* toString(ShapeKind kind) { return shapeFormat(kind).word; }

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
