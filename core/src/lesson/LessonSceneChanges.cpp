// A step's scene changes: each applied to a copy of the scene file's JSON, the changed scene
// read once, and a change that breaks it named at its own place in the lesson.
#include "lesson/LessonReader.h"

#include "raylab/core/SceneIO.h"

#include <algorithm>
#include <cctype>

namespace raylab::lessonfile {

using nlohmann::json;

json& Reader::namedEntry(json& doc, const char* list, const char* what, const json& name,
                         const std::string& path, std::size_t& index) const {
  const std::string wanted = string(name, path);
  json& entries = doc[list];
  std::string names;
  if (entries.is_array()) {
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const json& n =
          entries[i].is_object() && entries[i].contains("name") ? entries[i]["name"] : json();
      if (n == wanted) {
        index = i;
        return entries[i];
      }
      if (n.is_string()) names += (names.empty() ? "" : ", ") + n.get<std::string>();
    }
  }
  fail(path, std::string("no ") + what + " named \"" + wanted + "\" in " + m_scenePath + " (" +
                 (names.empty() ? std::string("it has none") : "it has " + names) + ")");
}

ChangeMapping Reader::applyChange(json& doc, const json& c, const std::string& path) const {
  static const char* const kTargets[] = {"material",   "object",         "point_light",
                                         "camera",     "render",         "add_material",
                                         "add_object", "add_point_light"};
  if (!c.is_object())
    fail(path,
         "a scene change is an object, e.g. {\"material\": \"glass\", \"set\": {\"ior\": 1}}");
  std::string target;
  for (const char* t : kTargets)
    if (c.contains(t)) {
      if (!target.empty())
        fail(path,
             "a change edits one thing; this one names both \"" + target + "\" and \"" + t + "\"");
      target = t;
    }
  if (target.empty())
    fail(path,
         "a change names what it edits: material, object, point_light, camera, render, "
         "add_material, add_object or add_point_light");

  if (target == "camera" || target == "render" || target.rfind("add_", 0) == 0)
    return blockChange(doc, c, target, path);
  return entryChange(doc, c, target, path);
}

ChangeMapping Reader::blockChange(json& doc, const json& c, const std::string& target,
                                  const std::string& path) const {
  // Whole blocks: merged into the camera or render block, or appended to a list.
  if (target == "camera" || target == "render") {
    const json& value = c[target];
    if (c.size() != 1 || !value.is_object())
      fail(path, "{\"" + target + "\": {...}} merges keys into the scene's " + target + " block");
    json& block = doc[target];
    if (!block.is_object()) block = json::object();
    block.merge_patch(value);
    return {"/" + target, path + "/" + target};
  }
  // "add_material", "add_object" or "add_point_light".
  if (c.size() != 1 || !c[target].is_object())
    fail(path, "{\"" + target + "\": {...}} adds one entry in the scene format");
  const char* list = target == "add_material" ? "materials"
                     : target == "add_object" ? "objects"
                                              : "point_lights";
  json& entries = doc[list];
  if (!entries.is_array()) entries = json::array();
  entries.push_back(c[target]);
  return {"/" + std::string(list) + "/" + std::to_string(entries.size() - 1), path + "/" + target};
}

ChangeMapping Reader::entryChange(json& doc, const json& c, const std::string& target,
                                  const std::string& path) const {
  // A named material, object or point light, and one operation on it.
  const bool material = target == "material", object = target == "object";
  if (material)
    onlyKeys(c, path, {"material", "set"});
  else if (object)
    onlyKeys(c, path, {"object", "set", "translate", "rotate", "scale", "remove"});
  else
    onlyKeys(c, path, {"point_light", "set", "translate", "remove"});
  if (c.size() != 2)
    fail(path, "a change does one thing: " +
                   std::string(material ? "set"
                               : object ? "set, translate, rotate, scale or remove"
                                        : "set, translate or remove"));
  const char* list = material ? "materials" : object ? "objects" : "point_lights";
  std::size_t index = 0;
  json& entry = namedEntry(doc, list,
                           material ? "material"
                           : object ? "object"
                                    : "point light",
                           c[target], path + "/" + target, index);
  const std::string scenePrefix = "/" + std::string(list) + "/" + std::to_string(index);
  if (c.contains("set")) {
    const json& set = c["set"];
    if (!set.is_object()) fail(path + "/set", "expected an object of keys to set");
    if (set.contains("name"))
      fail(path + "/set/name", "a step cannot rename (other entries refer to it by name)");
    entry.merge_patch(set);
    return {scenePrefix, path + "/set"};
  }
  if (c.contains("remove")) {
    if (c["remove"] != true) fail(path + "/remove", "write \"remove\": true");
    doc[list].erase(index);
    return {scenePrefix, path};
  }
  const std::string op = c.contains("translate") ? "translate"
                         : c.contains("rotate")  ? "rotate"
                                                 : "scale";
  if (!object) {
    // Point lights have a position, not a transform: translate moves it.
    const json& v = c[op];
    if (!v.is_array() || v.size() != 3)
      fail(path + "/" + op, "expected [x, y, z], got " + excerpt(v));
    json& position = entry["position"];
    if (position.is_array() && position.size() == 3)
      for (int i = 0; i < 3; ++i)
        position[i] = number(position[i], scenePrefix + "/position") +
                      number(v[i], path + "/" + op + "/" + std::to_string(i));
    return {scenePrefix + "/position", path + "/" + op};
  }
  json& transform = entry["transform"];
  if (!transform.is_array()) transform = json::array();
  transform.push_back(json{{op, c[op]}});
  return {scenePrefix + "/transform/" + std::to_string(transform.size() - 1) + "/" + op,
          path + "/" + op};
}

