#pragma once

#include "raylab/core/Scene.h"
#include "raylab/core/Shape.h"

#include <memory>
#include <optional>
#include <vector>

namespace raylab {

class Bvh;
class Sphere;
class SphereLightSampler;

/// The nearest hit of a ray in a scene.
struct SceneHit {
  int object = -1;        ///< Index in Scene::objects.
  SurfaceInteraction si;  ///< World-space geometry of the hit (moved objects included);
                          ///< uv is left (0, 0) on spheres (ask Sphere::uvAt).
};

/// A point sampled on an area light, seen from a reference point.
struct LightSample {
  int object = -1;        ///< The emitter's index in Scene::objects.
  Point3 p{0.0};          ///< Point on the light, world space.
  Normal3 n{0.0};         ///< Light's outward unit normal at p.
  Vec3 wi{0.0};           ///< Unit direction from the reference point to p.
  double distance = 0.0;  ///< From the reference point to p.
  Vec3 Le{0.0};           ///< Radiance emitted from p towards the reference point.
  double pdf = 0.0;       ///< Solid-angle density at the reference point, including the
                          ///< probability of choosing this light.
};

/**
 * \brief The scene as the tracers see it: nearest-hit and occlusion queries over all
 * objects (moving objects at the ray's time), and the list of area lights with their
 * sampling (lights chosen in proportion to their emitted power).
 *
 * Meshes are searched as the render settings say (lesson 8): through their BVH, one built
 * with the settings' split (the mesh's own when it matches, else one built here), or by
 * brute force over every triangle when acceleration is off. The hits are the same either
 * way, bit for bit; only the work differs.
 *
 * Light points: round sphere lights are sampled by solid angle, in the cone they subtend,
 * restricted to the part of the light no other sphere separates from the shading point
 * (SphereLightSampler, core/src/scene); every other shape uniformly by area. Moving lights
 * are sampled where they are at the given shutter time.
 */
class SceneIntersector {
 public:
  /// The scene with its own render block's acceleration settings.
  explicit SceneIntersector(const Scene& scene);
  /// The scene searched as `settings` say (acceleration, bvhSplit; the rest is unused).
  SceneIntersector(const Scene& scene, const RenderSettings& settings);

  /// Nearest hit with t in [ray.tMin, ray.tMax], over every object.
  std::optional<SceneHit> intersect(const Ray& ray) const;
  /// The same into `hit` (left as it was when nothing is hit): false when nothing is.
  bool intersect(const Ray& ray, SceneHit& hit) const;
  /// True when anything blocks the ray within [ray.tMin, ray.tMax].
  bool occluded(const Ray& ray) const;

  /// Emitter objects (indices into Scene::objects).
  const std::vector<int>& areaLights() const { return m_lights; }
  /// Samples a point on an area light for shading point `ref` at shutter time `time`.
  /// Nothing when the scene has no area light, the sample faces away or it falls on a
  /// part of the light that `ref` cannot see (see the class comment).
  std::optional<LightSample> sampleLight(const Point3& ref, const Vec2& uLight, double uPick,
                                         double time = 0.0) const;
  /// The same into `ls` (partly written when there is none): false when there is none.
  bool sampleLight(const Point3& ref, const Vec2& uLight, double uPick, double time,
                   LightSample& ls) const;
  /// Samples a point on the area light `object` (one of areaLights()) the way sampleLight
  /// does once it has picked that light: the pdf is this light's alone, without the pick
  /// probability. For algorithms that sample every light in turn (distributed tracing).
  std::optional<LightSample> sampleLightObject(int object, const Point3& ref, const Vec2& u,
                                               double time = 0.0) const;
  /// Solid-angle density with which sampleLight(ref, ..., time) would pick the point `hit`
  /// (on emitter `object`, where it is at `time`): used to MIS-weight emitters hit by BSDF
  /// sampling. It must be asked with the same ref and time as sampleLight.
  double lightPdf(const Point3& ref, int object, const SurfaceInteraction& hit,
                  double time = 0.0) const;
  /// Radiance an emitter sends from a hit towards the direction -rayDirection
  /// (front side only), 0 for non-emitters.
  Vec3 emitted(int object, const SurfaceInteraction& hit, const Vec3& rayDirection) const;

