#pragma once

#include "raylab/core/Camera.h"
#include "raylab/core/Limits.h"
#include "raylab/core/NestedMedia.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Sampler.h"
#include "raylab/core/SceneIntersector.h"

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

/// Rays traced, by kind (the cost figures of a comparison).
struct RayCounts {
  std::array<std::uint64_t, kRayKindCount> byKind{};  ///< Indexed by RayKind.
  /// Rays of every kind.
  std::uint64_t total() const;
  /// Adds another count kind by kind (merging threads or passes).
  RayCounts& operator+=(const RayCounts& other);
};

/// A ray waiting in the engine's queue, with what its parent decided about it.
struct QueuedRay {
  Ray ray;  ///< World space, unit direction.
  RayKind kind = RayKind::Camera;
  int depth = 0;         ///< Camera ray: 0.
  int parent = -1;       ///< Recorded id of the parent (-1 for the camera ray).
  int id = -1;           ///< Recorded id of this ray (-1 when not recording).
  Vec3 weight{1.0};      ///< Factor of its radiance in the parent's estimate.
  Vec3 throughput{1.0};  ///< Product of weights from the camera ray (beta).
  double pdf = 0.0;      ///< Solid-angle pdf it was sampled with (0: deterministic);
                         ///< path tracing MIS-weighs the emitter it finds by it.
  Vec3 shadowLe{0.0};    ///< Shadow rays: radiance delivered when unoccluded.
  int lightObject = -1;  ///< Shadow rays to an area light: its object (Scene::objects).
  int pointLight = -1;   ///< Shadow rays to a point light: its index (Scene::pointLights).
  MediumStack media;     ///< Nested volumes it travels inside (NestedMedia.h; empty unless the
                         ///< scene has some).
};

/// What the last step of the engine did: facts only, which the front ends narrate in
/// either language (RayWords.h, narrateStep).
struct StepEvent {
  int ray = -1;                        ///< Recorded id of the ray processed (-1: not recorded).
  RayKind kind = RayKind::Camera;      ///< Why the ray was spawned.
  EndReason end = EndReason::Pending;  ///< How it ended.
  int object = -1;  ///< Object it hit, or that blocked a shadow ray (Scene::objects), -1 if none.
  int lightObject = -1;  ///< Shadow rays to an area light: that light's object index.
  int pointLight = -1;   ///< Shadow rays to a point light: its index in Scene::pointLights.
  int firstChild = -1;   ///< Recorded id of its first child, -1 when none.
  int spawned = 0;       ///< Children appended to the queue (ids firstChild ...).
  int wanted = 0;        ///< Children the algorithm asked for: more than `spawned` when the ray
                         ///< budget stopped the ray (EndReason::Stopped).
};

class SpawnRule;

/// Bytes of ray segments a recorded tree may use by default (Stepper, tracePixel): about
/// 60,000 rays, which also bounds the rays traced and queued for one tree (a tree that
/// large takes seconds to dump as JSON and to draw; more would not be readable anyway).
constexpr std::size_t kDefaultTreeBudget = std::size_t(16) << 20;

/**
 * \brief The one engine of the four algorithms (the original course program's renderer):
 * a queue of rays; take the first, intersect it, ask the algorithm's SpawnRule which child
 * rays the hit spawns (the original's BRDF(intersection) factory), append them; a ray that
 * ends adds its radiance, weighted by its throughput, to the estimate — which equals
 * propagating the energy up the recorded tree to the camera ray (RayTree::propagate).
 *
 * The step itself is `engineStep` in core/src/integrators/Tracer.cpp, one screen long.
 * `trace` runs it for one (pixel, sample) with no recording (the image renderer's path);
 * `Stepper` runs the same step one ray at a time with a TreeRecorder, which keeps the tree.
 */
class Tracer {
 public:
  /// The engine for `scene` (which must outlive it) with the rule of settings.algorithm.
  Tracer(const Scene& scene, const RenderSettings& settings);
  ~Tracer();
  Tracer(const Tracer&) = delete;
  Tracer& operator=(const Tracer&) = delete;

  /// Estimate of sample `sample` of pixel (x, y): radiance, linear RGB. Adds the rays
  /// traced to `counts` when given. Thread-safe (const).
  ///
  /// At most `rayCap` rays are traced (limits::kMaxRaysPerSample by default), the camera
  /// ray included: once a ray's children would pass the cap, none of them is queued and
  /// no later ray spawns any, just as a Stepper whose budget holds `rayCap` segments (the
  /// estimates are then equal). `capped`, when given, is set to whether that happened.
  Vec3 trace(int x, int y, int sample, RayCounts* counts = nullptr, bool* capped = nullptr,
             std::size_t rayCap = limits::kMaxRaysPerSample) const;

