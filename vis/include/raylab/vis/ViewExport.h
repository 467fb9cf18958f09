#pragma once

#include "raylab/core/Language.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/Types.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/ViewCamera.h"

#include <cstdint>
#include <string>
#include <vector>

/// \file ViewExport.h
/// The 3D view as plain data for the web export (`raylab web`, doc/web-data.md): the
/// polydata of every actor SceneView draws (the same tessellation the window shows), and a
/// ray tree's rays, hits and legend in a style's colours. No VTK in this header.

namespace raylab::vis {

class SceneView;

/// One drawn actor's polydata, world space, and how it is drawn.
struct ExportedMesh {
  /// "object" (a scene object, `object` its index), "camera", "light", "bvh", "samples",
  /// "crossings", "outline" (the selected object's) or "overlay".
  std::string role;
  int object = -1;
  std::vector<float> points;  ///< x, y, z per point.
  /// VTK's legacy cell arrays: for each cell its point count, then its point ids.
  std::vector<std::uint32_t> polys, strips, lines, verts;
  /// RGB per cell (polys, strips, lines, verts in that order) where the window colours
  /// cell by cell; empty otherwise.
  std::vector<std::uint8_t> cellColours;
  Vec3 colour{1.0};
  double opacity = 1.0, lineWidth = 1.0, pointSize = 1.0;
  bool lit = true;
};

/// What a SceneView shows, as data.
struct ExportedView {
  ViewCamera camera;
  Vec3 background{0.0};
  std::vector<ExportedMesh> meshes;  ///< Every visible actor but the ray tree's.
  std::size_t pointCount = 0;        ///< Points over all meshes.
};

/// Every visible actor of `view` (after SceneView::show) but the ray tree's, which
/// exportRays gives from the tree itself. Throws std::length_error when a mesh has more
/// than `maxPoints` points.
ExportedView exportView(SceneView& view, std::size_t maxPoints);

/// One ray of a tree as the view draws it with a style.
struct ExportedRay {
  const RaySegment* segment = nullptr;  ///< The tree's ray (id, kind, ends, end point...).
  Vec3 colour{1.0};                     ///< The style's colour (rayColour).
  double width = 1.0;                   ///< Line width, pixels (rayLineWidth of its class).
  bool drawn = true;                    ///< Passes the style's filters.
};
/// Every ray of `tree`, in id order, with `style`'s colours and widths.
std::vector<ExportedRay> exportRays(const RayTree& tree, const RayTreeStyle& style);

/// One entry of the ray legend: a colour and its words in both languages.
struct ExportedLegendEntry {
  std::string kind;  ///< "energy.high", "kind.camera", "depth.2", "verdict.3".
  Vec3 colour{1.0};
  LocalText label;
};
/// The legend of `tree` drawn with `style`'s colouring (the window's entries).
std::vector<ExportedLegendEntry> exportLegend(const RayTree& tree, const RayTreeStyle& style);

}  // namespace raylab::vis