  const Scene& scene() const { return *m_scene; }
  /// The hierarchy searched for mesh object `object` (built with the settings' split; the
  /// mesh's own when acceleration is off), or null when that object is not a mesh. A
  /// rebuilt hierarchy belongs to this intersector: keep the intersector while using it.
  const Bvh* hierarchy(int object) const;

 private:
  /// sampleLightObject for light k of m_lights.
  bool sampleLightAt(std::size_t k, const Point3& ref, const Vec2& u, double time,
                     LightSample& ls) const;

  /// What the inner loops need of an object, gathered once.
  struct Entry {
    const Shape* shape = nullptr;
    const Sphere* round = nullptr;   ///< Static round spheres: intersected without a virtual call.
    const Sphere* sphere = nullptr;  ///< Any sphere: its hit geometry without uv (geometryAt).
    const Bvh* bvh = nullptr;        ///< Meshes: the hierarchy searched (null: other shapes).
    bool moving = false;
    Vec3 velocity{0.0};
  };

  /// Nearest hit of entry `e` (not a static round sphere) with `ray`, in the object's frame.
  std::optional<Hit> intersectEntry(const Entry& e, const Ray& ray) const;
  bool occludedEntry(const Entry& e, const Ray& ray) const;
  /// Nearest hit of static round sphere `e` (column `slot`) with `ray`: its batched root from
  /// `roots` (batchRoots), or Sphere::nearestRoot when `roots` is null.
  std::optional<Hit> roundHit(const Entry& e, int slot, const Ray& ray, const double* roots) const;

  const Scene* m_scene;
  bool m_bruteForce = false;     ///< RenderSettings::acceleration off: test every triangle.
  std::vector<Entry> m_entries;  ///< Parallel to Scene::objects.
  /// The static round spheres by decreasing radius, their centres and radii as columns
  /// (padded to a multiple of 4 with spheres of radius 0), for roots several at a time
  /// (roundRoots). Gathered, and searched, in core/src/scene/SphereBatch.cpp, beside the
  /// plain loop of intersect().
  std::vector<double> m_roundX, m_roundY, m_roundZ, m_roundR;
  std::vector<int> m_roundSlot;    ///< Per entry: its index in the columns, or -1.
  std::vector<int> m_roundObject;  ///< Per column slot (not padding): its entry.
  std::vector<double> m_roundPad;  ///< Per column slot: all bits set for padding, else 0.
  int m_roundCount = 0;
  bool m_allRound = false;  ///< Every object is a static round sphere.

  /// For every column slot k, the t that Sphere::nearestRoot(ray) gives for its sphere, or
  /// NaN when it gives none, into out[k] (m_roundCount values; out has room for the padded
  /// columns). Four spheres at a time with AVX, two with SSE2, the same operations in the
  /// same order as Sphere::roots: the same bits; a group of lanes that a cheap test proves
  /// all missed is skipped (NaN). With `segment` (occlusion), lanes whose segment [tMin,
  /// tMax] provably lies inside the sphere or ends before it are NaN without their roots.
  /// False when not on x86-64 (the caller loops).
  bool roundRoots(const Ray& ray, bool segment, double* out) const;
  /// Most columns (padding included) batchRoots answers for: callers keep the roots on the stack.
  static constexpr int kBatchSpheres = 64;
  /// roundRoots into `roots` (kBatchSpheres values) when there are round spheres and no more
  /// than fit; false when the caller must test them one by one.
  bool batchRoots(const Ray& ray, bool segment, double* roots) const;
  /// Fills the columns and m_roundSlot, m_roundObject, m_roundCount, m_allRound from
  /// m_entries (the constructor, once).
  void gatherRoundSpheres();
  /// intersect() for a scene of static round spheres only (m_allRound, smallpt), from their
  /// batched `roots`: the same answer without the loop's branches.
  bool intersectOnlySpheres(const Ray& ray, const double* roots, SceneHit& out) const;
  /// Meshes' hierarchies rebuilt with the settings' split (Entry::bvh points into them).
  std::vector<std::shared_ptr<const Bvh>> m_rebuilt;
  std::vector<int> m_lights;
  std::vector<double> m_lightCdf;  ///< Cumulative pick probabilities (by power).
  /// Per light (parallel to m_lights): its solid-angle sampler, null for area sampling.
  std::vector<std::shared_ptr<const SphereLightSampler>> m_sphereLights;
};

}  // namespace raylab
