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

/// A typical student bug planted in the engine for a bug hunt (`--fault NAME`, a lesson
/// step's "fault"; issue 35): off unless asked for, per render (RenderSettings::fault).
enum class Fault {
  None,                   ///< The engine as it is.
  NoOffset,               ///< Secondary rays start on the computed hit point: shadow acne.
  NoCosine,               ///< The Lambert (and Phong) term without its cos theta.
  EtaInverted,            ///< Refraction with eta inverted (n2 / n1 in place of n1 / n2).
  FlippedNormal,          ///< The facing normal points into the surface.
  PdfForgotten,           ///< Path tracing: f cos / pdf estimated as f cos.
  RouletteUncompensated,  ///< Path tracing: Russian roulette survivors not weighted by 1 / q.
  SchlickWrongSign,       ///< Schlick's Fresnel with cos theta = d.n of the incoming d (< 0):
                          ///< (1 + |cos|)^5, R >= 1; only where a material uses Schlick.
};
constexpr int kFaultCount = 8;
/// "none", "no_offset", "no_cosine", "eta_inverted", "flipped_normal", "pdf_forgotten",
/// "roulette_uncompensated", "schlick_wrong_sign".
const char* toString(Fault fault);
/// Parses the names above; nothing for an unknown name.
std::optional<Fault> parseFault(const std::string& name);

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
 * | fault | none | all: a typical student bug planted for a bug hunt (Fault) |
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
  /// A planted bug (bug hunt); Fault::None unless a command line or a lesson step asks.
  Fault fault = Fault::None;
  std::string toString() const;
};

}  // namespace raylab
