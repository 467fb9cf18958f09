#include "raylab/core/Tracer.h"

#include "integrators/TreeRecorder.h"
#include "raylab/core/Check.h"
#include "raylab/core/RayOffset.h"
#include "raylab/core/SpawnRule.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <utility>

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
  q.media = tracer.cameraMedia();
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

/// Nested volumes (NestedMedia.h): from the hit in `found`, goes straight on through every
/// false interface, updating `inside` (the volumes the ray is in, starting from its own).
/// Returns whether a surface remains hit (then in `found`); `crossing` is that surface's
/// crossing when it bounds a volume (crossing.real), else left with real = false.
bool passFalseInterfaces(const Tracer& tracer, const QueuedRay& ray, SceneHit& found,
                         MediumStack& inside, MediumCrossing& crossing) {
  const NestedMedia& media = tracer.media();
  crossing.real = false;
  // Each pass leaves one surface behind; a ray crosses few, the bound guards loops.
  double left = ray.ray.tMax;  // how far the ray may still go past the last surface
  for (int pass = 0; pass < 256; ++pass) {
    if (!media.isVolume(found.object)) return true;
    const MediumCrossing c = media.cross(inside, found.object, found.si.frontFace);
    if (c.real) {
      crossing = c;
      return true;
    }
    // A false interface: the medium does not change; only the list of volumes does.
    inside = c.after;
    left -= found.si.t;
    Ray next = spawnRay(found.si, ray.ray.direction, std::isfinite(left) ? left : kInfinity);
    next.time = ray.ray.time;
    if (!tracer.intersector().intersect(next, found)) return false;
  }
  return true;
}

/// The children of a ray that ends on a surface inside `inside` carry that list, changed
/// by `crossing` for those that pass through the surface of the volume hit.
void carryMedia(const QueuedRay& ray, const SceneHit& hit, const MediumStack& inside,
                const MediumCrossing& crossing, std::vector<QueuedRay>& children) {
  const double side = glm::dot(ray.ray.direction, hit.si.n);
  for (QueuedRay& child : children) {
    const bool through = crossing.real && child.kind != RayKind::Shadow &&
                         (glm::dot(child.ray.direction, hit.si.n) > 0.0) == (side > 0.0);
    child.media = through ? crossing.after : inside;
  }
}

/// `own` with its colour replaced by its texture's texel at the hit (Texture.h): the
/// algorithms then shade with Material::colour as for an untextured material.
const Material& texturedMaterial(const Material& own, const SceneHit& hit) {
  thread_local Material textured;
  textured = own;  // reuses the name's storage: no allocation once warmed up
  textured.colour = own.texture.eval(own.colour, hit.si.p, hit.si.n);
  return textured;
}

/// The material the rules see at a hit on a nested volume: the object's own, with the
/// index pair of the crossing as its ior (inside of the surface) and iorOutside.
const Material& nestedMaterial(const Material& own, const SceneHit& hit,
                               const MediumCrossing& crossing) {
  thread_local Material adjusted;
  adjusted = own;  // reuses the name's storage: no allocation once warmed up
  const bool entering = hit.si.frontFace;
  adjusted.iorOutside = entering ? crossing.etaIncident : crossing.etaTransmitted;
  adjusted.ior = entering ? crossing.etaTransmitted : crossing.etaIncident;
  return adjusted;
}

/// The surface `ray` ends on, written into `found`, or null when it leaves the scene; with
/// `Nested`, past the false interfaces of nested volumes (passFalseInterfaces).
template <bool Nested>
const SceneHit* nearestHit(const Tracer& tracer, const QueuedRay& ray, SceneHit& found,
                           MediumStack& inside, MediumCrossing& crossing) {
  if (!tracer.intersector().intersect(ray.ray, found)) return nullptr;
  if constexpr (Nested) {
    if (!passFalseInterfaces(tracer, ray, found, inside, crossing)) return nullptr;
  }
  return &found;
}

/// The engine's pieces are forced inline into engineStep, its hot path: no call or argument
/// passed through memory between them (callgrind counts slightly fewer instructions per
/// render than for the step as one function; doc/dev/perf/engine-step-split.md).
#define RAYLAB_STEP_INLINE inline __attribute__((always_inline))

