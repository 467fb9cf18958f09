#pragma once

#include "commands/Subcommand.h"

#include "raylab/core/CompareSize.h"
#include "raylab/core/Comparison.h"
#include "raylab/core/Scene.h"

#include <CLI/CLI.hpp>

#include <iosfwd>
#include <optional>
#include <string>

namespace raylab::app {

/**
 * \brief `raylab compare`: renders the scene with the four algorithms at equal samples
 * (--spp, default 4) or equal time (--time), at the scene's size fitted inside 160x120
 * unless --size says otherwise, measures each against a path-traced reference (rendered at
 * --reference-spp, default 16 x spp, and kept in the ReferenceCache unless --no-cache; or
 * read from --reference F.pfm), writes the four-panel picture
 * (--out, PNG of --picture size) and the figures as JSON (--json, default beside the PNG),
 * and prints the figures. With --pixel X Y each panel also shows that pixel's ray tree.
 */
Subcommand addCompareCommand(CLI::App& cli);

/// What `compare` and `plot` share: the reference, its cache, the threads and the
/// progress bar.
struct ReferenceOptions {
  std::string file;      ///< --reference: a PFM to measure against; empty = render one.
  int samples = 0;       ///< --reference-spp; 0 = ComparisonSettings' default rule.
  std::string saveAs;    ///< --save-reference: write the rendered reference as PFM.
  bool noCache = false;  ///< --no-cache: render the reference, read and write no cache.
  std::string cacheDir;  ///< --cache-dir; empty = ReferenceCache::defaultDirectory().
  int threads = 0;       ///< --threads; 0 = all.
  std::string picture;   ///< --picture WxH text (checked by checkSize).
  /// Adds --reference, --reference-spp, --save-reference, --no-cache, --cache-dir,
  /// --threads and --picture (`pictureDefault`, e.g. "1920x1080") to `command`.
  void add(CLI::App* command, const std::string& pictureDefault);
  /// Before any render, so that bad input fails first: the --reference image (nothing
  /// without one), and --save-reference checked writable. Throws naming the file.
  std::optional<FloatImage> load() const;
};

/// The image size `compare` and `plot` render at when --size is not given: the scene's
/// size fitted inside 160x120 (fitCompareSize, the window's rule too), so a first
/// comparison, reference included, takes seconds; the picture shows each pixel enlarged.
constexpr int kDefaultCompareWidth = kCompareWidth, kDefaultCompareHeight = kCompareHeight;
/// Fits `scene`'s camera inside the default size unless `common` has a --size.
void fitDefaultCompareSize(const CommonOptions& common, Scene& scene);

/// Runs the comparison with a ProgressBar labelled `label`, measuring against `image` (what
/// reference.load() read) or else a reference rendered, through the ReferenceCache unless
/// --no-cache (a cache problem is a note on stderr, never a failure), and saved as
/// `reference` says. Throws raylab::Exception subtypes naming the files.
ComparisonResult runComparison(const Scene& scene, const RenderSettings& settings,
                               ComparisonSettings compare, const ReferenceOptions& reference,
                               std::optional<FloatImage> image, const std::string& label);

/// Prints one line per algorithm: spp, time, rays and error (and the reference line).
void printFigures(const ComparisonResult& result, std::ostream& out);

/// Writes `text` to `path` through a temporary file and a rename, so `path` is never left
/// half written. Throws raylab::Exception naming the file when it cannot be written.
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace raylab::app
