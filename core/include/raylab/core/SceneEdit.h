#pragma once

#include "raylab/core/Scene.h"
#include "raylab/core/Types.h"

#include <optional>
#include <string>

/// \file SceneEdit.h
/// The edits a teacher makes to a scene in the window (the original course program's
/// rotate-about-an-axis and delete, and every value a scene file holds), as functions from
/// a scene to the edited scene.
///
/// Every edit is made on the scene's file form (SceneIO::serialize) and read back through
/// the scene loader (SceneIO::parse), so a value is checked by exactly the loader's rules
/// and refused with exactly its message: an invalid edit throws SceneIO::LoadError
/// ("ORIGIN: at /materials/1/ior: index of refraction must be positive") and the scene
/// given stays as it was. `origin` is the scene's file (or a name for an unsaved scene):
/// it starts the messages, and mesh files are found relative to its folder.
///
/// Object transforms are made about the object's centre (the centre of its bounds) and
/// appended to the object's transform steps, as a hand-written file would say them.

namespace raylab::edit {

/// `scene` with the JSON value at `pointer` replaced by `value`. `pointer` names a place of
/// the scene file (RFC 6901: "/materials/2/ior", "/objects/0/shape/radius",
/// "/camera/vertical_fov", "/render/spp", "/objects/3/name"); `value` is JSON text
/// ("1.5", "[0, 1, 0]", "\"glass\""). A pointer the file does not have yet is added (an
/// optional key); a pointer into nothing is refused.
Scene setValue(const Scene& scene, const std::string& pointer, const std::string& value,
               const std::string& origin);

/// The JSON text of the value at `pointer` in the scene file form (what setValue replaces).
std::string valueAt(const Scene& scene, const std::string& pointer, const std::string& origin);

/// Object `object` turned by `degrees` about `axis` through its centre (the original
/// program's rotation; a zero axis is refused as the loader refuses it).
Scene rotateObject(const Scene& scene, int object, double degrees, const Vec3& axis,
                   const std::string& origin);
/// Object `object` moved by `offset` (world units).
Scene translateObject(const Scene& scene, int object, const Vec3& offset,
                      const std::string& origin);
/// Object `object` scaled by `factors` per axis about its centre (uniform: equal factors;
/// a zero factor is refused).
Scene scaleObject(const Scene& scene, int object, const Vec3& factors, const std::string& origin);

/// `scene` without object `object`.
Scene removeObject(const Scene& scene, int object, const std::string& origin);
/// `scene` with a copy of object `object` appended, named "<name> copy" (or "<name> copy
/// 2", ...), moved by `offset` so both can be seen.
Scene duplicateObject(const Scene& scene, int object, const Vec3& offset,
                      const std::string& origin);
/// `scene` with object `object` renamed (names must stay unique: the loader's rule).
Scene renameObject(const Scene& scene, int object, const std::string& name,
                   const std::string& origin);

/// What can be added from the window's Add menu.
/// A shape that can be added as a new object: any built-in kind but a mesh (addMesh).
using NewShape = ShapeKind;
/// The kind whose word is `word` ("sphere"), when one can be added; nothing otherwise.
std::optional<NewShape> newShapeKind(const std::string& word);
/// The words of the shapes addShape takes, "sphere, box, plane, quad or triangle".
std::string newShapeWordList();
/// `scene` with a new object of `shape` appended, made of a new plain diffuse material,
/// sized to the scene (a fifth of its objects' extent) and placed in front of the camera
/// where the camera looks, so it can be seen; named "sphere", "sphere 2", ...
Scene addShape(const Scene& scene, NewShape shape, const std::string& origin);
/// `scene` with the mesh file `meshPath` (OBJ, PLY, OFF, STL) added as an object, scaled
/// to a fifth of the scene's extent and placed where the camera looks.
Scene addMesh(const Scene& scene, const std::string& meshPath, const std::string& origin);
/// `scene` with a new point light above the point the camera looks at.
Scene addPointLight(const Scene& scene, const std::string& origin);

/// A name not used by any object of `scene`: `base`, or "base 2", "base 3", ...
std::string uniqueObjectName(const Scene& scene, const std::string& base);

}  // namespace raylab::edit
