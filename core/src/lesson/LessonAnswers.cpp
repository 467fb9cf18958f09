// What a lesson step computes: a question's answer on its step's scene (renderer, tracer,
// BVH), a samples view's directions, and the step's camera ray and tree.
#include "raylab/core/Bvh.h"
#include "raylab/core/Check.h"
#include "raylab/core/Exception.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/Sampler.h"
#include "raylab/core/Sampling.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Tracer.h"

#include <algorithm>
#include <cmath>

namespace raylab {

double computeCheck(const LessonStep& step, const LessonCheck& c) {
  // A "change a value" step asks about its scene with the value tried.
  const Scene& scene = step.tryValue ? *step.tryValue->triedScene : *step.scene;
  RenderSettings settings = scene.render;
  settings.algorithm = c.algorithm;
  using Q = LessonCheck::Quantity;
  if (c.quantity == Q::CameraRays) {
    // Every algorithm sends the same camera rays; ray casting is the quickest to run.
    settings.algorithm = Algorithm::RayCasting;
    Renderer renderer(scene, settings);
    renderer.render();
    return double(renderer.stats().rays.byKind[static_cast<int>(RayKind::Camera)]);
  }
  if (c.quantity == Q::BvhNodes || c.quantity == Q::BvhBoxesEntered ||
      c.quantity == Q::BvhTriangleTests) {
    // The hierarchy the step's render searches, and the camera ray of the check's pixel.
    const SceneIntersector intersector(scene, step.settings());  // owns a rebuilt hierarchy
    const Bvh* bvh = intersector.hierarchy(c.object);
    if (!bvh) throw Exception("object " + std::to_string(c.object) + " is not a mesh");
    if (c.quantity == Q::BvhNodes) return bvh->stats().nodeCount;
    LessonStep at = step;
    at.pixelX = c.pixelX;
    at.pixelY = c.pixelY;
    at.sample = c.sample;
    const BvhTrace trace = bvh->traceVisits(*at.cameraRay());
    return c.quantity == Q::BvhBoxesEntered ? trace.boxesEntered : trace.triangleTests;
  }
  const Tracer tracer(scene, settings);
  if (c.quantity == Q::PixelLuminance) {
    const int spp = c.spp > 0 ? c.spp : settings.samplesPerPixel;
    double sum = 0.0;
    for (int s = 0; s < spp; ++s) sum += luminance(tracer.trace(c.pixelX, c.pixelY, s));
    return sum / spp;
  }
  Stepper stepper(tracer, c.pixelX, c.pixelY, c.sample, kDefaultTreeBudget, c.root);
  stepper.runToEnd();
  const RayTree& tree = stepper.tree();
  if (tree.truncated) throw Exception("the ray tree reached its budget: its counts are not whole");
  switch (c.quantity) {
    case Q::TreeRays:
      return double(
          std::count_if(tree.segments.begin(), tree.segments.end(), [&](const RaySegment& r) {
            return (!c.kind || r.kind == *c.kind) && (!c.end || r.endReason == *c.end);
          }));
    case Q::TreeDepth: {
      int depth = 0;
      for (const RaySegment& r : tree.segments) depth = std::max(depth, r.depth);
      return depth;
    }
    case Q::EstimateLuminance:
      return luminance(stepper.estimate());
    case Q::RayLength: {
      if (c.ray >= static_cast<int>(tree.segments.size()))
        throw Exception("ray " + std::to_string(c.ray) + " is not in the tree");
      const RaySegment& r = tree.segments[static_cast<std::size_t>(c.ray)];
      if (!r.hit)
        throw Exception("ray " + std::to_string(c.ray) +
                        " hits nothing: its length is not defined");
      return glm::length(r.endPoint - r.origin);
    }
    default:
      break;
  }
  throw Exception(std::string("no computation for quantity ") + toString(c.quantity));
}

std::vector<Vec3> LessonSamples::directions(std::uint64_t seed) const {
  std::vector<Vec3> result;
  result.reserve(std::size_t(std::max(count, 0)));
  for (int i = 0; i < count; ++i) {
    // Independent random points (sample i's stream), not a stratified pattern: the
    // cloud shows the density the sampler draws from, as a renderer meets it.
    raylab::Sampler random(seed, 0, 0, i);
    const Vec2 u = random.next2D();
    switch (sampler) {
      case Sampler::Cosine:
        result.push_back(sampleCosineHemisphere(u));
        break;
      case Sampler::Uniform: {
        Vec3 d = sampleUniformSphere(u);
        d.z = std::abs(d.z);
        result.push_back(d);
        break;
      }
      case Sampler::Sphere:
        result.push_back(sampleUniformSphere(u));
        break;
      case Sampler::Phong:
        result.push_back(samplePhongLobe(u, exponent));
        break;
    }
  }
  return result;
}

std::optional<Ray> LessonStep::cameraRay() const {
  if (ray) return ray;
  if (!pixelX || !pixelY) return std::nullopt;
  const Tracer tracer(*scene, settings());
  Stepper stepper(tracer, *pixelX, *pixelY, sample);
  stepper.step();
  const RaySegment& camera = stepper.tree().segments.at(0);
  return Ray::make(camera.origin, camera.direction, 0.0, kInfinity, camera.time);
}

PixelTrace LessonStep::trace(const TraceLimits& limits) const {
  RAYLAB_CHECK(traces());
  const Tracer tracer(*scene, settings());
  return ray ? traceRay(tracer, *ray, pixelX.value_or(0), pixelY.value_or(0), sample, limits)
             : tracePixel(tracer, *pixelX, *pixelY, sample, limits);
}

}  // namespace raylab