  const Scene& scene() const { return m_intersector.scene(); }
  const SceneIntersector& intersector() const { return m_intersector; }
  const RenderSettings& settings() const { return m_settings; }
  const Camera& camera() const { return m_camera; }
  const SpawnRule& rule() const { return *m_rule; }
  /// The material of object `object` (an index into Scene::objects).
  const Material& materialOf(int object) const;
  /// Length at which recorded escaped rays are drawn: the diagonal of the bounds of the
  /// scene's finite objects and the camera, world units (1 for an empty scene).
  double escapeLength() const { return m_escapeLength; }
  /// The scene's nested volumes (NestedMedia.h), and the ones the camera is inside.
  const NestedMedia& media() const { return m_media; }
  const MediumStack& cameraMedia() const { return m_cameraMedia; }

 private:
  friend class Stepper;
  SceneIntersector m_intersector;
  RenderSettings m_settings;
  Camera m_camera;
  std::unique_ptr<SpawnRule> m_rule;
  double m_escapeLength = 1.0;
  NestedMedia m_media;
  MediumStack m_cameraMedia;
};

/**
 * \brief Advances the real algorithm for one (pixel, sample) one ray at a time,
 * recording the tree: what the window animates and the lessons narrate.
 *
 * `memoryBudget` bounds the work, not only the tree: every ray queued is recorded, so at
 * most memoryBudget / sizeof(RaySegment) rays are ever queued and traced. When a ray's
 * children no longer fit, none of them is queued: the ray ends EndReason::Stopped, the
 * rays already waiting are still traced, and RayTree::truncated and RayTree::stop say
 * that the budget was reached. A bushy distributed tree (depth 8, 8 shadow and 8 glossy samples)
 * thus ends after about 60,000 rays (default budget) instead of growing without end. Under the
 * budget the estimate equals Tracer::trace bit for bit; past it, it covers the rays traced (it
 * always equals the recorded tree's RayTree::estimate() once done()).
 */
class Stepper {
 public:
  /// Prepares sample `sample` of pixel (x, y) of `tracer` (which must outlive the stepper):
  /// the camera ray waits in the queue. `memoryBudget` bounds the recorded segments, bytes,
  /// and so the rays traced (a budget below one segment traces nothing).
  ///
  /// With `root`, that ray (world space; its direction is normalised, its tMin, tMax and
  /// time are kept) is traced in place of the camera ray: a ray chosen by hand, as a
  /// lesson's tangent ray. The pixel and sample still choose the random numbers of the
  /// rays it spawns, so the trace is as deterministic as a pixel's.
  Stepper(const Tracer& tracer, int x, int y, int sample,
          std::size_t memoryBudget = kDefaultTreeBudget, std::optional<Ray> root = std::nullopt);

  /// Processes the first ray of the queue. Returns false when the queue was empty.
  /// The step that empties the queue also propagates the tree.
  bool step();
  /// Steps until the queue is empty; the tree is then propagated.
  void runToEnd();
  /// Back to the state before the first step (same pixel, sample and seed).
  void reset();
  /// Ends the trace now (a cancel from the front end): the waiting rays are dropped from
  /// the queue and the tree, their parents end Stopped, the tree is propagated and marked
  /// truncated, its RayTree::stop a cancel after the rays traced so far. Nothing happens
  /// when done().
  void stop();
  /// True when every ray has been processed.
  bool done() const { return m_queue.empty(); }

  /// Rays waiting to be processed, first in front (breadth-first: ids in queue order).
  const std::deque<QueuedRay>& queue() const { return m_queue; }
  /// The tree so far; radiance fields are final once done().
  const RayTree& tree() const { return m_tree; }
  /// What the last step did (before the first step: the camera ray waiting).
  const StepEvent& lastEvent() const { return m_event; }
  /// The sample's estimate so far (final once done()); equals Tracer::trace when done
  /// within the budget (tree().truncated false).
  Vec3 estimate() const { return m_estimate; }
  /// Rays processed so far, by kind.
  const RayCounts& counts() const { return m_counts; }

 private:
  const Tracer* m_tracer;
  int m_x, m_y, m_sample;
  std::size_t m_budget;
  std::optional<Ray> m_root;  ///< Traced in place of the camera ray, when set.
  Sampler m_sampler;
  std::deque<QueuedRay> m_queue;
  RayTree m_tree;
  StepEvent m_event;
  Vec3 m_estimate{0.0};
  RayCounts m_counts;
  std::vector<QueuedRay> m_children;  ///< Scratch for the rule's children.
};

}  // namespace raylab
