#pragma once

#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
class Option;
class Validator;
}  // namespace CLI

namespace raylab::app {

/// A checker for file options: the name must end in `extension` (any case), e.g. ".png" for
/// the commands that write PNG pictures only.
CLI::Validator endsIn(const std::string& extension);
/// Throws an Exception naming `path` when it cannot be written (cannotWrite): a command checks
/// its outputs before it renders, and before it asks for a display.
void checkWritable(const std::string& path);
/// Runs vis::requireDisplay after a command made its output folder `dir` (so that the folder's
/// own problem is reported first, with or without a display): when there is no display, the
/// folders that making `dir` added are removed again, and nothing stays behind. `missing` is
/// firstMissingFolder(dir), taken before the folder was made.
void requireDisplayAfterFolder(const std::string& missing);
/// The first of `dir` and its parents that does not exist, or "" when `dir` exists: what
/// creating `dir` adds.
std::string firstMissingFolder(const std::string& dir);
/// Removes what making a folder added (`missing`, firstMissingFolder's answer; nothing when
/// it is ""), when a command stops before it writes there.
void removeFoldersMade(const std::string& missing);

/// A subcommand of `raylab`: its CLI11 parser and what runs when it was chosen. The
/// argument of `run` is the top-level `--scene` (so `raylab --scene F trace ...` works).
struct Subcommand {
  CLI::App* parser = nullptr;
  std::function<int(const std::string& topLevelScene)> run;
};

/**
 * \brief The options every headless command shares: `--scene`, `--algorithm`, `--seed`,
 * `--size` and `--out`. Register them with add(), then after parsing read the fields;
 * unset options stay empty and fall back to the scene file's render block.
 */
struct CommonOptions {
  std::string scene;  ///< Scene file; empty for the built-in default scene.
  std::string out;    ///< Output file (or folder, for commands that write many).
  std::optional<Algorithm> algorithm;
  std::optional<std::uint64_t> seed;
  std::optional<std::pair<int, int>> size;  ///< Width, height.
  /// --set PLACE=VALUE, in order: a value of the scene file changed for this run, checked by
  /// the loader (PLACE a JSON pointer, /camera/aperture, or a key of the render block,
  /// max_depth; VALUE JSON, a bare word read as a string).
  std::vector<std::string> sets;
  /// --fault NAME (addFault): a typical student bug planted in the engine (bug hunt).
  std::optional<Fault> fault;

  /// Adds the options to `command`. `outHelp` describes --out (required when `outRequired`);
  /// `sizeHelp` describes --size. With `withAlgorithm` false there is no --algorithm.
  void add(CLI::App* command, const std::string& outHelp, const std::string& sizeHelp,
           bool outRequired = true, bool withAlgorithm = true);

  /// The scene (file or built-in default; the top-level --scene when --scene is absent)
  /// with each --set applied, then --size to its camera. Throws SceneIO::LoadError naming
  /// the file (and the place of a --set the loader refuses).
  Scene loadScene(const std::string& topLevelScene) const;
  /// The scene with each --set applied and nothing else (trace and animate take --size as
  /// the picture's size, not the image's).
  Scene loadWithSets(const std::string& topLevelScene) const;
  /// The scene's render settings with --algorithm and --seed applied.
  RenderSettings settings(const Scene& scene) const;

 private:
  std::string m_algorithmText, m_sizeText;
  std::uint64_t m_seedValue = 0;
  CLI::Option* m_algorithmOption = nullptr;
  CLI::Option* m_seedOption = nullptr;
  CLI::Option* m_sizeOption = nullptr;
  void finish();  ///< Fills the optionals from the parsed text (CLI11 final callback).
};

/// Adds `--fault NAME` to `command` (trace, render, lesson; never compare, whose reference
/// must be right): a typical student bug planted in the engine for a bug hunt, stored in
/// `fault` (which must outlive the parse). `--fault list` prints the faults, each with what
/// it does in English and Chinese, and stops (exit 0).
CLI::Option* addFaultOption(CLI::App* command, std::optional<Fault>& fault);

/// Parses "WIDTHxHEIGHT" (e.g. "300x300", each 16..8192); nothing when malformed.
std::optional<std::pair<int, int>> parseSize(const std::string& text);
/// CLI11 check text for --size: empty when `text` parses, else what is expected.
std::string checkSize(const std::string& text);

/// `text` as valid UTF-8 without terminal controls, for a message on the terminal
/// (core's printableText, raylab/core/Text.h: non-UTF-8 bytes and controls become \xNN).
std::string printable(const std::string& text);

/// The warning of a render in which `count` samples reached the cap on rays per sample
/// (limits::kMaxRaysPerSample; RenderStats::cappedSamples).
std::string cappedSamplesWarning(std::uint64_t count);

/**
 * \brief A progress bar on stderr for long runs: "[#####.....]  45% detail" redrawn in
 * place when stderr is a terminal, one "label: 45% (detail)" line per update otherwise
 * (logs and tests read those).
 */
class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  /// Shows `fraction` (0..1) done; the bar ends its line at 1.
  void update(double fraction, const std::string& detail = {});

 private:
  std::string m_label;
  bool m_terminal;
  int m_lastPercent = -1;
};

}  // namespace raylab::app
