#include "raylab/core/SceneIO.h"

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Camera.h"
#include "raylab/core/Limits.h"
#include "raylab/core/Transform.h"

#include "io/JsonChecks.h"
#include "io/PrettyJson.h"
#include "scene/ObjectForm.h"
#include "scene/SceneFields.h"
#include "scene/SceneKeys.h"
#include "shapes/ShapeFormat.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <vector>

// SceneIO's validating reader: JSON text -> Scene, or a LoadError naming the file and
// the place (line:column for syntax, the JSON path for content). The writer is
// SceneWriter.cpp.

namespace raylab {

namespace {

using nlohmann::json;

/// Reads one scene document and remembers the file name for every message.
class Reader : public SceneFields {
 public:
  using SceneFields::SceneFields;

  /// A shape, read by its kind's format (ShapeFormat.h); for a mesh, `object` receives the
  /// mesh file's path (SceneObject::source) and its normals' settings.
  std::unique_ptr<Shape> shape(const json& j, const std::string& path, SceneObject& object) const {
    const std::string type = string(member(j, path, "type"), path + "/type");
    const ShapeFormat* format = shapeFormat(type);
    if (!format)
      fail(path + "/type",
           "unknown shape type \"" + type + "\" (expected " + shapeWordList() + ")");
    try {
      return format->read(j, path, *this, object);
    } catch (const Shape::InvalidGeometry& e) {
      fail(path, e.what());
    }
  }

  Mat4 transform(const json& steps, const std::string& path) const {
    if (!steps.is_array()) fail(path, "expected a list of steps");
    Mat4 m(1.0);
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const std::string sp = path + "/" + std::to_string(i);
      const json& s = steps[i];
      if (!s.is_object() || s.size() != 1)
        fail(sp, "a step is one of translate, scale, rotate, matrix");
      Mat4 step(1.0);
      if (s.contains("translate")) {
        step = Transform::translate(vec3(s["translate"], sp + "/translate")).matrix();
      } else if (s.contains("scale")) {
        const Vec3 f = vec3(s["scale"], sp + "/scale");
        if (f.x == 0.0 || f.y == 0.0 || f.z == 0.0)
          fail(sp + "/scale", "scale factors must not be zero");
        for (int c = 0; c < 3; ++c)
          if (std::abs(f[c]) < limits::kMinLength)
            fail(sp + "/scale/" + std::to_string(c),
                 "scale factor " + excerpt(s["scale"][c]) + " is below 1e-9 in magnitude");
        step = Transform::scale(f).matrix();
      } else if (s.contains("rotate")) {
        const json& r = s["rotate"];
        const Vec3 axis = nonZero(member(r, sp + "/rotate", "axis"), sp + "/rotate/axis");
        const double degrees = number(member(r, sp + "/rotate", "degrees"), sp + "/rotate/degrees");
        step = Transform::rotate(radians(degrees), axis).matrix();
      } else if (s.contains("matrix")) {
        step = matrix(s["matrix"], sp + "/matrix");
      } else {
        fail(sp,
             "unknown step " + s.begin().key() + " (expected translate, scale, rotate, matrix)");
      }
      m = step * m;  // later steps apply after earlier ones
      // Steps may compose to more than any one of them: 13 scales by 1e12 overflow.
      const double det = glm::determinant(Mat3(m));
      if (!isFinite(Vec3(m[3])) || !std::isfinite(det) || std::abs(det) < 1e-200 ||
          std::abs(det) > 1e200)
        fail(sp, "the steps so far make a transform too large or too degenerate (determinant " +
                     json(det).dump() + ")");
    }
    return m;
  }

  /// The "display_name" of the scene, a material or an object: {"zh": "玻璃球"}, a
  /// Chinese name (at least one Chinese character); "" when there is none.
  std::string displayName(const json& j, const std::string& p) const {
    if (!j.contains("display_name")) return {};
    const std::string dp = p + "/display_name";
    const json& names = j["display_name"];
    if (!names.is_object())
      fail(dp, "expected the names in other languages, e.g. {\"zh\": \"玻璃球\"}");
    onlyKeys(names, dp, kDisplayNameKeys);
    const std::string zh = string(member(names, dp, "zh"), dp + "/zh");
    // A Chinese character: U+3400..U+9FFF, a three-byte UTF-8 sequence led by 0xE3..0xE9.
    const bool chinese = std::any_of(zh.begin(), zh.end(), [](char c) {
      const auto byte = static_cast<unsigned char>(c);
      return byte >= 0xE3 && byte <= 0xE9;
    });
    if (!chinese) fail(dp + "/zh", "\"" + zh + "\" has no Chinese character");
    return zh;
  }

