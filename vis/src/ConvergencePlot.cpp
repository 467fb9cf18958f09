#include "raylab/vis/ConvergencePlot.h"

#include "TextFonts.h"
#include "VtkImage.h"

#include "raylab/core/Check.h"
#include "raylab/core/Phrases.h"
#include "raylab/vis/ComparisonCaptions.h"
#include "raylab/vis/ComparisonView.h"
#include "raylab/vis/Display.h"
#include "raylab/vis/ImageIO.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace raylab::vis {

namespace {

/// Colour of the 1 / sqrt(N) guide and of the axes' text.
constexpr unsigned char kGuide[3] = {110, 110, 110};

/// A two-column table (x, y) whose y column is named `label`.
vtkSmartPointer<vtkTable> makeTable(const std::string& label, const std::vector<double>& x,
                                    const std::vector<double>& y) {
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkDoubleArray> xs;
  xs->SetName("x");
  vtkNew<vtkDoubleArray> ys;
  ys->SetName(label.c_str());
  table->AddColumn(xs);
  table->AddColumn(ys);
  table->SetNumberOfRows(vtkIdType(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    table->SetValue(vtkIdType(i), 0, x[i]);
    table->SetValue(vtkIdType(i), 1, y[i]);
  }
  return table;
}

/// Where a point lies on the horizontal axis: its samples per pixel or its seconds.
double across(const ConvergencePoint& point, bool samples) {
  return samples ? double(point.samplesPerPixel) : point.seconds;
}

/// The extent of the plotted data, grown point by point.
struct Extent {
  double xMin = HUGE_VAL, xMax = 0.0, yMin = HUGE_VAL, yMax = 0.0;

  void add(double x, double y) {
    xMin = std::min(xMin, x);
    xMax = std::max(xMax, x);
    yMin = std::min(yMin, y);
    yMax = std::max(yMax, y);
  }
};

/// One algorithm's curve, drawn in its colour, of the points (x, y); its table, to be kept
/// alive with the plot.
vtkSmartPointer<vtkTable> addCurve(vtkChartXY* chart, Algorithm algorithm,
                                   const std::vector<double>& x, const std::vector<double>& y,
                                   Language language) {
  auto table = makeTable(algorithmTitle(algorithm, language), x, y);
  vtkPlot* line = chart->AddPlot(vtkChart::LINE);
  line->SetInputData(table, 0, 1);
  const Rgb8 colour = algorithmColour(algorithm);
  line->SetColor(colour[0], colour[1], colour[2], 255);
  // Curves can coincide (ray casting and Whitted in a scene without mirrors or glass):
  // earlier algorithms are drawn wider, with larger markers of another shape, so the
  // one beneath still shows around the one on top.
  const int order = static_cast<int>(algorithm);  // 0 = ray casting .. 3 = path
  line->SetWidth(3.0 + 1.25 * (3 - order));
  if (auto* points = vtkPlotPoints::SafeDownCast(line)) {
    static const int kMarkers[4] = {vtkPlotPoints::SQUARE, vtkPlotPoints::DIAMOND,
                                    vtkPlotPoints::CIRCLE, vtkPlotPoints::CIRCLE};
    points->SetMarkerStyle(kMarkers[order]);
    points->SetMarkerSize(9.0 + 1.5 * (3 - order));
  }
  return table;
}

/// The Monte Carlo guide, error ~ 1 / sqrt(N), from path tracing's first plotted point to
/// the right end of the data (whose extent it widens downwards); its table, or null when
/// that point is already the rightmost.
vtkSmartPointer<vtkTable> addGuide(vtkChartXY* chart, const AlgorithmFigures& path, bool samples,
                                   Extent& extent) {
  const ConvergencePoint* first = nullptr;
  for (const ConvergencePoint& point : path.series)
    if (across(point, samples) > 0.0 && point.rmse > 0.0) {
      first = &point;
      break;
    }
  const double x0 = across(*first, samples);
  if (!(extent.xMax > x0)) return nullptr;
  std::vector<double> x, y;
  for (int i = 0; i <= 16; ++i) {
    const double xi = x0 * std::pow(extent.xMax / x0, i / 16.0);
    x.push_back(xi);
    y.push_back(first->rmse * std::sqrt(x0 / xi));
  }
  auto table = makeTable(samples ? "1 / sqrt(spp)" : "1 / sqrt(time)", x, y);
  vtkPlot* guide = chart->AddPlot(vtkChart::LINE);
  guide->SetInputData(table, 0, 1);
  guide->SetColor(kGuide[0], kGuide[1], kGuide[2], 255);
  guide->SetWidth(2.0);
  guide->GetPen()->SetLineType(vtkPen::DASH_LINE);
  if (auto* points = vtkPlotPoints::SafeDownCast(guide))
    points->SetMarkerStyle(vtkPlotPoints::NONE);
  extent.yMin = std::min(extent.yMin, y.back());
  return table;
}

/// Log-log axes a little wider than the data (whole decades when they fit), with their
/// titles.
void setAxes(vtkChartXY* chart, bool samples, const Extent& extent, Language language) {
  vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* left = chart->GetAxis(vtkAxis::LEFT);
  bottom->SetTitle(phrase(samples ? "plot.axis.samples" : "plot.axis.time", language));
  left->SetTitle(phrase("plot.axis.error", language));
  for (vtkAxis* axis : {bottom, left}) {
    axis->SetLogScale(true);
    axis->SetGridVisible(true);
  }
  if (extent.xMax > 0.0) {
    bottom->SetBehavior(vtkAxis::FIXED);
    bottom->SetUnscaledRange(extent.xMin / 1.3, extent.xMax * 1.3);
    left->SetBehavior(vtkAxis::FIXED);
    left->SetUnscaledRange(extent.yMin / 1.5, extent.yMax * 1.5);
  }
}

/// The title (the scene, the picture size, the budget), every text in the language's font,
/// and the legend at the bottom left. Against time, the plot compares the algorithms at
/// equal time (read it along a vertical line), whatever budget the passes were run at.
void setTitleAndLegend(vtkChartXY* chart, const ComparisonResult& result, ConvergenceAxis across,
                       Language language) {
  const bool equalTime = across == ConvergenceAxis::Time || result.compare.equalTime();
  const LocalText sceneName{result.sceneName,
                            result.sceneNameZh.empty() ? result.sceneName : result.sceneNameZh};
  const std::string& name = sceneName.in(language);
  chart->SetTitle(phrase(
      name.empty() ? "plot.title" : "plot.title.named", language,
      {{"scene", name},
       {"size", std::to_string(result.width) + "x" + std::to_string(result.height)},
       {"budget",
        phrase(equalTime ? "plot.budget.equal_time" : "plot.budget.equal_samples", language)}}));
  useFontFor(chart->GetTitleProperties(), language);
  for (vtkAxis* axis : {chart->GetAxis(vtkAxis::BOTTOM), chart->GetAxis(vtkAxis::LEFT)}) {
    useFontFor(axis->GetTitleProperties(), language);
    useFontFor(axis->GetLabelProperties(), language);
  }
  useFontFor(chart->GetLegend()->GetLabelProperties(), language);
  chart->SetShowLegend(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::LEFT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::BOTTOM);
}

}  // namespace

const char* toString(ConvergenceAxis axis) {
  return axis == ConvergenceAxis::Samples ? "samples" : "time";
}

struct ConvergencePlot::Impl {
  vtkNew<vtkContextView> view;
  vtkNew<vtkChartXY> chart;
  std::vector<vtkSmartPointer<vtkTable>> tables;  ///< Kept alive with their plots.
  std::vector<int> counts;
  bool offscreen = false;

