#include "raylab/core/SceneEdit.h"

#include "raylab/core/Check.h"
#include "raylab/core/Plane.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Text.h"

#include "shapes/ShapeFormat.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace raylab::edit {

namespace {

// Ordered, so that a scene's file form keeps the writer's key order through an edit.
using json = nlohmann::ordered_json;

std::string folderOf(const std::string& origin) {
  return std::filesystem::path(origin).parent_path().string();
}

/// The scene's file form, as the writer makes it for a file at `origin`.
json fileForm(const Scene& scene, const std::string& origin) {
  return json::parse(SceneIO::serialize(scene, folderOf(origin)));
}

/// The file form read back through the loader: its checks, its messages.
Scene readBack(const json& doc, const std::string& origin) {
  // (Text that is not UTF-8 becomes U+FFFD rather than an exception from dump(): the
  // loader then names the place, issue 38.)
  return SceneIO::parse(doc.dump(-1, ' ', false, json::error_handler_t::replace), origin);
}

[[noreturn]] void refuse(const std::string& origin, const std::string& where,
                         const std::string& problem) {
  throw SceneIO::LoadError(origin + ": at " + where + ": " + problem);
}

json& objectEntry(json& doc, int object, const std::string& origin) {
  json& objects = doc["objects"];
  if (object < 0 || object >= int(objects.size()))
    refuse(origin, "/objects", "there is no object #" + std::to_string(object));
  return objects[std::size_t(object)];
}

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }

/// Where an object is, for turning and scaling it about itself: the centre of its bounds
/// (a plane's own point: it has no finite bounds).
Point3 centreOf(const SceneObject& object) {
  if (object.shape->kind() == ShapeKind::Plane)
    return static_cast<const Plane&>(*object.shape).point();
  const Bounds3 b = object.shape->bounds();
  if (b.empty() || !isFinite(b.lower) || !isFinite(b.upper)) return Point3(0.0);
  return b.centre();
}

/// Appends transform steps to object `object`'s "transform" (making it when missing).
/// Appends transform steps to object `object`'s "transform" (making it when missing). A
/// move right after a move, or a turn about the same centre and axis right after a turn,
/// adds to the last one instead, so that clicking Move or Rotate again and again keeps the
/// file's list short: [translate t1] + [translate t2] = [translate t1 + t2], and
/// [to c, rotate a by d1, back] + [to c, rotate a by d2, back] = [to c, rotate a by d1 + d2,
/// back] (c and a exactly the same).
void appendSteps(json& doc, int object, const std::vector<json>& steps, const std::string& origin) {
  json& entry = objectEntry(doc, object, origin);
  if (!entry.contains("transform")) entry["transform"] = json::array();
  json& list = entry["transform"];
  const std::size_t n = list.size();
  const auto kindOf = [](const json& step) {
    return step.is_object() && step.size() == 1 ? step.begin().key() : std::string();
  };
  if (steps.size() == 1 && kindOf(steps[0]) == "translate" && n >= 1 &&
      kindOf(list[n - 1]) == "translate" && list[n - 1]["translate"].size() == 3) {
    json& last = list[n - 1]["translate"];
    for (std::size_t a = 0; a < 3; ++a)
      last[a] = last[a].get<double>() + steps[0]["translate"][a].get<double>();
    return;
  }
  if (steps.size() == 3 && kindOf(steps[1]) == "rotate" && n >= 3 &&
      kindOf(list[n - 2]) == "rotate" && list[n - 3] == steps[0] && list[n - 1] == steps[2] &&
      list[n - 2]["rotate"].contains("axis") &&
      list[n - 2]["rotate"]["axis"] == steps[1]["rotate"]["axis"]) {
    json& degrees = list[n - 2]["rotate"]["degrees"];
    degrees = degrees.get<double>() + steps[1]["rotate"]["degrees"].get<double>();
    return;
  }
  for (const json& step : steps) list.push_back(step);
}

/// The most transform steps an object's entry keeps before an edit folds them.
constexpr std::size_t kFoldSteps = 48;

/// The file form of `scene` for a turn, move or scale of `object`. When the object's entry
/// already holds kFoldSteps steps, the object is written as it is now instead (its steps
/// folded into its shape's keys, or into one matrix step), so that an edit costs the same
/// however many came before: each edit re-reads every step of the entry, and 2,000
/// alternating moves and turns (which cannot merge) took over 60 s (issue 38).
json transformForm(const Scene& scene, int object, const std::string& origin) {
  json doc = fileForm(scene, origin);
  const json& entry = objectEntry(doc, object, origin);
  if (!entry.contains("transform") || entry["transform"].size() < kFoldSteps) return doc;
  Scene alone;  // the object by itself, with the materials its entry names
  alone.materials = scene.materials;
  alone.objects.push_back(scene.objects[std::size_t(object)]);
  alone.objects.back().fileForm = nullptr;
  doc["objects"][std::size_t(object)] = fileForm(alone, origin)["objects"][0];
  return doc;
}