/// Drops the children the engine never lets in: a non-finite or negative weight (a bug in
/// the rule), and, by the no-leak rule of smooth surfaces, a direction on one side of the
/// shading surface and the other of the geometric one (a reflection below the triangle, a
/// light behind it): the shading normal never lets light through.
RAYLAB_STEP_INLINE void dropInvalidChildren(const SurfaceInteraction& si,
                                            std::vector<QueuedRay>& children) {
  const auto invalid = [](const QueuedRay& c) {
    const bool valid = isFinite(c.weight) && isNonNegative(c.weight) && isFinite(c.shadowLe);
    RAYLAB_DCHECK(valid);
    return !valid;
  };
  children.erase(std::remove_if(children.begin(), children.end(), invalid), children.end());
  const auto leaks = [&si](const QueuedRay& c) { return !si.sidesAgree(c.ray.direction); };
  children.erase(std::remove_if(children.begin(), children.end(), leaks), children.end());
}

/// The hit or material a planted bug (Fault) makes the rule see, written into `flipped` or
/// `swapped`; both stay empty for the faults that live elsewhere. Off the fast path.
[[gnu::noinline]] void plantFault(Fault fault, const SceneHit& hit, const Material& material,
                                  std::optional<SceneHit>& flipped,
                                  std::optional<Material>& swapped) {
  if (fault == Fault::FlippedNormal) {
    flipped = hit;
    flipped->si.frontFace = !hit.si.frontFace;
  } else if (fault == Fault::EtaInverted) {
    swapped = material;
    std::swap(swapped->ior, swapped->iorOutside);
  } else if (fault == Fault::SchlickWrongSign) {
    // Only the Schlick paths: a dielectric's Fresnel or the Fresnel weights of kr and kt.
    const bool rates = material.rateFresnel == FresnelModel::Schlick;
    const bool own = material.fresnel == FresnelModel::Schlick;
    if (!rates && !own) return;
    swapped = material;
    if (rates) swapped->rateFresnel = FresnelModel::SchlickWrongSign;
    if (own) swapped->fresnel = FresnelModel::SchlickWrongSign;
  }
}

/// Step 2c: asks the algorithm what the hit spawns into `children` (at a volume's surface,
/// with the indices of the media on its two sides); sets `emitted`, returns how the ray ends.
template <bool Nested>
RAYLAB_STEP_INLINE EndReason spawnAtHit(const Tracer& tracer, const QueuedRay& ray,
                                        const SceneHit& hit, const MediumStack& inside,
                                        const MediumCrossing& crossing, Sampler& sampler,
                                        bool spawns, std::vector<QueuedRay>& children,
                                        Vec3& emitted) {
  const Material& plain = tracer.materialOf(hit.object);
  // A textured material's colour is its texel at the hit: the one lookup every algorithm
  // shares.
  const Material& own = plain.texture.active() ? texturedMaterial(plain, hit) : plain;
  const Material& material = Nested && crossing.real ? nestedMaterial(own, hit, crossing) : own;
  // A planted bug (RenderSettings::fault, bug hunt; never on unless asked for): the rule
  // sees the normal flipped, the indices of refraction swapped (eta inverted) or Schlick's
  // Fresnel with the wrong sign of cos theta.
  std::optional<SceneHit> flipped;
  std::optional<Material> swapped;
  if (tracer.settings().fault != Fault::None)
    plantFault(tracer.settings().fault, hit, material, flipped, swapped);
  const HitContext context{
      tracer.intersector(),          tracer.settings(), ray,   flipped ? *flipped : hit,
      swapped ? *swapped : material, sampler,           spawns};
  const HitDecision decision = tracer.rule().onHit(context, children);
  emitted = decision.emitted;
  dropInvalidChildren(hit.si, children);
  if constexpr (Nested) carryMedia(ray, hit, inside, crossing, children);
  return !children.empty()                    ? EndReason::Spawned
         : decision.end == EndReason::Spawned ? EndReason::Absorbed
                                              : decision.end;
}

/// Step 4 before the queue: each child's parent and throughput (the parent's times the
/// child's weight); past the cap on queued rays, no child and the ray `Stopped`.
RAYLAB_STEP_INLINE void prepareChildren(const QueuedRay& ray, RayCap* cap,
                                        std::vector<QueuedRay>& children, EndReason& end) {
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
}

/**
 * The engine, one step: take the first ray of the queue, find where it ends, let the
 * rule spawn children, add the ray's own contribution `throughput * emitted` to the
 * estimate, queue the children with throughput `throughput * weight`. The same step runs
 * in Tracer::trace (images; `recorder` is null) and Stepper::step (ray trees). `Nested`:
 * the scene has nested volumes (NestedMedia.h), whose lists the step keeps.
 */