  Material material(const json& j, const std::string& p) const {
    onlyKeys(j, p, kMaterialKeys);
    Material m;
    m.name = string(member(j, p, "name"), p + "/name");
    m.nameZh = displayName(j, p);
    if (j.contains("type")) {
      const std::string type = string(j["type"], p + "/type");
      bool known = false;
      for (MaterialType t :
           {MaterialType::Diffuse, MaterialType::Mirror, MaterialType::Dielectric,
            MaterialType::Glossy, MaterialType::Phong, MaterialType::BlinnPhong,
            MaterialType::RoughConductor, MaterialType::RoughDielectric, MaterialType::Plastic})
        if (type == toString(t)) {
          m.type = t;
          known = true;
        }
      if (!known)
        fail(p + "/type", "unknown material type \"" + type +
                              "\" (expected diffuse, mirror, dielectric, glossy, phong, "
                              "blinn_phong, rough_conductor, rough_dielectric or plastic)");
    }
    // The classic materials reflect nothing unless told (kr = 0), unlike the mirror.
    if (m.isClassic()) m.reflectionRate = 0.0;
    if (j.contains("colour")) m.colour = vec3(j["colour"], p + "/colour");
    if (j.contains("texture")) m.texture = texture(j["texture"], p + "/texture");
    if (j.contains("emission")) m.emission = vec3(j["emission"], p + "/emission");
    if (j.contains("reflection_rate"))
      m.reflectionRate = number(j["reflection_rate"], p + "/reflection_rate");
    if (j.contains("refraction_rate"))
      m.refractionRate = number(j["refraction_rate"], p + "/refraction_rate");
    if (j.contains("ior")) m.ior = number(j["ior"], p + "/ior");
    if (j.contains("ior_outside")) m.iorOutside = number(j["ior_outside"], p + "/ior_outside");
    if (j.contains("exponent")) m.exponent = number(j["exponent"], p + "/exponent");
    if (j.contains("specular")) m.specular = number(j["specular"], p + "/specular");
    if (j.contains("opacity")) m.opacity = number(j["opacity"], p + "/opacity");
    classicAndRoughParameters(j, p, m);
    for (int c = 0; c < 3; ++c) {
      if (m.colour[c] < 0.0 || m.colour[c] > 1.0)
        fail(p + "/colour", "colour components must be in [0, 1]");
      if (m.emission[c] < 0.0) fail(p + "/emission", "emission must not be negative");
    }
    if (m.reflectionRate < 0.0 || m.reflectionRate > 1.0)
      fail(p + "/reflection_rate", "reflection_rate must be in [0, 1]");
    if (m.refractionRate < 0.0 || m.refractionRate > 1.0)
      fail(p + "/refraction_rate", "refraction_rate must be in [0, 1]");
    // With Fresnel the rays get kr R and kt (1 - R): each rate up to 1 creates no energy.
    if (m.reflectionRate + m.refractionRate > 1.0 &&
        !(m.hasRates() && m.rateFresnel != FresnelModel::None))
      fail(p, "reflection_rate + refraction_rate must not exceed 1 (energy would be created)");
    if (!(m.ior > 0.0)) fail(p + "/ior", "ior (index of refraction) must be positive");
    if (!(m.iorOutside > 0.0))
      fail(p + "/ior_outside", "ior_outside (index of the medium outside) must be positive");
    // Past these the tracers' refracted directions lose every digit (an ior of 1e20 on a
    // mirror aborted the program, issue 38): refused here, with the place.
    for (const auto& [key, value] :
         {std::pair{"ior", m.ior}, std::pair{"ior_outside", m.iorOutside}})
      if (value < limits::kMinIor || value > limits::kMaxIor) {
        std::ostringstream out;
        out << key << " " << value << " is outside [" << limits::kMinIor << ", " << limits::kMaxIor
            << "] (real media lie between 1 and about 4)";
        fail(p + "/" + key, out.str());
      }
    if (!(m.exponent > 0.0)) fail(p + "/exponent", "exponent (Phong) must be positive");
    if (m.specular < 0.0 || m.specular > 1.0) fail(p + "/specular", "specular must be in [0, 1]");
    if (m.opacity < 0.0 || m.opacity > 1.0) fail(p + "/opacity", "opacity must be in [0, 1]");
    return m;
  }