/// The scene's extent: the diagonal of its finite objects' bounds (1 for none), and the
/// point the camera looks at, where new things are put.
double extentOf(const Scene& scene) {
  Bounds3 bounds;
  for (const SceneObject& o : scene.objects) {
    const Bounds3 b = o.shape->bounds();
    if (!b.empty() && isFinite(b.lower) && isFinite(b.upper)) bounds.extend(b);
  }
  const double d = bounds.empty() ? 0.0 : glm::length(bounds.extent());
  return d > 0.0 && std::isfinite(d) ? d : 1.0;
}

/// A name not used by any entry of `list` (a JSON array of named entries).
std::string uniqueIn(const json& list, const std::string& base) {
  const auto used = [&](const std::string& name) {
    return std::any_of(list.begin(), list.end(),
                       [&](const json& e) { return e.contains("name") && e["name"] == name; });
  };
  if (!used(base)) return base;
  for (int k = 2;; ++k)
    if (!used(base + " " + std::to_string(k))) return base + " " + std::to_string(k);
}

}  // namespace

std::string uniqueObjectName(const Scene& scene, const std::string& base) {
  const auto used = [&](const std::string& name) { return scene.findObject(name) >= 0; };
  if (!used(base)) return base;
  for (int k = 2;; ++k)
    if (!used(base + " " + std::to_string(k))) return base + " " + std::to_string(k);
}

Scene setValue(const Scene& scene, const std::string& pointer, const std::string& value,
               const std::string& origin) {
  json doc = fileForm(scene, origin);
  json parsed;
  try {
    parsed = json::parse(value);
  } catch (const json::parse_error&) {
    refuse(origin, pointer, "'" + utf8Prefix(value, 80) + "' is not a JSON value");
  }
  json::json_pointer where;
  // A place with control characters or bytes that are not UTF-8 names no key of a scene
  // file (fuzzing `--set` found such a key made the JSON writer throw, issue 38).
  if (printableText(pointer) != pointer)
    refuse(origin, printableText(pointer), "not a place in a scene file");
  try {
    where = json::json_pointer(pointer);
  } catch (const json::exception&) {
    refuse(origin, pointer, "not a place in a scene file");
  }
  // The value's parent must exist. In an object the key itself may be new (an optional
  // key); in an array only an element that is there can be replaced.
  bool replaceable = false;
  try {
    if (!where.empty() && doc.contains(where.parent_pointer())) {
      const json& parent = doc[where.parent_pointer()];
      replaceable = parent.is_object() || (parent.is_array() && doc.contains(where));
    }
  } catch (const json::exception&) {
    // nlohmann 3.11's contains() throws for an empty name in an array's place
    // ("/materials//5", found by fuzzing `--set`) instead of answering false.
    replaceable = false;
  }
  if (!replaceable) refuse(origin, pointer, "the scene file has no such place");
  doc[where] = parsed;
  return readBack(doc, origin);
}

std::string valueAt(const Scene& scene, const std::string& pointer, const std::string& origin) {
  const json doc = fileForm(scene, origin);
  try {
    const json::json_pointer where(pointer);
    if (!doc.contains(where)) refuse(origin, pointer, "the scene file has no such place");
    return doc[where].dump();
  } catch (const json::exception&) {
    refuse(origin, pointer, "not a place in a scene file");
  }
}

Scene rotateObject(const Scene& scene, int object, double degrees, const Vec3& axis,
                   const std::string& origin) {
  json doc = transformForm(scene, object, origin);
  objectEntry(doc, object, origin);
  const Point3 c = centreOf(scene.objects[std::size_t(object)]);
  json rotate;
  rotate["axis"] = vec(axis);
  rotate["degrees"] = degrees;
  appendSteps(doc, object,
              {{{"translate", vec(-c)}}, {{"rotate", rotate}}, {{"translate", vec(c)}}}, origin);
  return readBack(doc, origin);
}

Scene translateObject(const Scene& scene, int object, const Vec3& offset,
                      const std::string& origin) {
  json doc = transformForm(scene, object, origin);
  appendSteps(doc, object, {{{"translate", vec(offset)}}}, origin);
  return readBack(doc, origin);
}

Scene scaleObject(const Scene& scene, int object, const Vec3& factors, const std::string& origin) {
  json doc = transformForm(scene, object, origin);
  objectEntry(doc, object, origin);
  const Point3 c = centreOf(scene.objects[std::size_t(object)]);
  appendSteps(doc, object,
              {{{"translate", vec(-c)}}, {{"scale", vec(factors)}}, {{"translate", vec(c)}}},
              origin);
  return readBack(doc, origin);
}

Scene removeObject(const Scene& scene, int object, const std::string& origin) {
  json doc = fileForm(scene, origin);
  objectEntry(doc, object, origin);
  doc["objects"].erase(std::size_t(object));
  return readBack(doc, origin);
}

