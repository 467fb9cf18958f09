#include "raylab/core/Scene.h"

namespace raylab {

SceneObject::SceneObject(const SceneObject& o)
    : name(o.name), shape(o.shape ? o.shape->clone() : nullptr), material(o.material) {}

SceneObject& SceneObject::operator=(const SceneObject& o) {
  if (this != &o) *this = SceneObject(o);
  return *this;
}

std::string SceneObject::toString() const {
  return "SceneObject[" + name + ", " + (shape ? shape->toString() : "no shape") +
         ", material=" + std::to_string(material) + "]";
}

std::string Material::toString() const {
  return "Material[" + name + ", colour=" + raylab::toString(colour) +
         ", emission=" + raylab::toString(emission) + ", opacity=" + std::to_string(opacity) + "]";
}

std::string CameraSpec::toString() const {
  return "Camera[position=" + raylab::toString(position) + ", lookAt=" + raylab::toString(lookAt) +
         ", up=" + raylab::toString(up) + ", vfov=" + std::to_string(verticalFov) + ", " +
         std::to_string(width) + "x" + std::to_string(height) + "]";
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

}  // namespace raylab
