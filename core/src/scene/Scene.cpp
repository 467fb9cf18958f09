#include "raylab/core/Scene.h"

#include "raylab/core/AlgorithmInfo.h"
#include "scene/SceneKeys.h"

namespace raylab {

SceneObject::SceneObject(const SceneObject& o)
    : name(o.name),
      nameZh(o.nameZh),
      shape(o.shape ? o.shape->clone() : nullptr),
      material(o.material),
      velocity(o.velocity),
      source(o.source),
      worldFromSource(o.worldFromSource),
      meshNormals(o.meshNormals),
      creaseAngle(o.creaseAngle),
      fileForm(o.fileForm) {}

SceneObject& SceneObject::operator=(const SceneObject& o) {
  if (this != &o) *this = SceneObject(o);
  return *this;
}

void SceneObject::apply(const Mat4& m) {
  if (shape) shape->apply(m);
  worldFromSource = m * worldFromSource;
}

std::string SceneObject::toString() const {
  return "SceneObject[" + name + ", " + (shape ? shape->toString() : "no shape") +
         ", material=" + std::to_string(material) + "]";
}

const char* toString(MeshNormals normals) {
  switch (normals) {
    case MeshNormals::File:
      return "file";
    case MeshNormals::Flat:
      return "flat";
    case MeshNormals::Smooth:
      return "smooth";
  }
  return "unknown";
}

const char* toString(MaterialType type) {
  switch (type) {
    case MaterialType::Diffuse:
      return "diffuse";
    case MaterialType::Mirror:
      return "mirror";
    case MaterialType::Dielectric:
      return "dielectric";
    case MaterialType::Glossy:
      return "glossy";
    case MaterialType::Phong:
      return "phong";
    case MaterialType::BlinnPhong:
      return "blinn_phong";
    case MaterialType::RoughConductor:
      return "rough_conductor";
    case MaterialType::RoughDielectric:
      return "rough_dielectric";
    case MaterialType::Plastic:
      return "plastic";
  }
  return "unknown";
}

const char* toString(FresnelModel model) {
  switch (model) {
    case FresnelModel::Schlick:
      return "schlick";
    case FresnelModel::None:
      return "none";
    case FresnelModel::SchlickWrongSign:
      return "schlick_wrong_sign";
    case FresnelModel::Exact:
      break;
  }
  return "exact";
}

std::string setFresnel(Material& m, const std::string& word) {
  const bool rates = m.hasRates();
  const std::string expected =
      rates ? " (expected none, exact or schlick)" : " (expected exact or schlick)";
  if (word == "none" && !rates)
    return "fresnel \"none\" is for the rates of mirror, phong and blinn_phong; a " +
           std::string(toString(m.type)) + " always splits its light by Fresnel" + expected;
  if (word != "none" && word != "exact" && word != "schlick")
    return "unknown Fresnel model \"" + word + "\"" + expected;
  (rates ? m.rateFresnel : m.fresnel) = word == "none"      ? FresnelModel::None
                                        : word == "schlick" ? FresnelModel::Schlick
                                                            : FresnelModel::Exact;
  return "";
}

const char* toString(MicrofacetModel model) {
  return model == MicrofacetModel::Beckmann ? "beckmann" : "ggx";
}

std::string Material::toString() const {
  return "Material[" + name + ", " + raylab::toString(type) +
         ", colour=" + raylab::toString(colour) +
         (texture.active() ? ", texture=" + texture.toString() : std::string()) +
         ", emission=" + raylab::toString(emission) +
         ", reflectionRate=" + std::to_string(reflectionRate) +
         ", refractionRate=" + std::to_string(refractionRate) + ", ior=" + std::to_string(ior) +
         ", exponent=" + std::to_string(exponent) + ", specular=" + std::to_string(specular) +
         ", opacity=" + std::to_string(opacity) + ", ambient=" + raylab::toString(ambient) +
         ", diffuse=" + std::to_string(diffuse) + ", attenuation=" + raylab::toString(attenuation) +
         ", fresnel=" + raylab::toString(fresnel) +
         ", rateFresnel=" + raylab::toString(rateFresnel) +
         ", priority=" + std::to_string(priority) +
         ", distribution=" + raylab::toString(distribution) +
         ", roughness=" + std::to_string(roughness) +
         ", visibleNormals=" + (visibleNormals ? "true" : "false") +
         ", iorOutside=" + std::to_string(iorOutside) + "]";
}

std::string PointLight::toString() const {
  return "PointLight[" + name + ", position=" + raylab::toString(position) +
         ", intensity=" + raylab::toString(intensity) + "]";
}

const char* toString(Algorithm algorithm) { return algorithmInfo(algorithm).word; }

std::optional<Algorithm> parseAlgorithm(const std::string& name) {
  for (Algorithm a : kAllAlgorithms)
    if (name == toString(a)) return a;
  return std::nullopt;
}

const char* toString(Fault fault) {
  static const char* const words[kFaultCount] = {"none",
                                                 "no_offset",
                                                 "no_cosine",
                                                 "eta_inverted",
                                                 "flipped_normal",
                                                 "pdf_forgotten",
                                                 "roulette_uncompensated",
                                                 "schlick_wrong_sign"};
  const int i = int(fault);
  return i >= 0 && i < kFaultCount ? words[i] : "none";
}

std::optional<Fault> parseFault(const std::string& name) {
  for (int i = 0; i < kFaultCount; ++i)
    if (name == toString(Fault(i))) return Fault(i);
  return std::nullopt;
}

std::string RenderSettings::toString() const {
  return std::string("RenderSettings[") + raylab::toString(algorithm) +
         ", spp=" + std::to_string(samplesPerPixel) + ", maxDepth=" + std::to_string(maxDepth) +
         ", seed=" + std::to_string(seed) + ", shadowSamples=" + std::to_string(shadowSamples) +
         ", glossySamples=" + std::to_string(glossySamples) +
         ", rrDepth=" + std::to_string(russianRouletteDepth) +
         ", nee=" + (nextEventEstimation ? "on" : "off") +
         ", mis=" + (multipleImportance ? "on" : "off") +
         ", background=" + raylab::toString(background) +
         ", rayOffset=" + (rayOffset ? "on" : "off") +
         ", acceleration=" + (acceleration ? "bvh" : "none") +
         ", bvhSplit=" + raylab::toString(bvhSplit) +
         (fault != Fault::None ? std::string(", fault=") + raylab::toString(fault) : "") + "]";
}

const char* toString(NearClipShape shape) {
  return shape == NearClipShape::Sphere ? "sphere" : "plane";
}

std::string CameraSpec::toString() const {
  std::string near;
  if (nearClip != 0.0)
    near = ", near=" + std::to_string(nearClip) + " (" + raylab::toString(nearClipShape) + ")";
  return "Camera[position=" + raylab::toString(position) + ", lookAt=" + raylab::toString(lookAt) +
         ", up=" + raylab::toString(up) + ", vfov=" + std::to_string(verticalFov) + ", " +
         std::to_string(width) + "x" + std::to_string(height) + near + "]";
}

int Scene::findObject(const std::string& objectName) const {
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (objects[i].name == objectName) return static_cast<int>(i);
  return -1;
}

int Scene::findMaterial(const std::string& materialName) const {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == materialName) return static_cast<int>(i);
  return -1;
}

