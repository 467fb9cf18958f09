#pragma once

#include "raylab/core/Check.h"
#include "raylab/core/Types.h"
#include "scene/SceneKeys.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstring>
#include <utility>
#include <vector>

/// \file ObjectWriter.h
/// What the scene writer (SceneWriter.cpp) and each shape's writer (ShapeFormat.h) build a
/// scene file's JSON with. Private to core.

namespace raylab {

using ojson = nlohmann::ordered_json;

/**
 * One JSON object of a scene file being written. Its keys can only come from the object's
 * list (SceneKeys.h, or the shape's own in its ShapeFormat), in the list's order, so the
 * writer cannot emit a key the reader would reject; breaking that is a bug in RayLab, caught
 * (RAYLAB_CHECK) at the first save.
 */
class ObjectWriter {
 public:
  template <std::size_t N>
  explicit ObjectWriter(const std::array<const char*, N>& keys)
      : m_keys(keys.data()), m_keyCount(N) {}
  explicit ObjectWriter(const std::vector<const char*>& keys)
      : m_keys(keys.data()), m_keyCount(keys.size()) {}

  /// Adds `key: value`; `key` must come later in the list than the keys added before it.
  ObjectWriter& add(const char* key, ojson value) {
    while (m_next < m_keyCount && std::strcmp(m_keys[m_next], key) != 0) ++m_next;
    RAYLAB_CHECK(m_next < m_keyCount);  // not in the list, or out of the list's order
    m_object[m_keys[m_next++]] = std::move(value);
    return *this;
  }

  ojson take() { return std::move(m_object); }

 private:
  const char* const* m_keys;
  std::size_t m_keyCount;
  std::size_t m_next = 0;  ///< First list entry that may still be added.
  ojson m_object = ojson::object();
};

inline ojson toJson(const Vec3& v) { return ojson::array({v.x, v.y, v.z}); }

inline ojson toJson(const Mat4& m) {
  ojson rows = ojson::array();
  for (int r = 0; r < 4; ++r) rows.push_back(ojson::array({m[0][r], m[1][r], m[2][r], m[3][r]}));
  return rows;
}

/// A "transform" of one matrix step.
inline ojson matrixTransform(const Mat4& m) {
  return ojson::array({ObjectWriter(kTransformStepKeys).add("matrix", toJson(m)).take()});
}

}  // namespace raylab
