#include "raylab/core/Tracer.h"

#include "integrators/TreeRecorder.h"
#include "raylab/core/Check.h"
#include "raylab/core/SpawnRule.h"

#include <algorithm>
#include <deque>
#include <optional>

namespace raylab {

std::uint64_t RayCounts::total() const {
  std::uint64_t sum = 0;
  for (std::uint64_t n : byKind) sum += n;
  return sum;
}

RayCounts& RayCounts::operator+=(const RayCounts& other) {
  for (int k = 0; k < kRayKindCount; ++k) byKind[std::size_t(k)] += other.byKind[std::size_t(k)];
  return *this;
}

namespace {

bool isNonNegative(const Vec3& v) { return v.x >= 0.0 && v.y >= 0.0 && v.z >= 0.0; }

/// First-in first-out queue over a reusable vector: the image renderer's queue, which
/// allocates nothing once a thread has traced its largest tree.
class RayFifo {
 public:
  bool empty() const { return m_head == m_items.size(); }
  const QueuedRay& front() const { return m_items[m_head]; }
  void pop_front() {
    if (++m_head == m_items.size()) clear();
  }
  void push_back(const QueuedRay& ray) { m_items.push_back(ray); }
  /// Appends `rays` and leaves it empty. Into an empty queue (a path's next vertex: its
  /// rays have all been traced) the two vectors trade buffers instead of copying: the copy
  /// read each ray back 16 bytes at a time just after the rule and the engine had written
  /// it in smaller pieces, a store-forwarding stall per ray.
  void append(std::vector<QueuedRay>& rays) {
    if (empty()) {
      clear();
      m_items.swap(rays);
    } else {
      m_items.insert(m_items.end(), rays.begin(), rays.end());
    }
    rays.clear();
  }
  void clear() {
    m_items.clear();
    m_head = 0;
  }

