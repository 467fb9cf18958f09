#include "raylab/core/ReferenceCache.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/Image.h"
#include "raylab/core/Limits.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"
#include "raylab/core/TriangleMesh.h"

#include <openssl/evp.h>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace raylab {

namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

/// Format name and version of the sidecar; bump the version when the key's text or the
/// files change meaning, so older entries miss.
constexpr const char* kFormat = "raylab-reference-cache";
constexpr int kVersion = 2;  // 2: SHA-256 keys and image hashes
/// Pixels re-traced to check an entry against the current path tracer.
constexpr int kCheckedPixels = 6;

/**
 * \brief SHA-256 (OpenSSL's libcrypto) of bytes, as 64 hex digits. It names cache entries
 * and seals each image to its key and settings: a forged or damaged image needs a
 * SHA-256 collision to pass (issue 38 replaced a hand-written FNV hash that a forger could
 * recompute).
 */
class Sha256 {
 public:
  Sha256() : m_context(EVP_MD_CTX_new(), &EVP_MD_CTX_free) {
    if (!m_context || EVP_DigestInit_ex(m_context.get(), EVP_sha256(), nullptr) != 1)
      throw std::runtime_error("OpenSSL cannot compute SHA-256");
  }
  void add(const void* data, std::size_t size) {
    if (size > 0) EVP_DigestUpdate(m_context.get(), data, size);
  }
  /// The text's length, then its bytes (so "ab" + "c" and "a" + "bc" differ).
  void add(const std::string& text) {
    const std::uint64_t size = text.size();
    add(&size, sizeof size);
    add(text.data(), text.size());
  }
  std::string hex() {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    EVP_DigestFinal_ex(m_context.get(), digest, &length);
    std::string out;
    char two[3];
    for (unsigned int i = 0; i < length; ++i) {
      std::snprintf(two, sizeof two, "%02x", digest[i]);
      out += two;
    }
    return out;
  }

 private:
  std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> m_context;
};

std::string hashBytes(const std::string& bytes) {
  Sha256 hash;
  hash.add(bytes);
  return hash.hex();
}

/// The settings path tracing reads, as the sidecar records them.
ojson settingsJson(const RenderSettings& s) {
  ojson j{{"algorithm", toString(s.algorithm)},
          {"samplesPerPixel", s.samplesPerPixel},
          {"seed", s.seed},
          {"maxDepth", s.maxDepth},
          {"russianRouletteDepth", s.russianRouletteDepth},
          {"nextEventEstimation", s.nextEventEstimation},
          {"multipleImportance", s.multipleImportance},
          {"background", {s.background.x, s.background.y, s.background.z}}};
  // A planted bug (bug hunt) renders another image: never the clean one's key. Absent when
  // none, so the keys of earlier caches stay valid.
  if (s.fault != Fault::None) j["fault"] = toString(s.fault);
  return j;
}

/// The text the key hashes: the scene as its file says it (name and render block left
/// out: the settings that matter are listed apart), the triangles of meshes (a file path
/// says nothing of its content), and the settings.
std::string keyText(const Scene& scene, const RenderSettings& settings) {
  Scene normalised = scene;
  normalised.name.clear();
  normalised.render = RenderSettings{};
  Sha256 meshes;
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

/**
 * \brief The bytes of a cache file, read only when it is a regular file of at most
 * `maxBytes`: never through a symbolic link (O_NOFOLLOW), never blocking on a FIFO
 * (O_NONBLOCK), never reading a device without end (issue 38). Otherwise nothing, and
 * `problem` says why (empty when the file does not exist: nothing is cached).
 */
std::optional<std::string> readCacheFile(const std::string& path, std::uint64_t maxBytes,
                                         std::string& problem) {
  problem.clear();
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    if (error != ENOENT)
      problem = error == ELOOP ? "a symbolic link, not a cache file" : std::strerror(error);
    return std::nullopt;
  }
  struct stat st {};
  std::string bytes;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    problem = "not a regular file (a FIFO, a folder or a device?)";
  } else if (std::uint64_t(st.st_size) > maxBytes) {
    problem = "larger than any cache file (" + std::to_string(st.st_size) + " bytes)";
  } else {
    // Up to one byte past the limit, so a file that grew meanwhile is noticed too.
    bytes.resize(std::size_t(maxBytes) + 1);
    std::size_t got = 0;
    for (ssize_t n = 0; got < bytes.size(); got += std::size_t(n)) {
      n = ::read(fd, bytes.data() + got, bytes.size() - got);
      if (n < 0 && errno == EINTR)
        n = 0;
      else if (n <= 0) {
        if (n < 0) problem = std::strerror(errno);
        break;
      }
    }
    bytes.resize(got);
    if (got > maxBytes) problem = "larger than any cache file";
  }
  ::close(fd);
  if (!problem.empty()) return std::nullopt;
  return bytes;
}