  /// A material's "texture" (Texture.h): {"type": "checker", "scale": s, "colour2": [r, g, b]}.
  Texture texture(const json& j, const std::string& p) const {
    if (!j.is_object())
      fail(p, "expected {\"type\": \"checker\", \"scale\": ..., \"colour2\": [r, g, b]}, got " +
                  excerpt(j));
    onlyKeys(j, p, kTextureKeys);
    Texture t;
    const std::string type = string(member(j, p, "type"), p + "/type");
    if (type != toString(TextureType::Checker))
      fail(p + "/type", "unknown texture type \"" + type + "\" (expected checker)");
    t.type = TextureType::Checker;
    if (j.contains("scale"))
      t.scale = length(j["scale"], p + "/scale", "scale (a checker cube's side)");
    if (j.contains("colour2")) t.colour2 = vec3(j["colour2"], p + "/colour2");
    for (int c = 0; c < 3; ++c)
      if (t.colour2[c] < 0.0 || t.colour2[c] > 1.0)
        fail(p + "/colour2", "colour components must be in [0, 1], got " + excerpt(j["colour2"]));
    return t;
  }

  /// The parameters of the classic Phong and the microfacet materials (see Material.h).
  void classicAndRoughParameters(const json& j, const std::string& p, Material& m) const {
    if (j.contains("ambient")) m.ambient = vec3(j["ambient"], p + "/ambient");
    if (j.contains("diffuse")) m.diffuse = number(j["diffuse"], p + "/diffuse");
    if (j.contains("attenuation")) m.attenuation = vec3(j["attenuation"], p + "/attenuation");
    if (j.contains("fresnel")) {
      const std::string problem = setFresnel(m, string(j["fresnel"], p + "/fresnel"));
      if (!problem.empty()) fail(p + "/fresnel", problem);
    }
    if (j.contains("distribution")) {
      const std::string d = string(j["distribution"], p + "/distribution");
      if (d == "ggx")
        m.distribution = MicrofacetModel::GGX;
      else if (d == "beckmann")
        m.distribution = MicrofacetModel::Beckmann;
      else
        fail(p + "/distribution",
             "unknown microfacet distribution \"" + d + "\" (expected ggx or beckmann)");
    }
    if (j.contains("roughness")) m.roughness = number(j["roughness"], p + "/roughness");
    if (j.contains("priority"))
      m.priority = integerIn(j["priority"], p + "/priority", 0, 1000);  // plenty of levels
    if (j.contains("visible_normals"))
      m.visibleNormals = boolean(j["visible_normals"], p + "/visible_normals");
    for (int c = 0; c < 3; ++c) {
      if (m.ambient[c] < 0.0) fail(p + "/ambient", "ambient must not be negative");
      if (m.attenuation[c] < 0.0)
        fail(p + "/attenuation", "attenuation coefficients [c, l, q] must not be negative");
    }
    if (isZero(m.attenuation))
      fail(p + "/attenuation",
           "attenuation [0, 0, 0] divides by zero (use [1, 0, 0] for no falloff, [0, 0, 1] "
           "for 1 / d^2)");
    if (m.diffuse < 0.0 || m.diffuse > 1.0) fail(p + "/diffuse", "diffuse (kd) must be in [0, 1]");
    if (!(m.roughness >= 1e-4 && m.roughness <= 4.0))
      fail(p + "/roughness", "roughness (alpha) must be in [0.0001, 4], got " +
                                 excerpt(j.contains("roughness") ? j["roughness"] : json()));
  }

