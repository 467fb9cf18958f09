#include "integrators/TreeRecorder.h"

#include <algorithm>

namespace raylab {

TreeRecorder::TreeRecorder(const Tracer& tracer, RayTree& tree, StepEvent& event,
                           std::size_t budget)
    : m_tracer(tracer), m_tree(tree), m_event(event), m_budget(budget) {}

int TreeRecorder::reserve(std::size_t count) {
  if (m_tree.truncated) return -1;
  const std::size_t needed = m_tree.segments.size() + count;
  const std::size_t limit = m_budget / sizeof(RaySegment);
  if (needed > limit) {
    // From now on no ray gets children: the rays already queued are traced and the
    // stepper ends, so the budget bounds the work (rays traced and queued), not only the
    // memory of the tree.
    m_tree.truncated = true;
    m_tree.stop = TreeStop{StopCause::Budget, m_tree.segments.size(), m_budget, limit};
    return -1;
  }
  if (needed > m_tree.segments.capacity())
    m_tree.segments.reserve(std::min(limit, std::max(needed, 2 * m_tree.segments.capacity())));
  const int first = int(m_tree.segments.size());
  m_tree.segments.resize(needed);
  return first;
}

void TreeRecorder::startSegment(const QueuedRay& ray) {
  RaySegment& seg = m_tree.segments[std::size_t(ray.id)];
  seg = RaySegment{};
  seg.id = ray.id;
  seg.parent = ray.parent;
  seg.kind = ray.kind;
  seg.depth = ray.depth;
  seg.origin = ray.ray.origin;
  seg.direction = ray.ray.direction;
  seg.time = ray.ray.time;
  seg.weight = ray.weight;
  seg.pdf = ray.pdf;
  seg.throughput = ray.throughput;
  seg.lightObject = ray.lightObject;
  seg.pointLight = ray.pointLight;
  seg.media = ray.media;
}

void TreeRecorder::recordCamera(QueuedRay& camera) {
  camera.id = reserve(1);
  if (camera.id >= 0) startSegment(camera);
  // Before the first step: the camera (or chosen) ray waits in the queue.
  m_event = StepEvent{};
}

void TreeRecorder::setFarEnd(RaySegment& seg, const QueuedRay& ray, EndReason end) const {
  if (ray.kind != RayKind::Shadow) {
    // Escaped: drawn out to the size of the scene.
    seg.endPoint = ray.ray.origin + m_tracer.escapeLength() * ray.ray.direction;
    return;
  }
  seg.endPoint = ray.ray.at(ray.ray.tMax);
  seg.lightPoint = seg.endPoint;
  if (end != EndReason::Occluded) return;
  // Find the blocker, for drawing only.
  if (const std::optional<SceneHit> blocker = m_tracer.intersector().intersect(ray.ray)) {
    seg.hit = true;
    seg.endPoint = blocker->si.p;
    seg.object = blocker->object;
    seg.normal = blocker->si.n;
  }
}

void TreeRecorder::recordStep(const QueuedRay& ray, const SceneHit* hit, EndReason end,
                              const Vec3& emitted, std::vector<QueuedRay>& children,
                              const MediumStack& media) {
  // Number the children: consecutive ids after everything recorded so far. Children that
  // do not fit in the budget are not traced at all: the ray ends Stopped.
  const std::size_t wanted = children.size();
  const int firstId = ray.id >= 0 && !children.empty() ? reserve(children.size()) : -1;
  if (firstId < 0 && !children.empty()) {
    children.clear();
    end = EndReason::Stopped;
  }
  for (std::size_t i = 0; i < children.size(); ++i) {
    children[i].id = firstId + int(i);
    startSegment(children[i]);
  }

  m_event = StepEvent{};
  m_event.ray = ray.id;
  m_event.kind = ray.kind;
  m_event.end = end;
  m_event.lightObject = ray.lightObject;
  m_event.pointLight = ray.pointLight;
  m_event.firstChild = children.empty() ? -1 : firstId;
  m_event.spawned = int(children.size());
  m_event.wanted = int(wanted);
  if (ray.id < 0) return;  // Not recorded (a budget below one segment): nothing is kept.

  // How the ray ended, and what it found there.
  RaySegment& seg = m_tree.segments[std::size_t(ray.id)];
  seg.emitted = emitted;
  seg.endReason = end;
  seg.media = media;
  if (firstId >= 0) {
    seg.firstChild = firstId;
    seg.childCount = int(children.size());
  }
  if (hit) {
    seg.hit = true;
    seg.endPoint = hit->si.p;
    seg.object = hit->object;
    seg.normal = hit->si.n;
    seg.shadingNormal = hit->si.ns;
  } else {
    setFarEnd(seg, ray, end);
  }
  m_event.object = seg.object;
}

}  // namespace raylab
