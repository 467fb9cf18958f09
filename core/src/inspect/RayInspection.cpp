// One recorded ray read against its scene (RayInspector::inspect).
#include "inspect/InspectorFormat.h"
#include "raylab/core/RayInspector.h"

namespace raylab {

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
      r.material = MaterialSummary{m.name, m.type, inspect::materialParameters(m), m.isEmitter()};
    }
  }
  std::vector<std::string> names;
  for (const SceneObject& o : scene.objects) names.push_back(o.name);
  r.ended = describeEnd(s, names);

  // Check the hit against the exact oracle.
  if (withOracle && s.hit && s.object >= 0 && s.object < int(scene.objects.size()) &&
      scene.objects[std::size_t(s.object)].shape)
    r.oracle = checkHit(scene, s.object, s.origin, s.direction, s.time, s.endPoint);
  return r;
}

}  // namespace raylab
