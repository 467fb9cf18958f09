// The 3D view as plain data for `raylab web`: SceneView's actors read back from its renderer
// (tagged by ExportRole.h), and a ray tree's rays in a style's colours.
#include "raylab/vis/ViewExport.h"

#include "ExportRole.h"
#include "RayTreeGeometry.h"

#include "raylab/core/Phrases.h"
#include "raylab/core/StudentHooks.h"
#include "raylab/vis/ComparisonCaptions.h"
#include "raylab/vis/SceneView.h"

#include <vtkActor.h>
#include <vtkAlgorithm.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdTypeArray.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <stdexcept>

namespace raylab::vis {

namespace {

/// VTK's legacy layout of `cells` (n, ids..., n, ids...).
std::vector<std::uint32_t> legacyCells(vtkCellArray* cells) {
  std::vector<std::uint32_t> out;
  if (!cells || cells->GetNumberOfCells() == 0) return out;
  vtkNew<vtkIdTypeArray> legacy;
  cells->ExportLegacyFormat(legacy);
  out.reserve(std::size_t(legacy->GetNumberOfValues()));
  for (vtkIdType i = 0; i < legacy->GetNumberOfValues(); ++i)
    out.push_back(std::uint32_t(legacy->GetValue(i)));
  return out;
}

/// The RGB per cell of a mapper that colours by cell scalars (unsigned char, 3 or 4
/// components), else nothing.
std::vector<std::uint8_t> cellColours(vtkMapper* mapper, vtkPolyData* data) {
  if (!mapper->GetScalarVisibility()) return {};
  auto* colours = vtkUnsignedCharArray::SafeDownCast(data->GetCellData()->GetScalars());
  if (!colours || colours->GetNumberOfComponents() < 3) return {};
  std::vector<std::uint8_t> out;
  const int components = colours->GetNumberOfComponents();
  for (vtkIdType c = 0; c < colours->GetNumberOfTuples(); ++c)
    for (int k = 0; k < 3; ++k) out.push_back(colours->GetValue(c * components + k));
  return out;
}

/// The mesh of `actor` (its mapper's input, brought up to date), or nothing.
bool readMesh(vtkActor* actor, ExportedMesh& mesh, std::size_t maxPoints) {
  vtkMapper* mapper = actor->GetMapper();
  if (!mapper) return false;
  if (vtkAlgorithm* source = mapper->GetInputAlgorithm()) source->Update();
  vtkPolyData* data = vtkPolyData::SafeDownCast(mapper->GetInputAsDataSet());
  if (!data || data->GetNumberOfPoints() == 0) return false;
  if (std::size_t(data->GetNumberOfPoints()) > maxPoints)
    throw std::length_error("a drawn mesh has " + std::to_string(data->GetNumberOfPoints()) +
                            " points, more than the web export's " + std::to_string(maxPoints));
  mesh.points.reserve(std::size_t(3 * data->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    for (double v : p) mesh.points.push_back(float(v));
  }
  mesh.polys = legacyCells(data->GetPolys());
  mesh.strips = legacyCells(data->GetStrips());
  mesh.lines = legacyCells(data->GetLines());
  mesh.verts = legacyCells(data->GetVerts());
  mesh.cellColours = cellColours(mapper, data);
  vtkProperty* p = actor->GetProperty();
  double c[3];
  p->GetColor(c);
  mesh.colour = Vec3(c[0], c[1], c[2]);
  mesh.opacity = p->GetOpacity();
  mesh.lineWidth = p->GetLineWidth();
  mesh.pointSize = p->GetPointSize();
  mesh.lit = p->GetLighting();
  return true;
}

}  // namespace

ExportedView exportView(SceneView& view, std::size_t maxPoints) {
  view.update();
  ExportedView out;
  const ViewCamera camera = view.viewCamera();
  out.camera = camera;
  double background[3];
  view.renderer()->GetBackground(background);
  out.background = Vec3(background[0], background[1], background[2]);
  // The view's props as added (not vtkRenderer::GetActors, which asks 3D text labels for
  // their actors, and they need a render window): the text labels are left out.
  vtkPropCollection* props = view.renderer()->GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp()) {
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    if (!actor || !actor->GetVisibility()) continue;
    std::string role = exportRole(actor);
    if (role == "rays") continue;  // exportRays gives them from the tree
    ExportedMesh mesh;
    if (role.rfind("object:", 0) == 0) {
      mesh.object = std::stoi(role.substr(7));
      role = "object";
    }
    mesh.role = role.empty() ? "overlay" : role;
    if (!readMesh(actor, mesh, maxPoints)) continue;
    out.pointCount += mesh.points.size() / 3;
    out.meshes.push_back(std::move(mesh));
  }
  return out;
}

std::vector<ExportedRay> exportRays(const RayTree& tree, const RayTreeStyle& style) {
  int deepest = 0;
  for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
  const std::vector<bool> reaches = reachesLight(tree);
  std::vector<ExportedRay> out;
  out.reserve(tree.segments.size());
  for (const RaySegment& s : tree.segments) {
    ExportedRay ray;
    ray.segment = &s;
    ray.colour = rayColour(s, style, deepest);
    // The width classes of the view (RayTreeGeometry.cpp's planRays).
    const int k = style.widthFollowsEnergy
                      ? std::min(kRayWidthClasses - 1,
                                 int(style.scale.position(s.energy()) * kRayWidthClasses))
                      : 0;
    ray.width = rayLineWidth(style, k);
    ray.drawn = style.filter.passes(tree, s.id, reaches);
    out.push_back(ray);
  }
  return out;
}

namespace {

LocalText bothLanguages(const std::string& key) {
  return {phrase(key, Language::English), phrase(key, Language::Chinese)};
}

}  // namespace

std::vector<ExportedLegendEntry> exportLegend(const RayTree& tree, const RayTreeStyle& style) {
  std::vector<ExportedLegendEntry> out;
  switch (style.colouring) {
    case RayColouring::Energy:
      for (const auto& [word, position] :
           {std::pair<const char*, double>{"high", 1.0}, {"medium", 0.5}, {"low", 0.0}})
        out.push_back({std::string("energy.") + word, EnergyScale::colour(position),
                       bothLanguages(std::string("legend.energy.") + word)});
      break;
    case RayColouring::Kind:
      for (int k = 0; k < kRayKindCount; ++k)
        out.push_back({std::string("kind.") + toString(RayKind(k)),
                       kindColour(RayKind(k)),
                       {rayKindName(RayKind(k), Language::English),
                        rayKindName(RayKind(k), Language::Chinese)}});
      break;
    case RayColouring::Depth: {
      int deepest = 0;
      for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
      for (int d = 0; d <= deepest; ++d)
        out.push_back({"depth." + std::to_string(d), depthColour(d, deepest),
                       d == 0 ? bothLanguages("legend.depth.camera")
                              : LocalText{std::to_string(d), std::to_string(d)}});
      break;
    }
    case RayColouring::Verdict: {
      std::vector<bool> present(kVerdictCount, false);
      for (const int v : style.verdicts)
        if (v >= 0 && v < kVerdictCount) present[std::size_t(v)] = true;
      for (int v = 0; v < kVerdictCount; ++v)
        if (present[std::size_t(v)])
          out.push_back({"verdict." + std::to_string(v),
                         verdictColour(v),
                         {verdictLabel(v, Language::English), verdictLabel(v, Language::Chinese)}});
      break;
    }
  }
  return out;
}

}  // namespace raylab::vis
