#pragma once

#include "raylab/core/Shape.h"
#include "raylab/core/Types.h"

#include <memory>
#include <string>
#include <vector>

namespace raylab {

/// Surface appearance. This issue only needs colour and emission for drawing; the light
/// transport issue extends it to the full material models.
struct Material {
  std::string name;      ///< Unique name, referenced by objects.
  Vec3 colour{0.8};      ///< Reflectance (albedo), linear RGB in [0, 1].
  Vec3 emission{0.0};    ///< Emitted radiance, linear RGB (non-zero for lights).
  double opacity = 1.0;  ///< For drawing only: 1 opaque, 0 invisible.

  bool isEmitter() const { return emission.x > 0.0 || emission.y > 0.0 || emission.z > 0.0; }
  std::string toString() const;
};

/// A named shape with a material.
struct SceneObject {
  std::string name;              ///< Unique name, shown in the object list.
  std::unique_ptr<Shape> shape;  ///< Geometry, world space.
  int material = 0;              ///< Index into Scene::materials.

  SceneObject() = default;
  SceneObject(std::string objectName, std::unique_ptr<Shape> objectShape, int materialIndex)
      : name(std::move(objectName)), shape(std::move(objectShape)), material(materialIndex) {}
  SceneObject(const SceneObject& o);
  SceneObject& operator=(const SceneObject& o);
  SceneObject(SceneObject&&) noexcept = default;
  SceneObject& operator=(SceneObject&&) noexcept = default;
  std::string toString() const;
};

/// The scene's camera: a pinhole looking from `position` at `lookAt` (down its local -z).
struct CameraSpec {
  Point3 position{0.0, 0.0, 5.0};  ///< Eye, world space.
  Point3 lookAt{0.0};              ///< Point the camera looks at, world space.
  Vec3 up{0.0, 1.0, 0.0};          ///< Approximate up direction, world space.
  double verticalFov = 40.0;       ///< Full vertical field of view, degrees.
  int width = 320;                 ///< Rays across (image width, pixels).
  int height = 240;                ///< Rays down (image height, pixels).
  std::string toString() const;
};

/// Everything that makes a scene: named objects, materials, the camera.
struct Scene {
  std::string name;                 ///< Title shown in the window.
  std::vector<Material> materials;  ///< Referenced by index from objects.
  std::vector<SceneObject> objects;
  CameraSpec camera;

  /// Index of the object with this name, or -1.
  int findObject(const std::string& name) const;
  /// Index of the material with this name, or -1.
  int findMaterial(const std::string& name) const;
  std::string toString() const;
};

/**
 * \brief The built-in scene, after the seed program's: a red sphere, a blue cube and a
 * flesh-coloured light cube inside a room (floor, back, left and right walls, ceiling,
 * open towards the viewer), seen by a camera in front of the room.
 */
Scene defaultScene();

}  // namespace raylab