std::shared_ptr<const Scene> Reader::changedScene(const json& changes, const std::string& path,
                                                  std::vector<std::string>& written) const {
  if (!changes.is_array()) fail(path, "expected a list of changes");
  if (changes.empty()) return m_scene;
  // Every change applied to the scene file's JSON, then the changed scene read once (issue
  // 38: reading it after each change made 3,000 changes of one step take 35 s).
  json doc = m_sceneDoc;
  std::vector<ChangeMapping> mappings;
  for (std::size_t k = 0; k < changes.size(); ++k) {
    written.push_back(changes[k].dump());
    mappings.push_back(applyChange(doc, changes[k], path + "/" + std::to_string(k)));
  }
  try {
    return std::make_shared<const Scene>(SceneIO::parse(doc.dump(), m_scenePath));
  } catch (const SceneIO::LoadError&) {
    // Name the change that breaks it: bisect for a k whose first k changes load and whose
    // first k + 1 do not (a few reads, not one per change).
  }
  const auto loadsAfter = [&](std::size_t count) -> std::optional<std::string> {
    json prefix = m_sceneDoc;
    for (std::size_t k = 0; k < count; ++k)
      applyChange(prefix, changes[k], path + "/" + std::to_string(k));
    try {
      SceneIO::parse(prefix.dump(), m_scenePath);
      return std::nullopt;
    } catch (const SceneIO::LoadError& e) {
      return std::string(e.what());
    }
  };
  std::size_t good = 0, bad = changes.size();  // loads after `good`, not after `bad`
  while (bad - good > 1) {
    const std::size_t mid = good + (bad - good) / 2;
    (loadsAfter(mid) ? bad : good) = mid;
  }
  changeError(loadsAfter(bad).value_or("the changed scene does not load"), mappings[bad - 1],
              path + "/" + std::to_string(bad - 1));
}

void Reader::changeError(std::string message, const ChangeMapping& mapping,
                         const std::string& cp) const {
  // SceneIO says "<scene>: at <path>: <problem>"; say it at the change's place.
  const std::string head = m_scenePath + ": at ";
  if (message.rfind(head, 0) == 0) message = message.substr(head.size());
  const std::size_t colon = message.find(": ");
  const std::string scenePath = colon == std::string::npos ? "" : message.substr(0, colon);
  const std::string problem = colon == std::string::npos ? message : message.substr(colon + 2);
  const std::string& prefix = mapping.scenePrefix;
  if (!scenePath.empty() && scenePath.rfind(prefix, 0) == 0 &&
      (scenePath.size() == prefix.size() || scenePath[prefix.size()] == '/'))
    fail(mapping.lessonPrefix + scenePath.substr(prefix.size()), problem);
  fail(cp, problem + (scenePath.empty() ? "" : " (at " + scenePath + " of the changed scene)"));
}

std::string Reader::scenePlace(const std::string& place, const std::string& path) const {
  if (place.empty() || place[0] != '/')
    fail(path, "a place is a JSON pointer into the scene file, e.g. \"/materials/glass/ior\"");
  const std::size_t second = place.find('/', 1);
  const std::string list =
      place.substr(1, second == std::string::npos ? std::string::npos : second - 1);
  if (second == std::string::npos ||
      (list != "materials" && list != "objects" && list != "point_lights"))
    return place;
  const std::size_t third = place.find('/', second + 1);
  const std::string name =
      place.substr(second + 1, third == std::string::npos ? std::string::npos : third - second - 1);
  if (!name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c));
      }))
    return place;
  json doc = m_sceneDoc;
  std::size_t index = 0;
  const char* what = list == "materials" ? "material"
                     : list == "objects" ? "object"
                                         : "point light";
  namedEntry(doc, list.c_str(), what, json(name), path, index);
  return "/" + list + "/" + std::to_string(index) +
         (third == std::string::npos ? std::string() : place.substr(third));
}

}  // namespace raylab::lessonfile
