#pragma once

#include "raylab/core/Material.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Sampler.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Tracer.h"

#include <memory>
#include <vector>

namespace raylab {

/// Everything an algorithm may look at when a (non-shadow) ray hits a surface.
struct HitContext {
  const SceneIntersector& intersector;  ///< The scene's queries: hits, lights, emission.
  const RenderSettings& settings;
  const QueuedRay& ray;      ///< The ray that hit.
  const SceneHit& hit;       ///< Where, and which object.
  const Material& material;  ///< The object's material.
  Sampler& sampler;          ///< This sample's random stream.
  /// False once the sample's ray cap or the tree's budget is reached: any children would be
  /// dropped, so a rule may skip drawing them (the distributed rule's 256 glossy and shadow
  /// directions per hit, issue 38). What the rule finds itself (`emitted`) must not change.
  bool spawns = true;
};

/// An algorithm's answer at a hit.
struct HitDecision {
  Vec3 emitted{0.0};                   ///< Radiance found here (emitter seen, local shading
                                       ///< that needs no shadow ray, ...).
  EndReason end = EndReason::Spawned;  ///< Why no children, or Spawned when there are some.
};

/**
 * \brief The rule that tells the four algorithms apart: which child rays a hit spawns
 * (the original course program's BRDF(intersection) factory), and how the camera samples.
 * The engine (Tracer.cpp's engineStep) does everything else: queueing, intersecting,
 * shadow-ray visibility, the estimate `throughput * emitted`, and (when stepping) handing
 * each step to the tree recorder.
 *
 * Children are appended to `children` with ray, kind, depth, weight (relative to this
 * ray), pdf and, for shadow rays, `shadowLe` (the radiance delivered when unoccluded, not
 * multiplied by the weight); the engine fills id, parent and throughput (the parent's
 * throughput times the weight). Random numbers come from `context.sampler` only, so the
 * image renderer and the stepper draw the same ones. Implementations are stateless and
 * thread-safe. The algorithms live in core/src/integrators/<name>/, each written with the
 * helpers of core/src/integrators/LocalShading.h only (no rule includes another).
 */
class SpawnRule {
 public:
  virtual ~SpawnRule() = default;
  virtual Algorithm kind() const = 0;
  /// True when a camera ray samples a point on the lens (depth of field) and a shutter
  /// time (motion blur); false when it leaves the lens centre at time 0 (the classic
  /// algorithms). Either way the camera ray draws the same sampler dimensions.
  virtual bool samplesLensAndShutter() const = 0;
  /// Decides what a hit spawns; appends the children.
  virtual HitDecision onHit(const HitContext& context, std::vector<QueuedRay>& children) const = 0;
  /// Radiance of a ray that left the scene.
  virtual Vec3 onEscape(const QueuedRay& ray, const RenderSettings& settings) const {
    return settings.background;
  }

  /// The rule of settings.algorithm.
  static std::unique_ptr<SpawnRule> create(const RenderSettings& settings);
};

}  // namespace raylab