  void camera(const json& c, CameraSpec& cam) const {
    onlyKeys(c, "/camera", kCameraKeys);
    if (c.contains("position")) cam.position = vec3(c["position"], "/camera/position");
    if (c.contains("look_at")) cam.lookAt = vec3(c["look_at"], "/camera/look_at");
    if (c.contains("up")) cam.up = nonZero(c["up"], "/camera/up");
    if (c.contains("vertical_fov"))
      cam.verticalFov = number(c["vertical_fov"], "/camera/vertical_fov");
    if (c.contains("width")) cam.width = integer(c["width"], "/camera/width");
    if (c.contains("height")) cam.height = integer(c["height"], "/camera/height");
    if (c.contains("aperture")) cam.aperture = bounded(c["aperture"], "/camera/aperture");
    if (c.contains("focus_distance"))
      cam.focusDistance = bounded(c["focus_distance"], "/camera/focus_distance");
    if (c.contains("near_clip")) cam.nearClip = bounded(c["near_clip"], "/camera/near_clip");
    if (c.contains("near_clip_shape")) {
      const std::string shape = string(c["near_clip_shape"], "/camera/near_clip_shape");
      if (shape == "plane")
        cam.nearClipShape = NearClipShape::Plane;
      else if (shape == "sphere")
        cam.nearClipShape = NearClipShape::Sphere;
      else
        fail("/camera/near_clip_shape",
             "unknown near clip shape \"" + shape + "\" (expected plane or sphere)");
    }
    if (cam.position == cam.lookAt) fail("/camera/look_at", "camera looks at its own position");
    if (glm::length(glm::cross(cam.lookAt - cam.position, cam.up)) == 0.0)
      fail("/camera/up", "up is parallel to the viewing direction");
    if (!(cam.verticalFov > 0.0 && cam.verticalFov < 180.0))
      fail("/camera/vertical_fov", "vertical_fov must be in (0, 180) degrees");
    if (cam.width < 1 || cam.height < 1 || cam.width > limits::kMaxImageSide ||
        cam.height > limits::kMaxImageSide)
      fail("/camera", "width and height must be in [1, " + std::to_string(limits::kMaxImageSide) +
                          "], got " + std::to_string(cam.width) + " x " +
                          std::to_string(cam.height));
    if (std::int64_t(cam.width) * cam.height > limits::kMaxImagePixels)
      fail("/camera", "width x height must be at most 4096 x 4096 = " +
                          std::to_string(limits::kMaxImagePixels) + " pixels, got " +
                          std::to_string(cam.width) + " x " + std::to_string(cam.height));
    if (cam.aperture < 0.0) fail("/camera/aperture", "aperture (lens radius) must not be negative");
    if (cam.nearClip < 0.0) fail("/camera/near_clip", "near_clip must not be negative");
    if (cam.focusDistance < 0.0)
      fail("/camera/focus_distance",
           "focus_distance must not be negative (0: distance to look_at)");
    // Whatever else the camera would refuse, refused here with the file and the place.
    try {
      const Camera probe(cam);
    } catch (const Exception& e) {
      fail("/camera", e.what());
    }
  }