std::string Scene::toString() const {
  std::string s = "Scene[" + name + "\n";
  for (const Material& m : materials) s += "  " + m.toString() + "\n";
  for (const SceneObject& o : objects) s += "  " + o.toString() + "\n";
  return s + "  " + camera.toString() + "]";
}

namespace {

/// True when something in `scene` gives light: a point light, an object with an emissive
/// material, a classic material's ambient term, or a background that is not black.
bool hasLight(const Scene& scene) {
  if (!scene.pointLights.empty()) return true;
  if (scene.render.background != Vec3(0.0)) return true;
  for (const SceneObject& object : scene.objects) {
    const Material& m = scene.materials[std::size_t(object.material)];
    if (m.isEmitter() || (m.isClassic() && m.ambient != Vec3(0.0))) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> sceneWarnings(const Scene& scene) {
  if (scene.objects.empty()) return {"the scene has no objects: every pixel shows the background"};
  if (!hasLight(scene))
    return {
        "the scene has no light (no point light, no emissive material, no ambient term, "
        "a black background): the image is black"};
  return {};
}

Scene sceneAsShown(const Scene& scene, bool chinese) {
  Scene shown = scene;
  if (!chinese) return shown;
  if (!shown.nameZh.empty()) shown.name = shown.nameZh;
  for (Material& m : shown.materials) m.name = m.shownName(true);
  for (SceneObject& o : shown.objects) {
    o.name = o.shownName(true);
    o.fileForm = nullptr;  // no longer the file's entry
  }
  return shown;
}

}  // namespace raylab
