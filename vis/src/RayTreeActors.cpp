#include "RayTreeActors.h"

#include "ExportRole.h"

#include "LegendText.h"
#include "TextFonts.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/StudentHooks.h"
#include "raylab/vis/ComparisonCaptions.h"

#include <vtkCellArray.h>
#include <vtkConeSource.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace raylab::vis {

namespace {

/// Colour of the selected segment: a magenta no colouring uses.
constexpr double kSelectedRay[3] = {1.0, 0.2, 0.8};
/// Colour of the legend's title and of the energy bar's labels.
const Vec3 kLegendText(0.95, 0.95, 0.95);

/// An unlit actor drawing the direct RGB colours of its polydata (cell or point scalars).
vtkSmartPointer<vtkActor> makeColouredActor() {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  return actor;
}

void setInput(vtkActor* actor, vtkPolyData* data) {
  static_cast<vtkPolyDataMapper*>(actor->GetMapper())->SetInputData(data);
}

void layoutCallback(vtkObject* caller, unsigned long, void* clientData, void*) {
  auto* renderer = static_cast<vtkRenderer*>(caller);
  const int* size = renderer->GetSize();
  auto* actors = static_cast<RayTreeActors*>(clientData);
  actors->ensureBuilt();
  actors->layoutLegend(size[0], size[1]);
}

}  // namespace

RayTreeActors::RayTreeActors(const Vec3& background) : m_background(background) {
  for (auto& actor : m_lines) actor = makeColouredActor();
  m_blocked = makeColouredActor();
  m_blocked->GetProperty()->SetLineWidth(1.5);
  m_hitPoints = makeColouredActor();
  m_hitPoints->GetMapper()->ScalarVisibilityOff();
  m_hitPoints->GetProperty()->SetColor(0.95, 0.95, 0.95);
  m_hitPoints->GetProperty()->RenderPointsAsSpheresOn();
  m_fronts = makeColouredActor();
  m_fronts->GetProperty()->RenderPointsAsSpheresOn();
  m_normals = makeColouredActor();
  m_normals->GetMapper()->ScalarVisibilityOff();
  m_normals->GetProperty()->SetColor(1.0, 0.5, 0.5);
  m_normals->GetProperty()->SetLineWidth(2.5);

  // Arrow heads: small cones whose tip sits on the ray front, pointing along the ray,
  // in the ray's colour.
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(12);
  cone->SetHeight(1.0);
  cone->SetRadius(0.3);
  cone->SetCenter(-0.5, 0.0, 0.0);
  m_arrowGlyphs = vtkSmartPointer<vtkGlyph3D>::New();
  m_arrowGlyphs->SetSourceConnection(cone->GetOutputPort());
  m_arrowGlyphs->SetVectorModeToUseVector();
  m_arrowGlyphs->OrientOn();
  m_arrowGlyphs->SetInputData(vtkSmartPointer<vtkPolyData>::New());  // until the first build
  m_arrowGlyphs->SetScaleModeToDataScalingOff();
  m_arrowGlyphs->SetColorModeToColorByScalar();
  vtkNew<vtkPolyDataMapper> arrowMapper;
  arrowMapper->SetInputConnection(m_arrowGlyphs->GetOutputPort());
  arrowMapper->SetColorModeToDirectScalars();
  m_arrows = vtkSmartPointer<vtkActor>::New();
  m_arrows->SetMapper(arrowMapper);
  m_arrows->GetProperty()->LightingOff();

  m_selection = makeColouredActor();
  m_selection->GetMapper()->ScalarVisibilityOff();
  m_selection->GetProperty()->SetColor(kSelectedRay[0], kSelectedRay[1], kSelectedRay[2]);
  // Drawn over the ray it marks.
  m_selection->GetMapper()->SetRelativeCoincidentTopologyLineOffsetParameters(-2.0, -20.0);

  // The legend: a title, then a colour bar (energy) or coloured names (kinds, depths).
  m_legendTitle = vtkSmartPointer<vtkTextActor>::New();
  styleLegendText(m_legendTitle->GetTextProperty(), kLegendText, m_background);
  m_legendTitle->GetTextProperty()->BoldOn();
  for (auto& entry : m_legendEntries) {
    entry = vtkSmartPointer<vtkTextActor>::New();
    styleLegendText(entry->GetTextProperty(), kLegendText, m_background);
    entry->GetTextProperty()->BoldOn();
  }
  m_energyBar = vtkSmartPointer<vtkScalarBarActor>::New();
  m_energyBar->SetOrientationToVertical();
  m_energyBar->SetTextPositionToSucceedScalarBar();
  m_energyBar->UnconstrainedFontSizeOn();
  m_energyBar->SetBarRatio(0.3);
  m_energyBar->SetTextPad(4);
  m_energyBar->SetTitle("");
  m_energyBar->SetLabelFormat("%g");
  m_energyBar->DrawAnnotationsOff();
  styleLegendText(m_energyBar->GetLabelTextProperty(), kLegendText, m_background);
  for (std::size_t i = 0; i < m_energyWords.size(); ++i) {
    m_energyWords[i] = vtkSmartPointer<vtkTextActor>::New();
    styleLegendText(m_energyWords[i]->GetTextProperty(), kLegendText, m_background);
    m_energyWords[i]->GetTextProperty()->SetVerticalJustificationToCentered();
  }
  m_energyBar->GetLabelTextProperty()->SetVerticalJustificationToCentered();
  m_energyBar->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
  m_energyBar->GetPosition2Coordinate()->SetCoordinateSystemToDisplay();

  m_layout = vtkSmartPointer<vtkCallbackCommand>::New();
  m_layout->SetCallback(layoutCallback);
  m_layout->SetClientData(this);
}

