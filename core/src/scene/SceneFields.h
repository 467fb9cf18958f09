#pragma once

#include "io/JsonChecks.h"
#include "raylab/core/Types.h"

#include <nlohmann/json.hpp>

#include <string>

/// \file SceneFields.h
/// The checked reads of a scene file's values (numbers, points, sizes, directions,
/// matrices), each failing with a SceneIO::LoadError that names the file and the JSON place.
/// The scene reader (SceneReader.cpp) and each shape's reader (ShapeFormat.h) use them.
/// Private to core.

namespace raylab {

class SceneFields : public JsonChecks<SceneFields> {
  friend class JsonChecks<SceneFields>;

 public:
  using json = nlohmann::json;

  /// Reads for the scene file `origin` (its name starts every message).
  explicit SceneFields(std::string origin);

  /// Throws SceneIO::LoadError "<origin>: at <path>: <what>".
  [[noreturn]] void fail(const std::string& path, const std::string& what) const;

  /// The folder of the scene file: mesh paths are relative to it.
  const std::string& baseDir() const { return m_baseDir; }

  using JsonChecks::boolean;
  using JsonChecks::integer;
  using JsonChecks::integerIn;
  using JsonChecks::member;
  using JsonChecks::number;
  using JsonChecks::onlyKeys;
  using JsonChecks::string;

  /// A number within +-limits::kMaxCoordinate (a coordinate, a size, a colour).
  double bounded(const json& j, const std::string& path) const;
  Vec3 vec3(const json& j, const std::string& path) const;
  /// A size (radius, box side): positive, in [limits::kMinLength, limits::kMaxCoordinate].
  double length(const json& j, const std::string& path, const char* what) const;
  /// A vector that gives a direction: not zero, and not so short that its squared length
  /// underflows ([0, 1e-300, 0] used to abort in Transform).
  Vec3 nonZero(const json& j, const std::string& path) const;
  /// An affine, invertible 4 x 4 matrix, given as 4 rows of 4 numbers.
  Mat4 matrix(const json& j, const std::string& path) const;

 private:
  std::string m_origin;
  std::string m_baseDir;
};

}  // namespace raylab
