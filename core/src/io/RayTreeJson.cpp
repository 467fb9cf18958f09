#include "raylab/core/RayTreeJson.h"
#include "raylab/core/AtomicFile.h"
#include "raylab/core/RayWords.h"

#include "io/JsonChecks.h"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <type_traits>

namespace raylab {

namespace {

using nlohmann::json;

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }

/// `v` as the integer type T: a JSON integer within T's range, else nothing. Never a cast
/// of a fraction or of a number out of range (nlohmann's get<int> of -6.7e33 is undefined
/// behaviour; found by FuzzRayTree, issue 14).
template <typename T>
std::optional<T> integerOf(const json& v) {
  using Limits = std::numeric_limits<T>;
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(Limits::max())) return std::nullopt;
    return static_cast<T>(u);
  }
  if (!v.is_number_integer()) return std::nullopt;
  const auto i = v.get<std::int64_t>();
  if constexpr (std::is_signed_v<T>) {
    if (i >= static_cast<std::int64_t>(Limits::min()) &&
        i <= static_cast<std::int64_t>(Limits::max()))
      return static_cast<T>(i);
  }
  return std::nullopt;
}

/// The header's integer `key` of `doc`, read from `origin`.
template <typename T>
T headerInteger(const json& doc, const char* key, const std::string& origin) {
  const json& v = doc.at(key);
  if (auto value = integerOf<T>(v)) return *value;
  throw RayTreeJson::Error(origin + ": /" + key + " must be a whole number in range, got " +
                           excerpt(v));
}

/// Reads the field `key` of segment object `s` (of segment `index`) as T.
template <typename T>
T field(const json& s, const char* key, std::size_t index, const std::string& origin) {
  const auto it = s.find(key);
  if (it == s.end())
    throw RayTreeJson::Error(origin + ": /segments/" + std::to_string(index) + " has no \"" + key +
                             "\"");
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    if (auto value = integerOf<T>(*it)) return *value;
    throw RayTreeJson::Error(origin + ": /segments/" + std::to_string(index) + "/" + key +
                             " must be a whole number in range, got " + excerpt(*it));
  }
  try {
    return it->get<T>();
  } catch (const json::exception&) {
    throw RayTreeJson::Error(origin + ": /segments/" + std::to_string(index) + "/" + key +
                             " has the wrong type");
  }
}

Vec3 vecField(const json& s, const char* key, std::size_t index, const std::string& origin) {
  const auto a = field<std::vector<double>>(s, key, index, origin);
  if (a.size() != 3)
    throw RayTreeJson::Error(origin + ": /segments/" + std::to_string(index) + "/" + key +
                             " must have 3 numbers");
  return Vec3(a[0], a[1], a[2]);
}

/// The links of a tree as the engine makes them (RayTree): segment i has id i; the camera
/// ray (segment 0) alone has no parent, every other ray's parent comes before it; a ray's
/// children are the consecutive ids firstChild .. firstChild + childCount - 1, after it,
/// and name it as their parent. RayTree::propagate and the views rely on this, so a dump
/// that breaks it is refused (issue 14: it indexed outside the segments).
void checkStructure(const RayTree& tree, const std::string& origin) {
  const auto fail = [&](std::size_t i, const std::string& what) {
    throw RayTreeJson::Error(origin + ": /segments/" + std::to_string(i) + ": " + what);
  };
  const auto count = std::int64_t(tree.segments.size());
  // Each ray's own id and parent first, then the children each ray lists.
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const RaySegment& s = tree.segments[i];
    if (s.id != std::int64_t(i)) fail(i, "id " + std::to_string(s.id) + " is not its index");
    if (i == 0 ? s.parent != -1 : (s.parent < 0 || s.parent >= s.id))
      fail(i, "parent " + std::to_string(s.parent) +
                  (i == 0 ? " (the camera ray has none: -1)" : " is not an earlier ray"));
    if (s.childCount < 0) fail(i, "child_count is negative");
  }
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const RaySegment& s = tree.segments[i];
    if (s.childCount == 0) continue;
    const std::int64_t first = s.firstChild;
    if (first <= std::int64_t(i) || first + s.childCount > count)
      fail(i, "children " + std::to_string(first) + ".." +
                  std::to_string(first + s.childCount - 1) + " are not later rays of the tree");
    for (std::int64_t c = first; c < first + s.childCount; ++c)
      if (tree.segments[std::size_t(c)].parent != s.id)
        fail(std::size_t(c), "parent is not ray " + std::to_string(s.id) + ", which lists it");
  }
}

