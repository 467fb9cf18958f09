#pragma once

#include "raylab/core/Shape.h"

#include <nlohmann/json_fwd.hpp>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

/// \file ShapeFormat.h
/// The shape descriptors: each built-in shape's word, keys, reader and writer in a scene
/// file, defined beside the shape (`core/src/shapes/<Shape>.cpp`, `detail::<shape>Format()`)
/// and listed once, in `shapeFormats()` (Shape.cpp). The scene reader and writer look a
/// shape up here by its word or its kind (as pbrt-v4's Shape::Create by name). Private to
/// core.

namespace raylab {

class SceneFields;
struct SceneObject;

/// How one kind of shape is read from and written to a scene file.
struct ShapeFormat {
  ShapeKind kind;
  /// Its "type" in a scene file, and toString(kind).
  const char* word;
  /// The keys its JSON object may hold, in the order the writer emits them.
  std::vector<const char*> keys;
  /// Reads the shape's JSON object `j` at JSON place `path`, its keys checked, every problem
  /// a SceneIO::LoadError through `in`; a mesh also fills `object`'s source and normals.
  /// Shape::InvalidGeometry may escape: the scene reader names `path` with it.
  std::unique_ptr<Shape> (*read)(const nlohmann::json& j, const std::string& path,
                                 const SceneFields& in, SceneObject& object);
  /// The JSON object of `object`'s shape as it now is, for a file in folder `sceneDir`; a
  /// transform its keys cannot hold goes to `transform` (left untouched otherwise).
  nlohmann::ordered_json (*write)(const SceneObject& object, const std::string& sceneDir,
                                  nlohmann::ordered_json& transform);
  /// The JSON object of a new one added from the window or Python (edit::addShape): about
  /// `size` across at `p`, facing the camera, whose right and up are `right` and `up`;
  /// nullptr for a shape made otherwise (a mesh, from its file).
  nlohmann::ordered_json (*example)(const Point3& p, double size, const Vec3& right,
                                    const Vec3& up);
};

/// Every built-in shape's format, in the order of ShapeKind.
const std::vector<const ShapeFormat*>& shapeFormats();
/// The format whose word is `word`, or nullptr.
const ShapeFormat* shapeFormat(std::string_view word);
/// The format of `kind`.
const ShapeFormat& shapeFormat(ShapeKind kind);
/// The words of every shape, "sphere, box, plane, quad, triangle or mesh".
std::string shapeWordList();

}  // namespace raylab
