#pragma once

#include "raylab/core/Comparison.h"
#include "raylab/core/Language.h"
#include "raylab/vis/Image.h"

#include <memory>
#include <string>

class vtkRenderer;

namespace raylab::vis {

/// What the convergence plot puts across.
enum class ConvergenceAxis {
  Samples,  ///< Samples per pixel: the estimator's convergence.
  Time,     ///< Seconds: what a sample costs (the fair race).
};
/// "samples", "time".
const char* toString(ConvergenceAxis axis);

/**
 * \brief The convergence plot of a comparison: error against the path-traced reference
 * (displayRmse) against samples per pixel or seconds, log-log, one curve per algorithm in
 * its colour (algorithmColour), drawn with VTK's charts (vtkChartXY, log axes).
 *
 * Monte Carlo error falls as 1 / sqrt(N): a straight line of slope -1/2 on log-log axes,
 * drawn as a dashed guide through path tracing's first point. Ray casting and Whitted
 * level off: their error is bias, not noise. Points with no error (0, not drawable on a
 * log axis) are left out.
 */
class ConvergencePlot {
 public:
  /// A plot of `result`; `language` is that of its words (title, axes, legend; Chinese
  /// drawn with a CJK font when one is installed).
  explicit ConvergencePlot(const ComparisonResult& result,
                           ConvergenceAxis axis = ConvergenceAxis::Samples,
                           Language language = Language::English);
  ~ConvergencePlot();
  ConvergencePlot(const ConvergencePlot&) = delete;
  ConvergencePlot& operator=(const ConvergencePlot&) = delete;

  void setResult(const ComparisonResult& result);
  void setAxis(ConvergenceAxis axis);
  ConvergenceAxis axis() const { return m_axis; }
  void setLanguage(Language language);
  Language language() const { return m_language; }
  /// The title drawn over the plot: the scene, the picture size and the budget read
  /// across (equal samples, or equal time when the axis is time).
  std::string title() const;
  /// Number of points drawn for each algorithm, in the result's order.
  std::vector<int> pointCounts() const;

  /// The chart's renderer, for a window to show (at most one window at a time).
  vtkRenderer* renderer() const;
  /// Font sizes for a picture of width x height pixels (call when a window resizes).
  void layout(int width, int height);
  /// Renders the plot offscreen (own window, no multisampling; needs an X server).
  SrgbImage renderOffscreen(int width, int height);
  /// renderOffscreen, then vis::writePng (throws vis::ImageError naming the file).
  void renderToPng(const std::string& path, int width, int height);

 private:
  void build();
  struct Impl;
  std::unique_ptr<Impl> m_impl;
  ComparisonResult m_result;
  ConvergenceAxis m_axis;
  Language m_language;
};

}  // namespace raylab::vis
