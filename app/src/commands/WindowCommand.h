#pragma once

#include "raylab/core/RenderSettings.h"

#include <optional>
#include <string>
#include <utility>

namespace raylab::app {

/// Options of the window (`raylab` with no subcommand).
struct WindowOptions {
  std::string scene;  ///< Scene file; empty for the built-in default scene.
  /// The scene is the file given alone (`raylab FILE`, a file manager's double-click): one
  /// that cannot be read opens the window anyway, on the scene open last time or the
  /// built-in one, with the error in File > Open's dialog.
  bool sceneGivenAlone = false;
  int quitAfterMs = -1;                ///< Close by itself this long after showing; -1 stays open.
  std::string screenshot;              ///< When set: grab the window into this PNG, then quit.
  std::string select;                  ///< Object to select at start (by name); empty selects none.
  std::optional<Algorithm> algorithm;  ///< Ray-tree panel's algorithm (else the scene's).
  std::optional<std::pair<int, int>> trace;     ///< Trace this pixel (x, y) when the window opens.
  int sample = 0;                               ///< With trace: the pixel sample.
  std::optional<int> frame;                     ///< With trace: show this animation frame.
  std::optional<int> ray;                       ///< With trace: inspect this ray.
  std::optional<std::pair<int, int>> simulate;  ///< Simulate this grid (across, down).
  std::string language;               ///< "en" or "zh"; empty: the last chosen, else the system's.
  bool render = false;                ///< Render the image at start (a screenshot waits for it).
  std::optional<int> renderSamples;   ///< With render: samples per pixel (else the scene's).
  bool presentation = false;          ///< Start in presentation mode.
  bool compare = false;               ///< Compare the four algorithms at start (a screenshot
                                      ///< waits for it).
  std::optional<int> compareSamples;  ///< With compare: equal samples, this many spp.
  std::string lesson;                 ///< Open this lesson file at start.
  int lessonStep = 1;                 ///< With lesson: the step shown (1-based).
};

/**
 * \brief Opens the main window and runs Qt's event loop until it closes.
 *
 * For tests, `quitAfterMs` and/or `screenshot` make the window leave by itself after it
 * has been shown and painted (a screenshot alone waits 1500 ms). The scene is loaded
 * before any window appears, so a bad `--scene` file (or an unknown `select` name) fails
 * like in the headless commands, with a raylab::Exception (a bad file given alone is shown
 * in the window instead, see `sceneGivenAlone`); so does a `trace` pixel outside the
 * scene camera's film, a `sample` outside its samples per pixel, or a `ray` the traced
 * tree does not have.
 * \return kExitOk, or kExitRuntimeError when the screenshot cannot be written.
 */
int runWindow(int argc, char** argv, const WindowOptions& options);

}  // namespace raylab::app
