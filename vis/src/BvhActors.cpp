#include "BvhActors.h"

#include "ExportRole.h"

#include "raylab/core/Lesson.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/TriangleMesh.h"

#include "LegendText.h"
#include "TextFonts.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace raylab::vis {

namespace {

/// Line widths, pixels: level boxes, boxes a ray entered, boxes it skipped.
constexpr double kLevelWidth = 2.0;
constexpr double kEnteredWidth = 3.5;
constexpr double kSkippedWidth = 1.5;

/// Boxes as lines (12 edges each) with one colour per box.
struct BoxLines {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colours;
  int boxes = 0;

  BoxLines() { colours->SetNumberOfComponents(3); }

  void add(const Bounds3& b, const Vec3& colour) {
    const vtkIdType base = points->GetNumberOfPoints();
    for (int k = 0; k < 8; ++k)
      points->InsertNextPoint(k & 1 ? b.upper.x : b.lower.x, k & 2 ? b.upper.y : b.lower.y,
                              k & 4 ? b.upper.z : b.lower.z);
    // The 12 edges: corners differing in one coordinate bit.
    const unsigned char rgb[3] = {static_cast<unsigned char>(std::lround(255.0 * colour.x)),
                                  static_cast<unsigned char>(std::lround(255.0 * colour.y)),
                                  static_cast<unsigned char>(std::lround(255.0 * colour.z))};
    for (int k = 0; k < 8; ++k)
      for (int bit = 1; bit < 8; bit <<= 1)
        if (!(k & bit)) {
          const vtkIdType edge[2] = {base + k, base + (k | bit)};
          lines->InsertNextCell(2, edge);
          colours->InsertNextTypedTuple(rgb);
        }
    ++boxes;
  }

  void into(vtkActor* actor) {
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    poly->SetLines(lines);
    poly->GetCellData()->SetScalars(colours);
    auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
    mapper->SetInputData(poly);
    actor->SetVisibility(boxes > 0);
  }
};

vtkSmartPointer<vtkActor> lineActor(double width) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  // Box edges lie on triangles' planes (a leaf's box touches its triangles): pull the
  // lines towards the eye so the mesh does not hide them.
  mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-2.0, -20.0);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(width);
  actor->GetProperty()->LightingOff();
  actor->VisibilityOff();
  return actor;
}

}  // namespace

Vec3 bvhLevelColour(int depth) {
  static const std::array<Vec3, 8> kPalette = {
      Vec3(1.0, 0.9, 0.1),   Vec3(1.0, 0.5, 0.0), Vec3(1.0, 0.35, 0.75),  Vec3(0.1, 0.85, 0.95),
      Vec3(0.25, 0.45, 1.0), Vec3(0.6, 1.0, 0.2), Vec3(0.95, 0.15, 0.15), Vec3(1.0, 1.0, 1.0)};
  return kPalette[static_cast<std::size_t>(std::max(depth, 0)) % kPalette.size()];
}

Vec3 bvhMissedColour() { return Vec3(0.4, 0.4, 0.43); }
Vec3 bvhCulledColour() { return Vec3(0.72, 0.72, 0.76); }

namespace {

void layoutCallback(vtkObject* caller, unsigned long, void* clientData, void*) {
  const int* size = static_cast<vtkRenderer*>(caller)->GetSize();
  static_cast<BvhActors*>(clientData)->layoutLegend(size[0], size[1]);
}

}  // namespace

BvhActors::BvhActors()
    : levels(lineActor(kLevelWidth)),
      entered(lineActor(kEnteredWidth)),
      skipped(lineActor(kSkippedWidth)) {
  for (auto& row : legend) {
    row = vtkSmartPointer<vtkTextActor>::New();
    row->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    row->VisibilityOff();
  }
  m_layout = vtkSmartPointer<vtkCallbackCommand>::New();
  m_layout->SetCallback(layoutCallback);
  m_layout->SetClientData(this);
}

BvhActors::~BvhActors() {
  if (m_observed) m_observed->RemoveObserver(m_observer);
}

void BvhActors::addTo(vtkRenderer* renderer) {
  for (vtkActor* actor : {levels.Get(), entered.Get(), skipped.Get()}) setExportRole(actor, "bvh");
  renderer->AddActor(levels);
  renderer->AddActor(entered);
  renderer->AddActor(skipped);
  for (const auto& row : legend) renderer->AddViewProp(row);
  if (m_observed != renderer) {
    if (m_observed) m_observed->RemoveObserver(m_observer);
    m_observer = renderer->AddObserver(vtkCommand::StartEvent, m_layout);
    m_observed = renderer;
  }
}

void BvhActors::layoutLegend(int width, int height) {
  if (width <= 0 || height <= 0) return;
  // The ray tree legend's size, in the other top corner.
  const auto [font, margin, line] = legendMetrics(height);
  int y = height - margin - font;
  for (const auto& row : legend) {
    row->GetTextProperty()->SetFontSize(font);
    row->SetDisplayPosition(width - margin, y);
    y -= line;
  }
}