/// Largest PFM a reference can be: the image limit's pixels and a header.
constexpr std::uint64_t kMaxPfmBytes = std::uint64_t(limits::kMaxImagePixels) * 12 + 64;

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
/// pixels at places drawn afresh at each check (the system's random device), so no forger
/// can know which pixels to leave intact; empty when they match.
std::string retraceProblem(const Scene& scene, const RenderSettings& settings,
                           const FloatImage& image) {
  const Tracer tracer(scene, settings);
  std::random_device device;
  std::mt19937_64 random((std::uint64_t(device()) << 32) ^ device());
  for (int i = 0; i < kCheckedPixels; ++i) {
    const int x = int(random() % std::uint64_t(image.width));
    const int y = int(random() % std::uint64_t(image.height));
    const glm::vec3 expected = retrace(tracer, x, y, settings.samplesPerPixel);
    if (std::memcmp(&expected, &image.at(x, y), sizeof expected) != 0)
      return "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
             ") differs from the same pixel traced now (written by another version of the "
             "path tracer?)";
  }
  return {};
}

/// The image's seal: SHA-256 over the entry's key, its settings and every byte of the PFM.
std::string imageSeal(const std::string& key, const RenderSettings& settings,
                      const std::string& pfmBytes) {
  Sha256 hash;
  hash.add(key);
  hash.add(settingsJson(settings).dump());
  hash.add(pfmBytes);
  return hash.hex();
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
  const auto ignore = [&](const std::string& file, const std::string& why) {
    out.problem = file + ": ignored (" + why + ")";
    return out;
  };
  std::string problem;
  const std::optional<std::string> sidecarText =
      readCacheFile(sidecarFile, limits::kMaxCacheSidecarBytes, problem);
  if (!sidecarText) return problem.empty() ? out : ignore(sidecarFile, problem);

  // Step 1: the sidecar names this key, these settings and this size, every field of the
  // type it must have (a string "seconds" or a numeric "imageHash" is a damaged entry).
  const ojson sidecar = ojson::parse(*sidecarText, nullptr, /*allow_exceptions=*/false);
  if (sidecar.is_discarded() || !sidecar.is_object()) return ignore(sidecarFile, "not valid JSON");
  std::string seal;
  double seconds = 0.0;
  try {
    if (sidecar.at("format") != ojson(kFormat) || sidecar.at("version") != ojson(kVersion))
      return ignore(sidecarFile, "another format or version");
    if (sidecar.at("key") != ojson(k)) return ignore(sidecarFile, "another key");
    if (sidecar.at("settings") != settingsJson(referenceSettings))
      return ignore(sidecarFile, "other settings");
    // Compared as JSON numbers: get<int> of a corrupt 1e30 would be undefined behaviour.
    if (sidecar.at("width") != ojson(scene.camera.width) ||
        sidecar.at("height") != ojson(scene.camera.height))
      return ignore(sidecarFile, "another size");
    if (!sidecar.at("imageHash").is_string() || !sidecar.at("seconds").is_number())
      return ignore(sidecarFile, "imageHash must be a string and seconds a number");
    seal = sidecar.at("imageHash").get<std::string>();
    seconds = sidecar.at("seconds").get<double>();
  } catch (const nlohmann::json::exception& e) {
    return ignore(sidecarFile, std::string("a field is missing or wrong: ") + e.what());
  }

  // Step 2: the image's bytes are the ones written for this key and these settings, and
  // they are a PFM of that size.
  const std::optional<std::string> bytes = readCacheFile(imageFile, kMaxPfmBytes, problem);
  if (!bytes) return ignore(imageFile, problem.empty() ? "missing" : problem);
  if (imageSeal(k, referenceSettings, *bytes) != seal)
    return ignore(imageFile, "its bytes do not match the hash (SHA-256) its sidecar recorded");
  FloatImage image;
  try {
    image = imageio::decodePfm(*bytes, imageFile);
  } catch (const imageio::ReadError& e) {
    return ignore(imageFile, e.what());
  }
  if (image.width != scene.camera.width || image.height != scene.camera.height)
    return ignore(imageFile, "another size");

  // Step 3: a few pixels, drawn afresh, traced now equal the cached ones.
  if (const std::string different = retraceProblem(scene, referenceSettings, image);
      !different.empty())
    return ignore(imageFile, different);

  ComparisonReference reference;
  reference.image = std::move(image);
  reference.samplesPerPixel = referenceSettings.samplesPerPixel;
  reference.seed = referenceSettings.seed;
  reference.seconds = std::isfinite(seconds) && seconds >= 0.0 ? seconds : 0.0;
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
  sidecar["imageHash"] = imageSeal(k, referenceSettings, bytes);
  // The image first: a sidecar is only ever beside the image it describes.
  if (auto problem = writeFileAtomically(imagePath(k), bytes))
    return imagePath(k) + ": " + *problem;
  if (auto problem = writeFileAtomically(sidecarPath(k), sidecar.dump(2) + "\n"))
    return sidecarPath(k) + ": " + *problem;
  return std::nullopt;
}

}  // namespace raylab
