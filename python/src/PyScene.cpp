// raylab.Scene: scene files and every value a scene file holds, read and changed from
// Python through core's SceneIO and SceneEdit, so a value is checked by the loader's own
// rules and refused with its message (raylab.SceneError).

#include "Bindings.h"

#include "raylab/core/Scene.h"
#include "raylab/core/SceneEdit.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Shape.h"

#include <pybind11/stl.h>

#include <utility>
#include <vector>

namespace raylab::python {
namespace {

/// The name an unsaved scene's messages start with, as the window's (SceneDocument).
constexpr const char* kUntitled = "untitled.json";

SceneHandle handleOf(Scene scene, std::string origin) {
  return SceneHandle{std::make_shared<const Scene>(std::move(scene)), std::move(origin)};
}

/// The JSON text of a Python value (json.dumps; NaN becomes NaN, which the loader refuses).
std::string jsonText(const py::handle& value) {
  return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

py::object fromJsonText(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

/// Index of the object given by name or index; KeyError / IndexError otherwise.
int objectIndex(const Scene& scene, const py::handle& which) {
  if (py::isinstance<py::str>(which)) {
    const std::string name = which.cast<std::string>();
    const int index = scene.findObject(name);
    if (index < 0) throw py::key_error("no object named '" + name + "'");
    return index;
  }
  const int index = which.cast<int>();
  if (index < 0 || index >= int(scene.objects.size()))
    throw py::index_error("object index " + std::to_string(index) + " is out of range (" +
                          std::to_string(scene.objects.size()) + " objects)");
  return index;
}

int materialIndex(const Scene& scene, const py::handle& which) {
  if (py::isinstance<py::str>(which)) {
    const std::string name = which.cast<std::string>();
    const int index = scene.findMaterial(name);
    if (index < 0) throw py::key_error("no material named '" + name + "'");
    return index;
  }
  const int index = which.cast<int>();
  if (index < 0 || index >= int(scene.materials.size()))
    throw py::index_error("material index " + std::to_string(index) + " is out of range (" +
                          std::to_string(scene.materials.size()) + " materials)");
  return index;
}

/// Sets every (pointer, value) in order on a copy; the handle changes only when all pass.
void setValues(SceneHandle& handle,
               const std::vector<std::pair<std::string, std::string>>& values) {
  Scene edited = *handle.scene;
  for (const auto& [pointer, value] : values)
    edited = edit::setValue(edited, pointer, value, handle.origin);
  handle.scene = std::make_shared<const Scene>(std::move(edited));
}

/// The (pointer, JSON text) pairs of keyword arguments under `prefix` ("/camera").
std::vector<std::pair<std::string, std::string>> keyValues(const std::string& prefix,
                                                           const py::kwargs& values) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [key, value] : values)
    out.emplace_back(prefix + "/" + key.cast<std::string>(), jsonText(value));
  return out;
}

/// Replaces the handle's scene with `edit(scene)`.
template <typename Edit>
void apply(SceneHandle& handle, Edit&& edit) {
  handle.scene = std::make_shared<const Scene>(edit(*handle.scene));
}

std::vector<std::string> names(const Scene& scene, int which) {
  std::vector<std::string> out;
  if (which == 0)
    for (const SceneObject& o : scene.objects) out.push_back(o.name);
  if (which == 1)
    for (const Material& mat : scene.materials) out.push_back(mat.name);
  if (which == 2)
    for (const PointLight& l : scene.pointLights) out.push_back(l.name);
  return out;
}

}  // namespace

namespace {

/// Scene.parse, its name and origin, the names of its parts, its size and get.
void bindSceneReading(py::class_<SceneHandle>& scene) {
  scene
      .def_static(
          "parse",
          [](const std::string& text, const std::string& origin) {
            return handleOf(SceneIO::parse(text, origin), origin);
          },
          py::arg("text"), py::arg("origin") = kUntitled,
          "A scene from scene-file text; `origin` starts error messages and is where mesh "
          "files are looked for.")
      .def_property_readonly("name", [](const SceneHandle& h) { return h.scene->name; })
      .def_readwrite("origin", &SceneHandle::origin,
                     "The file the scene came from (or 'untitled.json'): it starts error "
                     "messages, and mesh files are found relative to its folder.")
      .def_property_readonly("object_names",
                             [](const SceneHandle& h) { return names(*h.scene, 0); })
      .def_property_readonly("material_names",
                             [](const SceneHandle& h) { return names(*h.scene, 1); })
      .def_property_readonly("point_light_names",
                             [](const SceneHandle& h) { return names(*h.scene, 2); })
      .def_property_readonly(
          "size",
          [](const SceneHandle& h) {
            return py::make_tuple(h.scene->camera.width, h.scene->camera.height);
          },
          "(width, height) of the camera's image, pixels.")
      .def(
          "get",
          [](const SceneHandle& h, const std::string& pointer) {
            return fromJsonText(edit::valueAt(*h.scene, pointer, h.origin));
          },
          py::arg("pointer") = "",
          "The value at a JSON pointer of the scene file ('/materials/1/ior', "
          "'/camera'; '' = the whole file) as Python values.");
}

/// Scene.set, update and the set_* shorthands; the parts as the file lists them.
void bindSceneSetting(py::class_<SceneHandle>& scene) {
  scene
      .def(
          "set",
          [](SceneHandle& h, const std::string& pointer, const py::object& value) {
            setValues(h, {{pointer, jsonText(value)}});
          },
          py::arg("pointer"), py::arg("value"),
          "Sets the value at a JSON pointer of the scene file ('/render/spp', 64), checked "
          "by the scene loader's rules.")
      .def(
          "update",
          [](SceneHandle& h, const py::dict& values) {
            std::vector<std::pair<std::string, std::string>> pairs;
            for (const auto& [pointer, value] : values)
              pairs.emplace_back(pointer.cast<std::string>(), jsonText(value));
            setValues(h, pairs);
          },
          py::arg("values"), "Sets several {pointer: value} at once: all are applied, or none.")
      .def(
          "set_camera",
          [](SceneHandle& h, const py::kwargs& kw) { setValues(h, keyValues("/camera", kw)); },
          "Camera values by their file names: set_camera(vertical_fov=30, width=160).")
      .def(
          "set_render",
          [](SceneHandle& h, const py::kwargs& kw) { setValues(h, keyValues("/render", kw)); },
          "Render settings by their file names: set_render(spp=4, max_depth=3).")
      .def(
          "set_material",
          [](SceneHandle& h, const py::object& which, const py::kwargs& kw) {
            const int index = materialIndex(*h.scene, which);
            setValues(h, keyValues("/materials/" + std::to_string(index), kw));
          },
          py::arg("material"),
          "A material's values (by name or index): set_material('glass', ior=1.33); a checker "
          "on its colour: set_material('floor', texture={'type': 'checker', 'scale': 0.5, "
          "'colour2': [0.1, 0.1, 0.1]}).")
      .def(
          "set_object",
          [](SceneHandle& h, const py::object& which, const py::kwargs& kw) {
            const int index = objectIndex(*h.scene, which);
            setValues(h, keyValues("/objects/" + std::to_string(index), kw));
          },
          py::arg("object"),
          "An object's values (by name or index): set_object('ball', material='glass').")
      .def_property_readonly(
          "objects",
          [](const SceneHandle& h) {
            return fromJsonText(edit::valueAt(*h.scene, "/objects", h.origin));
          },
          "The objects as the scene file lists them (a copy: change them with set_object).")
      .def_property_readonly("materials",
                             [](const SceneHandle& h) {
                               return fromJsonText(edit::valueAt(*h.scene, "/materials", h.origin));
                             })
      .def_property_readonly("camera",
                             [](const SceneHandle& h) {
                               return fromJsonText(edit::valueAt(*h.scene, "/camera", h.origin));
                             })
      .def_property_readonly("render_settings", [](const SceneHandle& h) {
        return fromJsonText(edit::valueAt(*h.scene, "/render", h.origin));
      });
}

/// The window's edits of one object: rotate, translate, scale, remove, duplicate, rename.
void bindSceneEdits(py::class_<SceneHandle>& scene) {
  scene
      .def(
          "rotate_object",
          [](SceneHandle& h, const py::object& which, double degrees, const py::object& axis) {
            const int index = objectIndex(*h.scene, which);
            const Vec3 a = toVec3(axis, "axis");
            apply(h, [&](const Scene& s) {
              return edit::rotateObject(s, index, degrees, a, h.origin);
            });
          },
          py::arg("object"), py::arg("degrees"), py::arg("axis") = py::make_tuple(0, 0, 1),
          "Turns an object about an axis through its centre (the original program's rotation).")
      .def(
          "translate_object",
          [](SceneHandle& h, const py::object& which, const py::object& offset) {
            const int index = objectIndex(*h.scene, which);
            const Vec3 d = toVec3(offset, "offset");
            apply(h, [&](const Scene& s) { return edit::translateObject(s, index, d, h.origin); });
          },
          py::arg("object"), py::arg("offset"))
      .def(
          "scale_object",
          [](SceneHandle& h, const py::object& which, const py::object& factors) {
            const int index = objectIndex(*h.scene, which);
            const Vec3 f = py::isinstance<py::float_>(factors) || py::isinstance<py::int_>(factors)
                               ? Vec3(factors.cast<double>())
                               : toVec3(factors, "factors");
            apply(h, [&](const Scene& s) { return edit::scaleObject(s, index, f, h.origin); });
          },
          py::arg("object"), py::arg("factors"),
          "Scales about the centre: a number or (sx, sy, sz).")
      .def(
          "remove_object",
          [](SceneHandle& h, const py::object& which) {
            const int index = objectIndex(*h.scene, which);
            apply(h, [&](const Scene& s) { return edit::removeObject(s, index, h.origin); });
          },
          py::arg("object"))
      .def(
          "duplicate_object",
          [](SceneHandle& h, const py::object& which, const py::object& offset) {
            const int index = objectIndex(*h.scene, which);
            const Vec3 d = toVec3(offset, "offset");
            apply(h, [&](const Scene& s) { return edit::duplicateObject(s, index, d, h.origin); });
          },
          py::arg("object"), py::arg("offset") = py::make_tuple(0.5, 0, 0))
      .def(
          "rename_object",
          [](SceneHandle& h, const py::object& which, const std::string& name) {
            const int index = objectIndex(*h.scene, which);
            apply(h, [&](const Scene& s) { return edit::renameObject(s, index, name, h.origin); });
          },
          py::arg("object"), py::arg("name"));
}

/// New shapes, meshes and point lights; saving, copying; one shape and the nearest hit.
void bindSceneAdditions(py::class_<SceneHandle>& scene) {
  scene
      .def(
          "add_shape",
          [](SceneHandle& h, const std::string& kind) {
            const std::optional<edit::NewShape> shape = edit::newShapeKind(kind);
            if (!shape)
              throw py::value_error("unknown shape '" + kind + "': use " +
                                    edit::newShapeWordList());
            apply(h, [&](const Scene& s) { return edit::addShape(s, *shape, h.origin); });
            return h.scene->objects.back().name;
          },
          py::arg("kind"),
          "Adds a sphere, box, plane, quad or triangle where the camera looks; returns its name.")
      .def(
          "add_mesh",
          [](SceneHandle& h, const std::string& path) {
            apply(h, [&](const Scene& s) { return edit::addMesh(s, path, h.origin); });
            return h.scene->objects.back().name;
          },
          py::arg("path"), "Adds a mesh file (OBJ, PLY, OFF, STL); returns its name.")
      .def("add_point_light",
           [](SceneHandle& h) {
             apply(h, [&](const Scene& s) { return edit::addPointLight(s, h.origin); });
             return h.scene->pointLights.back().name;
           })
      .def(
          "save",
          [](const SceneHandle& h, const std::string& path) { SceneIO::save(*h.scene, path); },
          py::arg("path"),
          "Writes the scene file (a temporary file renamed over the target: never half written).")
      .def(
          "to_json", [](const SceneHandle& h) { return SceneIO::serialize(*h.scene); },
          "The scene file's text (mesh paths relative to the current directory).")
      .def(
          "copy",
          [](const SceneHandle& h) {
            return SceneHandle{h.scene, h.origin};
          },
          "An independent copy (edits to one do not change the other).")
      .def(
          "shape",
          [](const SceneHandle& h, const py::object& which) {
            const int index = objectIndex(*h.scene, which);
            return std::shared_ptr<Shape>(h.scene->objects[std::size_t(index)].shape->clone());
          },
          py::arg("object"), "A copy of an object's shape, for intersect and the exact oracle.")
      .def(
          "intersect",
          [](const SceneHandle& h, const Ray& ray) -> py::object {
            const SceneIntersector intersector(*h.scene);
            const std::optional<SceneHit> hit = intersector.intersect(ray);
            if (!hit) return py::none();
            py::dict out;
            out["object"] = hit->object;
            out["name"] = h.scene->objects[std::size_t(hit->object)].name;
            out["surface"] = hit->si;
            return std::move(out);
          },
          py::arg("ray"),
          "The nearest object the ray meets: {'object', 'name', 'surface'} or None.")
      .def("__repr__", [](const SceneHandle& h) {
        return "<raylab.Scene '" + h.scene->name + "' from " + h.origin + ": " +
               std::to_string(h.scene->objects.size()) + " objects, " +
               std::to_string(h.scene->camera.width) + "x" +
               std::to_string(h.scene->camera.height) + ">";
      });
}

}  // namespace

void bindScene(py::module_& m) {
  py::class_<SceneHandle> scene(m, "Scene", R"(A scene: objects, materials, point lights,
camera and render settings. Made by load_scene, default_scene or Scene.parse.

Values are read and changed in the scene file's own key names (see the README's "Writing a
scene"), and every change is checked by the scene loader's rules: a bad value raises
raylab.SceneError with the loader's message and leaves the scene as it was. Renders and
traces work on the scene as it was when they started.)");

  bindSceneReading(scene);
  bindSceneSetting(scene);
  bindSceneEdits(scene);
  bindSceneAdditions(scene);

  m.def(
      "load_scene", [](const std::string& path) { return handleOf(SceneIO::load(path), path); },
      py::arg("path"),
      "Reads a scene file; a bad file raises raylab.SceneError naming the file, the JSON place "
      "and the problem.");
  m.def(
      "default_scene", [] { return handleOf(defaultScene(), kUntitled); },
      "The built-in scene (after the original course program's).");
}

}  // namespace raylab::python
