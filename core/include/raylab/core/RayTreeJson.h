#pragma once

#include "raylab/core/Exception.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

/**
 * \brief A recorded ray tree as JSON: the dump of `raylab trace --json`, for students'
 * scripts and for tests that compare trees.
 *
 * The document holds what the tree is of (format version, scene name, algorithm, seed,
 * pixel, sample, the estimate and the rays traced by kind) and every field of every
 * RaySegment under a snake_case name, vectors as [x, y, z] arrays, kinds and end reasons
 * as words ("camera", "occluded", ...), plus the hit object's name. Numbers are written
 * with enough digits to read back the same doubles.
 *
 *     {"raylab_ray_tree": 1, "scene": "...", "algorithm": "whitted", "seed": 1,
 *      "pixel": [64, 150], "sample": 0, "estimate": [r, g, b], "rays": 22,
 *      "rays_by_kind": {"camera": 1, ...}, "truncated": false, "message": "",
 *      "segments": [{"id": 0, "parent": -1, "first_child": 1, "child_count": 2,
 *                    "kind": "camera", "depth": 0, "origin": [...], "direction": [...],
 *                    "time": 0, "hit": true, "end_point": [...], "light_point": [...],
 *                    "object": 2, "object_name": "glass sphere", "normal": [...],
 *                    "weight": [...], "pdf": 0, "throughput": [...], "emitted": [...],
 *                    "radiance": [...], "end_reason": "spawned"}, ...]}
 */
class RayTreeJson {
 public:
  /// A file that cannot be written or a document that is not a ray tree.
  class Error : public Exception {
   public:
    using Exception::Exception;
  };

  /// What a dump says about the tree besides its segments.
  struct Info {
    int version = kVersion;
    std::string scene;                     ///< Scene::name.
    std::string algorithm;                 ///< toString(Algorithm), e.g. "whitted".
    std::uint64_t seed = 0;                ///< RenderSettings::seed.
    Vec3 estimate{0.0};                    ///< RayTree::estimate().
    std::vector<std::string> objectNames;  ///< "object_name" of each segment (empty: none).
  };

  /// Format version written in "raylab_ray_tree".
  static constexpr int kVersion = 1;

  /// The JSON text of `tree`, traced in `scene` with `settings` (indented by 1 space).
  static std::string serialize(const RayTree& tree, const Scene& scene,
                               const RenderSettings& settings);
  /// Writes serialize() to `path` through a temporary file and a rename, so the file is
  /// either complete or untouched. Throws Error naming the file.
  static void save(const RayTree& tree, const Scene& scene, const RenderSettings& settings,
                   const std::string& path);
  /// Reads a dump back (every segment field, pixel, sample, truncation). `origin` names
  /// the text in errors. Fills `info` when given. Throws Error on a malformed document.
  static RayTree parse(const std::string& text, const std::string& origin, Info* info = nullptr);
  /// parse() of the file at `path`.
  static RayTree load(const std::string& path, Info* info = nullptr);

  /// Stable word of an end reason in dumps ("reached_light", "russian_roulette", ...).
  static const char* endReasonName(EndReason reason);

  /// Calls `put(key, value)` for each field of ray `s` that its dump holds, under the dump's
  /// key, in order; a value is an int, a bool, a double, a std::string or a Vec3. The one
  /// list of a ray's fields: serialize writes it, Python's Segment.to_dict reads it.
  template <typename Put>
  static void forEachField(const RaySegment& s, const Scene& scene, Put&& put);
};

template <typename Put>
void RayTreeJson::forEachField(const RaySegment& s, const Scene& scene, Put&& put) {
  const bool named = s.object >= 0 && s.object < int(scene.objects.size());
  put("id", s.id);
  put("parent", s.parent);
  put("first_child", s.firstChild);
  put("child_count", s.childCount);
  put("kind", std::string(toString(s.kind)));
  put("depth", s.depth);
  put("origin", s.origin);
  put("direction", s.direction);
  put("time", s.time);
  put("hit", s.hit);
  put("end_point", s.endPoint);
  put("light_point", s.lightPoint);
  put("object", s.object);
  put("object_name", named ? scene.objects[std::size_t(s.object)].name : std::string());
  // A shadow ray's light: an area light (an object) or a point light, and its name.
  const std::string light = lightNameOf(s, scene);
  if (!light.empty()) {
    if (s.lightObject >= 0)
      put("light_object", s.lightObject);
    else
      put("point_light", s.pointLight);
    put("light_name", light);
  }
  put("normal", s.normal);
  if (!isZero(s.shadingNormal)) put("shading_normal", s.shadingNormal);
  put("weight", s.weight);
  put("pdf", s.pdf);
  put("throughput", s.throughput);
  put("emitted", s.emitted);
  put("radiance", s.radiance);
  put("end_reason", std::string(endReasonName(s.endReason)));
}

}  // namespace raylab
