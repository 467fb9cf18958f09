#include "raylab/core/ReferenceCache.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/Image.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"
#include "raylab/core/TriangleMesh.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace raylab {

namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

/// Format name and version of the sidecar; bump the version when the key's text or the
/// files change meaning, so older entries miss.
constexpr const char* kFormat = "raylab-reference-cache";
constexpr int kVersion = 1;
/// Pixels re-traced to check an entry against the current path tracer.
constexpr int kCheckedPixels = 6;

/**
 * \brief A 128-bit hash of bytes, as 32 hex digits: two 64-bit FNV-1a lanes with
 * different offsets, each finished by the splitmix64 mixer. Not cryptographic: it tells
 * cache entries apart and catches damaged files; the re-traced pixels catch the rest.
 */
class Hash128 {
 public:
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      m_a = (m_a ^ bytes[i]) * 0x100000001b3ULL;
      m_b = (m_b ^ bytes[i]) * 0x100000001b3ULL;
      m_b ^= m_b >> 29;
    }
  }
  void add(const std::string& text) {
    const std::uint64_t size = text.size();
    add(&size, sizeof size);
    add(text.data(), text.size());
  }
  std::string hex() const {
    char out[33];
    std::snprintf(out, sizeof out, "%016llx%016llx", static_cast<unsigned long long>(mix(m_a)),
                  static_cast<unsigned long long>(mix(m_b)));
    return out;
  }

 private:
  static std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::uint64_t m_a = 0xcbf29ce484222325ULL;
  std::uint64_t m_b = 0x84222325cbf29ce4ULL;
};

std::string hashBytes(const std::string& bytes) {
  Hash128 hash;
  hash.add(bytes);
  return hash.hex();
}

/// The settings path tracing reads, as the sidecar records them.
ojson settingsJson(const RenderSettings& s) {
  return ojson{{"algorithm", toString(s.algorithm)},
               {"samplesPerPixel", s.samplesPerPixel},
               {"seed", s.seed},
               {"maxDepth", s.maxDepth},
               {"russianRouletteDepth", s.russianRouletteDepth},
               {"nextEventEstimation", s.nextEventEstimation},
               {"multipleImportance", s.multipleImportance},
               {"background", {s.background.x, s.background.y, s.background.z}}};
}

/// The text the key hashes: the scene as its file says it (name and render block left
/// out: the settings that matter are listed apart), the triangles of meshes (a file path
/// says nothing of its content), and the settings.
std::string keyText(const Scene& scene, const RenderSettings& settings) {
  Scene normalised = scene;
  normalised.name.clear();
  normalised.render = RenderSettings{};
  Hash128 meshes;
  for (std::size_t i = 0; i < normalised.objects.size(); ++i) {
    SceneObject& object = normalised.objects[i];
    const auto* mesh = dynamic_cast<const TriangleMesh*>(object.shape.get());
    if (mesh == nullptr) continue;
    // Meshes made in code have no file; the writer needs one, the hash below has content.
    if (object.source.empty()) object.source = "mesh-" + std::to_string(i) + ".obj";
    const std::uint64_t counts[2] = {mesh->vertices().size(), mesh->triangles().size()};
    meshes.add(counts, sizeof counts);
    if (!mesh->vertices().empty())
      meshes.add(mesh->vertices().data(), mesh->vertices().size() * sizeof(mesh->vertices()[0]));
    if (!mesh->triangles().empty())
      meshes.add(mesh->triangles().data(), mesh->triangles().size() * sizeof(mesh->triangles()[0]));
  }
  return std::string(kFormat) + " " + std::to_string(kVersion) + "\n" +
         SceneIO::serialize(normalised) + "\nmeshes " + meshes.hex() + "\nsettings " +
         settingsJson(settings).dump() + "\n";
}

std::optional<std::string> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return bytes.str();
}

/// Pixel (x, y) of a reference as the Renderer computes it: the finite estimates of
/// samples 0 .. spp-1 summed in sample order, times 1/spp, as float.
glm::vec3 retrace(const Tracer& tracer, int x, int y, int spp) {
  glm::dvec3 sum(0.0);
  for (int s = 0; s < spp; ++s) {
    const Vec3 L = tracer.trace(x, y, s);
    if (std::isfinite(L.x) && std::isfinite(L.y) && std::isfinite(L.z)) sum += L;
  }
  return glm::vec3(sum * (1.0 / spp));
}

/// Why `image` is not the reference of `scene` at `settings`, judged by re-tracing a few
/// pixels spread over it (the centre and points chosen by the key); empty when they match.
std::string retraceProblem(const Scene& scene, const RenderSettings& settings,
                           const FloatImage& image, const std::string& key) {
  const Tracer tracer(scene, settings);
  std::uint64_t state = std::strtoull(key.substr(0, 16).c_str(), nullptr, 16);
  for (int i = 0; i < kCheckedPixels; ++i) {
    int x = image.width / 2, y = image.height / 2;
    if (i > 0) {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      x = int((state >> 33) % std::uint64_t(image.width));
      y = int((state >> 13) % std::uint64_t(image.height));
    }
    const glm::vec3 expected = retrace(tracer, x, y, settings.samplesPerPixel);
    if (std::memcmp(&expected, &image.at(x, y), sizeof expected) != 0)
      return "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
             ") differs from the same pixel traced now (written by another version of the "
             "path tracer?)";
  }
  return {};
}

}  // namespace

