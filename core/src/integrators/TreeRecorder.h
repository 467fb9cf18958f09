#pragma once

#include "raylab/core/RayTree.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Tracer.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace raylab {

/**
 * \brief What the stepper keeps of each engine step: the ray tree (one RaySegment per ray,
 * with its end, hit and children) and the facts of the last step (StepEvent), which the
 * front ends narrate (RayWords.h).
 *
 * The engine step calls it only when it is given one: the image renderer passes none
 * (nullptr), so recording costs images nothing. Recording stops for good at `budget`
 * bytes of segments, with the facts in RayTree::stop; the estimate is still exact.
 * Private to the integrators.
 */
class TreeRecorder {
 public:
  /// A recorder writing into `tree` and `event`, for the scene of `tracer`.
  TreeRecorder(const Tracer& tracer, RayTree& tree, StepEvent& event, std::size_t budget);

  /// Records the camera ray as segment 0 when the budget allows one; sets camera.id.
  void recordCamera(QueuedRay& camera);
  /// Records how `ray` ended (hit, end reason, what it found) and numbers its `children`
  /// (ids, parent links and their segments), before the engine queues them; tells the
  /// step's facts in the event. `media`: the nested volumes the ray is inside at its end.
  void recordStep(const QueuedRay& ray, const SceneHit* hit, EndReason end, const Vec3& emitted,
                  std::vector<QueuedRay>& children, const MediumStack& media);
  /// Whether the budget has run out: no ray gets children any more.
  bool full() const { return m_tree.truncated; }

 private:
  /// Ids for `count` new segments, or -1 when they would exceed the budget (recording
  /// stops for good then). Capacity grows within the budget only.
  int reserve(std::size_t count);
  /// Segment `id` as a child ray starts it: where it leaves from, its weight and pdf.
  void startSegment(const QueuedRay& ray);
  /// Where a ray that hit nothing (or a shadow ray) is drawn to end.
  void setFarEnd(RaySegment& seg, const QueuedRay& ray, EndReason end) const;

  const Tracer& m_tracer;
  RayTree& m_tree;
  StepEvent& m_event;
  std::size_t m_budget;
};

}  // namespace raylab
