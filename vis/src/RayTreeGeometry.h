#pragma once

#include "raylab/core/RayTree.h"
#include "raylab/core/Types.h"
#include "raylab/vis/BounceAnimation.h"
#include "raylab/vis/RayTreeStyle.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <vector>

/// \file RayTreeGeometry.h
/// A recorded ray tree as VTK polydata (world space), ready for SceneView's actors.
/// Private to vis: the public API speaks RayTree and RayTreeStyle only.

namespace raylab::vis {

/// Width classes of drawn rays when RayTreeStyle::widthFollowsEnergy is on: bottom, middle
/// and top third of the energy scale. Without it every ray is in class 0.
constexpr int kRayWidthClasses = 3;
/// Line width of width class `k`, pixels: lineWidth, 1.75 lineWidth, 2.5 lineWidth.
double rayLineWidth(const RayTreeStyle& style, int widthClass);
/// Dashes drawn between the blocker and the light of an occluded shadow ray.
constexpr int kBlockedDashes = 8;

/**
 * \brief Every drawn ray of a tree, by width class, plus the optional glyph data.
 *
 * Each `lines[k]` holds two points per ray (origin and the ray front) and one line cell,
 * with a cell array "colour" (unsigned char RGB, the style's colouring) and
 * `cellSegment[k][c]` the segment id of cell c. Rays are drawn from their origin to
 * origin + fraction * (endPoint - origin); rays with fraction 0 or failing the filter
 * are left out. An occluded shadow ray is drawn solid up to its blocker; once wholly
 * revealed the rest of its way to the light is drawn as dimmed dashes in `blocked`.
 */
struct RayTreeGeometry {
  std::array<vtkSmartPointer<vtkPolyData>, kRayWidthClasses> lines;
  std::array<std::vector<int>, kRayWidthClasses> cellSegment;
  vtkSmartPointer<vtkPolyData> blocked;    ///< Dashes, "colour" per cell (dimmed).
  vtkSmartPointer<vtkPolyData> hitPoints;  ///< One vertex per wholly drawn ray that hit.
  vtkSmartPointer<vtkPolyData> fronts;     ///< One vertex per travelling front, "colour".
  vtkSmartPointer<vtkPolyData> normals;    ///< Lines of `glyphLength` along hit normals.
  vtkSmartPointer<vtkPolyData> arrows;     ///< Points at ray fronts, "direction" vectors.
  int drawnRays = 0;                       ///< Rays drawn (cells over all classes).
  int deepest = 0;                         ///< Deepest depth in the whole tree.
};

/// Colour of segment `id` in `style` (linear RGB in [0, 1]); `deepest` for Depth.
Vec3 rayColour(const RaySegment& segment, const RayTreeStyle& style, int deepest);

/**
 * \brief Builds the polydata of `tree` drawn with `style`.
 *
 * \param reachesLightFlags reachesLight(tree), needed by the filter's onlyReachingLight.
 * \param fraction          revealed fraction per segment (RevealFrame), or null for all.
 * \param glyphLength       length of normals and arrows, world units.
 * \param background        view background (linear RGB), that blocked dashes fade to.
 *
 * Fills raw arrays (points, cell offsets and connectivity, colours) without per-cell VTK
 * calls: a million rays take well under 0.2 s (see tests/bench/BenchVis.cpp). Glyph data
 * is built only when the style shows it.
 */
RayTreeGeometry buildRayTreeGeometry(const RayTree& tree, const RayTreeStyle& style,
                                     const std::vector<bool>& reachesLightFlags,
                                     const std::vector<float>* fraction, double glyphLength,
                                     const Vec3& background);

}  // namespace raylab::vis
