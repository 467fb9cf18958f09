#include "raylab/vis/ComparisonView.h"

#include "raylab/vis/ComparisonCaptions.h"
#include "raylab/vis/Display.h"

#include "ComparisonLayout.h"
#include "TextFonts.h"

#include "VtkImage.h"

#include "raylab/core/Check.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/SceneView.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageMapper3D.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace raylab::vis {

namespace {

/// Background of the panels (the 3D view's dark slate) and of the header band.
constexpr double kPanelBackground[3] = {0.12, 0.13, 0.16};
constexpr double kHeaderBackground[3] = {0.06, 0.07, 0.09};
/// Colour of the figures and header text.
constexpr double kTextColour[3] = {0.93, 0.93, 0.93};
/// Colour of the mark around the traced pixel.
constexpr double kPixelMark[3] = {1.0, 0.9, 0.0};
/// Colour of the explanation under the panels (a little softer than the figures).
constexpr double kExplanationColour[3] = {0.80, 0.82, 0.86};
/// Font sizes at 1920x1080 in pixels, scaled with the picture: the figures and the
/// explanation readable from the back of a classroom on a projector.
constexpr double kFiguresFontAt1080 = 28.0;
constexpr double kExplanationFontAt1080 = 24.0;

double channel(std::uint8_t value) { return value / 255.0; }

/// Black or white, whichever reads better on `background` (Rec. 709 luminance of sRGB).
bool darkTextOn(const Rgb8& background) {
  const Vec3 colour(channel(background[0]), channel(background[1]), channel(background[2]));
  return luminance(colour) > 0.45;
}

/// Viewport of `rect` (pixels, y down) in a width x height window (normalised, y up).
void setViewport(vtkRenderer* renderer, const PixelRect& rect, int width, int height) {
  renderer->SetViewport(double(rect.x) / width, double(height - rect.y - rect.height) / height,
                        double(rect.x + rect.width) / width, double(height - rect.y) / height);
}

/// Width and height in pixels of `text` drawn with `property` (72 dpi: 1 point = 1 pixel).
std::pair<int, int> textSize(vtkTextProperty* property, const std::string& text) {
  vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
  RAYLAB_CHECK(renderer != nullptr);
  int box[4] = {0, 0, 0, 0};
  if (!renderer->GetBoundingBox(property, text, box, 72)) return {0, 0};
  return {box[1] - box[0] + 1, box[3] - box[2] + 1};
}

void styleText(vtkTextProperty* p, int size, const double colour[3], bool bold,
               Language language = Language::English) {
  useFontFor(p, language);
  p->SetFontSize(size);
  p->SetColor(colour[0], colour[1], colour[2]);
  p->SetBold(bold);
  p->SetJustificationToLeft();
  p->SetVerticalJustificationToTop();
  p->SetLineSpacing(1.15);
  p->ShadowOff();
}

/// `line` cut into pieces no wider than `width` pixels in `property`'s font: between words,
/// and between any two Chinese characters (which have no spaces between them), never
/// inside a word.
std::vector<std::string> wrapToWidth(vtkTextProperty* property, const std::string& line,
                                     int width) {
  // The pieces that may not be split: a word with its following space, or one character
  // of three or four UTF-8 bytes (CJK) with the punctuation after it.
  std::vector<std::string> tokens;
  for (std::size_t i = 0; i < line.size();) {
    const unsigned char lead = static_cast<unsigned char>(line[i]);
    std::size_t end = i;
    if (lead >= 0xE0) {
      end = i + (lead >= 0xF0 ? 4 : 3);
    } else {
      while (end < line.size() && line[end] != ' ' && static_cast<unsigned char>(line[end]) < 0xE0)
        ++end;
      while (end < line.size() && line[end] == ' ') ++end;
    }
    tokens.push_back(line.substr(i, std::max(end, i + 1) - i));
    i = std::max(end, i + 1);
  }
  std::vector<std::string> out;
  std::string current;
  for (const std::string& token : tokens) {
    const std::string candidate = current + token;
    std::string trimmed = candidate;
    while (!trimmed.empty() && trimmed.back() == ' ') trimmed.pop_back();
    if (!current.empty() && textSize(property, trimmed).first > width) {
      while (!current.empty() && current.back() == ' ') current.pop_back();
      out.push_back(current);
      current = token;
    } else {
      current = candidate;
    }
  }
  while (!current.empty() && current.back() == ' ') current.pop_back();
  if (!current.empty()) out.push_back(current);
  return out;
}

std::string joinLines(const std::vector<std::string>& lines) {
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) text += (i ? "\n" : "") + lines[i];
  return text;
}

