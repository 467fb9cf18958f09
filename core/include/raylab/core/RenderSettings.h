#pragma once

#include "raylab/core/Bvh.h"
#include "raylab/core/Types.h"

#include <cstdint>
#include <optional>
#include <string>

namespace raylab {

/// The four algorithms RayLab teaches, in historical order.
enum class Algorithm {
  RayCasting,   ///< Appel 1968: primary ray, local shading, shadow rays; no recursion.
  Whitted,      ///< Whitted 1979: + recursive perfect reflection and refraction.
  Distributed,  ///< Cook 1984: many rays per pixel and per bounce (soft shadows, gloss,
                ///< depth of field, motion blur).
  PathTracing,  ///< Kajiya 1986: one sampled continuation per bounce, Russian roulette,
                ///< next-event estimation with MIS; unbiased.
};
/// "raycast", "whitted", "distributed", "path".
const char* toString(Algorithm algorithm);
/// Parses the names above; nothing for an unknown name.
std::optional<Algorithm> parseAlgorithm(const std::string& name);

/**
 * \brief Parameters of a render. Every algorithm reads the fields it needs.
 *
 * | field | default | used by |
 * | --- | --- | --- |
 * | algorithm | path | all |
 * | samplesPerPixel | 16 | all (classic algorithms: antialiasing samples) |
 * | maxDepth | 5 | all but ray casting (camera ray = depth 0) |
 * | seed | 1 | all |
 * | shadowSamples | 4 | distributed: shadow rays per area light per hit |
 * | glossySamples | 4 | distributed: rays per glossy bounce |
 * | russianRouletteDepth | 3 | path: first depth where paths may be stopped |
 * | nextEventEstimation | true | path: shadow rays to lights at every diffuse/glossy hit |
 * | multipleImportance | true | path: MIS (power heuristic) of light and BSDF sampling |
 * | rayOffset | true | all: secondary rays start past the hit's error bound (RayOffset.h); |
 * | | | false starts them on the computed hit point and shows shadow acne (lesson 2) |
 * | acceleration | true | all: meshes are searched through their BVH; false tests every |
 * | | | triangle of every mesh (brute force, lesson 8): the same hits, bit for bit, slower |
 * | bvhSplit | sah | all: how the meshes' BVHs split nodes (surface-area heuristic or median); |
 * | | | the hits are the same either way, only the boxes visited differ (lesson 8) |
 */
struct RenderSettings {
  Algorithm algorithm = Algorithm::PathTracing;  ///< Which algorithm renders.
  int samplesPerPixel = 16;                      ///< Samples per pixel (camera rays per pixel).
  int maxDepth = 5;                 ///< Longest chain of bounces; the camera ray has depth 0.
  std::uint64_t seed = 1;           ///< Seed of every random decision.
  int shadowSamples = 4;            ///< Distributed: shadow rays per area light at each hit.
  int glossySamples = 4;            ///< Distributed: rays spawned at each glossy hit.
  int russianRouletteDepth = 3;     ///< Path tracing: depth from which roulette may end paths.
  bool nextEventEstimation = true;  ///< Path tracing: sample lights directly.
  bool multipleImportance = true;   ///< Path tracing: weight light/BSDF samples by MIS.
  Vec3 background{0.0};             ///< Radiance of escaped rays, linear RGB.
  bool rayOffset = true;  ///< Secondary rays leave past the hit's error bound; false: from the
                          ///< computed hit point itself (shows shadow acne, for teaching).
  /// Meshes are searched through their bounding volume hierarchy; false: every ray is
  /// tested against every triangle (brute force, for teaching). The hits are identical.
  bool acceleration = true;
  /// How the meshes' hierarchies choose their splits; a mesh built with another split is
  /// rebuilt for the render (SceneIntersector). The hits are identical either way.
  BvhSettings::Split bvhSplit = BvhSettings::Split::Sah;
  std::string toString() const;
};

}  // namespace raylab
