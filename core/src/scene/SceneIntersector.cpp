#include "raylab/core/SceneIntersector.h"

#include "raylab/core/Bvh.h"
#include "raylab/core/RayOffset.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/TriangleMesh.h"
#include "scene/SphereLightSampler.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

/// The ray in the frame of an object moving with `velocity`: at ray time tau the object
/// is displaced by tau * velocity, which is the same as moving the ray origin back.
Ray toObjectFrame(const Ray& ray, const Vec3& velocity) {
  Ray r = ray;
  r.origin -= ray.time * velocity;
  return r;
}

bool isMoving(const SceneObject& object) {
  return object.velocity.x != 0.0 || object.velocity.y != 0.0 || object.velocity.z != 0.0;
}

}  // namespace

SceneIntersector::SceneIntersector(const Scene& scene) : SceneIntersector(scene, scene.render) {}

SceneIntersector::SceneIntersector(const Scene& scene, const RenderSettings& settings)
    : m_scene(&scene), m_bruteForce(!settings.acceleration) {
  for (const SceneObject& object : scene.objects) {
    Entry e;
    e.shape = object.shape.get();
    e.moving = isMoving(object);
    e.velocity = object.velocity;
    if (object.shape->kind() == ShapeKind::Sphere)
      e.sphere = static_cast<const Sphere*>(object.shape.get());
    if (!e.moving && object.shape->kind() == ShapeKind::Sphere &&
        static_cast<const Sphere&>(*object.shape).isRound())
      e.round = static_cast<const Sphere*>(object.shape.get());
    if (object.shape->kind() == ShapeKind::TriangleMesh) {
      // The mesh's own hierarchy, or one built with the split the settings ask for.
      const auto& mesh = static_cast<const TriangleMesh&>(*object.shape);
      e.bvh = &mesh.bvh();
      if (!m_bruteForce && mesh.bvh().settings().split != settings.bvhSplit) {
        BvhSettings bvhSettings = mesh.bvh().settings();
        bvhSettings.split = settings.bvhSplit;
        m_rebuilt.push_back(
            std::make_shared<const Bvh>(mesh.vertices(), mesh.triangles(), bvhSettings));
        e.bvh = m_rebuilt.back().get();
      }
    }
    m_entries.push_back(e);
  }
  // The static round spheres as columns, for their roots several at a time (SphereBatch.cpp).
  gatherRoundSpheres();

  // Every object with an emissive material is an area light; it is picked with
  // probability proportional to its power, luminance(emission) * area (the radiance is
  // uniform, so power = pi * L * area for one-sided emission; the pi cancels).
  double total = 0.0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    if (object.material < 0 || object.material >= static_cast<int>(scene.materials.size()))
      continue;
    const Material& material = scene.materials[static_cast<std::size_t>(object.material)];
    if (!material.isEmitter() || !object.shape) continue;
    const double area = object.shape->area();
    if (!(area > 0.0) || !std::isfinite(area))
      throw Shape::InvalidGeometry("object '" + object.name + "' has emissive material '" +
                                   material.name + "' but its area (" + std::to_string(area) +
                                   ") cannot be sampled: a plane cannot be a light, use a quad");
    m_lights.push_back(static_cast<int>(i));
    const bool round = object.shape->kind() == ShapeKind::Sphere &&
                       static_cast<const Sphere&>(*object.shape).isRound();
    m_sphereLights.push_back(
        round ? std::make_shared<const SphereLightSampler>(scene, static_cast<int>(i)) : nullptr);
    total += luminance(material.emission) * area;
    m_lightCdf.push_back(total);
  }
  for (double& c : m_lightCdf) c /= total;
  if (!m_lightCdf.empty()) m_lightCdf.back() = 1.0;
}

std::optional<SceneHit> SceneIntersector::intersect(const Ray& ray) const {
  std::optional<SceneHit> out(std::in_place);
  if (!intersect(ray, *out)) out.reset();
  return out;
}