/// A square outline around image pixel (x, y) (row 0 at the top) of an image `height`
/// pixels high, in the image actor's world coordinates (pixel centres at integers, row 0
/// of VTK at the bottom), a little in front of the image.
vtkSmartPointer<vtkPolyData> pixelMark(int x, int y, int height) {
  const double cx = x;
  const double cy = height - 1 - y;
  const double r = 1.5;  // pixels: the mark surrounds the pixel with a one-pixel gap
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(cx - r, cy - r, 1.0);
  points->InsertNextPoint(cx + r, cy - r, 1.0);
  points->InsertNextPoint(cx + r, cy + r, 1.0);
  points->InsertNextPoint(cx - r, cy + r, 1.0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType loop[5] = {0, 1, 2, 3, 0};
  lines->InsertNextCell(5, loop);
  auto mark = vtkSmartPointer<vtkPolyData>::New();
  mark->SetPoints(points);
  mark->SetLines(lines);
  return mark;
}

}  // namespace

Rgb8 algorithmColour(Algorithm algorithm) {
  const auto& colour = algorithmInfo(algorithm).colour;
  return {colour[0], colour[1], colour[2]};
}

std::string ComparisonViewOptions::toString() const {
  return "ComparisonViewOptions[columns=" + std::to_string(columns) +
         ", showTimes=" + (showTimes ? "on" : "off") +
         ", showHeader=" + (showHeader ? "on" : "off") +
         ", showExplanation=" + (showExplanation ? "on" : "off") +
         ", language=" + raylab::toString(language) +
         ", minimumFont=" + std::to_string(minimumFont) + "]";
}

/// One algorithm's panel: its renderers and actors.
struct Panel {
  vtkNew<vtkRenderer> background;  ///< The whole panel; holds the figures text.
  vtkNew<vtkRenderer> title;       ///< The title band in the algorithm's colour.
  vtkNew<vtkRenderer> image;       ///< The image, exactly its aspect ratio.
  vtkNew<vtkTextActor> titleText;
  vtkNew<vtkTextActor> figuresText;
  vtkNew<vtkImageActor> imageActor;
  vtkNew<vtkActor> mark;                    ///< The traced pixel (hidden without trees).
  std::unique_ptr<SceneView> tree;          ///< The 3D view of the pixel's tree, when shown.
  std::vector<std::string> lines;           ///< Title, then the figures.
  std::string titleTwoLines;                ///< Name, then citation (side layout).
  double titleColour[3] = {1.0, 1.0, 1.0};  ///< Black or white on the band.
  PixelRect panelRect, titleRect, imageRect, treeRect;  ///< From the last layout.
};

struct ComparisonView::Impl {
  ComparisonResult result;
  ComparisonViewOptions options;
  std::vector<std::unique_ptr<Panel>> panels;
  vtkNew<vtkRenderer> header;
  vtkNew<vtkTextActor> headerText;
  vtkNew<vtkRenderer> footer;  ///< The explanation band under the panels.
  vtkNew<vtkTextActor> footerText;
  int figuresFont = 0;  ///< From the last layout.
  vtkSmartPointer<vtkRenderWindow> offscreen;
  int layoutWidth = 0, layoutHeight = 0;

  ~Impl() {
    if (offscreen) {
      offscreen->GetRenderers()->RemoveAllItems();
      offscreen->Finalize();
    }
  }