namespace {

/// Walks what `style` draws of `scene`: box(bounds, colour, kind) for every box, kind 0 a
/// level box, 1 entered, 2 skipped; returns the counts.
template <class BoxFn>
BvhSummary walkBoxes(const Scene& scene, const BvhStyle& style, BoxFn&& box) {
  BvhSummary summary;
  // The hierarchy a render with this split searches (as SceneIntersector chooses it):
  // the mesh's own, or one built with the split.
  if (!style.shown() || style.object >= static_cast<int>(scene.objects.size())) return summary;
  const Shape& shape = *scene.objects[static_cast<std::size_t>(style.object)].shape;
  if (shape.kind() != ShapeKind::TriangleMesh) return summary;
  const auto& mesh = static_cast<const TriangleMesh&>(shape);
  const Bvh* bvh = &mesh.bvh();
  std::optional<Bvh> rebuilt;
  if (bvh->settings().split != style.split) {
    BvhSettings settings = bvh->settings();
    settings.split = style.split;
    bvh = &rebuilt.emplace(mesh.vertices(), mesh.triangles(), settings);
  }
  summary.depth = bvh->stats().depth;
  summary.nodes = bvh->stats().nodeCount;
  const std::vector<std::vector<BvhBox>> levelBoxes = bvh->levels();
  const auto inLevels = [&](int depth) {
    return depth >= style.firstLevel && depth <= style.lastLevel;
  };
  if (!style.ray) {
    for (const auto& level : levelBoxes)
      for (const BvhBox& b : level)
        if (inLevels(b.depth)) {
          box(b.bounds, bvhLevelColour(b.depth), 0);
          ++summary.boxes;
        }
    return summary;
  }
  // Node -> its box, for the ray's visits.
  std::vector<const BvhBox*> boxOf(static_cast<std::size_t>(bvh->nodeSlots()), nullptr);
  for (const auto& level : levelBoxes)
    for (const BvhBox& b : level) boxOf[static_cast<std::size_t>(b.node)] = &b;
  const BvhTrace trace = bvh->traceVisits(*style.ray);
  summary.triangleTests = trace.triangleTests;
  summary.hit = trace.hit.has_value();
  for (const BvhVisit& v : trace.visits) {
    if (!inLevels(v.depth)) continue;
    const Bounds3& b = boxOf[static_cast<std::size_t>(v.node)]->bounds;
    ++summary.boxes;
    if (v.kind == BvhVisitKind::Entered) {
      ++summary.entered;
      box(b, bvhLevelColour(v.depth), 1);
    } else if (v.kind == BvhVisitKind::Missed) {
      ++summary.missed;
      box(b, bvhMissedColour(), 2);
    } else {
      ++summary.culled;
      box(b, bvhCulledColour(), 2);
    }
  }
  return summary;
}

}  // namespace

BvhSummary summarizeBvh(const Scene& scene, const BvhStyle& style) {
  return walkBoxes(scene, style, [](const Bounds3&, const Vec3&, int) {});
}

BvhStyle lessonBvhStyle(const LessonStep& step) {
  BvhStyle style;
  if (!step.bvh) return style;
  style.object = step.bvh->object;
  style.firstLevel = step.bvh->firstLevel;
  style.lastLevel = step.bvh->lastLevel;
  style.split = step.settings().bvhSplit;
  if (step.bvh->visits) style.ray = step.cameraRay();
  return style;
}

void BvhActors::build(const Scene& scene, const BvhStyle& newStyle) {
  style = newStyle;
  BoxLines lines[3];
  summary = walkBoxes(scene, style, [&](const Bounds3& b, const Vec3& colour, int kind) {
    lines[kind].add(b, colour);
  });
  lines[0].into(levels);
  lines[1].into(entered);
  lines[2].into(skipped);

  // The legend: which colour is which level, and with a ray the greys of the boxes it
  // passed by or met only beyond its nearest hit.
  const Language language = style.language;
  std::vector<std::pair<std::string, Vec3>> rows;
  if (summary.boxes > 0) {
    rows.emplace_back(phrase("legend.bvh.level", language), Vec3(0.95));
    const int last = std::min({style.lastLevel, summary.depth, style.firstLevel + 7});
    for (int level = std::max(0, style.firstLevel); level <= last; ++level)
      rows.emplace_back(
          phrase("legend.bvh.level_number", language, {{"level", std::to_string(level)}}),
          bvhLevelColour(level));
    if (style.ray) {
      rows.emplace_back(phrase("legend.bvh.missed", language), bvhMissedColour());
      rows.emplace_back(phrase("legend.bvh.culled", language), bvhCulledColour());
    }
  }
  for (std::size_t i = 0; i < legend.size(); ++i) {
    vtkTextActor* row = legend[i];
    row->SetVisibility(i < rows.size());
    if (i >= rows.size()) continue;
    row->SetInput(rows[i].first.c_str());
    vtkTextProperty* text = row->GetTextProperty();
    styleLegendText(text, rows[i].second, background);
    text->SetJustificationToRight();
    text->SetBold(i == 0);
    useFontFor(text, style.language);
  }
}

}  // namespace raylab::vis
