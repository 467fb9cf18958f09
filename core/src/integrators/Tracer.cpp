#include "raylab/core/Tracer.h"

#include "raylab/core/Check.h"
#include "raylab/core/SpawnRule.h"

#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

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

bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

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
  void clear() {
    m_items.clear();
    m_head = 0;
  }

 private:
  std::vector<QueuedRay> m_items;
  std::size_t m_head = 0;
};

/// What the stepper records; absent (nullptr) in the image renderer's path.
struct Recording {
  RayTree& tree;
  std::size_t budget;   ///< Bytes the segments may use.
  double escapeLength;  ///< Drawing length of escaped rays, world units.
  const Scene& scene;
  StepEvent& event;

  /// Ids for `count` new segments, or -1 when they would exceed the budget (recording
  /// stops for good then). Capacity grows within the budget only.
  int reserve(std::size_t count) {
    if (tree.truncated) return -1;
    const std::size_t needed = tree.segments.size() + count;
    const std::size_t limit = budget / sizeof(RaySegment);
    if (needed > limit) {
      tree.truncated = true;
      std::ostringstream out;
      out << "ray tree truncated at " << tree.segments.size() << " rays (" << std::setprecision(3)
          << double(budget) / double(1 << 20) << " MiB budget); the estimate is still exact";
      tree.message = out.str();
      return -1;
    }
    if (needed > tree.segments.capacity())
      tree.segments.reserve(std::min(limit, std::max(needed, 2 * tree.segments.capacity())));
    const int first = int(tree.segments.size());
    tree.segments.resize(needed);
    return first;
  }

  std::string objectName(int object) const {
    if (object < 0 || object >= int(scene.objects.size())) return "nothing";
    return "'" + scene.objects[std::size_t(object)].name + "'";
  }
};

/// The camera ray of one (pixel, sample). It always draws five dimensions (film jitter,
/// lens, time) so every algorithm consumes the sampler alike. Film and lens samples are
/// stratified over the pixel's samples (Sampler::nextStratified2D); the film position is the
/// pixel centre when there is one sample per pixel, and ray casting and Whitted look
/// through the lens centre at time 0.
QueuedRay cameraRay(const Tracer& tracer, int x, int y, Sampler& sampler) {
  const RenderSettings& settings = tracer.settings();
  const Vec2 jitter = sampler.nextStratified2D();
  const Vec2 lens = sampler.nextStratified2D();
  const double time = sampler.next1D();
  const bool classic =
      settings.algorithm == Algorithm::RayCasting || settings.algorithm == Algorithm::Whitted;
  const Vec2 film =
      Vec2(double(x), double(y)) + (settings.samplesPerPixel > 1 ? jitter : Vec2(0.5));
  QueuedRay q;
  q.ray = tracer.camera().generateRay(film, classic ? Vec2(0.5) : lens, classic ? 0.0 : time);
  q.kind = RayKind::Camera;
  return q;
}

/**
 * The one step of the engine, shared by Tracer::trace and Stepper::step: take the first
 * ray, find where it ends, let the rule spawn children, add the ray's own contribution
 * (throughput * emitted) to the estimate, queue the children. `recording` is null in the
 * image renderer.
 */