template <bool Nested, typename Queue>
void engineStep(const Tracer& tracer, Queue& queue, Sampler& sampler,
                std::vector<QueuedRay>& children, SceneHit& found, Vec3& estimate,
                RayCounts* counts, TreeRecorder* recorder, RayCap* cap) {
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
  // With `Nested` only: the volumes the ray is inside, and the crossing where it ends.
  MediumStack inside = ray.media;
  MediumCrossing crossing;
  crossing.real = false;
  if (ray.kind == RayKind::Shadow) {
    // 2a. A shadow ray only asks whether anything blocks its way to the light.
    const bool blocked = tracer.intersector().occluded(ray.ray);
    end = blocked ? EndReason::Occluded : EndReason::ReachedLight;
    if (!blocked) emitted = ray.shadowLe;
  } else if (!(hit = nearestHit<Nested>(tracer, ray, found, inside, crossing))) {
    // 2b. Nothing in the way (false interfaces of nested volumes passed): the ray leaves.
    end = EndReason::Escaped;
    emitted = tracer.rule().onEscape(ray, tracer.settings());
  } else {
    // 2c. Ask the algorithm what the hit spawns.
    const bool spawns = !(cap && cap->reached) && !(recorder && recorder->full());
    end =
        spawnAtHit<Nested>(tracer, ray, *hit, inside, crossing, sampler, spawns, children, emitted);
  }
  // No NaN or Inf leaves the engine.
  RAYLAB_DCHECK(isFinite(emitted));
  if (!isFinite(emitted)) emitted = Vec3(0.0);

  // 3. The ray's own contribution to the pixel: its throughput times what it found.
  estimate += ray.throughput * emitted;

  // 4. Queue the children: throughput is the parent's times the child's weight.
  prepareChildren(ray, cap, children, end);
  if (recorder) recorder->recordStep(ray, hit, end, emitted, children, Nested ? inside : ray.media);
  queue.pop_front();  // `ray` is gone from here on
  append(queue, children);
}

#undef RAYLAB_STEP_INLINE

/// The settings a Tracer keeps: Fault::NoOffset (bug hunt) is the rayOffset switch off.
RenderSettings withFault(RenderSettings settings) {
  if (settings.fault == Fault::NoOffset) settings.rayOffset = false;
  return settings;
}

}  // namespace

Tracer::Tracer(const Scene& scene, const RenderSettings& settings)
    : m_intersector(scene, settings),
      m_settings(withFault(settings)),
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
  // Nested volumes, and those the camera starts inside (a camera under water).
  m_media = NestedMedia(scene);
  if (m_media.active()) m_cameraMedia = m_media.volumesAt(scene, scene.camera.position);
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
  // Scenes with nested volumes run the step that tracks them; the others pay nothing.
  if (m_media.active()) {
    while (!queue.empty())
      engineStep<true>(*this, queue, sampler, children, found, estimate, counts, nullptr, &cap);
  } else {
    while (!queue.empty())
      engineStep<false>(*this, queue, sampler, children, found, estimate, counts, nullptr, &cap);
  }
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
  if (m_root && m_tracer->media().active())
    camera.media = m_tracer->media().volumesAt(m_tracer->scene(), m_root->origin);
  TreeRecorder(*m_tracer, m_tree, m_event, m_budget).recordCamera(camera);
  // A budget below one segment traces nothing: the work is bounded by the budget too.
  if (camera.id >= 0) m_queue.push_back(camera);
}

bool Stepper::step() {
  if (m_queue.empty()) return false;
  TreeRecorder recorder(*m_tracer, m_tree, m_event, m_budget);
  SceneHit found;
  if (m_tracer->media().active())
    engineStep<true>(*m_tracer, m_queue, m_sampler, m_children, found, m_estimate, &m_counts,
                     &recorder, nullptr);
  else
    engineStep<false>(*m_tracer, m_queue, m_sampler, m_children, found, m_estimate, &m_counts,
                      &recorder, nullptr);
  // Once the queue is empty every ray has ended: propagate energy up the tree.
  if (m_queue.empty()) m_tree.propagate();
  return true;
}

void Stepper::runToEnd() {
  while (step()) {
  }
}

void Stepper::stop() {
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
  m_tree.stop = TreeStop{StopCause::Cancelled, std::size_t(m_counts.total()), 0, 0};
  m_tree.propagate();
}

}  // namespace raylab
