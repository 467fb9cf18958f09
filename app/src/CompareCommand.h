#pragma once

#include "Subcommand.h"

#include "raylab/core/Comparison.h"
#include "raylab/core/Scene.h"

#include <CLI/CLI.hpp>

#include <iosfwd>
#include <string>

namespace raylab::app {

/**
 * \brief `raylab compare`: renders the scene with the four algorithms at equal samples
 * (--spp) or equal time (--time), measures each against a path-traced reference (rendered
 * at --reference-spp, or read from --reference F.pfm), writes the four-panel picture
 * (--out, PNG of --picture size) and the figures as JSON (--json, default beside the PNG),
 * and prints the figures. With --pixel X Y each panel also shows that pixel's ray tree.
 */
Subcommand addCompareCommand(CLI::App& cli);

/// What `compare` and `plot` share: the reference, the threads and the progress bar.
struct ReferenceOptions {
  std::string file;     ///< --reference: a PFM to measure against; empty = render one.
  int samples = 0;      ///< --reference-spp; 0 = ComparisonSettings' default rule.
  std::string saveAs;   ///< --save-reference: write the rendered reference as PFM.
  int threads = 0;      ///< --threads; 0 = all.
  std::string picture;  ///< --picture WxH text (checked by checkSize).
  /// Adds --reference, --reference-spp, --save-reference, --threads and --picture
  /// (`pictureDefault`, e.g. "1920x1080") to `command`.
  void add(CLI::App* command, const std::string& pictureDefault);
};

/// Runs the comparison with a ProgressBar labelled `label`, reading or saving the
/// reference as `reference` says. Throws raylab::Exception subtypes naming the files.
ComparisonResult runComparison(const Scene& scene, const RenderSettings& settings,
                               ComparisonSettings compare, const ReferenceOptions& reference,
                               const std::string& label);

/// Prints one line per algorithm: spp, time, rays and error (and the reference line).
void printFigures(const ComparisonResult& result, std::ostream& out);

/// Writes `text` to `path` through a temporary file and a rename, so `path` is never left
/// half written. Throws raylab::Exception naming the file when it cannot be written.
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace raylab::app