RayTreeActors::~RayTreeActors() {
  if (m_observed) m_observed->RemoveObserver(m_observer);
}

std::vector<vtkProp*> RayTreeActors::props() const {
  std::vector<vtkProp*> all(m_lines.begin(), m_lines.end());
  all.insert(all.end(),
             {m_blocked.Get(), m_hitPoints.Get(), m_fronts.Get(), m_normals.Get(), m_arrows.Get(),
              m_selection.Get(), m_legendTitle.Get(), m_energyBar.Get()});
  for (const auto& entry : m_legendEntries) all.push_back(entry);
  for (const auto& word : m_energyWords) all.push_back(word);
  return all;
}

void RayTreeActors::addTo(vtkRenderer* renderer) {
  for (vtkProp* prop : props()) {
    setExportRole(prop, "rays");  // exported from the tree itself (ViewExport.cpp)
    renderer->AddViewProp(prop);
  }
  if (m_observed != renderer) {
    if (m_observed) m_observed->RemoveObserver(m_observer);
    m_observer = renderer->AddObserver(vtkCommand::StartEvent, m_layout);
    m_observed = renderer;
  }
}

const RayTree& RayTreeActors::drawnTree() const {
  static const RayTree kNone;
  return tree ? *tree : kNone;
}

void RayTreeActors::ensureBuilt() {
  if (m_dirty) rebuild();
}

