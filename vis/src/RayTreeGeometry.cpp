#include "RayTreeGeometry.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstdint>

namespace raylab {

namespace {

/// Share of a blocked dash's colour kept against the background (the rest fades).
constexpr double kBlockedDim = 0.55;

std::uint8_t toByte(double c) { return std::uint8_t(std::clamp(c, 0.0, 1.0) * 255.0 + 0.5); }

/// Growable raw arrays of one polydata: float points, line or vertex cells, RGB colours.
/// Sized up front (reserve) and written through pointers, no per-cell VTK call.
struct RawCells {
  std::vector<float> points;            ///< x y z per point.
  std::vector<vtkIdType> connectivity;  ///< Point ids, cell after cell.
  std::vector<std::uint8_t> colours;    ///< RGB per cell (empty when uncoloured).
  std::vector<float> vectors;           ///< x y z per point (empty when none).
  int pointsPerCell = 2;

  void addPoint(const Point3& p) {
    points.push_back(float(p.x));
    points.push_back(float(p.y));
    points.push_back(float(p.z));
    connectivity.push_back(vtkIdType(connectivity.size()));
  }
  void addColour(const std::array<std::uint8_t, 3>& c) {
    colours.insert(colours.end(), c.begin(), c.end());
  }
};

/// Moves the raw arrays into a polydata (lines when pointsPerCell is 2, else vertices).
vtkSmartPointer<vtkPolyData> toPolyData(const RawCells& raw) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  const vtkIdType nPoints = vtkIdType(raw.points.size() / 3);
  const vtkIdType nCells = vtkIdType(raw.connectivity.size()) / raw.pointsPerCell;

  vtkNew<vtkFloatArray> coords;
  coords->SetNumberOfComponents(3);
  coords->SetNumberOfTuples(nPoints);
  std::copy(raw.points.begin(), raw.points.end(), coords->WritePointer(0, nPoints * 3));
  vtkNew<vtkPoints> points;
  points->SetData(coords);
  poly->SetPoints(points);

  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(nCells + 1);
  vtkIdType* o = offsets->WritePointer(0, nCells + 1);
  for (vtkIdType c = 0; c <= nCells; ++c) o[c] = c * raw.pointsPerCell;
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(vtkIdType(raw.connectivity.size()));
  std::copy(raw.connectivity.begin(), raw.connectivity.end(),
            connectivity->WritePointer(0, vtkIdType(raw.connectivity.size())));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  if (raw.pointsPerCell == 2)
    poly->SetLines(cells);
  else
    poly->SetVerts(cells);

  if (!raw.colours.empty()) {
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("colour");
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(nCells);
    std::copy(raw.colours.begin(), raw.colours.end(), colours->WritePointer(0, nCells * 3));
    poly->GetCellData()->SetScalars(colours);
  }
  if (!raw.vectors.empty()) {
    vtkNew<vtkFloatArray> vectors;
    vectors->SetName("direction");
    vectors->SetNumberOfComponents(3);
    vectors->SetNumberOfTuples(nPoints);
    std::copy(raw.vectors.begin(), raw.vectors.end(), vectors->WritePointer(0, nPoints * 3));
    poly->GetPointData()->SetVectors(vectors);
  }
  return poly;
}

}  // namespace

double rayLineWidth(const RayTreeStyle& style, int widthClass) {
  return style.lineWidth * (1.0 + 0.75 * double(std::clamp(widthClass, 0, kRayWidthClasses - 1)));
}

Vec3 rayColour(const RaySegment& segment, const RayTreeStyle& style, int deepest) {
  switch (style.colouring) {
    case RayColouring::Energy:
      return EnergyScale::colour(style.scale.position(segmentEnergy(segment)));
    case RayColouring::Kind:
      return kindColour(segment.kind);
    case RayColouring::Depth:
      return depthColour(segment.depth, deepest);
  }
  return Vec3(0.5);
}

