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
  const SceneIntersector& scene;
  const RenderSettings& settings;
  const QueuedRay& ray;      ///< The ray that hit.
  const SceneHit& hit;       ///< Where, and which object.
  const Material& material;  ///< The object's material.
  Sampler& sampler;          ///< This sample's random stream.
};

/// An algorithm's answer at a hit.
struct HitDecision {
  Vec3 emitted{0.0};                   ///< Radiance found here (emitter seen, local shading
                                       ///< that needs no shadow ray, ...).
  EndReason end = EndReason::Spawned;  ///< Why no children, or Spawned when there are some.
};

/**
 * \brief The rule that tells the four algorithms apart: which child rays a hit spawns
 * (the seed's BRDF(intersection) factory). The engine (Tracer) does everything else:
 * queueing, intersecting, shadow-ray visibility, energy bookkeeping, recording.
 *
 * Children are appended to `children` with ray, kind, depth, weight (relative to this
 * ray), pdf and, for shadow rays, `shadowLe` (the radiance delivered when unoccluded, not
 * multiplied by the weight); the engine fills id, parent and throughput (the parent's
 * throughput times the weight). Random numbers come from `context.sampler` only, so the
 * image renderer and the stepper draw the same ones. Implementations are stateless and
 * thread-safe. The algorithms live in core/src/integrators/<name>/.
 */
class SpawnRule {
 public:
  virtual ~SpawnRule() = default;
  virtual Algorithm kind() const = 0;
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