void RayTreeActors::rebuild() {
  m_dirty = false;
  ++m_builds;
  const RayTree& drawn = drawnTree();
  const std::vector<float>* revealed = fraction.empty() ? nullptr : &fraction;
  geometry = buildRayTreeGeometry(drawn, style, reaches, revealed, glyphLength, m_background);
  for (int k = 0; k < kRayWidthClasses; ++k) {
    vtkActor* actor = m_lines[std::size_t(k)];
    setInput(actor, geometry.lines[std::size_t(k)]);
    actor->GetProperty()->SetLineWidth(float(rayLineWidth(style, k)));
    actor->SetVisibility(shown && geometry.lines[std::size_t(k)]->GetNumberOfCells() > 0);
  }
  setInput(m_blocked, geometry.blocked);
  m_blocked->SetVisibility(shown && geometry.blocked->GetNumberOfCells() > 0);
  setInput(m_hitPoints, geometry.hitPoints);
  m_hitPoints->GetProperty()->SetPointSize(float(2.0 * style.lineWidth + 2.0));
  m_hitPoints->SetVisibility(shown && style.showHitPoints &&
                             geometry.hitPoints->GetNumberOfCells() > 0);
  setInput(m_fronts, geometry.fronts);
  m_fronts->GetProperty()->SetPointSize(float(3.0 * style.lineWidth + 3.0));
  m_fronts->SetVisibility(shown && geometry.fronts->GetNumberOfCells() > 0);
  setInput(m_normals, geometry.normals);
  m_normals->SetVisibility(shown && style.showNormals && geometry.normals->GetNumberOfCells() > 0);
  m_arrowGlyphs->SetInputData(geometry.arrows);
  m_arrowGlyphs->SetScaleFactor(glyphLength * 0.8);
  m_arrows->SetVisibility(shown && style.showArrows && geometry.arrows->GetNumberOfPoints() > 0);

  // The selected segment, as far as it is revealed, thick and magenta.
  auto selectionData = vtkSmartPointer<vtkPolyData>::New();
  bool selectionShown = false;
  if (shown && selected >= 0 && selected < int(drawn.segments.size())) {
    const RaySegment& s = drawn.segments[std::size_t(selected)];
    const double f = fraction.empty() ? 1.0 : double(fraction[std::size_t(selected)]);
    if (f > 0.0) {
      const Point3 end = s.origin + f * (s.endPoint - s.origin);
      vtkNew<vtkPoints> points;
      points->InsertNextPoint(s.origin.x, s.origin.y, s.origin.z);
      points->InsertNextPoint(end.x, end.y, end.z);
      vtkNew<vtkCellArray> cells;
      const vtkIdType ids[2] = {0, 1};
      cells->InsertNextCell(2, ids);
      selectionData->SetPoints(points);
      selectionData->SetLines(cells);
      selectionShown = true;
    }
  }
  setInput(m_selection, selectionData);
  m_selection->GetProperty()->SetLineWidth(float(rayLineWidth(style, kRayWidthClasses - 1) + 3.0));
  m_selection->SetVisibility(selectionShown);

  updateLegend();
}