 private:
  std::vector<QueuedRay> m_items;
  std::size_t m_head = 0;
};

/// The camera ray of one (pixel, sample). It always draws five dimensions (film jitter,
/// lens, time) so every algorithm consumes the sampler alike. Film and lens samples are
/// stratified over the pixel's samples (Sampler::nextStratified2D); the film position is the
/// pixel centre when there is one sample per pixel. The rule says whether the lens point
/// and the shutter time are used (SpawnRule::samplesLensAndShutter).
QueuedRay cameraRay(const Tracer& tracer, int x, int y, Sampler& sampler) {
  const RenderSettings& settings = tracer.settings();
  const Vec2 jitter = sampler.nextStratified2D();
  const Vec2 lens = sampler.nextStratified2D();
  const double time = sampler.next1D();
  const bool sampled = tracer.rule().samplesLensAndShutter();
  const Vec2 film =
      Vec2(double(x), double(y)) + (settings.samplesPerPixel > 1 ? jitter : Vec2(0.5));
  QueuedRay q;
  q.ray = tracer.camera().generateRay(film, sampled ? lens : Vec2(0.5), sampled ? time : 0.0);
  q.kind = RayKind::Camera;
  return q;
}

/// The image renderer's bound on the rays of one sample (Tracer::trace): the rays queued
/// so far, camera ray included, against the cap. Once children do not fit, no ray spawns
/// any more, as when a Stepper's tree budget runs out (TreeRecorder::reserve).
struct RayCap {
  std::size_t queued = 1;
  std::size_t limit = limits::kMaxRaysPerSample;
  bool reached = false;
};

/// The children at the end of the queue (`children` is left empty): the image renderer's
/// queue, or a Stepper's.
void append(RayFifo& queue, std::vector<QueuedRay>& children) { queue.append(children); }
void append(std::deque<QueuedRay>& queue, std::vector<QueuedRay>& children) {
  queue.insert(queue.end(), children.begin(), children.end());
  children.clear();
}

/**
 * The engine, one step: take the first ray of the queue, find where it ends, let the
 * rule spawn children, add the ray's own contribution `throughput * emitted` to the
 * estimate, queue the children with throughput `throughput * weight`. The same step runs
 * in Tracer::trace (images; `recorder` is null) and Stepper::step (ray trees).
 */
template <typename Queue>
void engineStep(const Tracer& tracer, Queue& queue, Sampler& sampler,
                std::vector<QueuedRay>& children, SceneHit& found, Vec3& estimate,
                RayCounts* counts, TreeRecorder* recorder, RayCap* cap) {
  const SceneIntersector& intersector = tracer.intersector();

  // 1. Take the first ray of the queue (by reference: it leaves the queue at the end of
  // the step, before its children join it).
  const QueuedRay& ray = queue.front();
  if (counts) ++counts->byKind[std::size_t(ray.kind)];

  Vec3 emitted(0.0);
  EndReason end = EndReason::Pending;
  // The hit, written in place into the caller's `found` (SceneHit is large: an optional of
  // it was zero-filled on every step); `hit` points to it when the ray hit something.
  const SceneHit* hit = nullptr;
  children.clear();
  if (ray.kind == RayKind::Shadow) {
    // 2a. A shadow ray only asks whether anything blocks its way to the light.
    const bool blocked = intersector.occluded(ray.ray);
    end = blocked ? EndReason::Occluded : EndReason::ReachedLight;
    if (!blocked) emitted = ray.shadowLe;
  } else if (!(hit = intersector.intersect(ray.ray, found) ? &found : nullptr)) {
    // 2b. Nothing in the way: the ray leaves the scene.
    end = EndReason::Escaped;
    emitted = tracer.rule().onEscape(ray, tracer.settings());
  } else {
    // 2c. Ask the algorithm what the hit spawns.
    const bool spawns = !(cap && cap->reached) && !(recorder && recorder->full());
    const HitContext context{
        intersector, tracer.settings(), ray, *hit, tracer.materialOf(hit->object), sampler, spawns};
    const HitDecision decision = tracer.rule().onHit(context, children);
    emitted = decision.emitted;
    // A child with a non-finite or negative weight is a bug in the rule: never let it in.
    const auto invalid = [](const QueuedRay& c) {
      const bool valid = isFinite(c.weight) && isNonNegative(c.weight) && isFinite(c.shadowLe);
      RAYLAB_DCHECK(valid);
      return !valid;
    };
    children.erase(std::remove_if(children.begin(), children.end(), invalid), children.end());
    // The no-leak rule of smooth surfaces: a child whose direction lies on one side of the
    // shading surface and the other of the geometric one (a reflection below the triangle,
    // a light behind it) is absorbed: the shading normal never lets light through.
    const SurfaceInteraction& si = hit->si;
    const auto leaks = [&si](const QueuedRay& c) { return !si.sidesAgree(c.ray.direction); };
    children.erase(std::remove_if(children.begin(), children.end(), leaks), children.end());
    end = !children.empty()                    ? EndReason::Spawned
          : decision.end == EndReason::Spawned ? EndReason::Absorbed
                                               : decision.end;
  }
  // No NaN or Inf leaves the engine.
  RAYLAB_DCHECK(isFinite(emitted));
  if (!isFinite(emitted)) emitted = Vec3(0.0);

  // 3. The ray's own contribution to the pixel: its throughput times what it found.
  estimate += ray.throughput * emitted;

  // 4. Queue the children: throughput is the parent's times the child's weight.
  for (QueuedRay& child : children) {
    child.parent = ray.id;
    child.throughput = ray.throughput * child.weight;
  }
  if (cap && !children.empty()) {
    if (cap->reached || cap->queued + children.size() > cap->limit) {
      cap->reached = true;
      children.clear();
      end = EndReason::Stopped;
    } else {
      cap->queued += children.size();
    }
  }
  if (recorder) recorder->recordStep(ray, hit, end, emitted, children);
  queue.pop_front();  // `ray` is gone from here on
  append(queue, children);
}

}  // namespace

Tracer::Tracer(const Scene& scene, const RenderSettings& settings)
    : m_intersector(scene, settings),
      m_settings(settings),
      m_camera(scene.camera),
      m_rule(SpawnRule::create(settings)) {
  // The drawing length of escaped rays: the diagonal of everything finite in the scene.
  Bounds3 bounds;
  bounds.extend(scene.camera.position);
  for (const SceneObject& object : scene.objects) {
    if (!object.shape) continue;
    const Bounds3 b = object.shape->bounds();
    if (b.empty() || !isFinite(b.lower) || !isFinite(b.upper)) continue;
    bounds.extend(b);
  }
  const double diagonal = glm::length(bounds.extent());
  m_escapeLength = diagonal > 0.0 ? diagonal : 1.0;
  for (const SceneObject& object : scene.objects) m_objectNames.push_back(object.name);
  for (const PointLight& light : scene.pointLights) m_pointLightNames.push_back(light.name);
}

const Material& Tracer::materialOf(int object) const {
  const Scene& s = scene();
  return s.materials[std::size_t(s.objects[std::size_t(object)].material)];
}

Tracer::~Tracer() = default;

Vec3 Tracer::trace(int x, int y, int sample, RayCounts* counts, bool* capped,
                   std::size_t rayCap) const {
  // One reusable queue per thread: no allocation per sample once warmed up.
  thread_local RayFifo queue;
  thread_local std::vector<QueuedRay> children;
  queue.clear();
  Sampler sampler(m_settings.seed, x, y, sample);
  // A cap below one ray traces nothing, as a Stepper's budget below one segment.
  RayCap cap;
  cap.limit = rayCap;
  if (rayCap >= 1) queue.push_back(cameraRay(*this, x, y, sampler));
  Vec3 estimate(0.0);
  SceneHit found;
  while (!queue.empty())
    engineStep(*this, queue, sampler, children, found, estimate, counts, nullptr, &cap);
  if (capped) *capped = cap.reached;
  return estimate;
}

Stepper::Stepper(const Tracer& tracer, int x, int y, int sample, std::size_t memoryBudget,
                 std::optional<Ray> root)
    : m_tracer(&tracer),
      m_x(x),
      m_y(y),
      m_sample(sample),
      m_budget(memoryBudget),
      m_root(root ? std::optional<Ray>(Ray::make(root->origin, root->direction, root->tMin,
                                                 root->tMax, root->time))
                  : std::nullopt),
      m_sampler(tracer.settings().seed, x, y, sample) {
  reset();
}

void Stepper::reset() {
  m_sampler = Sampler(m_tracer->settings().seed, m_x, m_y, m_sample);
  m_queue.clear();
  m_tree = RayTree{};
  m_tree.pixelX = m_x;
  m_tree.pixelY = m_y;
  m_tree.sample = m_sample;
  m_estimate = Vec3(0.0);
  m_counts = RayCounts{};

  // The camera ray is the root of the tree (segment 0) and waits in the queue.
  // A chosen root ray takes the camera ray's place after the camera's random numbers were
  // drawn, so its children draw the same numbers as the pixel's own would.
  QueuedRay camera = cameraRay(*m_tracer, m_x, m_y, m_sampler);
  if (m_root) camera.ray = *m_root;
  TreeRecorder(*m_tracer, m_tree, m_event, m_budget).recordCamera(camera, m_root.has_value());
  // A budget below one segment traces nothing: the work is bounded by the budget too.
  if (camera.id >= 0) m_queue.push_back(camera);
}

bool Stepper::step() {
  if (m_queue.empty()) return false;
  TreeRecorder recorder(*m_tracer, m_tree, m_event, m_budget);
  SceneHit found;
  engineStep(*m_tracer, m_queue, m_sampler, m_children, found, m_estimate, &m_counts, &recorder,
             nullptr);
  // Once the queue is empty every ray has ended: propagate energy up the tree.
  if (m_queue.empty()) m_tree.propagate();
  return true;
}

void Stepper::runToEnd() {
  while (step()) {
  }
}

void Stepper::stop(const std::string& why) {
  if (m_queue.empty()) return;
  // The waiting rays are the last ids of the tree (children are numbered in queue order):
  // drop them, and cut their parents' child lists where they start.
  const std::size_t cut = std::size_t(m_queue.front().id);
  m_queue.clear();
  m_tree.segments.resize(std::min(cut, m_tree.segments.size()));
  for (RaySegment& s : m_tree.segments) {
    if (s.childCount == 0 || std::size_t(s.firstChild + s.childCount) <= cut) continue;
    s.childCount = std::max(0, int(cut) - s.firstChild);
    if (s.childCount == 0) s.firstChild = -1;
    s.endReason = EndReason::Stopped;
  }
  m_tree.truncated = true;
  m_tree.message = why;
  m_tree.propagate();
}

}  // namespace raylab
