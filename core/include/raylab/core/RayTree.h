#pragma once

#include "raylab/core/NestedMedia.h"
#include "raylab/core/RayKind.h"
#include "raylab/core/Types.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

struct Scene;

/// Why a ray spawned no further rays.
enum class EndReason {
  Pending,          ///< Still in the queue (stepping) or not processed yet.
  Escaped,          ///< Left the scene: gets the background radiance.
  HitLight,         ///< Hit an emitter; the algorithm does not continue from lights.
  MaxDepth,         ///< Hit a surface at the maximum depth.
  RussianRoulette,  ///< Path tracing stopped it at random (survivors are reweighted).
  Absorbed,         ///< No further ray leaves the hit: the material scatters nothing the algorithm
                    ///< follows here (black, no lobe applies, no light faces it).
  Occluded,         ///< Shadow ray blocked before reaching its light.
  ReachedLight,     ///< Shadow ray reached its light unblocked.
  Spawned,          ///< Ended by spawning children (an inner node of the tree).
  Stopped,          ///< Traced, but tracing stopped before all its children were: the ray
                    ///< budget ran out, or the trace was cancelled (Stepper::stop).
};
/// The short English label of an end reason ("hit a light"), from the phrase table
/// (endReasonLabel in RayWords.h), for debugging output.
std::string toString(EndReason reason);

/**
 * \brief How one end reason is named: its word in JSON dumps and scripts and in the phrase
 * table's keys (`end_reason.<json>`, `narrate.<json>`: RayWords.h says it to people; the
 * engine keeps no words of its own).
 */
struct EndReasonWords {
  EndReason reason;
  const char* json;  ///< Name in JSON dumps, scripts and phrase keys: "hit_light".
};
/// The words of `reason` (a row of one table, in enum order).
const EndReasonWords& words(EndReason reason);
/// The reason whose JSON name is `json`, nothing when none is.
std::optional<EndReason> endReasonFromJson(const std::string& json);

/**
 * \brief One ray of a recorded tree: where it went, what it hit, what it carried.
 *
 * Energy bookkeeping (the original course program's propagation to parents): a ray's `radiance` is
 * what it brings back along itself, `emitted + sum over children of child.weight * child.radiance`;
 * the camera ray's radiance is the sample's estimate. `throughput` is the product of the
 * weights from the camera ray down to this one (beta), so `throughput * emitted` is this
 * ray's own contribution to the pixel. Children of one ray have consecutive ids.
 */
struct RaySegment {
  int id = 0;           ///< Index in RayTree::segments; processing order of the engine.
  int parent = -1;      ///< Parent id, -1 for the camera ray.
  int firstChild = -1;  ///< Id of the first child, -1 when none.
  int childCount = 0;   ///< Number of children (ids firstChild ...).
  RayKind kind = RayKind::Camera;
  int depth = 0;               ///< Bounces from the camera ray (which has depth 0).
  Point3 origin{0.0};          ///< World space.
  Vec3 direction{0.0};         ///< Unit, world space.
  double time = 0.0;           ///< Shutter time in [0, 1].
  bool hit = false;            ///< True when the ray ended on a surface.
  Point3 endPoint{0.0};        ///< Hit point, or the far end of a shadow ray; for escaped
                               ///< rays origin + escapeLength * direction (for drawing).
  int object = -1;             ///< Index of the object hit (Scene::objects), -1 if none.
  Normal3 normal{0.0};         ///< Unit geometric normal at the hit, world space.
  Normal3 shadingNormal{0.0};  ///< Unit shading normal at the hit where the surface is
                               ///< smooth (interpolated, SurfaceInteraction::ns), else zero.
  Vec3 weight{1.0};            ///< Factor of this ray's radiance in its parent's estimate
                               ///< (f |cos| / pdf, a Fresnel or rate weight, 1 / N ...).
  double pdf = 0.0;            ///< Solid-angle density the direction was sampled with
                               ///< (0 for deterministic directions).
  Vec3 throughput{1.0};        ///< Product of weights from the camera ray to this one.
  Vec3 emitted{0.0};           ///< Radiance found at this ray's end itself: an emitter seen
                               ///< (MIS-weighted) or a shadow ray's light contribution.
  Vec3 radiance{0.0};          ///< After propagation: emitted + sum of weighted children.
  EndReason endReason = EndReason::Pending;  ///< Why it spawned nothing (or Spawned).
  Point3 lightPoint{0.0};  ///< Shadow rays: the point on the light aimed at (the far end);
                           ///< when Occluded, endPoint is where the blocker was hit.
  int lightObject = -1;    ///< Shadow rays to an area light: that light's object index.
  int pointLight = -1;     ///< Shadow rays to a point light: its index in Scene::pointLights.
  MediumStack media;       ///< Nested volumes the ray is inside where it ends, false
                           ///< interfaces it went through counted (NestedMedia.h).

  /// The ray's energy: the luminance of `throughput * radiance`, the share of the pixel's
  /// light this ray carries (what the ray-tree view colours by and the inspector shows).
  double energy() const { return luminance(throughput * radiance); }
};

/// A shadow ray's light by name: an area light's object from `objectNames` (indexed by
/// RaySegment::lightObject) or a point light from `pointLightNames` (RaySegment::pointLight);
/// "" for other rays, or when the name is not among those given.
std::string lightNameOf(const RaySegment& s, const std::vector<std::string>& objectNames,
                        const std::vector<std::string>& pointLightNames);
/// The same from a scene's objects and point lights.
std::string lightNameOf(const RaySegment& s, const Scene& scene);

/// Why a trace stopped before its end: the ray-tree budget ran out, or the front end
/// cancelled. A fact, not words: stopWords (RayWords.h) says it from the phrase table.
enum class StopCause : std::uint8_t { None, Budget, Cancelled };

/// The facts of a tree that stopped early (RayTree::stop).
struct TreeStop {
  StopCause cause = StopCause::None;
  std::size_t rays = 0;         ///< Budget: rays in the tree; Cancelled: rays traced.
  std::size_t budgetBytes = 0;  ///< Budget: the memory budget of ray segments, bytes.
  std::size_t maxRays = 0;      ///< Budget: the most rays that budget holds.
};

/// The rays of one (pixel, sample), in the engine's processing order.
struct RayTree {
  int pixelX = 0, pixelY = 0, sample = 0;  ///< Which sample this is.
  std::vector<RaySegment> segments;        ///< segments[0] is the camera ray.
  bool truncated = false;  ///< Tracing stopped early (ray budget reached, or cancelled):
                           ///< rays ending Stopped lack some or all of their children.
  TreeStop stop;           ///< Why tracing stopped (cause None when it did not).

  /// Recomputes every `radiance` bottom-up from `emitted` and children's weights.
  void propagate();
  /// The sample's estimate: the camera ray's weight times its radiance.
  Vec3 estimate() const;
  /// Approximate memory used by the segments, bytes.
  std::size_t memoryBytes() const { return segments.capacity() * sizeof(RaySegment); }
  std::string toString() const;
};

}  // namespace raylab