  void render(const json& r, RenderSettings& s) const {
    const std::string p = "/render";
    onlyKeys(r, p, kRenderKeys);
    if (r.contains("algorithm")) {
      const std::string name = string(r["algorithm"], p + "/algorithm");
      const auto algorithm = parseAlgorithm(name);
      if (!algorithm)
        fail(p + "/algorithm",
             "unknown algorithm \"" + name + "\" (expected " + algorithmWordList() + ")");
      s.algorithm = *algorithm;
    }
    if (r.contains("spp"))
      s.samplesPerPixel = integerIn(r["spp"], p + "/spp", 1, limits::kMaxSamplesPerPixel);
    if (r.contains("max_depth"))
      s.maxDepth = integerIn(r["max_depth"], p + "/max_depth", 0, limits::kMaxDepth);
    if (r.contains("seed")) {
      if (!r["seed"].is_number_unsigned())
        fail(p + "/seed", "expected a non-negative integer, got " + excerpt(r["seed"]));
      s.seed = r["seed"].get<std::uint64_t>();
    }
    if (r.contains("shadow_samples"))
      s.shadowSamples =
          integerIn(r["shadow_samples"], p + "/shadow_samples", 1, limits::kMaxLightSamples);
    if (r.contains("glossy_samples"))
      s.glossySamples =
          integerIn(r["glossy_samples"], p + "/glossy_samples", 1, limits::kMaxLightSamples);
    if (r.contains("russian_roulette_depth"))
      s.russianRouletteDepth = integerIn(r["russian_roulette_depth"], p + "/russian_roulette_depth",
                                         0, limits::kMaxDepth);
    if (r.contains("next_event_estimation"))
      s.nextEventEstimation = boolean(r["next_event_estimation"], p + "/next_event_estimation");
    if (r.contains("multiple_importance"))
      s.multipleImportance = boolean(r["multiple_importance"], p + "/multiple_importance");
    if (r.contains("background")) {
      s.background = vec3(r["background"], p + "/background");
      if (s.background.x < 0.0 || s.background.y < 0.0 || s.background.z < 0.0)
        fail(p + "/background", "background radiance must not be negative");
    }
    if (r.contains("ray_offset")) s.rayOffset = boolean(r["ray_offset"], p + "/ray_offset");
    if (r.contains("acceleration")) {
      const std::string name = string(r["acceleration"], p + "/acceleration");
      if (name != "bvh" && name != "none")
        fail(p + "/acceleration",
             "unknown acceleration \"" + name + "\" (expected bvh, or none for brute force)");
      s.acceleration = name == "bvh";
    }
    if (r.contains("bvh_split")) {
      const std::string name = string(r["bvh_split"], p + "/bvh_split");
      const auto split = parseBvhSplit(name);
      if (!split)
        fail(p + "/bvh_split", "unknown BVH split \"" + name + "\" (expected sah or median)");
      s.bvhSplit = *split;
    }
  }

  /// One entry of "objects"; the scene's materials are read already (objects name them).
  SceneObject object(const json& j, const std::string& p, const Scene& scene) const {
    onlyKeys(j, p, kObjectKeys);
    SceneObject o;
    o.name = string(member(j, p, "name"), p + "/name");
    o.nameZh = displayName(j, p);
    if (!m_objectNames.insert(o.name).second)
      fail(p + "/name", "duplicate object \"" + o.name + "\"");
    const std::string material = string(member(j, p, "material"), p + "/material");
    const auto named = m_materialIndex.find(material);
    if (named == m_materialIndex.end())
      fail(p + "/material", "unknown material \"" + material + "\"");
    o.material = named->second;
    o.shape = shape(member(j, p, "shape"), p + "/shape", o);
    if (j.contains("transform")) {
      const Mat4 m = transform(j["transform"], p + "/transform");
      try {
        o.apply(m);
      } catch (const Shape::InvalidGeometry& e) {
        fail(p + "/transform", e.what());
      }
      // A finite object must stay within reach of double arithmetic once moved.
      const Bounds3 b = o.shape->bounds();
      const double far = 1e3 * limits::kMaxCoordinate;
      if (o.shape->kind() != ShapeKind::Plane &&
          !(glm::all(glm::lessThanEqual(glm::abs(b.lower), Vec3(far))) &&
            glm::all(glm::lessThanEqual(glm::abs(b.upper), Vec3(far)))))
        fail(p + "/transform", "the transformed object reaches beyond 1e15 world units");
    }
    if (j.contains("velocity")) o.velocity = vec3(j["velocity"], p + "/velocity");
    // An area light must have a finite area to sample.
    if (scene.materials[o.material].isEmitter() && o.shape->kind() == ShapeKind::Plane)
      fail(p + "/material", "emitting material \"" + material +
                                "\" on a plane: an area light needs a finite shape "
                                "(use a quad)");
    // A nested volume needs an inside (NestedMedia.h): open surfaces have none.
    if (scene.materials[o.material].priority > 0 && !o.shape->isClosed())
      fail(p + "/material", "material \"" + material + "\" has a priority (a nested volume) but " +
                                toString(o.shape->kind()) +
                                " has no inside: use a closed shape or priority 0");
    return o;
  }

