#pragma once

#include "raylab/core/Comparison.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"

#include <optional>
#include <string>

namespace raylab {

/**
 * \brief Path-traced references kept on disk, so that a second comparison of the same
 * scene starts at once: `raylab compare`, `raylab plot` and the window's Compare view
 * share them.
 *
 * An entry is two files in directory(): `<key>.pfm` (the reference, linear radiance) and
 * `<key>.json` (a sidecar naming the key, the reference's spp, seed, size and render time,
 * and the image's seal: SHA-256 over the key, the settings and every byte of the PFM). The
 * key is a SHA-256 (OpenSSL's libcrypto) of everything the reference's pixels
 * depend on: the scene's content as SceneIO::serialize writes it (its name and render
 * block left out), the triangles of its meshes, and the settings path tracing reads (spp,
 * seed, maxDepth, Russian roulette depth, next-event estimation, MIS, background). The
 * image size is part of the scene's camera. Settings path tracing does not read (threads,
 * the distributed rays) share one entry.
 *
 * Nothing read is trusted: an entry is used only when both files are regular files of
 * bounded size (opened without following a symbolic link and without blocking on a FIFO),
 * its sidecar names the same key and settings with fields of the right types, the PFM's
 * bytes have the recorded seal, and a few pixels re-traced now (at places drawn afresh at
 * each check, not derivable from the key; at the full spp, with the current code) equal
 * the cached ones bit for bit, which also catches a
 * cache written by a program whose path tracer has since changed. Anything else is
 * ignored (load says why) and the reference is rendered and stored again. Both files are
 * written atomically (writeFileAtomically), the PFM first, so a reader never sees a
 * sidecar before its image.
 */
class ReferenceCache {
 public:
  /// What a lookup found: a verified reference, or why there is none.
  struct Lookup {
    std::optional<ComparisonReference> reference;  ///< Set on a hit (`cached` true).
    std::string problem;  ///< On a miss with files present: why they were ignored
                          ///< ("corrupt: ..."); empty on a hit or when nothing was cached.
  };

  /**
   * \brief The cache folder the environment asks for: $RAYLAB_CACHE_DIR when set (as
   * is), else $XDG_CACHE_HOME/raylab/references, else $HOME/.cache/raylab/references.
   * Empty when none of these variables is set (then there is no cache).
   */
  static std::string defaultDirectory();
  /// The cache in defaultDirectory(), or nothing when it is empty.
  static std::optional<ReferenceCache> fromEnvironment();

  /// A cache in `directory` (created when the first entry is stored).
  explicit ReferenceCache(std::string directory);
  const std::string& directory() const { return m_directory; }

  /// The 32-hex-digit key of the reference of `scene` rendered with `referenceSettings`
  /// (those of Comparison::referenceSettings).
  static std::string key(const Scene& scene, const RenderSettings& referenceSettings);
  /// Where the image of entry `key` is (`<directory>/<key>.pfm`).
  std::string imagePath(const std::string& key) const;
  /// Where the sidecar of entry `key` is (`<directory>/<key>.json`).
  std::string sidecarPath(const std::string& key) const;

  /// The verified reference of `scene` at `referenceSettings`, or why there is none.
  /// Never throws for a missing, unreadable or corrupt entry.
  Lookup load(const Scene& scene, const RenderSettings& referenceSettings) const;
  /**
   * \brief Stores `reference` (rendered from `scene` with `referenceSettings`) for later
   * comparisons, replacing any entry of the same key. Returns what went wrong (folder not
   * writable, disk full), for the caller to report; the comparison itself is unaffected.
   */
  std::optional<std::string> store(const Scene& scene, const RenderSettings& referenceSettings,
                                   const ComparisonReference& reference) const;

 private:
  std::string m_directory;
};

}  // namespace raylab