/// The header of dump `doc` (the version, the pixel and sample, the settings) into `tree`
/// and `read`.
void readHeader(const json& doc, const std::string& origin, RayTree& tree,
                RayTreeJson::Info& read) {
  using Error = RayTreeJson::Error;
  read.version = headerInteger<int>(doc, "raylab_ray_tree", origin);
  if (read.version != RayTreeJson::kVersion)
    throw Error(origin + ": ray tree format " + std::to_string(read.version) +
                " is not supported (this RayLab reads " + std::to_string(RayTreeJson::kVersion) +
                ")");
  const json& pixel = doc.at("pixel");
  const auto x = pixel.is_array() && pixel.size() == 2 ? integerOf<int>(pixel[0]) : std::nullopt;
  const auto y = pixel.is_array() && pixel.size() == 2 ? integerOf<int>(pixel[1]) : std::nullopt;
  if (!x || !y) throw Error(origin + ": /pixel must be two whole numbers, got " + excerpt(pixel));
  tree.pixelX = *x;
  tree.pixelY = *y;
  tree.sample = headerInteger<int>(doc, "sample", origin);
  tree.truncated = doc.value("truncated", false);
  // "message" is words for people (stopWords): read by nobody, its facts are not kept.
  read.scene = doc.value("scene", std::string());
  read.algorithm = doc.value("algorithm", std::string());
  if (doc.contains("seed")) read.seed = headerInteger<std::uint64_t>(doc, "seed", origin);
  const auto estimate = doc.value("estimate", std::array<double, 3>{0.0, 0.0, 0.0});
  read.estimate = Vec3(estimate[0], estimate[1], estimate[2]);
}

/// Segment `i` of the dump, the object `j`; its links are checked later, with the others'.
RaySegment readSegment(const json& j, std::size_t i, const std::string& origin) {
  using Error = RayTreeJson::Error;
  RaySegment s;
  s.id = field<int>(j, "id", i, origin);
  s.parent = field<int>(j, "parent", i, origin);
  s.firstChild = field<int>(j, "first_child", i, origin);
  s.childCount = field<int>(j, "child_count", i, origin);
  const auto kind = field<std::string>(j, "kind", i, origin);
  int k = 0;
  while (k < kRayKindCount && kind != toString(RayKind(k))) ++k;
  if (k == kRayKindCount)
    throw Error(origin + ": /segments/" + std::to_string(i) + "/kind: unknown kind '" + kind + "'");
  s.kind = RayKind(k);
  s.depth = field<int>(j, "depth", i, origin);
  s.origin = vecField(j, "origin", i, origin);
  s.direction = vecField(j, "direction", i, origin);
  s.time = field<double>(j, "time", i, origin);
  s.hit = field<bool>(j, "hit", i, origin);
  s.endPoint = vecField(j, "end_point", i, origin);
  s.lightPoint = vecField(j, "light_point", i, origin);
  s.object = field<int>(j, "object", i, origin);
  if (j.contains("light_object")) s.lightObject = field<int>(j, "light_object", i, origin);
  if (j.contains("point_light")) s.pointLight = field<int>(j, "point_light", i, origin);
  s.normal = vecField(j, "normal", i, origin);
  if (j.contains("shading_normal")) s.shadingNormal = vecField(j, "shading_normal", i, origin);
  s.weight = vecField(j, "weight", i, origin);
  s.pdf = field<double>(j, "pdf", i, origin);
  s.throughput = vecField(j, "throughput", i, origin);
  s.emitted = vecField(j, "emitted", i, origin);
  s.radiance = vecField(j, "radiance", i, origin);
  const auto reason = field<std::string>(j, "end_reason", i, origin);
  const std::optional<EndReason> known = endReasonFromJson(reason);
  if (!known)
    throw Error(origin + ": /segments/" + std::to_string(i) + "/end_reason: unknown '" + reason +
                "'");
  s.endReason = *known;
  return s;
}

}  // namespace