RayTreeGeometry buildRayTreeGeometry(const RayTree& tree, const RayTreeStyle& style,
                                     const std::vector<bool>& reachesLightFlags,
                                     const std::vector<float>* fraction, double glyphLength,
                                     const Vec3& background) {
  RayTreeGeometry out;
  const std::size_t n = tree.segments.size();
  for (const RaySegment& s : tree.segments) out.deepest = std::max(out.deepest, s.depth);

  // Step 1: which rays are drawn, in which width class, and their colour.
  std::vector<std::int8_t> widthClass(n, -1);
  std::vector<std::array<std::uint8_t, 3>> colour(n);
  std::array<std::size_t, kRayWidthClasses> counts{};
  std::size_t blockedCount = 0, hitCount = 0, frontCount = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const float f = fraction ? (*fraction)[i] : 1.0f;
    if (!(f > 0.0f)) continue;
    if (!style.filter.passes(tree, int(i), reachesLightFlags)) continue;
    const RaySegment& s = tree.segments[i];
    int k = 0;
    if (style.widthFollowsEnergy) {
      const double position = style.scale.position(segmentEnergy(s));
      k = std::min(kRayWidthClasses - 1, int(position * kRayWidthClasses));
    }
    widthClass[i] = std::int8_t(k);
    ++counts[std::size_t(k)];
    const Vec3 c = rayColour(s, style, out.deepest);
    colour[i] = {toByte(c.x), toByte(c.y), toByte(c.z)};
    const bool whole = f >= 1.0f;
    if (whole && s.kind == RayKind::Shadow && s.endReason == EndReason::Occluded && s.hit)
      ++blockedCount;
    if (whole && s.hit) ++hitCount;
    if (!whole) ++frontCount;
  }

  // Step 2: two points and one coloured line per drawn ray, class by class.
  std::array<RawCells, kRayWidthClasses> raw;
  for (int k = 0; k < kRayWidthClasses; ++k) {
    RawCells& r = raw[std::size_t(k)];
    r.points.reserve(counts[std::size_t(k)] * 6);
    r.connectivity.reserve(counts[std::size_t(k)] * 2);
    r.colours.reserve(counts[std::size_t(k)] * 3);
    out.cellSegment[std::size_t(k)].reserve(counts[std::size_t(k)]);
  }
  RawCells blocked, hits, fronts, normals, arrows;
  hits.pointsPerCell = fronts.pointsPerCell = arrows.pointsPerCell = 1;
  blocked.points.reserve(blockedCount * kBlockedDashes * 6);
  hits.points.reserve(style.showHitPoints ? hitCount * 3 : 0);
  fronts.points.reserve(frontCount * 3);
  for (std::size_t i = 0; i < n; ++i) {
    const int k = widthClass[i];
    if (k < 0) continue;
    const RaySegment& s = tree.segments[i];
    const float f = fraction ? (*fraction)[i] : 1.0f;
    const bool whole = f >= 1.0f;
    const Point3 front = whole ? s.endPoint : s.origin + double(f) * (s.endPoint - s.origin);
    RawCells& r = raw[std::size_t(k)];
    r.addPoint(s.origin);
    r.addPoint(front);
    r.addColour(colour[i]);
    out.cellSegment[std::size_t(k)].push_back(int(i));

    if (!whole) {
      // The travelling ray front: a dot in the ray's colour.
      fronts.addPoint(front);
      fronts.addColour(colour[i]);
    }
    if (whole && s.kind == RayKind::Shadow && s.endReason == EndReason::Occluded && s.hit) {
      // The part of a blocked shadow ray it never travelled: dimmed dashes to the light.
      const Vec3 c = kBlockedDim * Vec3(colour[i][0], colour[i][1], colour[i][2]) / 255.0 +
                     (1.0 - kBlockedDim) * background;
      const std::array<std::uint8_t, 3> dim = {toByte(c.x), toByte(c.y), toByte(c.z)};
      const Vec3 rest = s.lightPoint - s.endPoint;
      for (int d = 0; d < kBlockedDashes; ++d) {
        const double a = (double(d) + 0.25) / kBlockedDashes;
        const double b = (double(d) + 0.75) / kBlockedDashes;
        blocked.addPoint(s.endPoint + a * rest);
        blocked.addPoint(s.endPoint + b * rest);
        blocked.addColour(dim);
      }
    }
    if (whole && s.hit && style.showHitPoints) hits.addPoint(s.endPoint);
    if (whole && s.hit && style.showNormals) {
      normals.addPoint(s.endPoint);
      normals.addPoint(s.endPoint + glyphLength * s.normal);
    }
    if (style.showArrows) {
      arrows.addPoint(front);
      arrows.vectors.push_back(float(s.direction.x));
      arrows.vectors.push_back(float(s.direction.y));
      arrows.vectors.push_back(float(s.direction.z));
    }
  }

  // Step 3: hand the arrays to VTK.
  for (int k = 0; k < kRayWidthClasses; ++k) {
    out.lines[std::size_t(k)] = toPolyData(raw[std::size_t(k)]);
    out.drawnRays += int(out.cellSegment[std::size_t(k)].size());
  }
  out.blocked = toPolyData(blocked);
  out.hitPoints = toPolyData(hits);
  out.fronts = toPolyData(fronts);
  out.normals = toPolyData(normals);
  out.arrows = toPolyData(arrows);
  return out;
}

}  // namespace raylab