  /// One entry of "point_lights"; `others` are the lights read before it.
  PointLight pointLight(const json& j, const std::string& p,
                        const std::vector<PointLight>& others) const {
    onlyKeys(j, p, kPointLightKeys);
    PointLight light;
    light.name = string(member(j, p, "name"), p + "/name");
    if (!m_lightNames.insert(light.name).second)
      fail(p + "/name", "duplicate point light \"" + light.name + "\"");
    light.position = vec3(member(j, p, "position"), p + "/position");
    if (j.contains("intensity")) light.intensity = vec3(j["intensity"], p + "/intensity");
    for (int c = 0; c < 3; ++c)
      if (light.intensity[c] < 0.0) fail(p + "/intensity", "intensity must not be negative");
    return light;
  }

  /// The whole document, in the order of the checks: version, keys, materials, objects,
  /// point lights, camera, render.
  Scene scene(const json& root) const {
    if (!root.is_object()) fail("", "a scene file is a JSON object");
    if (!root.contains("raylab_scene"))
      fail("", "missing \"raylab_scene\": <version> (is this a RayLab scene file?)");
    const int version = integer(root["raylab_scene"], "/raylab_scene");
    if (version < SceneIO::kFirstVersion || version > SceneIO::kVersion)
      fail("/raylab_scene", "unsupported version " + std::to_string(version) +
                                " (this RayLab reads versions " +
                                std::to_string(SceneIO::kFirstVersion) + " to " +
                                std::to_string(SceneIO::kVersion) + ")");
    onlyKeys(root, "", kSceneKeys);
    Scene scene;
    scene.name = root.contains("name") ? string(root["name"], "/name") : "untitled";
    scene.nameZh = displayName(root, "");

    // Materials first: objects refer to them by name.
    const json& materials = member(root, "", "materials");
    if (!materials.is_array()) fail("/materials", "expected a list");
    for (std::size_t i = 0; i < materials.size(); ++i) {
      const std::string p = "/materials/" + std::to_string(i);
      Material m = material(materials[i], p);
      if (!m_materialIndex.emplace(m.name, int(scene.materials.size())).second)
        fail(p + "/name", "duplicate material \"" + m.name + "\"");
      scene.materials.push_back(std::move(m));
    }

    const json& objects = member(root, "", "objects");
    if (!objects.is_array()) fail("/objects", "expected a list");
    for (std::size_t i = 0; i < objects.size(); ++i)
      scene.objects.push_back(object(objects[i], "/objects/" + std::to_string(i), scene));
    // Each built-in shape's entry as written, saved as it is while the object is unchanged
    // (meshes are saved by reference, their paths relative to where they are saved).
    for (std::size_t i = 0; i < objects.size(); ++i) {
      SceneObject& o = scene.objects[i];
      if (o.shape->kind() == ShapeKind::TriangleMesh) continue;
      o.fileForm = std::make_shared<const SceneObject::FileForm>(
          SceneObject::FileForm{objects[i].dump(), detail::bakedObjectForm(o, scene)});
    }

    if (root.contains("point_lights")) {
      const json& lights = root["point_lights"];
      if (!lights.is_array()) fail("/point_lights", "expected a list");
      for (std::size_t i = 0; i < lights.size(); ++i)
        scene.pointLights.push_back(
            pointLight(lights[i], "/point_lights/" + std::to_string(i), scene.pointLights));
    }

    if (root.contains("camera")) camera(root["camera"], scene.camera);
    if (root.contains("render")) render(root["render"], scene.render);
    return scene;
  }

 private:
  /// Names read so far, for the duplicate and reference checks in constant time (a scene
  /// of 40,000 objects took 9 s with a linear search per name).
  mutable std::unordered_map<std::string, int> m_materialIndex;
  mutable std::unordered_set<std::string> m_objectNames, m_lightNames;
};

}  // namespace

Scene SceneIO::parse(const std::string& text, const std::string& origin) {
  json root;
  if (const auto problem = parseJson(text, origin, root)) throw LoadError(*problem);
  return Reader(origin).scene(root);
}

Scene SceneIO::load(const std::string& path) {
  std::string text;
  if (const auto problem = readTextFile(path, "scene file", text)) throw LoadError(*problem);
  return parse(text, path);
}

}  // namespace raylab
