#pragma once

// `raylab trace --lesson FILE --step N`: a lesson step's tree, traced through the lesson
// stager (stageTree / stageStep), as the window, the handout and the web export show it.

#include "commands/TraceCommand.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace raylab::app {

/// The options of `raylab trace --lesson`.
struct LessonTraceOptions {
  std::string lesson;              ///< --lesson FILE (or a lesson id in the lessons folder).
  std::string steps;               ///< --step N, N,M,... or all (1 = the first step).
  std::optional<double> tryValue;  ///< --try-value V: the step's try_value set to V.

  /// Registers --lesson, --step and --try-value on `command`.
  void add(CLI::App* command);
};

/**
 * \brief Runs `raylab trace --lesson FILE --step N [--try-value V] [--json OUT] [--out PNG]`.
 *
 * One step: its scene after its scene_changes (and --fault, and --try-value), algorithm,
 * pixel, sample, bundle or chosen ray, exactly as the lesson stager traces it; --json writes
 * the tree's dump (RayTreeJson, as plain `raylab trace`), --out the step's 3D view as staged
 * (needs a display). Several steps (--step 2,5 or all): --json writes one document with
 * every step's tree ({"raylab_lesson_trees": 1, "steps": [...]}, a step without a traced
 * pixel has "tree": null and says why); no picture. Options that would change what the
 * lesson stages (--scene, --set, --pixel, --algorithm, --colour, ...) are usage errors
 * (exit 2); a step that is not in the lesson, or (named alone) traces nothing, exits 1
 * naming the file and the step.
 */
int runLessonTrace(const LessonTraceOptions& lesson, const RayTreeOptions& tree,
                   const std::string& json, const CLI::App& command,
                   const std::string& topLevelScene);

}  // namespace raylab::app