const char* RayTreeJson::endReasonName(EndReason reason) { return words(reason).json; }

std::string RayTreeJson::serialize(const RayTree& tree, const Scene& scene,
                                   const RenderSettings& settings) {
  json doc;
  doc["raylab_ray_tree"] = kVersion;
  doc["scene"] = scene.name;
  doc["algorithm"] = toString(settings.algorithm);
  doc["seed"] = settings.seed;
  doc["pixel"] = json::array({tree.pixelX, tree.pixelY});
  doc["sample"] = tree.sample;
  doc["estimate"] = vec(tree.estimate());
  doc["rays"] = tree.segments.size();
  std::array<std::size_t, kRayKindCount> byKind{};
  for (const RaySegment& s : tree.segments) ++byKind[std::size_t(s.kind)];
  json kinds = json::object();
  for (int k = 0; k < kRayKindCount; ++k) kinds[toString(RayKind(k))] = byKind[std::size_t(k)];
  doc["rays_by_kind"] = kinds;
  doc["truncated"] = tree.truncated;
  doc["message"] = stopWords(tree.stop, Language::English);

  json segments = json::array();
  for (const RaySegment& s : tree.segments) {
    json j = json::object();
    forEachField(s, scene, [&j](const char* key, const auto& value) {
      if constexpr (std::is_same_v<std::decay_t<decltype(value)>, Vec3>)
        j[key] = vec(value);
      else
        j[key] = value;
    });
    segments.push_back(std::move(j));
  }
  doc["segments"] = std::move(segments);
  return doc.dump(1) + "\n";
}

void RayTreeJson::save(const RayTree& tree, const Scene& scene, const RenderSettings& settings,
                       const std::string& path) {
  const std::string text = serialize(tree, scene, settings);
  // A temporary file beside the target, then a rename: never a half-written dump.
  if (auto problem = writeFileAtomically(path, text)) throw Error(path + ": " + *problem);
}

RayTree RayTreeJson::parse(const std::string& text, const std::string& origin, Info* info) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    // A syntax error, or a number too large for a double (1e999: out_of_range).
    throw Error(origin + ": not JSON (" + e.what() + ")");
  }
  if (!doc.is_object() || !doc.contains("raylab_ray_tree"))
    throw Error(origin + ": not a ray tree dump (no \"raylab_ray_tree\" version)");
  RayTree tree;
  Info read;
  try {
    readHeader(doc, origin, tree, read);
  } catch (const json::exception& e) {
    throw Error(origin + ": bad ray tree header (" + e.what() + ")");
  }
  const auto segments = doc.find("segments");
  if (segments == doc.end() || !segments->is_array())
    throw Error(origin + ": no \"segments\" array");
  tree.segments.resize(segments->size());
  for (std::size_t i = 0; i < segments->size(); ++i) {
    const json& j = (*segments)[i];
    tree.segments[i] = readSegment(j, i, origin);
    read.objectNames.push_back(j.value("object_name", std::string()));
  }
  checkStructure(tree, origin);
  if (info) *info = std::move(read);
  return tree;
}

RayTree RayTreeJson::load(const std::string& path, Info* info) {
  // A regular file of at most limits::kMaxJsonFileBytes (a whole tree of the default
  // 16 MiB budget dumps to about 55 MB): /dev/zero or a folder would read without end.
  std::string text;
  if (const auto problem = readTextFile(path, "ray tree file", text)) throw Error(*problem);
  return parse(text, path, info);
}

}  // namespace raylab
