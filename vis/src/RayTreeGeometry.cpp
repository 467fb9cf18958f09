#include "RayTreeGeometry.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstdint>

namespace raylab::vis {

namespace {

/// Share of a blocked dash's colour kept against the background (the rest fades).
constexpr double kBlockedDim = 0.55;

std::uint8_t toByte(double c) { return std::uint8_t(std::clamp(c, 0.0, 1.0) * 255.0 + 0.5); }

/// One polydata being filled through raw pointers into VTK arrays sized up front: float
/// points, 32-bit line or vertex cells, RGB colours per cell and optional vectors. No VTK
/// call per cell: what makes a million rays convert in well under 0.2 s.
class CellWriter {
 public:
  /// Room for `cells` cells of `pointsPerCell` points (2 lines, 1 vertices).
  CellWriter(std::size_t cells, int pointsPerCell, bool coloured, bool withVectors)
      : m_pointsPerCell(pointsPerCell) {
    const vtkIdType n = vtkIdType(cells);
    const vtkIdType nPoints = n * pointsPerCell;
    m_coords->SetNumberOfComponents(3);
    m_coords->SetNumberOfTuples(nPoints);
    m_point = m_coords->WritePointer(0, nPoints * 3);
    m_offsets->SetNumberOfTuples(n + 1);
    m_connectivity->SetNumberOfTuples(nPoints);
    if (coloured) {
      m_colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
      m_colours->SetName("colour");
      m_colours->SetNumberOfComponents(3);
      m_colours->SetNumberOfTuples(n);
      m_colour = m_colours->WritePointer(0, n * 3);
    }
    if (withVectors) {
      m_vectors = vtkSmartPointer<vtkFloatArray>::New();
      m_vectors->SetName("direction");
      m_vectors->SetNumberOfComponents(3);
      m_vectors->SetNumberOfTuples(nPoints);
      m_vector = m_vectors->WritePointer(0, nPoints * 3);
    }
  }

  void point(const Point3& p) {
    *m_point++ = float(p.x);
    *m_point++ = float(p.y);
    *m_point++ = float(p.z);
  }
  void colour(const std::array<std::uint8_t, 3>& c) {
    *m_colour++ = c[0];
    *m_colour++ = c[1];
    *m_colour++ = c[2];
  }
  void vector(const Vec3& v) {
    *m_vector++ = float(v.x);
    *m_vector++ = float(v.y);
    *m_vector++ = float(v.z);
  }

  /// The polydata; cells are numbered in the order their points were written.
  vtkSmartPointer<vtkPolyData> finish() {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    const vtkIdType nPoints = m_coords->GetNumberOfTuples();
    const vtkIdType nCells = nPoints / m_pointsPerCell;
    std::int32_t* o = m_offsets->WritePointer(0, nCells + 1);
    for (vtkIdType c = 0; c <= nCells; ++c) o[c] = std::int32_t(c * m_pointsPerCell);
    std::int32_t* ids = m_connectivity->WritePointer(0, nPoints);
    for (vtkIdType i = 0; i < nPoints; ++i) ids[i] = std::int32_t(i);
    vtkNew<vtkPoints> points;
    points->SetData(m_coords);
    poly->SetPoints(points);
    vtkNew<vtkCellArray> cells;
    cells->SetData(m_offsets, m_connectivity);
    if (m_pointsPerCell == 2)
      poly->SetLines(cells);
    else
      poly->SetVerts(cells);
    if (m_colours) {
      // Vertices carry their colour on the point too (vtkGlyph3D colours by point data).
      if (m_pointsPerCell == 1)
        poly->GetPointData()->SetScalars(m_colours);
      else
        poly->GetCellData()->SetScalars(m_colours);
    }
    if (m_vectors) poly->GetPointData()->SetVectors(m_vectors);
    return poly;
  }

