#pragma once

#include "commands/Subcommand.h"

#include "raylab/core/RayTree.h"
#include "raylab/core/Scene.h"
#include "raylab/vis/BounceAnimation.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/SceneView.h"
#include "raylab/vis/TreeViewState.h"
#include "raylab/vis/ViewCamera.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace raylab::app {

/**
 * \brief The options `trace` and `animate` share: which (pixel, sample) to trace, how its
 * tree is drawn (--colour, filters, toggles) and from where (--view, --size is the picture).
 *
 * `--size` is the size of the picture of the 3D view; the traced pixel is one of the scene
 * camera's image (its size from the scene, or --image-size).
 */
struct RayTreeOptions {
  CommonOptions common;
  std::pair<int, int> pixel{-1, -1};  ///< --pixel X Y, image coordinates (y down).
  int sample = 0;                     ///< --sample.
  std::string colour = "energy";      ///< --colour energy|kind|depth.
  std::string kinds;                  ///< --kinds a,b,...; empty = all.
  std::optional<int> maxDepth;        ///< --max-depth.
  bool reachingLight = false;         ///< --reaching-light.
  double minEnergy = 0.0;             ///< --min-energy.
  bool hitPoints = true, normals = false, arrows = false, legend = true;
  std::string view = "default";  ///< --view default|camera.
  std::string lang = "en";       ///< --lang en|zh: the legend's words (and animate's captions).
  std::optional<std::pair<int, int>> imageSize;                ///< --image-size (the traced image).
  std::string order = "depth";                                 ///< --order processing|depth.
  int framesPerStep = vis::AnimationSettings{}.framesPerStep;  ///< --frames-per-step.
  int raysPerStep = vis::AnimationSettings{}.raysPerStep;      ///< --rays-per-step.

  /// Registers the options on `command`; `defaultSize` is the picture size without --size.
  /// `pixelRequired` false lets the command trace something else instead (trace --grid).
  /// `outRequired` false: the command checks --out itself (trace --lesson may write JSON only).
  void add(CLI::App* command, const std::string& outHelp, const std::string& defaultSize,
           bool pixelRequired = true, bool outRequired = true);
  /// The scene with --image-size applied (not --size: that is the picture).
  Scene loadScene(const std::string& topLevelScene) const;
  /// Checks --pixel against the scene camera's image and --kinds; the message on failure.
  std::optional<std::string> usageError(const Scene& scene) const;
  /// The drawing style the options ask for (valid once usageError() is empty).
  vis::RayTreeStyle style() const;
  /// The picture size (--size, or the command's default).
  std::pair<int, int> pictureSize() const;
  /// The bounce animation's settings (--order, --frames-per-step, --rays-per-step).
  vis::AnimationSettings animation() const;
  /// What the options ask the view to show, as the window and the handouts give it
  /// (vis::TreeViewState): the pixel and sample, the style, the animation, the view camera.
  vis::TreeViewState viewState() const;
  /// A view of `scene` showing `tree` in `state` (SceneView::show), for a picture of
  /// pictureSize().
  std::unique_ptr<vis::SceneView> makeView(const Scene& scene, const RayTree& tree,
                                           const vis::TreeViewState& state) const;
  /// The same with viewState().
  std::unique_ptr<vis::SceneView> makeView(const Scene& scene, const RayTree& tree) const {
    return makeView(scene, tree, viewState());
  }

 private:
  std::string m_imageSizeText;
  std::pair<int, int> m_defaultSize{1024, 768};
};

/// The --colour check of `trace` and `animate`: empty for energy, kind or depth; for verdict,
/// why a plain trace cannot be coloured by verdict and what draws verdicts instead.
std::string colourUsageError(const std::string& name);
/// The usage error of tracing pixel (x, y) of `scene`'s image with the ray kinds `kinds`
/// (a comma-separated list, empty for all), named after `option` ("--pixel", "--trace"):
/// a pixel outside the image (naming the image size) or an unknown kind. Shared by
/// `trace`, `animate` and the window's --trace, which all exit 2 on it.
std::optional<std::string> pixelUsageError(int x, int y, const Scene& scene,
                                           const std::string& option,
                                           const std::string& kinds = {});

/**
 * \brief `raylab trace --pixel X Y`: traces one sample of one pixel with the chosen
 * algorithm, recording its ray tree, and renders the 3D view with the tree to a PNG plus a
 * JSON dump of the tree (RayTreeJson; --json, default beside the PNG). Prints the files
 * and a one-line summary (rays by kind, estimate). A pixel outside the image is a usage
 * error (exit 2) naming the pixel and the image size. `--frame N` draws the tree as in
 * frame N of `raylab animate` with the same options. `--grid NxM` traces the window's
 * Simulate grid instead of one pixel (N rays across, M down, spread evenly over the
 * image) and draws all the trees together; the JSON holds every tree.
 */
Subcommand addTraceCommand(CLI::App& cli);

}  // namespace raylab::app