  void build();
  /// The header band's text, empty when it is hidden.
  std::string headerCaption() const {
    return options.showHeader ? headerLine(result, options.language) : std::string();
  }
  std::vector<std::string> explanation() const {
    return options.showExplanation ? errorExplanation(result, options.language)
                                   : std::vector<std::string>();
  }
  void layoutPanel(Panel& panel, const PixelRect& rect, int width, int height, int font);
  /// Lays out a band of text across the window (the header, the explanation): the font
  /// `size`, smaller while the text is wider than the window (and wrapped when it still is
  /// at 8 pixels), or (`wrap`) the lines wrapped to the window's width (the font smaller
  /// only past four lines); returns the band's height.
  int layoutBand(vtkRenderer* band, vtkTextActor* text, const std::vector<std::string>& lines,
                 int size, const double colour[3], int y, int width, int height, bool top,
                 bool wrap) const;
  /// Takes every renderer out of the offscreen window (before renderers change).
  void detach();
  /// Panel `panel` laid out for a width x height picture.
  const Panel& laidOut(int panel, int width, int height);
  ComparisonView* owner = nullptr;
};

void ComparisonView::Impl::detach() {
  if (!offscreen) return;
  vtkRendererCollection* renderers = offscreen->GetRenderers();
  while (renderers->GetNumberOfItems() > 0)
    offscreen->RemoveRenderer(vtkRenderer::SafeDownCast(renderers->GetItemAsObject(0)));
}

void ComparisonView::Impl::layoutPanel(Panel& panel, const PixelRect& rect, int width, int height,
                                       int font) {
  // The rectangles, from the panel's size and the largest measured text of all panels.
  const Language language = options.language;
  vtkTextProperty* figures = panel.figuresText->GetTextProperty();
  const auto measure = [&](int size) {
    styleText(figures, size, kTextColour, false, language);
    std::pair<int, int> largest{0, 0};
    for (const auto& other : panels) {
      const char* text = other->figuresText->GetInput();
      const auto [w, h] = textSize(figures, text ? text : "");
      largest = {std::max(largest.first, w), std::max(largest.second, h)};
    }
    return largest;
  };
  vtkTextProperty* title = panel.titleText->GetTextProperty();
  const auto measureTitle = [&](int size, bool twoLines) {
    styleText(title, size, panel.titleColour, true, language);
    std::pair<int, int> largest{0, 0};
    for (const auto& other : panels) {
      const auto [w, h] = textSize(title, twoLines ? other->titleTwoLines : other->lines.front());
      largest = {std::max(largest.first, w), std::max(largest.second, h)};
    }
    return largest;
  };
  const bool trees = panel.tree != nullptr;
  const PanelLayout laid = layoutComparisonPanel(rect, result.width, result.height, trees, font,
                                                 measure, measureTitle, options.minimumFont);
  figuresFont = laid.figuresFont;

  // Viewports and text, in VTK's coordinates.
  panel.panelRect = rect;
  panel.titleRect = laid.titleRect;
  panel.imageRect = laid.imageRect;
  panel.treeRect = laid.treeRect;
  setViewport(panel.background, rect, width, height);
  setViewport(panel.title, laid.titleRect, width, height);
  setViewport(panel.image, panel.imageRect, width, height);
  if (trees) setViewport(panel.tree->renderer(), panel.treeRect, width, height);
  styleText(figures, laid.figuresFont, kTextColour, false, language);
  panel.figuresText->SetPosition(laid.textX - rect.x, rect.height - (laid.textY - rect.y));
  styleText(title, laid.titleFont, panel.titleColour, true, language);
  title->SetVerticalJustificationToCentered();
  panel.titleText->SetInput(laid.side ? panel.titleTwoLines.c_str() : panel.lines.front().c_str());
  panel.titleText->SetPosition(std::max(3, int(std::lround(laid.titleFont * 0.3))),
                               laid.titleRect.height / 2.0);
}

