// One recorded ray read against its scene (RayInspector::inspect).
#include "raylab/core/Fresnel.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Shape.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

/// Why a Reflection / Refraction child of a Fresnel-weighted Mirror, Phong or BlinnPhong hit
/// has its weight (kr R or kt (1 - R)); nothing for other rays.
std::optional<RateWeight> rateWeightOf(const Scene& scene, const RayTree& tree,
                                       const RaySegment& s) {
  if (s.parent < 0 || (s.kind != RayKind::Reflection && s.kind != RayKind::Refraction)) return {};
  const RaySegment& p = tree.segments[std::size_t(s.parent)];
  if (!p.hit || p.object < 0 || p.object >= int(scene.objects.size())) return {};
  const int material = scene.objects[std::size_t(p.object)].material;
  if (material < 0 || material >= int(scene.materials.size())) return {};
  const Material& m = scene.materials[std::size_t(material)];
  if (!m.hasRates() || m.rateFresnel == FresnelModel::None) return {};
  // The incidence at the parent's hit, on the side it came from.
  const Normal3 n = isZero(p.shadingNormal) ? p.normal : p.shadingNormal;
  const double cosI = std::abs(glm::dot(p.direction, n));
  const bool entering = glm::dot(p.direction, p.normal) < 0.0;
  const double eta = entering ? 1.0 / m.relativeIor() : m.relativeIor();
  // The scene's planted bug (bug hunt) shows here as it did in the engine.
  const bool fault =
      scene.render.fault == Fault::SchlickWrongSign && m.rateFresnel == FresnelModel::Schlick;
  const FresnelModel model = fault ? FresnelModel::SchlickWrongSign : m.rateFresnel;
  const double R = fresnel::reflectance(model, cosI, eta);
  RateWeight w;
  w.reflected = s.kind == RayKind::Reflection;
  w.rate = w.reflected ? m.reflectionRate : m.refractionRate;
  w.share = w.reflected ? R : 1.0 - R;
  w.timesTint = m.type == MaterialType::Mirror;
  w.model = model;
  w.incidence = std::acos(std::min(1.0, cosI)) * 180.0 / kPi;
  return w;
}

}  // namespace

RayInspection RayInspector::inspect(const Scene& scene, const RayTree& tree, int id,
                                    bool withOracle) {
  if (id < 0 || id >= int(tree.segments.size()))
    throw BadSegment("ray #" + std::to_string(id) + " is not in the tree (it has " +
                     std::to_string(tree.segments.size()) + " rays: #0..#" +
                     std::to_string(int(tree.segments.size()) - 1) + ")");
  const RaySegment& s = tree.segments[std::size_t(id)];
  RayInspection r;

  // Keep what the tree recorded, and what follows from it.
  r.segment = s;
  r.lightPoint = s.kind == RayKind::Shadow ? s.lightPoint : s.endPoint;
  r.distance = glm::length(s.endPoint - s.origin);
  r.energy = s.energy();

  // Name the object and its material.
  if (s.object >= 0 && s.object < int(scene.objects.size())) {
    const SceneObject& o = scene.objects[std::size_t(s.object)];
    r.objectName = o.name;
    if (o.material >= 0 && o.material < int(scene.materials.size())) {
      const Material& m = scene.materials[std::size_t(o.material)];
      r.material = MaterialSummary{m.name, m.type, m.isEmitter(), m, std::nullopt};
      // A textured colour: the texel the algorithms shaded this hit with.
      if (m.texture.active() && s.hit && s.kind != RayKind::Shadow)
        r.material->texel = m.texture.eval(m.colour, s.endPoint, s.normal);
    }
  }
  r.lightName = lightNameOf(s, scene);

  r.rateWeight = rateWeightOf(scene, tree, s);

  // Nested volumes: the ones it is inside, and the index pair where it meets one.
  const NestedMedia media(scene);
  if (media.active() && s.kind != RayKind::Shadow) {
    r.nested = true;
    for (std::int16_t o : s.media.objects) {
      if (o < 0 || std::size_t(o) >= scene.objects.size()) continue;
      const SceneObject& volume = scene.objects[std::size_t(o)];
      const Material& m = scene.materials[std::size_t(volume.material)];
      r.media.push_back({volume.name, m.ior, std::max(0, m.priority)});
    }
    r.mediumIor = media.ior(s.media, 1.0);
    if (s.hit && media.isVolume(s.object)) {
      const bool entering = glm::dot(s.direction, s.normal) < 0.0;
      const MediumCrossing c = media.cross(s.media, s.object, entering);
      r.indices = IndexCrossing{c.etaIncident, c.etaTransmitted, entering,
                                scene.objects[std::size_t(s.object)].name};
    }
  }

  // Check the hit against the exact oracle.
  if (withOracle && s.hit && s.object >= 0 && s.object < int(scene.objects.size()) &&
      scene.objects[std::size_t(s.object)].shape)
    r.oracle = checkHit(scene, s.object, s.origin, s.direction, s.time, s.endPoint);
  return r;
}

std::vector<SceneCrossing> sceneCrossings(const Scene& scene, const Point3& origin,
                                          const Vec3& direction, double time,
                                          std::size_t maxCount) {
  std::vector<SceneCrossing> all;
  const double length = glm::length(direction);
  if (!(length > 0.0) || !std::isfinite(length)) return all;
  const Vec3 unit = direction / length;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    if (!object.shape) continue;
    // A moving object is met in its own frame: the origin moved back by its displacement.
    const Ray ray = Ray::make(origin - object.displacementAt(time), unit, 0.0, kInfinity, time);
    const bool closed = object.shape->isClosed();
    for (const Crossing& c : object.shape->intersectAll(ray)) {
      if (!(c.t > 0.0)) continue;
      all.push_back({int(i), c.t, origin + c.t * unit, c.entering, closed});
    }
  }
  std::stable_sort(all.begin(), all.end(),
                   [](const SceneCrossing& a, const SceneCrossing& b) { return a.t < b.t; });
  if (all.size() > maxCount) all.resize(maxCount);
  return all;
}

}  // namespace raylab
