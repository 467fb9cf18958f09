#include "raylab/core/SceneIO.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/Box.h"
#include "raylab/core/Check.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Triangle.h"

#include "io/PrettyJson.h"
#include "scene/ObjectForm.h"
#include "scene/SceneKeys.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstring>
#include <filesystem>
#include <utility>

// SceneIO's writer: Scene -> version-2 file text (and the atomic save). The reader is
// SceneReader.cpp; the keys both use are in SceneKeys.h.

namespace raylab {

namespace {

using ojson = nlohmann::ordered_json;

/**
 * One JSON object of a scene file being written. Its keys can only come from the object's
 * list in SceneKeys.h, in the list's order, so the writer cannot emit a key the reader
 * would reject; breaking that is a bug in RayLab, caught (RAYLAB_CHECK) at the first save.
 */
class ObjectWriter {
 public:
  template <std::size_t N>
  explicit ObjectWriter(const std::array<const char*, N>& keys)
      : m_keys(keys.data()), m_keyCount(N) {}

  /// Adds `key: value`; `key` must come later in the list than the keys added before it.
  ObjectWriter& add(const char* key, ojson value) {
    while (m_next < m_keyCount && std::strcmp(m_keys[m_next], key) != 0) ++m_next;
    RAYLAB_CHECK(m_next < m_keyCount);  // not in the list, or out of the list's order
    m_object[m_keys[m_next++]] = std::move(value);
    return *this;
  }

  ojson take() { return std::move(m_object); }