 private:
  int m_pointsPerCell;
  vtkNew<vtkFloatArray> m_coords;
  vtkNew<vtkTypeInt32Array> m_offsets, m_connectivity;
  vtkSmartPointer<vtkUnsignedCharArray> m_colours;
  vtkSmartPointer<vtkFloatArray> m_vectors;
  float* m_point = nullptr;
  std::uint8_t* m_colour = nullptr;
  float* m_vector = nullptr;
};

}  // namespace

double rayLineWidth(const RayTreeStyle& style, int widthClass) {
  return style.lineWidth * (1.0 + 0.75 * double(std::clamp(widthClass, 0, kRayWidthClasses - 1)));
}

Vec3 rayColour(const RaySegment& segment, const RayTreeStyle& style, int deepest) {
  switch (style.colouring) {
    case RayColouring::Energy:
      return EnergyScale::colour(style.scale.position(segment.energy()));
    case RayColouring::Kind:
      return kindColour(segment.kind);
    case RayColouring::Depth:
      return depthColour(segment.depth, deepest);
    case RayColouring::Verdict:
      return verdictColour(segment.id >= 0 && std::size_t(segment.id) < style.verdicts.size()
                               ? style.verdicts[std::size_t(segment.id)]
                               : 0);
  }
  return Vec3(0.5);
}

namespace {

/// A shadow ray stopped by an occluder before its light.
bool isBlockedShadow(const RaySegment& s) {
  return s.kind == RayKind::Shadow && s.endReason == EndReason::Occluded && s.hit;
}

/// The part of blocked shadow ray `s` it never travelled: kBlockedDashes dashes to the
/// light, in its `colour` dimmed towards the background.
void writeBlockedDashes(CellWriter& blocked, const RaySegment& s,
                        const std::array<std::uint8_t, 3>& colour, const Vec3& background) {
  const Vec3 c = kBlockedDim * Vec3(colour[0], colour[1], colour[2]) / 255.0 +
                 (1.0 - kBlockedDim) * background;
  const std::array<std::uint8_t, 3> dim = {toByte(c.x), toByte(c.y), toByte(c.z)};
  const Vec3 rest = s.lightPoint - s.endPoint;
  for (int d = 0; d < kBlockedDashes; ++d) {
    blocked.point(s.endPoint + (double(d) + 0.25) / kBlockedDashes * rest);
    blocked.point(s.endPoint + (double(d) + 0.75) / kBlockedDashes * rest);
    blocked.colour(dim);
  }
}

/// Which rays of a tree are drawn (width class -1: not), in which width class and colour,
/// and how many cells of each kind they make.
struct RayDrawing {
  std::vector<std::int8_t> widthClass;
  std::vector<std::array<std::uint8_t, 3>> colour;
  std::array<std::size_t, kRayWidthClasses> counts{};  ///< Drawn rays per width class.
  std::size_t blocked = 0, hits = 0, fronts = 0, drawn = 0;
};

RayDrawing planRays(const RayTree& tree, const RayTreeStyle& style,
                    const std::vector<bool>& reachesLightFlags, const std::vector<float>* fraction,
                    int deepest) {
  RayDrawing plan;
  const std::size_t n = tree.segments.size();
  plan.widthClass.assign(n, -1);
  plan.colour.resize(n);
  const bool needEnergy = style.widthFollowsEnergy || style.colouring == RayColouring::Energy;
  for (std::size_t i = 0; i < n; ++i) {
    const float f = fraction ? (*fraction)[i] : 1.0f;
    if (!(f > 0.0f)) continue;
    if (!style.filter.passes(tree, int(i), reachesLightFlags)) continue;
    const RaySegment& s = tree.segments[i];
    const double position = needEnergy ? style.scale.position(s.energy()) : 0.0;
    const int k = style.widthFollowsEnergy
                      ? std::min(kRayWidthClasses - 1, int(position * kRayWidthClasses))
                      : 0;
    plan.widthClass[i] = std::int8_t(k);
    ++plan.counts[std::size_t(k)];
    ++plan.drawn;
    const Vec3 c = style.colouring == RayColouring::Energy ? EnergyScale::colour(position)
                                                           : rayColour(s, style, deepest);
    plan.colour[i] = {toByte(c.x), toByte(c.y), toByte(c.z)};
    const bool whole = f >= 1.0f;
    if (whole && isBlockedShadow(s)) ++plan.blocked;
    if (whole && s.hit) ++plan.hits;
    if (!whole) ++plan.fronts;
  }
  return plan;
}

}  // namespace

RayTreeGeometry buildRayTreeGeometry(const RayTree& tree, const RayTreeStyle& style,
                                     const std::vector<bool>& reachesLightFlags,
                                     const std::vector<float>* fraction, double glyphLength,
                                     const Vec3& background) {
  RayTreeGeometry out;
  const std::size_t n = tree.segments.size();
  for (const RaySegment& s : tree.segments) out.deepest = std::max(out.deepest, s.depth);

  // Step 1: which rays are drawn, in which width class, and their colour; count cells.
  const RayDrawing plan = planRays(tree, style, reachesLightFlags, fraction, out.deepest);
  const std::vector<std::int8_t>& widthClass = plan.widthClass;
  const std::vector<std::array<std::uint8_t, 3>>& colour = plan.colour;

  // Step 2: two points and one coloured line per drawn ray, class by class, and the extras.
  std::vector<CellWriter> lines;
  lines.reserve(kRayWidthClasses);
  for (int k = 0; k < kRayWidthClasses; ++k) {
    lines.emplace_back(plan.counts[std::size_t(k)], 2, true, false);
    out.cellSegment[std::size_t(k)].reserve(plan.counts[std::size_t(k)]);
  }
  CellWriter blocked(plan.blocked * kBlockedDashes, 2, true, false);
  CellWriter hits(style.showHitPoints ? plan.hits : 0, 1, false, false);
  CellWriter fronts(plan.fronts, 1, true, false);
  CellWriter normals(style.showNormals ? plan.hits : 0, 2, false, false);
  CellWriter arrows(style.showArrows ? plan.drawn : 0, 1, true, true);
  for (std::size_t i = 0; i < n; ++i) {
    const int k = widthClass[i];
    if (k < 0) continue;
    const RaySegment& s = tree.segments[i];
    const float f = fraction ? (*fraction)[i] : 1.0f;
    const bool whole = f >= 1.0f;
    const Point3 front = whole ? s.endPoint : s.origin + double(f) * (s.endPoint - s.origin);
    CellWriter& line = lines[std::size_t(k)];
    line.point(s.origin);
    line.point(front);
    line.colour(colour[i]);
    out.cellSegment[std::size_t(k)].push_back(int(i));

    if (!whole) {
      // The travelling ray front: a dot in the ray's colour.
      fronts.point(front);
      fronts.colour(colour[i]);
    }
    // The part of a blocked shadow ray it never travelled: dimmed dashes to the light.
    if (whole && isBlockedShadow(s)) writeBlockedDashes(blocked, s, colour[i], background);
    if (whole && s.hit && style.showHitPoints) hits.point(s.endPoint);
    if (whole && s.hit && style.showNormals) {
      normals.point(s.endPoint);
      normals.point(s.endPoint + glyphLength * s.normal);
    }
    if (style.showArrows) {
      arrows.point(front);
      arrows.colour(colour[i]);
      arrows.vector(s.direction);
    }
  }

  // Step 3: hand the arrays to VTK.
  for (int k = 0; k < kRayWidthClasses; ++k) {
    out.lines[std::size_t(k)] = lines[std::size_t(k)].finish();
    out.drawnRays += int(out.cellSegment[std::size_t(k)].size());
  }
  out.blocked = blocked.finish();
  out.hitPoints = hits.finish();
  out.fronts = fronts.finish();
  out.normals = normals.finish();
  out.arrows = arrows.finish();
  return out;
}

}  // namespace raylab::vis