int ComparisonView::Impl::layoutBand(vtkRenderer* band, vtkTextActor* text,
                                     const std::vector<std::string>& lines, int size,
                                     const double colour[3], int y, int width, int height, bool top,
                                     bool wrap) const {
  const int margin = std::max(4, width / 100);
  vtkTextProperty* p = text->GetTextProperty();
  std::vector<std::string> shown;
  const int smallest = std::max(8, options.minimumFont);
  for (size = std::max(smallest, size);; --size) {
    styleText(p, size, colour, false, options.language);
    shown.clear();
    for (const std::string& line : lines) {
      if (!wrap) {
        shown.push_back(line);
        continue;
      }
      for (const std::string& piece : wrapToWidth(p, line, width - 2 * margin))
        shown.push_back(piece);
    }
    const std::string caption = joinLines(shown);
    if (size <= smallest) break;
    if (wrap ? shown.size() <= 4 : textSize(p, caption).first <= width - 2 * margin) break;
  }
  // Still too wide at the smallest font (a narrow window): wrapped rather than cut off.
  if (!wrap && textSize(p, joinLines(shown)).first > width - 2 * margin) {
    shown.clear();
    for (const std::string& line : lines)
      for (const std::string& piece : wrapToWidth(p, line, width - 2 * margin))
        shown.push_back(piece);
  }
  text->SetInput(joinLines(shown).c_str());
  p->SetVerticalJustificationToCentered();
  const int count = int(shown.size());
  const int bandHeight = int(std::lround(size * (count <= 1 ? 1.9 : 1.3 * count + 0.7)));
  setViewport(band, {0, top ? y : y - bandHeight, width, bandHeight}, width, height);
  text->SetPosition(margin, bandHeight / 2.0);
  return bandHeight;
}

void ComparisonView::Impl::build() {
  panels.clear();
  header->RemoveAllViewProps();
  header->SetBackground(kHeaderBackground[0], kHeaderBackground[1], kHeaderBackground[2]);
  header->AddViewProp(headerText);
  headerText->SetInput(headerCaption().c_str());
  footer->RemoveAllViewProps();
  footer->SetBackground(kHeaderBackground[0], kHeaderBackground[1], kHeaderBackground[2]);
  footer->AddViewProp(footerText);
  footerText->SetInput(joinLines(explanation()).c_str());
  for (const AlgorithmFigures& figures : result.algorithms) {
    auto panel = std::make_unique<Panel>();
    panel->background->SetBackground(kPanelBackground[0], kPanelBackground[1], kPanelBackground[2]);
    panel->background->AddViewProp(panel->figuresText);

    // The title band: the algorithm's colour, its name in black or white on it.
    const Rgb8 colour = algorithmColour(figures.algorithm);
    panel->title->SetBackground(channel(colour[0]), channel(colour[1]), channel(colour[2]));
    panel->title->AddViewProp(panel->titleText);
    const double ink = darkTextOn(colour) ? 0.0 : 1.0;
    std::fill(std::begin(panel->titleColour), std::end(panel->titleColour), ink);
    panel->lines = {algorithmTitle(figures.algorithm, options.language)};
    for (const std::string& line :
         figureLines(result, figures, options.showTimes, options.language))
      panel->lines.push_back(line);
    // Whitted's name is already the title: the year alone under it.
    panel->titleTwoLines = algorithmTitleTwoLines(figures.algorithm, options.language);
    panel->titleText->SetInput(panel->lines.front().c_str());
    panel->figuresText->SetInput(joinLines({panel->lines.begin() + 1, panel->lines.end()}).c_str());

    // The image: sRGB bytes on a slice seen by a parallel camera that frames it exactly.
    panel->imageActor->SetInputData(detail::toVtkImage(imageio::toSrgb(figures.image)));
    panel->imageActor->InterpolateOff();         // show the pixels: the noise is the lesson
    panel->imageActor->GetMapper()->BorderOn();  // cover whole pixels up to the edge
    panel->image->SetBackground(0.0, 0.0, 0.0);
    panel->image->AddViewProp(panel->imageActor);
    // One camera for the four images (all of the same size): zooming into one zooms into
    // the same place of all of them.
    if (!panels.empty()) panel->image->SetActiveCamera(panels.front()->image->GetActiveCamera());
    vtkCamera* camera = panel->image->GetActiveCamera();
    const double w = figures.image.width, h = figures.image.height;
    camera->ParallelProjectionOn();
    camera->SetFocalPoint((w - 1.0) / 2.0, (h - 1.0) / 2.0, 0.0);
    camera->SetPosition((w - 1.0) / 2.0, (h - 1.0) / 2.0, 10.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(h / 2.0);
    camera->SetClippingRange(1.0, 20.0);

    vtkNew<vtkPolyDataMapper> markMapper;
    panel->mark->SetMapper(markMapper);
    panel->mark->GetProperty()->SetColor(kPixelMark[0], kPixelMark[1], kPixelMark[2]);
    panel->mark->GetProperty()->SetLineWidth(3.0);
    panel->mark->GetProperty()->LightingOff();
    panel->mark->VisibilityOff();
    panel->image->AddViewProp(panel->mark);
    panels.push_back(std::move(panel));
  }
}

}  // namespace raylab::vis

