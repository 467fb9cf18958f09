#include "raylab/core/SceneIO.h"

#include "raylab/core/AtomicFile.h"

#include "io/PrettyJson.h"
#include "scene/ObjectForm.h"
#include "scene/ObjectWriter.h"
#include "scene/SceneKeys.h"
#include "shapes/ShapeFormat.h"

#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <utility>

// SceneIO's writer: Scene -> version-2 file text (and the atomic save). The reader is
// SceneReader.cpp; the keys both use are in SceneKeys.h.

namespace raylab {

namespace {

/// A "display_name": {"zh": ...}.
ojson displayNameJson(const std::string& zh) {
  return ObjectWriter(kDisplayNameKeys).add("zh", zh).take();
}

/// A material as JSON: always name, type, colour, emission and opacity; its texture if any; the
/// parameters the type uses; and any other parameter that differs from its default (so nothing is
/// lost in a round trip).
ojson materialToJson(const Material& m) {
  const Material defaults;
  const bool mirror = m.type == MaterialType::Mirror;
  const bool dielectric = m.type == MaterialType::Dielectric;
  const bool glossy = m.type == MaterialType::Glossy;
  const bool classic = m.isClassic();
  const bool rough = m.isRough();
  const bool roughGlass = m.type == MaterialType::RoughDielectric;
  const bool plastic = m.isPlastic();
  ObjectWriter j(kMaterialKeys);
  j.add("name", m.name);
  if (!m.nameZh.empty()) j.add("display_name", displayNameJson(m.nameZh));
  j.add("type", toString(m.type)).add("colour", toJson(m.colour));
  if (m.texture.active())
    j.add("texture", ObjectWriter(kTextureKeys)
                         .add("type", toString(m.texture.type))
                         .add("scale", m.texture.scale)
                         .add("colour2", toJson(m.texture.colour2))
                         .take());
  j.add("emission", toJson(m.emission));
  if (mirror || classic || m.reflectionRate != defaults.reflectionRate)
    j.add("reflection_rate", m.reflectionRate);
  if (mirror || classic || m.refractionRate != defaults.refractionRate)
    j.add("refraction_rate", m.refractionRate);
  if (mirror || dielectric || roughGlass || plastic || (classic && m.refractionRate > 0.0) ||
      m.ior != defaults.ior)
    j.add("ior", m.ior);
  if (glossy || classic || m.exponent != defaults.exponent) j.add("exponent", m.exponent);
  if (glossy || classic || m.specular != defaults.specular) j.add("specular", m.specular);
  j.add("opacity", m.opacity);
  if (classic || m.ambient != defaults.ambient) j.add("ambient", toJson(m.ambient));
  if (classic || m.diffuse != defaults.diffuse) j.add("diffuse", m.diffuse);
  if (classic || m.attenuation != defaults.attenuation) j.add("attenuation", toJson(m.attenuation));
  // One key, two fields: the rates' weighting (mirror, phong, blinn_phong; left out when
  // none, so older files read the same), else a dielectric interface's reflectance.
  if (m.hasRates()) {
    if (m.rateFresnel != FresnelModel::None) j.add("fresnel", toString(m.rateFresnel));
  } else if (dielectric || roughGlass || plastic || m.fresnel != defaults.fresnel)
    j.add("fresnel", toString(m.fresnel));
  if (rough || plastic || m.distribution != defaults.distribution)
    j.add("distribution", toString(m.distribution));
  if (rough || plastic || m.roughness != defaults.roughness) j.add("roughness", m.roughness);
  if (rough || plastic || m.visibleNormals != defaults.visibleNormals)
    j.add("visible_normals", m.visibleNormals);
  if (m.iorOutside != defaults.iorOutside) j.add("ior_outside", m.iorOutside);
  if (m.priority != defaults.priority) j.add("priority", m.priority);
  return j.take();
}

/// An object as JSON from what it is now, any transform of a built-in shape baked in; mesh
/// paths are written relative to `sceneDir`.
ojson bakedObject(const SceneObject& o, const Scene& scene, const std::string& sceneDir) {
  if (!o.shape) throw SceneIO::SaveError("object \"" + o.name + "\" has no shape");
  if (o.material < 0 || o.material >= static_cast<int>(scene.materials.size()))
    throw SceneIO::SaveError("object \"" + o.name + "\" refers to a missing material");
  ojson transform;
  ojson shape = shapeFormat(o.shape->kind()).write(o, sceneDir, transform);
  ObjectWriter object(kObjectKeys);
  object.add("name", o.name);
  if (!o.nameZh.empty()) object.add("display_name", displayNameJson(o.nameZh));
  object.add("material", scene.materials[o.material].name).add("shape", std::move(shape));
  if (!transform.is_null()) object.add("transform", std::move(transform));
  if (o.velocity != Vec3(0.0)) object.add("velocity", toJson(o.velocity));
  return object.take();
}

/// `j` (read unordered) with the keys of `keys` in that list's order.
template <class Keys>
ojson inKeyOrder(const nlohmann::json& j, const Keys& keys) {
  ObjectWriter out(keys);
  for (const char* key : keys)
    if (j.contains(key)) out.add(key, ojson::parse(j[key].dump()));
  return out.take();
}

/// The shape of a file's entry in the writer's key order for its type.
ojson shapeInKeyOrder(const nlohmann::json& shape) {
  const ShapeFormat* format = shapeFormat(shape.value("type", std::string()));
  if (format) return inKeyOrder(shape, format->keys);
  return ojson::parse(shape.dump());
}

/// An object as JSON: the file's own entry while the object is as it was read (see
/// SceneObject::FileForm), else its baked form.
ojson objectToJson(const SceneObject& o, const Scene& scene, const std::string& sceneDir) {
  ojson baked = bakedObject(o, scene, sceneDir);
  if (!o.fileForm || baked.dump() != o.fileForm->whenRead) return baked;
  const nlohmann::json entry = nlohmann::json::parse(o.fileForm->inFile);
  ojson object = inKeyOrder(entry, kObjectKeys);
  if (entry.contains("shape")) object["shape"] = shapeInKeyOrder(entry["shape"]);
  return object;
}

ojson pointLightToJson(const PointLight& l) {
  return ObjectWriter(kPointLightKeys)
      .add("name", l.name)
      .add("position", toJson(l.position))
      .add("intensity", toJson(l.intensity))
      .take();
}

/// Every camera field; near_clip and near_clip_shape only when set (files before they were
/// added stay the same).
ojson cameraToJson(const CameraSpec& c) {
  ObjectWriter camera(kCameraKeys);
  camera.add("position", toJson(c.position))
      .add("look_at", toJson(c.lookAt))
      .add("up", toJson(c.up))
      .add("vertical_fov", c.verticalFov)
      .add("width", c.width)
      .add("height", c.height)
      .add("aperture", c.aperture)
      .add("focus_distance", c.focusDistance);
  if (c.nearClip != 0.0) camera.add("near_clip", c.nearClip);
  if (c.nearClipShape != NearClipShape::Plane)
    camera.add("near_clip_shape", toString(c.nearClipShape));
  return camera.take();
}

ojson renderToJson(const RenderSettings& r) {
  ObjectWriter j(kRenderKeys);
  j.add("algorithm", toString(r.algorithm))
      .add("spp", r.samplesPerPixel)
      .add("max_depth", r.maxDepth)
      .add("seed", r.seed)
      .add("shadow_samples", r.shadowSamples)
      .add("glossy_samples", r.glossySamples)
      .add("russian_roulette_depth", r.russianRouletteDepth)
      .add("next_event_estimation", r.nextEventEstimation)
      .add("multiple_importance", r.multipleImportance)
      .add("background", toJson(r.background));
  // Only a scene that switches the offset off says so (the lesson on shadow acne).
  if (!r.rayOffset) j.add("ray_offset", false);
  // Likewise the lesson on acceleration structures: brute force, or a median split.
  if (!r.acceleration) j.add("acceleration", "none");
  if (r.bvhSplit != BvhSettings::Split::Sah) j.add("bvh_split", toString(r.bvhSplit));
  return j.take();
}

}  // namespace

std::string detail::bakedObjectForm(const SceneObject& o, const Scene& scene) {
  return bakedObject(o, scene, std::string()).dump();
}

std::string SceneIO::serialize(const Scene& scene, const std::string& sceneDir) {
  ojson materials = ojson::array();
  for (const Material& m : scene.materials) materials.push_back(materialToJson(m));
  ojson objects = ojson::array();
  for (const SceneObject& o : scene.objects) objects.push_back(objectToJson(o, scene, sceneDir));
  ojson pointLights = ojson::array();
  for (const PointLight& l : scene.pointLights) pointLights.push_back(pointLightToJson(l));
  ObjectWriter root(kSceneKeys);
  root.add("raylab_scene", kVersion).add("name", scene.name);
  if (!scene.nameZh.empty()) root.add("display_name", displayNameJson(scene.nameZh));
  root.add("materials", std::move(materials))
      .add("objects", std::move(objects))
      .add("point_lights", std::move(pointLights))
      .add("camera", cameraToJson(scene.camera))
      .add("render", renderToJson(scene.render));
  // nlohmann prints doubles with enough digits to round-trip exactly.
  return prettyJson(root.take()) + "\n";
}

void SceneIO::save(const Scene& scene, const std::string& path) {
  // Mesh paths are written relative to the folder of the new file.
  const std::string text = serialize(scene, std::filesystem::path(path).parent_path().string());
  // A temporary file beside the target, then a rename: the old file or the whole new one.
  if (auto problem = writeFileAtomically(path, text)) throw SaveError(path + ": " + *problem);
}

}  // namespace raylab