void RayTreeActors::updateLegend() {
  const bool legend = shown && style.showLegend;
  m_legendEntryCount = 0;
  auto addEntry = [&](const std::string& text, const Vec3& colour) {
    vtkTextActor* entry = m_legendEntries[std::size_t(m_legendEntryCount++)];
    entry->SetInput(text.c_str());
    entry->GetTextProperty()->SetColor(colour.x, colour.y, colour.z);
  };
  // The legend's words in the style's language.
  const Language language = style.language;
  const auto say = [&](const char* key) { return phrase(key, language); };
  useFontFor(m_legendTitle->GetTextProperty(), style.language);
  for (auto& entry : m_legendEntries) useFontFor(entry->GetTextProperty(), style.language);
  const char* energyWords[3] = {"legend.energy.high", "legend.energy.medium", "legend.energy.low"};
  for (std::size_t i = 0; i < m_energyWords.size(); ++i) {
    useFontFor(m_energyWords[i]->GetTextProperty(), style.language);
    m_energyWords[i]->SetInput(say(energyWords[i]).c_str());
  }
  switch (style.colouring) {
    case RayColouring::Energy: {
      // The shared log scale: grey at `low`, green at the geometric mean, blue at `high`.
      m_legendTitle->SetInput(say("legend.energy").c_str());
      vtkNew<vtkLookupTable> table;
      const int n = 256;
      table->SetNumberOfTableValues(n);
      table->SetScaleToLog10();
      table->SetRange(style.scale.low, style.scale.high);
      for (int i = 0; i < n; ++i) {
        const Vec3 c = EnergyScale::colour(double(i) / double(n - 1));
        table->SetTableValue(i, c.x, c.y, c.z, 1.0);
      }
      table->Build();
      m_energyBar->SetLookupTable(table);
      const double decades = std::log10(style.scale.high / style.scale.low);
      m_energyBar->SetNumberOfLabels(std::clamp(int(std::lround(decades)) + 1, 2, 6));
      break;
    }
    case RayColouring::Kind:
      m_legendTitle->SetInput(say("legend.kind").c_str());
      for (int k = 0; k < kRayKindCount; ++k)
        addEntry(rayKindName(RayKind(k), style.language), kindColour(RayKind(k)));
      break;
    case RayColouring::Depth: {
      m_legendTitle->SetInput(say("legend.depth").c_str());
      const int deepest = geometry.deepest;
      const int every = deepest / kLegendEntries + 1;
      for (int d = 0; d <= deepest && m_legendEntryCount < kLegendEntries; d += every)
        addEntry(d == 0 ? say("legend.depth.camera") : std::to_string(d), depthColour(d, deepest));
      break;
    }
    case RayColouring::Verdict: {
      // Only the verdicts this tree has, best first (at most kVerdictCount entries).
      m_legendTitle->SetInput(say("legend.verdict").c_str());
      std::vector<bool> present(kVerdictCount, false);
      for (const int v : style.verdicts)
        if (v >= 0 && v < kVerdictCount) present[std::size_t(v)] = true;
      for (int v = 0; v < kVerdictCount; ++v)
        if (present[std::size_t(v)]) addEntry(verdictLabel(v, style.language), verdictColour(v));
      break;
    }
  }
  m_legendTitle->SetVisibility(legend);
  m_energyBar->SetVisibility(legend && style.colouring == RayColouring::Energy);
  for (const auto& word : m_energyWords)
    word->SetVisibility(legend && style.colouring == RayColouring::Energy);
  for (int i = 0; i < kLegendEntries; ++i)
    m_legendEntries[std::size_t(i)]->SetVisibility(legend && i < m_legendEntryCount);
}

void RayTreeActors::layoutLegend(int width, int height) {
  if (width <= 0 || height <= 0) return;
  const auto [font, margin, line] = legendMetrics(height);
  int y = height - margin - font;
  m_legendTitle->GetTextProperty()->SetFontSize(font);
  m_legendTitle->SetDisplayPosition(margin, y);
  for (int i = 0; i < m_legendEntryCount; ++i) {
    y -= line;
    vtkTextActor* entry = m_legendEntries[std::size_t(i)];
    entry->GetTextProperty()->SetFontSize(font);
    entry->SetDisplayPosition(margin + font / 2, y);
  }
  // The energy bar under the title: labels half a line tall above and below the bar.
  const int barTop = height - margin - font - line / 2;
  const int barHeight = std::max(4 * font, int(0.3 * height));
  m_energyBar->GetLabelTextProperty()->SetFontSize(font);
  m_energyBar->GetPositionCoordinate()->SetValue(margin + font / 2, barTop - barHeight);
  m_energyBar->GetPosition2Coordinate()->SetValue(5 * font, barHeight);
  m_energyBar->SetMaximumWidthInPixels(5 * font);
  m_energyBar->SetMaximumHeightInPixels(barHeight);
  // What the colours mean, beside the bar's numbers: high at the top, none at the bottom,
  // a font's width past the bar's box (at the smallest font, 10 px, "0.0001" fills the box).
  const int wordsX = margin + font / 2 + 6 * font + font / 2;
  const int rows[] = {barTop - font, barTop - barHeight / 2, barTop - barHeight + font};
  for (std::size_t i = 0; i < m_energyWords.size(); ++i) {
    m_energyWords[i]->GetTextProperty()->SetFontSize(font);
    m_energyWords[i]->SetDisplayPosition(wordsX, rows[i]);
  }
  // The bar caches its layout by its own modification time, which a new label font size
  // does not touch: without this its first picture would use another layout than the next.
  m_energyBar->Modified();
}

}  // namespace raylab::vis