namespace raylab::vis {

ComparisonView::ComparisonView(const ComparisonResult& result, const ComparisonViewOptions& options)
    : m_impl(std::make_unique<Impl>()) {
  m_impl->owner = this;
  m_impl->options = options;
  setResult(result);
}

ComparisonView::~ComparisonView() = default;

void ComparisonView::setResult(const ComparisonResult& result) {
  m_impl->detach();
  m_impl->result = result;
  m_impl->build();
}

const ComparisonResult& ComparisonView::result() const { return m_impl->result; }

void ComparisonView::setOptions(const ComparisonViewOptions& options) {
  m_impl->detach();
  m_impl->options = options;
  m_impl->build();
}

const ComparisonViewOptions& ComparisonView::options() const { return m_impl->options; }

int ComparisonView::panelCount() const { return int(m_impl->panels.size()); }

void ComparisonView::layout(int width, int height) {
  RAYLAB_CHECK(width > 0 && height > 0);
  Impl& d = *m_impl;
  d.layoutWidth = width;
  d.layoutHeight = height;

  // Step 1: the header band across the top and the explanation band across the bottom,
  // their text as large as fits the width; the fonts follow the picture's size.
  const double unit = std::min(width / 1920.0, height / 1080.0);
  int headerHeight = 0, footerHeight = 0;
  if (d.options.showHeader) {
    const int size = std::clamp(int(std::lround(std::min(width / 55.0, height / 28.0))), 9, 40);
    headerHeight = d.layoutBand(d.header, d.headerText, {d.headerCaption()}, size, kTextColour, 0,
                                width, height, true, false);
  }
  const std::vector<std::string> explanation = d.explanation();
  if (!explanation.empty()) {
    const int size = int(std::lround(kExplanationFontAt1080 * unit));
    footerHeight = d.layoutBand(d.footer, d.footerText, explanation, size, kExplanationColour,
                                height, width, height, false, true);
  }

  // Step 2: the panels in a grid of `columns` across, row by row, between the bands.
  const int count = panelCount();
  if (count == 0) return;
  const int columns = std::clamp(d.options.columns, 1, count);
  const int rows = (count + columns - 1) / columns;
  const int below = height - headerHeight - footerHeight;
  const int font = int(std::lround(kFiguresFontAt1080 * unit));
  for (int i = 0; i < count; ++i) {
    const int r = i / columns, c = i % columns;
    const int x0 = c * width / columns, x1 = (c + 1) * width / columns;
    const int y0 = headerHeight + r * below / rows, y1 = headerHeight + (r + 1) * below / rows;
    d.layoutPanel(*d.panels[std::size_t(i)], {x0, y0, x1 - x0, y1 - y0}, width, height, font);
  }

  // Step 3: the shared camera of the tree views sees the whole scene.
  if (hasRayTrees()) d.panels.front()->tree->renderer()->ResetCameraClippingRange();
}

std::vector<vtkRenderer*> ComparisonView::renderers() const {
  std::vector<vtkRenderer*> out;
  if (m_impl->options.showHeader) out.push_back(m_impl->header);
  for (const auto& panel : m_impl->panels) {
    out.push_back(panel->background);
    out.push_back(panel->title);
    out.push_back(panel->image);
    if (panel->tree) out.push_back(panel->tree->renderer());
  }
  if (!m_impl->explanation().empty()) out.push_back(m_impl->footer);
  return out;
}

const Panel& ComparisonView::Impl::laidOut(int panel, int width, int height) {
  RAYLAB_CHECK(panel >= 0 && panel < int(panels.size()));
  if (layoutWidth != width || layoutHeight != height) owner->layout(width, height);
  return *panels[std::size_t(panel)];
}

PixelRect ComparisonView::panelRect(int panel, int width, int height) const {
  return m_impl->laidOut(panel, width, height).panelRect;
}

PixelRect ComparisonView::titleRect(int panel, int width, int height) const {
  return m_impl->laidOut(panel, width, height).titleRect;
}

PixelRect ComparisonView::imageRect(int panel, int width, int height) const {
  return m_impl->laidOut(panel, width, height).imageRect;
}

PixelRect ComparisonView::treeRect(int panel, int width, int height) const {
  const Panel& laid = m_impl->laidOut(panel, width, height);
  return laid.tree ? laid.treeRect : PixelRect{laid.treeRect.x, laid.treeRect.y, 0, 0};
}

std::vector<std::string> ComparisonView::panelText(int panel) const {
  RAYLAB_CHECK(panel >= 0 && panel < panelCount());
  return m_impl->panels[std::size_t(panel)]->lines;
}

std::string ComparisonView::headerText() const { return m_impl->headerCaption(); }

std::vector<std::string> ComparisonView::explanationText() const { return m_impl->explanation(); }

int ComparisonView::figuresFontSize() const { return m_impl->figuresFont; }

void ComparisonView::setRayTrees(const Scene& scene, const std::vector<RayTree>& trees, int pixelX,
                                 int pixelY, const RayTreeStyle& style) {
  if (int(trees.size()) != panelCount())
    throw std::invalid_argument("ComparisonView::setRayTrees: " + std::to_string(trees.size()) +
                                " trees for " + std::to_string(panelCount()) + " panels");
  Impl& d = *m_impl;
  d.detach();
  vtkCamera* shared = nullptr;
  for (std::size_t i = 0; i < trees.size(); ++i) {
    Panel& panel = *d.panels[i];
    panel.tree = std::make_unique<SceneView>(scene);
    panel.tree->setRayTree(trees[i], style);
    // One camera for the four views: turning one turns them all.
    if (shared == nullptr)
      shared = panel.tree->renderer()->GetActiveCamera();
    else
      panel.tree->renderer()->SetActiveCamera(shared);
    panel.mark->GetMapper()->SetInputDataObject(pixelMark(pixelX, pixelY, d.result.height));
    panel.mark->VisibilityOn();
  }
  // The scene's default view, a little closer: the trees, not the room, are the subject.
  d.panels.front()->tree->resetViewCamera(double(d.result.width) / std::max(1, d.result.height));
  shared->Zoom(1.35);
  d.layoutWidth = d.layoutHeight = 0;
}

void ComparisonView::clearRayTrees() {
  m_impl->detach();
  for (auto& panel : m_impl->panels) {
    panel->tree.reset();
    panel->mark->VisibilityOff();
  }
  m_impl->layoutWidth = m_impl->layoutHeight = 0;
}

bool ComparisonView::hasRayTrees() const {
  return !m_impl->panels.empty() && m_impl->panels.front()->tree != nullptr;
}

SrgbImage ComparisonView::renderOffscreen(int width, int height) {
  RAYLAB_CHECK(width > 0 && height > 0);
  requireDisplay();
  Impl& d = *m_impl;
  const std::vector<vtkRenderer*> all = renderers();
  for (vtkRenderer* renderer : all)
    RAYLAB_CHECK(renderer->GetRenderWindow() == nullptr ||
                 renderer->GetRenderWindow() == d.offscreen.Get());

  // Step 1: our own offscreen window, no multisampling, holding every renderer in order.
  if (!d.offscreen) {
    d.offscreen = vtkSmartPointer<vtkRenderWindow>::New();
    RAYLAB_CHECK(d.offscreen != nullptr);
    d.offscreen->SetOffScreenRendering(1);
    d.offscreen->SetMultiSamples(0);
  }
  d.detach();
  for (vtkRenderer* renderer : all) d.offscreen->AddRenderer(renderer);
  d.offscreen->SetSize(width, height);
  layout(width, height);

  // Step 2: render, then read the back buffer (VTK's rows bottom-up, ours top-down).
  d.offscreen->Render();
  return detail::grabWindow(d.offscreen, width, height);
}

void ComparisonView::renderToPng(const std::string& path, int width, int height) {
  writePng(renderOffscreen(width, height), path);
}

}  // namespace raylab::vis