 private:
  const char* const* m_keys;
  std::size_t m_keyCount;
  std::size_t m_next = 0;  ///< First list entry that may still be added.
  ojson m_object = ojson::object();
};

ojson toJson(const Vec3& v) { return ojson::array({v.x, v.y, v.z}); }

/// A "display_name": {"zh": ...}.
ojson displayNameJson(const std::string& zh) {
  return ObjectWriter(kDisplayNameKeys).add("zh", zh).take();
}

ojson toJson(const Mat4& m) {
  ojson rows = ojson::array();
  for (int r = 0; r < 4; ++r) rows.push_back(ojson::array({m[0][r], m[1][r], m[2][r], m[3][r]}));
  return rows;
}

/// A "transform" of one matrix step.
ojson matrixTransform(const Mat4& m) {
  return ojson::array({ObjectWriter(kTransformStepKeys).add("matrix", toJson(m)).take()});
}

/// A built-in shape as JSON. A sphere's own transform, which its parameters cannot hold,
/// goes to `transform` (left untouched otherwise).
ojson shapeToJson(const Shape& shape, ojson& transform) {
  switch (shape.kind()) {
    case ShapeKind::Sphere: {
      const auto& s = static_cast<const Sphere&>(shape);
      if (!s.worldFromObject().isIdentity())
        transform = matrixTransform(s.worldFromObject().matrix());
      return ObjectWriter(kSphereKeys)
          .add("type", "sphere")
          .add("centre", toJson(s.centre()))
          .add("radius", s.radius())
          .add("m", s.m())
          .add("n", s.n())
          .take();
    }
    case ShapeKind::Box: {
      const auto& b = static_cast<const Box&>(shape);
      const Box readable(b.centre(), b.size(), b.axis(0), b.axis(1), b.axis(2));
      ObjectWriter box(kBoxKeys);
      box.add("type", "box");
      // Prefer centre/size/axes; fall back to the exact matrix when they do not
      // reproduce the box bit for bit.
      if (readable.worldFromBox().matrix() == b.worldFromBox().matrix()) {
        box.add("centre", toJson(b.centre())).add("size", toJson(b.size()));
        if (b.axis(0) != Vec3(1, 0, 0) || b.axis(1) != Vec3(0, 1, 0) || b.axis(2) != Vec3(0, 0, 1))
          box.add("axes", ojson::array({toJson(b.axis(0)), toJson(b.axis(1)), toJson(b.axis(2))}));
        return box.take();
      }
      return box.add("matrix", toJson(b.worldFromBox().matrix())).take();
    }
    case ShapeKind::Plane: {
      const auto& p = static_cast<const Plane&>(shape);
      return ObjectWriter(kPlaneKeys)
          .add("type", "plane")
          .add("point", toJson(p.point()))
          .add("normal", toJson(p.planeNormal()))
          .take();
    }
    case ShapeKind::Quad: {
      const auto& q = static_cast<const Quad&>(shape);
      return ObjectWriter(kQuadKeys)
          .add("type", "quad")
          .add("corner", toJson(q.corner()))
          .add("u", toJson(q.edgeU()))
          .add("v", toJson(q.edgeV()))
          .take();
    }
    case ShapeKind::Triangle: {
      const auto& t = static_cast<const Triangle&>(shape);
      return ObjectWriter(kTriangleKeys)
          .add("type", "triangle")
          .add("vertices",
               ojson::array({toJson(t.vertex(0)), toJson(t.vertex(1)), toJson(t.vertex(2))}))
          .take();
    }
    case ShapeKind::TriangleMesh:
      break;
  }
  throw SceneIO::SaveError(std::string("cannot save shape of kind ") + toString(shape.kind()));
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

/// The path to write for a mesh file `source` (see SceneObject::source) in a scene file
/// in folder `sceneDir` ("" = the current directory): relative to that folder, as the
/// format says.
std::string meshPathFrom(const std::string& source, const std::string& sceneDir) {
  namespace fs = std::filesystem;
  fs::path file = fs::path(source).lexically_normal();
  fs::path base = fs::path(sceneDir.empty() ? "." : sceneDir).lexically_normal();
  if (file.is_absolute() || base.is_absolute()) {
    file = fs::absolute(file).lexically_normal();
    base = fs::absolute(base).lexically_normal();
  }
  const fs::path relative = file.lexically_relative(base);
  return relative.empty() ? file.generic_string() : relative.generic_string();
}

/// An object as JSON from what it is now, any transform of a built-in shape baked in; mesh
/// paths are written relative to `sceneDir`.
ojson bakedObject(const SceneObject& o, const Scene& scene, const std::string& sceneDir) {
  if (!o.shape) throw SceneIO::SaveError("object \"" + o.name + "\" has no shape");
  if (o.material < 0 || o.material >= static_cast<int>(scene.materials.size()))
    throw SceneIO::SaveError("object \"" + o.name + "\" refers to a missing material");
  ojson transform;
  ojson shape;
  if (o.shape->kind() == ShapeKind::TriangleMesh) {
    // Meshes are saved by reference: the file and the transform applied to it.
    if (o.source.empty())
      throw SceneIO::SaveError("mesh object \"" + o.name +
                               "\" has no source file (meshes are saved as a path to their file)");
    ObjectWriter mesh(kMeshKeys);
    mesh.add("type", "mesh").add("file", meshPathFrom(o.source, sceneDir));
    // The normals' source when it is not the default; the crease angle of computed ones.
    if (o.meshNormals != MeshNormals::File) mesh.add("normals", toString(o.meshNormals));
    if (o.meshNormals == MeshNormals::Smooth) mesh.add("crease_angle", o.creaseAngle);
    shape = mesh.take();
    if (o.worldFromSource != Mat4(1.0)) transform = matrixTransform(o.worldFromSource);
  } else {
    shape = shapeToJson(*o.shape, transform);
  }
  ObjectWriter object(kObjectKeys);
  object.add("name", o.name);
  if (!o.nameZh.empty()) object.add("display_name", displayNameJson(o.nameZh));
  object.add("material", scene.materials[o.material].name).add("shape", std::move(shape));
  if (!transform.is_null()) object.add("transform", std::move(transform));
  if (o.velocity != Vec3(0.0)) object.add("velocity", toJson(o.velocity));
  return object.take();
}

/// `j` (read unordered) with the keys of `keys` in that list's order.
template <std::size_t N>
ojson inKeyOrder(const nlohmann::json& j, const std::array<const char*, N>& keys) {
  ObjectWriter out(keys);
  for (const char* key : keys)
    if (j.contains(key)) out.add(key, ojson::parse(j[key].dump()));
  return out.take();
}

/// The shape of a file's entry in the writer's key order for its type.
ojson shapeInKeyOrder(const nlohmann::json& shape) {
  const std::string type = shape.value("type", std::string());
  if (type == "sphere") return inKeyOrder(shape, kSphereKeys);
  if (type == "box") return inKeyOrder(shape, kBoxKeys);
  if (type == "plane") return inKeyOrder(shape, kPlaneKeys);
  if (type == "quad") return inKeyOrder(shape, kQuadKeys);
  if (type == "triangle") return inKeyOrder(shape, kTriangleKeys);
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
