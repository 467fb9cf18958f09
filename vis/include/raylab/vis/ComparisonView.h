#pragma once

#include "raylab/core/Comparison.h"
#include "raylab/core/Language.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/Scene.h"
#include "raylab/vis/Image.h"
#include "raylab/vis/RayTreeStyle.h"

#include <memory>
#include <string>
#include <vector>

class vtkRenderer;

namespace raylab::vis {

/// The colour that stands for an algorithm in every comparison picture and plot (the
/// Okabe-Ito palette, told apart with any colour vision): ray casting orange, Whitted
/// bluish green, distributed blue, path tracing vermillion.
Rgb8 algorithmColour(Algorithm algorithm);

/// How the four-panel picture is laid out and what it shows.
struct ComparisonViewOptions {
  int columns = 2;              ///< Panels per row: 2 (a 2x2 grid) or 4 (one row), 1 (a column).
  bool showTimes = true;        ///< Show measured times. Off for baselines: times vary by run.
  bool showHeader = true;       ///< A top line naming the scene, the mode and the reference.
  bool showExplanation = true;  ///< A bottom band saying what the error measures and why
                                ///< path tracing, the noisiest-looking, has the lowest.
  /// The language of every word drawn (ComparisonCaptions); Chinese is drawn with a CJK
  /// font (Noto Sans CJK, fonts-noto-cjk) when one is installed.
  Language language = Language::English;
  /// The smallest text in pixels (0: 8): the fonts follow the picture's size but never go
  /// below it. A window sets the size its text is readable at (ComparePanel: 12).
  int minimumFont = 0;
  std::string toString() const;
};

/// A rectangle of a picture in pixels, x right and y down from its top-left corner.
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

/**
 * \brief The side-by-side comparison a teacher projects: one panel per algorithm, each with
 * its image and its figures (time, samples per pixel, rays traced by kind, error against
 * the path-traced reference), optionally the ray tree of one pixel beside the image.
 *
 * One vtkRenderer per element, each with its own viewport of one window: per panel a
 * background renderer holding the figures text, a title band in the algorithm's colour,
 * the image (a vtkImageActor seen by a parallel camera, nearest-neighbour, never
 * stretched: its viewport has the image's aspect ratio) and, with trees, a 3D view; a
 * header band over all panels and an explanation band under them. `layout(width,
 * height)` places them for a window of that size, so a window can host `renderers()` and
 * call `layout` when it is resized; `renderOffscreen` does both in its own window.
 *
 * Sized for a classroom: each image takes its panel's whole height, the title and
 * figures standing in a column beside it (or, in tall panels, a title band above and the
 * figures below); the fonts scale with the picture: at 1920x1080 the figures are 28 px
 * and the titles 34 px, readable from the back of a room on a projector.
 *
 * Synchronised views: the images share one vtkCamera (zooming into one zooms into the same
 * place of all four), and so do the tree views (turning one turns all four).
 */
class ComparisonView {
 public:
  explicit ComparisonView(const ComparisonResult& result,
                          const ComparisonViewOptions& options = {});
  ~ComparisonView();
  ComparisonView(const ComparisonView&) = delete;
  ComparisonView& operator=(const ComparisonView&) = delete;

  /// Shows another comparison (the tree views are removed).
  void setResult(const ComparisonResult& result);
  const ComparisonResult& result() const;
  void setOptions(const ComparisonViewOptions& options);
  const ComparisonViewOptions& options() const;
  /// Number of panels: one per algorithm of the result.
  int panelCount() const;

  /**
   * \brief Shows beside each image the ray tree of the same pixel: `trees[i]` in panel i
   * (recorded for result().algorithms[i].algorithm), drawn in a 3D view of `scene` with
   * `style` (one energy scale for all four). The views share one camera, set to the scene's
   * default view. Throws std::invalid_argument when the tree count is not panelCount().
   * `pixel` (x, y) is marked on each image.
   */
  void setRayTrees(const Scene& scene, const std::vector<RayTree>& trees, int pixelX, int pixelY,
                   const RayTreeStyle& style = {});
  /// Removes the tree views.
  void clearRayTrees();
  /// True when the panels show ray trees.
  bool hasRayTrees() const;

  /// Places every renderer for a window of width x height pixels (viewports, text
  /// positions and sizes). Call it before rendering and whenever the window is resized.
  void layout(int width, int height);
  /// Every renderer of the picture in drawing order, for a window to add (at most one
  /// window at a time): the header (when shown), then per panel its background, title
  /// band, image and tree view (when shown), then the explanation band (when shown).
  /// Valid until setResult / setOptions / setRayTrees / clearRayTrees.
  std::vector<vtkRenderer*> renderers() const;
  /// Where panel `panel` lies in a width x height picture; its title band is at its top.
  PixelRect panelRect(int panel, int width, int height) const;
  /// Where panel `panel`'s title band (in the algorithm's colour) lies.
  PixelRect titleRect(int panel, int width, int height) const;
  /// Where panel `panel`'s image lies in a width x height picture.
  PixelRect imageRect(int panel, int width, int height) const;
  /// Where panel `panel`'s ray-tree view lies (width 0 without trees).
  PixelRect treeRect(int panel, int width, int height) const;
  /// The title and figure lines drawn in panel `panel` (what the text actors show).
  std::vector<std::string> panelText(int panel) const;
  /// The header line (empty when options().showHeader is false).
  std::string headerText() const;
  /// The explanation band's lines (empty when options().showExplanation is false).
  std::vector<std::string> explanationText() const;
  /// The size in points of the figures text at the last layout.
  int figuresFontSize() const;

  /**
   * \brief Renders the picture offscreen into a width x height image, in this view's own
   * vtkRenderWindow (no multisampling, so pictures are repeatable). Needs an X server
   * (Debian's VTK, use xvfb-run). Must not be called while a window shows the renderers.
   */
  SrgbImage renderOffscreen(int width, int height);
  /// renderOffscreen, then vis::writePng (throws vis::ImageError naming the file).
  void renderToPng(const std::string& path, int width, int height);

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace raylab::vis