std::string ReferenceCache::defaultDirectory() {
  if (const char* dir = std::getenv("RAYLAB_CACHE_DIR"); dir != nullptr && *dir != '\0') return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0')
    return (fs::path(xdg) / "raylab" / "references").string();
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
    return (fs::path(home) / ".cache" / "raylab" / "references").string();
  return {};
}

std::optional<ReferenceCache> ReferenceCache::fromEnvironment() {
  std::string directory = defaultDirectory();
  if (directory.empty()) return std::nullopt;
  return ReferenceCache(std::move(directory));
}

ReferenceCache::ReferenceCache(std::string directory) : m_directory(std::move(directory)) {}

std::string ReferenceCache::key(const Scene& scene, const RenderSettings& referenceSettings) {
  return hashBytes(keyText(scene, referenceSettings));
}

std::string ReferenceCache::imagePath(const std::string& key) const {
  return (fs::path(m_directory) / (key + ".pfm")).string();
}

std::string ReferenceCache::sidecarPath(const std::string& key) const {
  return (fs::path(m_directory) / (key + ".json")).string();
}

ReferenceCache::Lookup ReferenceCache::load(const Scene& scene,
                                            const RenderSettings& referenceSettings) const {
  Lookup out;
  const std::string k = key(scene, referenceSettings);
  const std::string sidecarFile = sidecarPath(k), imageFile = imagePath(k);
  const std::optional<std::string> sidecarText = readBytes(sidecarFile);
  if (!sidecarText) return out;  // nothing cached
  const auto ignore = [&](const std::string& file, const std::string& why) {
    out.problem = file + ": ignored (" + why + ")";
    return out;
  };

  // Step 1: the sidecar names this key, these settings and this size.
  const ojson sidecar = ojson::parse(*sidecarText, nullptr, /*allow_exceptions=*/false);
  if (sidecar.is_discarded() || !sidecar.is_object()) return ignore(sidecarFile, "not valid JSON");
  try {
    if (sidecar.value("format", "") != kFormat || sidecar.value("version", 0) != kVersion)
      return ignore(sidecarFile, "another format or version");
    if (sidecar.at("key").get<std::string>() != k) return ignore(sidecarFile, "another key");
    if (sidecar.at("settings") != settingsJson(referenceSettings))
      return ignore(sidecarFile, "other settings");
    // Compared as JSON numbers: get<int> of a corrupt 1e30 would be undefined behaviour.
    if (sidecar.at("width") != ojson(scene.camera.width) ||
        sidecar.at("height") != ojson(scene.camera.height))
      return ignore(sidecarFile, "another size");
  } catch (const nlohmann::json::exception& e) {
    return ignore(sidecarFile, std::string("a field is missing or wrong: ") + e.what());
  }

  // Step 2: the image's bytes are the ones written, and they are a PFM of that size.
  const std::optional<std::string> bytes = readBytes(imageFile);
  if (!bytes) return ignore(imageFile, "cannot be read");
  if (hashBytes(*bytes) != sidecar.value("imageHash", ""))
    return ignore(imageFile, "its bytes do not match the hash its sidecar recorded");
  FloatImage image;
  try {
    image = imageio::decodePfm(*bytes, imageFile);
  } catch (const imageio::ReadError& e) {
    return ignore(imageFile, e.what());
  }
  if (image.width != scene.camera.width || image.height != scene.camera.height)
    return ignore(imageFile, "another size");

  // Step 3: a few pixels traced now equal the cached ones.
  if (const std::string problem = retraceProblem(scene, referenceSettings, image, k);
      !problem.empty())
    return ignore(imageFile, problem);

  ComparisonReference reference;
  reference.image = std::move(image);
  reference.samplesPerPixel = referenceSettings.samplesPerPixel;
  reference.seed = referenceSettings.seed;
  reference.seconds = sidecar.value("seconds", 0.0);
  reference.cached = true;
  reference.cacheFile = imageFile;
  out.reference = std::move(reference);
  return out;
}

std::optional<std::string> ReferenceCache::store(const Scene& scene,
                                                 const RenderSettings& referenceSettings,
                                                 const ComparisonReference& reference) const {
  if (reference.image.width != scene.camera.width || reference.image.height != scene.camera.height)
    return std::string("the reference is not the scene's size; not cached");
  std::error_code ec;
  fs::create_directories(m_directory, ec);
  if (ec) return m_directory + ": cannot create the cache folder (" + ec.message() + ")";
  const std::string k = key(scene, referenceSettings);
  std::string bytes;
  try {
    bytes = imageio::encodePfm(reference.image, imagePath(k));
  } catch (const imageio::WriteError& e) {
    return std::string(e.what());
  }
  ojson sidecar;
  sidecar["format"] = kFormat;
  sidecar["version"] = kVersion;
  sidecar["key"] = k;
  sidecar["settings"] = settingsJson(referenceSettings);
  sidecar["width"] = reference.image.width;
  sidecar["height"] = reference.image.height;
  sidecar["seconds"] = reference.seconds;
  sidecar["imageHash"] = hashBytes(bytes);
  // The image first: a sidecar is only ever beside the image it describes.
  if (auto problem = writeFileAtomically(imagePath(k), bytes))
    return imagePath(k) + ": " + *problem;
  if (auto problem = writeFileAtomically(sidecarPath(k), sidecar.dump(2) + "\n"))
    return sidecarPath(k) + ": " + *problem;
  return std::nullopt;
}

}  // namespace raylab