bool SceneIntersector::intersect(const Ray& ray, SceneHit& out) const {
  // The static round spheres' roots, all at once (SphereBatch.cpp); a scene of nothing else
  // (smallpt) takes its own fast path there.
  double roots[kBatchSpheres];
  const bool batched = batchRoots(ray, false, roots);
  if (batched && m_allRound) return intersectOnlySpheres(ray, roots, out);

  // Nearest hit over all objects: each accepted hit shortens the ray, so later objects
  // only report closer hits.
  Ray r = ray;
  int nearest = -1;
  Hit nearestHit;
  for (std::size_t i = 0; i < m_entries.size(); ++i) {
    const Entry& e = m_entries[i];
    const std::optional<Hit> hit =
        e.round ? roundHit(e, m_roundSlot[i], r, batched ? roots : nullptr)
                : intersectEntry(e, e.moving ? toObjectFrame(r, e.velocity) : r);
    if (hit) {
      nearest = static_cast<int>(i);
      nearestHit = *hit;
      r.tMax = hit->t;
    }
  }
  if (nearest < 0) return false;

  // Surface geometry of the nearest hit only, moved back to where the object is at the
  // ray's time. A sphere's uv is left out: nothing in the engine reads it (Sphere::uvAt).
  const Entry& e = m_entries[static_cast<std::size_t>(nearest)];
  out.object = nearest;
  const Ray objectRay = e.moving ? toObjectFrame(ray, e.velocity) : ray;
  out.si = e.sphere ? e.sphere->geometryAt(objectRay, nearestHit)
                    : e.shape->surfaceAt(objectRay, nearestHit);
  if (e.moving) {
    // The shift adds two roundings (the product and the sum).
    const Vec3 shift = ray.time * e.velocity;
    out.si.pError += kRoundingGamma<2> * (absolute(out.si.p) + absolute(shift));
    out.si.p += shift;
  }
  return true;
}

std::optional<Hit> SceneIntersector::roundHit(const Entry& e, int slot, const Ray& ray,
                                              const double* roots) const {
  // Static round sphere: the same roots as Sphere::intersect, called directly. A batched
  // root is the first in [tMin, tMax] of the ray as given: the one nearestRoot picks with
  // tMax shortened by the hits before it, if it is within that shorter tMax at all (roots
  // are sorted).
  if (roots) {
    const double t = roots[slot];
    if (t <= ray.tMax) return Hit{t, 0, {}};  // false for NaN: no root
    return std::nullopt;
  }
  if (const std::optional<double> t = e.round->nearestRoot(ray)) return Hit{*t, 0, {}};
  return std::nullopt;
}

bool SceneIntersector::batchRoots(const Ray& ray, bool segment, double* roots) const {
  return m_roundCount > 0 && m_roundCount + 3 <= kBatchSpheres && roundRoots(ray, segment, roots);
}

bool SceneIntersector::occluded(const Ray& ray) const {
  // Any hit in range blocks: the round spheres all at once, then the rest one by one.
  double roots[kBatchSpheres];
  const bool precomputed = batchRoots(ray, true, roots);
  if (precomputed) {
    for (int k = 0; k < m_roundCount; ++k)
      if (roots[k] == roots[k]) return true;  // not NaN: a root in range
  }
  for (const Entry& e : m_entries) {
    if (e.round) {
      if (!precomputed && e.round->nearestRoot(ray)) return true;
    } else if (occludedEntry(e, e.moving ? toObjectFrame(ray, e.velocity) : ray)) {
      return true;
    }
  }
  return false;
}

const Bvh* SceneIntersector::hierarchy(int object) const {
  if (object < 0 || object >= static_cast<int>(m_entries.size())) return nullptr;
  return m_entries[static_cast<std::size_t>(object)].bvh;
}

std::optional<Hit> SceneIntersector::intersectEntry(const Entry& e, const Ray& ray) const {
  if (!e.bvh) return e.shape->intersect(ray);
  return m_bruteForce ? e.bvh->intersectBruteForce(ray) : e.bvh->intersect(ray);
}

bool SceneIntersector::occludedEntry(const Entry& e, const Ray& ray) const {
  if (!e.bvh) return bool(e.shape->intersect(ray));
  // A mesh stops at the first triangle that blocks (any hit), not the nearest.
  return m_bruteForce ? e.bvh->occludedBruteForce(ray) : e.bvh->occluded(ray);
}

std::optional<LightSample> SceneIntersector::sampleLight(const Point3& ref, const Vec2& uLight,
                                                         double uPick, double time) const {
  std::optional<LightSample> ls(std::in_place);
  if (!sampleLight(ref, uLight, uPick, time, *ls)) ls.reset();
  return ls;
}

