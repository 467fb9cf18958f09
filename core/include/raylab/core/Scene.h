#pragma once

#include "raylab/core/Material.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Shape.h"
#include "raylab/core/Types.h"

#include <memory>
#include <string>
#include <vector>

namespace raylab {

/// Where a mesh object's shading normals come from (the scene file's mesh key "normals").
enum class MeshNormals {
  File,    ///< "file": the mesh file's vertex normals when it has them, else flat (default).
  Flat,    ///< "flat": every triangle shades with its own normal, whatever the file has.
  Smooth,  ///< "smooth": normals computed with SceneObject::creaseAngle (the file's ignored).
};
const char* toString(MeshNormals normals);

/// A named shape with a material.
struct SceneObject {
  std::string name;    ///< Unique name, shown in the object list.
  std::string nameZh;  ///< "display_name": {"zh": ...}, the Chinese reader's name; empty: name.
  std::unique_ptr<Shape> shape;  ///< Geometry, world space.
  int material = 0;              ///< Index into Scene::materials.
  Vec3 velocity{0.0};            ///< Linear motion over the shutter interval: at ray time
                                 ///< tau in [0, 1] the shape is displaced by tau * velocity.
  /// Mesh objects: the file the mesh was loaded from, as a path usable from the current
  /// directory (the scene file's folder joined with the path written in it); empty for
  /// shapes written out in the scene file. SceneIO saves it relative to the new file.
  std::string source;
  /// Mesh objects: world space from the mesh file's space, the transform applied to the
  /// file's vertices (SceneIO saves it as the object's "transform"). Keep it in step by
  /// moving objects with apply().
  Mat4 worldFromSource{1.0};
  /// Mesh objects: where the shading normals come from (file, flat or smooth).
  MeshNormals meshNormals = MeshNormals::File;
  /// Mesh objects with MeshNormals::Smooth: edges between faces whose normals differ by
  /// more than this stay sharp (TriangleMesh::computeCreaseNormals), degrees in [0, 180],
  /// measured in the mesh file's space.
  double creaseAngle = 60.0;

  /// An object as its scene file wrote it: the JSON text of its entry there ("transform"
  /// steps and the shape before them, as written), and the writer's form of the object as
  /// it was read. While the writer still makes that form of it (nothing about the object has
  /// changed), SceneIO saves the file's own entry: readable steps stay steps, and edits
  /// through the file's keys (SceneEdit, Python's scene.set) reach the values the file
  /// holds, not the shape they made.
  struct FileForm {
    std::string inFile;    ///< The object's entry in the file (JSON).
    std::string whenRead;  ///< The writer's form of the object when it was read (JSON).
  };
  /// Set by SceneIO for objects of built-in shapes read from a file; null otherwise.
  std::shared_ptr<const FileForm> fileForm;

  /// How far the object has moved at shutter time `time` in [0, 1]: time * velocity, world
  /// units. The one rule of motion: a ray at time tau meets the object where it rests when
  /// the ray's origin is moved back by this much.
  Vec3 displacementAt(double time) const { return time * velocity; }
  /// The name shown to a reader: nameZh when `chinese` and set, else name.
  const std::string& shownName(bool chinese) const {
    return chinese && !nameZh.empty() ? nameZh : name;
  }

  SceneObject() = default;
  SceneObject(std::string objectName, std::unique_ptr<Shape> objectShape, int materialIndex)
      : name(std::move(objectName)), shape(std::move(objectShape)), material(materialIndex) {}
  SceneObject(const SceneObject& o);
  SceneObject& operator=(const SceneObject& o);
  SceneObject(SceneObject&&) noexcept = default;
  SceneObject& operator=(SceneObject&&) noexcept = default;
  /// Transforms the shape in world space (new = m * old) and worldFromSource with it.
  void apply(const Mat4& m);
  std::string toString() const;
};

/// Where a camera ray starts when the camera has a near clip distance d.
enum class NearClipShape {
  Plane,   ///< On the plane d in front of the eye: d along the viewing direction (OpenGL's).
  Sphere,  ///< d along the ray itself, on a sphere of radius d around the eye (smallpt's).
};
/// The scene file's word for a near clip shape: "plane" or "sphere".
const char* toString(NearClipShape shape);

/// The scene's camera: a pinhole looking from `position` at `lookAt` (down its local -z).
struct CameraSpec {
  Point3 position{0.0, 0.0, 5.0};  ///< Eye, world space.
  Point3 lookAt{0.0};              ///< Point the camera looks at, world space.
  Vec3 up{0.0, 1.0, 0.0};          ///< Approximate up direction, world space.
  double verticalFov = 40.0;       ///< Full vertical field of view, degrees.
  int width = 320;                 ///< Rays across (image width, pixels).
  int height = 240;                ///< Rays down (image height, pixels).
  double aperture = 0.0;           ///< Thin lens: lens radius, world units; 0 = pinhole.
  double focusDistance = 0.0;      ///< Thin lens: distance to the plane in focus; 0 means
                                   ///< the distance from position to lookAt.
  double nearClip = 0.0;           ///< Camera rays start this far from the eye (or lens),
                                   ///< world units, measured as nearClipShape says;
                                   ///< smallpt's 140. 0 = at the eye (or lens).
  NearClipShape nearClipShape = NearClipShape::Plane;  ///< How nearClip is measured.
  std::string toString() const;
};

/// A point light for the classic algorithms (ray casting, Whitted): radiant intensity
/// `intensity` (W sr^-1) from `position`, falling off with the squared distance.
struct PointLight {
  std::string name;      ///< Unique name.
  Point3 position{0.0};  ///< World space.
  Vec3 intensity{10.0};  ///< Linear RGB radiant intensity.
  std::string toString() const;
};

/// Everything that makes a scene: named objects, materials, lights, camera, settings.
struct Scene {
  std::string name;    ///< Title shown in the window.
  std::string nameZh;  ///< "display_name": {"zh": ...}, the Chinese title; empty: name.
  std::vector<Material> materials;  ///< Referenced by index from objects.
  std::vector<SceneObject> objects;
  std::vector<PointLight> pointLights;  ///< Area lights are objects with emissive materials.
  CameraSpec camera;
  RenderSettings render;  ///< Default settings for rendering this scene.

  /// Index of the object with this name, or -1.
  int findObject(const std::string& name) const;
  /// Index of the material with this name, or -1.
  int findMaterial(const std::string& name) const;
  std::string toString() const;
};

/**
 * \brief The built-in scene, after the original course program's: a red sphere, a blue cube and a
 * flesh-coloured light cube inside a room (floor, back, left and right walls, ceiling,
 * open towards the viewer), seen by a camera in front of the room. As in the original,
 * the sphere is a mirror material that reflects half the light and refracts the other
 * half (index of refraction 1.5), and the cube is Phong glossy, so the algorithms differ
 * on it: ray casting leaves the sphere black, Whitted follows its reflection and
 * refraction, distributed tracing fans the cube's highlight out into glossy rays.
 */
Scene defaultScene();

/// What a front end warns about a scene (the command line on stderr, Python as a
/// UserWarning): no objects (every pixel shows the background), or nothing that gives light
/// (no point light, emissive material, ambient term or background: the image is black).
/// Such a scene is valid (a teacher may start from it), so these are warnings, not errors.
std::vector<std::string> sceneWarnings(const Scene& scene);

/// A copy of `scene` whose own, object and material names are the ones a reader sees
/// (shownName): the Chinese display names when `chinese`, else the scene's own. For words
/// only (the inspector's lines, captions, handouts), never for finding things by name.
Scene sceneAsShown(const Scene& scene, bool chinese);

}  // namespace raylab