template <typename Queue>
void stepEngine(const Tracer& tracer, Queue& queue, Sampler& sampler,
                std::vector<QueuedRay>& children, Vec3& estimate, RayCounts* counts,
                Recording* recording) {
  const SceneIntersector& scene = tracer.intersector();
  const RenderSettings& settings = tracer.settings();

  // Take the first ray of the queue.
  const QueuedRay ray = queue.front();
  queue.pop_front();
  if (counts) ++counts->byKind[std::size_t(ray.kind)];

  Vec3 emitted(0.0);
  EndReason end = EndReason::Pending;
  std::optional<SceneHit> hit;
  children.clear();
  if (ray.kind == RayKind::Shadow) {
    // A shadow ray only asks whether anything blocks its way to the light.
    if (scene.occluded(ray.ray)) {
      end = EndReason::Occluded;
    } else {
      end = EndReason::ReachedLight;
      emitted = ray.shadowLe;
    }
  } else {
    // Find the nearest surface along the ray.
    hit = scene.intersect(ray.ray);
    if (!hit) {
      end = EndReason::Escaped;
      emitted = tracer.rule().onEscape(ray, settings);
    } else {
      // Ask the algorithm what the hit spawns.
      const Scene& s = scene.scene();
      const Material& material =
          s.materials[std::size_t(s.objects[std::size_t(hit->object)].material)];
      const HitContext context{scene, settings, ray, *hit, material, sampler};
      const HitDecision decision = tracer.rule().onHit(context, children);
      emitted = decision.emitted;
      // A child with a non-finite or negative weight is a bug in the rule: never let it in.
      std::size_t kept = 0;
      for (std::size_t i = 0; i < children.size(); ++i) {
        const bool valid = isFinite(children[i].weight) && isNonNegative(children[i].weight) &&
                           isFinite(children[i].shadowLe);
        RAYLAB_DCHECK(valid);
        if (valid) children[kept++] = children[i];
      }
      children.resize(kept);
      if (!children.empty())
        end = EndReason::Spawned;
      else
        end = decision.end == EndReason::Spawned ? EndReason::Absorbed : decision.end;
    }
  }
  // No NaN or Inf leaves the engine.
  RAYLAB_DCHECK(isFinite(emitted));
  if (!isFinite(emitted)) emitted = Vec3(0.0);

  // The ray's own contribution to the pixel: its throughput times what it found.
  estimate += ray.throughput * emitted;

  // Queue the children: ids are consecutive, throughput is the parent's times the weight.
  int firstId = -1;
  if (recording && ray.id >= 0 && !children.empty()) firstId = recording->reserve(children.size());
  for (std::size_t i = 0; i < children.size(); ++i) {
    QueuedRay& child = children[i];
    child.parent = ray.id;
    child.id = firstId >= 0 ? firstId + int(i) : -1;
    child.throughput = ray.throughput * child.weight;
    queue.push_back(child);
  }
  if (!recording) return;

  // Record the processed ray and its children (stepper only).
  StepEvent& event = recording->event;
  event.ray = ray.id;
  event.end = end;
  event.spawned = int(children.size());
  std::string text = std::string(toString(ray.kind)) + " ray #" + std::to_string(ray.id);
  if (ray.id >= 0) {
    RaySegment& seg = recording->tree.segments[std::size_t(ray.id)];
    seg.emitted = emitted;
    seg.endReason = end;
    if (firstId >= 0) {
      seg.firstChild = firstId;
      seg.childCount = int(children.size());
    }
    if (hit) {
      seg.hit = true;
      seg.endPoint = hit->si.p;
      seg.object = hit->object;
      seg.normal = hit->si.n;
    } else if (ray.kind == RayKind::Shadow) {
      seg.endPoint = ray.ray.at(ray.ray.tMax);
      seg.lightPoint = seg.endPoint;
      if (end == EndReason::Occluded) {
        // Find the blocker, for drawing only.
        if (const std::optional<SceneHit> blocker = scene.intersect(ray.ray)) {
          seg.hit = true;
          seg.endPoint = blocker->si.p;
          seg.object = blocker->object;
          seg.normal = blocker->si.n;
        }
      }
    } else {
      seg.endPoint = ray.ray.origin + recording->escapeLength * ray.ray.direction;
    }
    if (seg.object >= 0)
      text += (end == EndReason::Occluded ? " was blocked by " : " hit ") +
              recording->objectName(seg.object);
  }
  switch (end) {
    case EndReason::Escaped:
      text += " escaped the scene";
      break;
    case EndReason::ReachedLight:
      text += " reached its light";
      break;
    case EndReason::Spawned:
      text += " and spawned " + std::to_string(children.size()) +
              (children.size() == 1 ? " ray" : " rays");
      break;
    case EndReason::Occluded:
      break;
    case EndReason::HitLight:
      text += ", a light: the path ends there";
      break;
    case EndReason::MaxDepth:
      text += " at the maximum depth: the path ends there";
      break;
    case EndReason::RussianRoulette:
      text += ": Russian roulette ended the path";
      break;
    default:
      text += std::string(": ") + toString(end);
      break;
  }
  event.text = std::move(text);
  if (firstId < 0) return;
  for (std::size_t i = 0; i < children.size(); ++i) {
    const QueuedRay& child = children[i];
    RaySegment& seg = recording->tree.segments[std::size_t(child.id)];
    seg = RaySegment{};
    seg.id = child.id;
    seg.parent = child.parent;
    seg.kind = child.kind;
    seg.depth = child.depth;
    seg.origin = child.ray.origin;
    seg.direction = child.ray.direction;
    seg.time = child.ray.time;
    seg.weight = child.weight;
    seg.pdf = child.pdf;
    seg.throughput = child.throughput;
  }
}

}  // namespace

Tracer::Tracer(const Scene& scene, const RenderSettings& settings)
    : m_intersector(scene),
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
}

Tracer::~Tracer() = default;

Vec3 Tracer::trace(int x, int y, int sample, RayCounts* counts) const {
  // One reusable queue per thread: no allocation per sample once warmed up.
  thread_local RayFifo queue;
  thread_local std::vector<QueuedRay> children;
  queue.clear();
  Sampler sampler(m_settings.seed, x, y, sample);
  queue.push_back(cameraRay(*this, x, y, sampler));
  Vec3 estimate(0.0);
  while (!queue.empty()) stepEngine(*this, queue, sampler, children, estimate, counts, nullptr);
  return estimate;
}

Stepper::Stepper(const Tracer& tracer, int x, int y, int sample, std::size_t memoryBudget)
    : m_tracer(&tracer),
      m_x(x),
      m_y(y),
      m_sample(sample),
      m_budget(memoryBudget),
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
  m_event = StepEvent{};
  m_estimate = Vec3(0.0);
  m_counts = RayCounts{};

  // The camera ray is the root of the tree (segment 0) when the budget allows one segment.
  QueuedRay camera = cameraRay(*m_tracer, m_x, m_y, m_sampler);
  Recording recording{m_tree, m_budget, m_tracer->escapeLength(), m_tracer->scene(), m_event};
  camera.id = recording.reserve(1);
  if (camera.id >= 0) {
    RaySegment& seg = m_tree.segments[0];
    seg = RaySegment{};
    seg.origin = camera.ray.origin;
    seg.direction = camera.ray.direction;
    seg.time = camera.ray.time;
  }
  m_queue.push_back(camera);
  m_event.text = "camera ray through pixel (" + std::to_string(m_x) + ", " + std::to_string(m_y) +
                 "), sample " + std::to_string(m_sample) + ", waits in the queue";
}

bool Stepper::step() {
  if (m_queue.empty()) return false;
  Recording recording{m_tree, m_budget, m_tracer->escapeLength(), m_tracer->scene(), m_event};
  stepEngine(*m_tracer, m_queue, m_sampler, m_children, m_estimate, &m_counts, &recording);
  // Once the queue is empty every ray has ended: propagate energy up the tree.
  if (m_queue.empty()) m_tree.propagate();
  return true;
}

void Stepper::runToEnd() {
  while (step()) {
  }
}

}  // namespace raylab