bool SceneIntersector::sampleLight(const Point3& ref, const Vec2& uLight, double uPick, double time,
                                   LightSample& ls) const {
  if (m_lights.empty()) return false;
  // Pick a light by power: the first CDF entry above uPick.
  const auto it = std::upper_bound(m_lightCdf.begin(), m_lightCdf.end(), uPick);
  const std::size_t k =
      std::min<std::size_t>(static_cast<std::size_t>(it - m_lightCdf.begin()), m_lights.size() - 1);
  const double pick = m_lightCdf[k] - (k == 0 ? 0.0 : m_lightCdf[k - 1]);
  if (!sampleLightAt(k, ref, uLight, time, ls)) return false;
  ls.pdf *= pick;
  return ls.pdf > 0.0 && std::isfinite(ls.pdf);
}

std::optional<LightSample> SceneIntersector::sampleLightObject(int object, const Point3& ref,
                                                               const Vec2& u, double time) const {
  const auto it = std::lower_bound(m_lights.begin(), m_lights.end(), object);
  if (it == m_lights.end() || *it != object) return std::nullopt;
  std::optional<LightSample> ls(std::in_place);
  if (!sampleLightAt(static_cast<std::size_t>(it - m_lights.begin()), ref, u, time, *ls))
    ls.reset();
  return ls;
}

bool SceneIntersector::sampleLightAt(std::size_t k, const Point3& ref, const Vec2& uLight,
                                     double time, LightSample& ls) const {
  const int index = m_lights[k];
  const SceneObject& object = m_scene->objects[static_cast<std::size_t>(index)];

  // Work where the light is at rest: a light displaced by time * velocity sees ref
  // displaced the other way.
  const Vec3 shift = object.displacementAt(time);
  const Point3 localRef = ref - shift;
  if (m_sphereLights[k]) {
    // A round sphere: by solid angle, on the part of it ref can see.
    if (!m_sphereLights[k]->sample(localRef, uLight, ls)) return false;
  } else {
    // A point on its surface, uniform in area; only the front side emits.
    if (!lightSampleFromArea(object.shape->sampleArea(uLight), localRef, ls)) return false;
  }
  ls.object = index;
  ls.p += shift;
  ls.Le = m_scene->materials[static_cast<std::size_t>(object.material)].emission;
  return ls.pdf > 0.0 && std::isfinite(ls.pdf);
}

double SceneIntersector::lightPdf(const Point3& ref, int object, const SurfaceInteraction& hit,
                                  double time) const {
  // The probability of picking this light (0 if it is not one).
  const auto it = std::lower_bound(m_lights.begin(), m_lights.end(), object);
  if (it == m_lights.end() || *it != object) return 0.0;
  const std::size_t k = static_cast<std::size_t>(it - m_lights.begin());
  const double pick = m_lightCdf[k] - (k == 0 ? 0.0 : m_lightCdf[k - 1]);

  // Back to where the light is at rest, as sampleLight does.
  const SceneObject& light = m_scene->objects[static_cast<std::size_t>(object)];
  const Vec3 shift = light.displacementAt(time);
  const Point3 localRef = ref - shift;
  const Point3 p = hit.p - shift;
  if (m_sphereLights[k]) return m_sphereLights[k]->pdf(localRef, p, hit.n) * pick;

  // The same conversion as sampleLight, and the same rule: back faces are never sampled.
  const Vec3 toLight = p - localRef;
  const double distance2 = glm::dot(toLight, toLight);
  if (!(distance2 > 0.0)) return 0.0;
  const double cosLight = -glm::dot(hit.n, toLight) / std::sqrt(distance2);
  if (!(cosLight > 0.0)) return 0.0;
  return light.shape->pdfArea(p) * distance2 / cosLight * pick;
}

Vec3 SceneIntersector::emitted(int object, const SurfaceInteraction& hit,
                               const Vec3& rayDirection) const {
  if (object < 0 || object >= static_cast<int>(m_scene->objects.size())) return Vec3(0.0);
  const int m = m_scene->objects[static_cast<std::size_t>(object)].material;
  if (m < 0 || m >= static_cast<int>(m_scene->materials.size())) return Vec3(0.0);
  const Material& material = m_scene->materials[static_cast<std::size_t>(m)];
  // Emission leaves the front side only: the ray must arrive against the outward normal.
  if (!material.isEmitter() || !(glm::dot(hit.n, rayDirection) < 0.0)) return Vec3(0.0);
  return material.emission;
}

}  // namespace raylab