Scene duplicateObject(const Scene& scene, int object, const Vec3& offset,
                      const std::string& origin) {
  json doc = fileForm(scene, origin);
  json copy = objectEntry(doc, object, origin);
  copy["name"] = uniqueIn(doc["objects"], copy["name"].get<std::string>() + " copy");
  if (!copy.contains("transform")) copy["transform"] = json::array();
  copy["transform"].push_back({{"translate", vec(offset)}});
  doc["objects"].push_back(copy);
  return readBack(doc, origin);
}

Scene renameObject(const Scene& scene, int object, const std::string& name,
                   const std::string& origin) {
  json doc = fileForm(scene, origin);
  objectEntry(doc, object, origin)["name"] = name;
  return readBack(doc, origin);
}

std::optional<NewShape> newShapeKind(const std::string& word) {
  const ShapeFormat* format = shapeFormat(word);
  if (!format || !format->example) return std::nullopt;
  return format->kind;
}

std::string newShapeWordList() {
  std::vector<std::string> words;
  for (const ShapeFormat* format : shapeFormats())
    if (format->example) words.push_back(format->word);
  std::string list;
  for (std::size_t i = 0; i < words.size(); ++i)
    list += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return list;
}

Scene addShape(const Scene& scene, NewShape shape, const std::string& origin) {
  json doc = fileForm(scene, origin);
  const CameraSpec& camera = scene.camera;
  const double size = 0.2 * extentOf(scene);
  const Point3 p = camera.lookAt;
  // The camera's frame, for shapes that face it.
  Vec3 forward = camera.lookAt - camera.position;
  forward = glm::length(forward) > 0.0 ? glm::normalize(forward) : Vec3(0, 0, -1);
  Vec3 right = glm::cross(forward, camera.up);
  right = glm::length(right) > 0.0 ? glm::normalize(right) : Vec3(1, 0, 0);
  const Vec3 up = glm::cross(right, forward);

  const ShapeFormat& format = shapeFormat(shape);
  RAYLAB_CHECK(format.example != nullptr);  // newShapeKind gives only shapes with one
  const json shapeJson = format.example(p, size, right, up);
  const std::string base = format.word;
  const std::string name = uniqueIn(doc["objects"], base);
  const std::string material = uniqueIn(doc["materials"], name + " material");
  doc["materials"].push_back(
      {{"name", material}, {"type", "diffuse"}, {"colour", vec(Vec3(0.9, 0.7, 0.2))}});
  doc["objects"].push_back({{"name", name}, {"material", material}, {"shape", shapeJson}});
  return readBack(doc, origin);
}

Scene addMesh(const Scene& scene, const std::string& meshPath, const std::string& origin) {
  json doc = fileForm(scene, origin);
  // The path as the file will say it: relative to the scene's folder when it can be.
  std::filesystem::path file(meshPath);
  const std::string folder = folderOf(origin);
  std::error_code ec;
  const std::filesystem::path relative =
      std::filesystem::relative(std::filesystem::absolute(file, ec),
                                std::filesystem::absolute(folder.empty() ? "." : folder, ec), ec);
  const std::string written = ec || relative.empty() ? meshPath : relative.string();
  const std::string base = file.stem().string().empty() ? "mesh" : file.stem().string();
  const std::string name = uniqueIn(doc["objects"], base);
  const std::string material = uniqueIn(doc["materials"], name + " material");
  doc["materials"].push_back(
      {{"name", material}, {"type", "diffuse"}, {"colour", vec(Vec3(0.9, 0.7, 0.2))}});
  doc["objects"].push_back(
      {{"name", name}, {"material", material}, {"shape", {{"type", "mesh"}, {"file", written}}}});
  // Read it once to learn its size, then scale and move it to where the camera looks.
  const Scene loaded = readBack(doc, origin);
  const Bounds3 b = loaded.objects.back().shape->bounds();
  const double d = glm::length(b.extent());
  const double factor = d > 0.0 && std::isfinite(d) ? 0.2 * extentOf(scene) / d : 1.0;
  doc["objects"].back()["transform"] = json::array({{{"translate", vec(-b.centre())}},
                                                    {{"scale", vec(Vec3(factor))}},
                                                    {{"translate", vec(scene.camera.lookAt)}}});
  return readBack(doc, origin);
}

Scene addPointLight(const Scene& scene, const std::string& origin) {
  json doc = fileForm(scene, origin);
  const double height = 0.3 * extentOf(scene);
  if (!doc.contains("point_lights")) doc["point_lights"] = json::array();
  // Bright enough to light the point below it like a white surface: I / d^2 = 1.
  doc["point_lights"].push_back({{"name", uniqueIn(doc["point_lights"], "point light")},
                                 {"position", vec(scene.camera.lookAt + Vec3(0.0, height, 0.0))},
                                 {"intensity", vec(Vec3(height * height))}});
  return readBack(doc, origin);
}

}  // namespace raylab::edit