  ~Impl() {
    if (offscreen) view->GetRenderWindow()->Finalize();
  }
};

ConvergencePlot::ConvergencePlot(const ComparisonResult& result, ConvergenceAxis axis,
                                 Language language)
    : m_impl(std::make_unique<Impl>()), m_result(result), m_axis(axis), m_language(language) {
  m_impl->view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  m_impl->view->GetScene()->AddItem(m_impl->chart);
  build();
}

ConvergencePlot::~ConvergencePlot() = default;

void ConvergencePlot::setResult(const ComparisonResult& result) {
  m_result = result;
  build();
}

std::string ConvergencePlot::title() const { return m_impl->chart->GetTitle(); }

void ConvergencePlot::setAxis(ConvergenceAxis axis) {
  m_axis = axis;
  build();
}

void ConvergencePlot::setLanguage(Language language) {
  m_language = language;
  build();
}

std::vector<int> ConvergencePlot::pointCounts() const { return m_impl->counts; }

vtkRenderer* ConvergencePlot::renderer() const { return m_impl->view->GetRenderer(); }

void ConvergencePlot::build() {
  vtkChartXY* chart = m_impl->chart;
  chart->ClearPlots();
  m_impl->tables.clear();
  m_impl->counts.clear();
  const bool samples = m_axis == ConvergenceAxis::Samples;

  // Step 1: one curve per algorithm, its points where the error can go on a log axis.
  Extent extent;
  const AlgorithmFigures* path = nullptr;
  for (const AlgorithmFigures& figures : m_result.algorithms) {
    std::vector<double> x, y;
    for (const ConvergencePoint& point : figures.series) {
      if (!(across(point, samples) > 0.0) || !(point.rmse > 0.0)) continue;
      x.push_back(across(point, samples));
      y.push_back(point.rmse);
      extent.add(x.back(), y.back());
    }
    m_impl->counts.push_back(int(x.size()));
    if (x.empty()) continue;
    if (figures.algorithm == Algorithm::PathTracing) path = &figures;
    m_impl->tables.push_back(addCurve(chart, figures.algorithm, x, y, m_language));
  }

  // Step 2: the Monte Carlo guide, error ~ 1 / sqrt(N), through path tracing's first point.
  if (path != nullptr)
    if (auto table = addGuide(chart, *path, samples, extent)) m_impl->tables.push_back(table);

  // Step 3: the axes, the title and the legend.
  setAxes(chart, samples, extent, m_language);
  setTitleAndLegend(chart, m_result, m_axis, m_language);
}

void ConvergencePlot::layout(int width, int height) {
  RAYLAB_CHECK(width > 0 && height > 0);
  const int base = std::clamp(int(std::lround(std::min(width, height) / 36.0)), 9, 32);
  vtkChartXY* chart = m_impl->chart;
  // The title names the scene, which can be long: shrink it to fit the width (a bold
  // glyph of this font is about 0.62 of its size wide).
  const double titleChars = std::max<double>(1.0, double(chart->GetTitle().size()));
  const double titleFit = 0.95 * width / (0.62 * titleChars);
  chart->GetTitleProperties()->SetFontSize(
      std::max(8, int(std::min(base * 1.25, std::floor(titleFit)))));
  chart->GetTitleProperties()->SetBold(true);
  for (int a : {vtkAxis::BOTTOM, vtkAxis::LEFT}) {
    vtkAxis* axis = chart->GetAxis(a);
    axis->GetTitleProperties()->SetFontSize(base);
    axis->GetTitleProperties()->SetBold(false);
    axis->GetLabelProperties()->SetFontSize(int(std::lround(base * 0.85)));
  }
  chart->GetLegend()->SetLabelSize(base);
}

SrgbImage ConvergencePlot::renderOffscreen(int width, int height) {
  RAYLAB_CHECK(width > 0 && height > 0);
  requireDisplay();
  vtkRenderWindow* window = m_impl->view->GetRenderWindow();
  if (!m_impl->offscreen) {
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    m_impl->offscreen = true;
  }
  window->SetSize(width, height);
  layout(width, height);
  m_impl->view->Render();

  return detail::grabWindow(window, width, height);
}

void ConvergencePlot::renderToPng(const std::string& path, int width, int height) {
  writePng(renderOffscreen(width, height), path);
}

}  // namespace raylab::vis
