#pragma once

#include "RayTreeGeometry.h"

#include "raylab/core/RayTree.h"
#include "raylab/core/Types.h"
#include "raylab/vis/RayTreeStyle.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkGlyph3D.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <array>
#include <memory>
#include <vector>

class vtkProp;
class vtkRenderer;

/// \file RayTreeActors.h
/// The actors of the ray tree in SceneView (private to vis).

namespace raylab::vis {

/// Most entries the kind or depth legend lists (deeper trees show every few depths).
constexpr int kLegendEntries = 10;

/**
 * \brief The ray tree drawn in a 3D view: a line actor per width class (all rays of a
 * class in one polydata), the dimmed dashes of blocked shadow rays, hit points, travelling
 * fronts, normals, arrow heads, the selected ray and the legend.
 *
 * Created once per view. Changing the tree, the style, the revealed fractions or the
 * selection only marks the actors dirty (markDirty); the polydata are built once, just
 * before the next render (or the next pick), however many changes came before it. The legend is
 * text laid out in pixels before every render (a StartEvent observer), so it reads the same at
 * 320x240 and on a projector.
 */
class RayTreeActors {
 public:
  explicit RayTreeActors(const Vec3& background);
  RayTreeActors(const RayTreeActors&) = delete;
  RayTreeActors& operator=(const RayTreeActors&) = delete;
  ~RayTreeActors();

  /// The tree drawn, shared with whoever traced it (never copied); empty when none.
  std::shared_ptr<const RayTree> tree;
  bool shown = false;
  RayTreeStyle style;
  std::vector<bool> reaches;    ///< reachesLight(tree).
  std::vector<float> fraction;  ///< Revealed fraction per segment; empty = all.
  int selected = -1;            ///< Selected segment id or -1.
  double glyphLength = 0.1;     ///< Normals and arrows, world units.
  RayTreeGeometry geometry;     ///< As last built (segmentAt reads it).

  /// Adds every actor to `renderer` (again after RemoveAllViewProps) and lays the legend
  /// out before each of its renders.
  void addTo(vtkRenderer* renderer);
  /// The tree drawn, or an empty one.
  const RayTree& drawnTree() const;
  /// Something changed: build again before the next render.
  void markDirty() { m_dirty = true; }
  /// Builds the polydata and the legend from tree, style, fraction and selection when
  /// something changed since the last build (called before every render and pick).
  void ensureBuilt();
  /// How many times the polydata were built (one per render after changes, at most).
  int buildCount() const { return m_builds; }
  /// Places and sizes the legend for a viewport of width x height pixels.
  void layoutLegend(int width, int height);

 private:
  Vec3 m_background;
  std::array<vtkSmartPointer<vtkActor>, kRayWidthClasses> m_lines;
  vtkSmartPointer<vtkActor> m_blocked, m_hitPoints, m_fronts, m_normals, m_arrows, m_selection;
  vtkSmartPointer<vtkGlyph3D> m_arrowGlyphs;
  vtkSmartPointer<vtkTextActor> m_legendTitle;
  std::array<vtkSmartPointer<vtkTextActor>, kLegendEntries> m_legendEntries;
  int m_legendEntryCount = 0;
  vtkSmartPointer<vtkScalarBarActor> m_energyBar;  ///< The energy colouring's legend.
  /// Words beside the energy bar: high, medium, low / none (the original's meaning).
  std::array<vtkSmartPointer<vtkTextActor>, 3> m_energyWords;
  vtkSmartPointer<vtkCallbackCommand> m_layout;  ///< Calls layoutLegend before renders.
  vtkRenderer* m_observed = nullptr;
  unsigned long m_observer = 0;

  bool m_dirty = true;
  int m_builds = 0;

  void rebuild();
  void updateLegend();
  std::vector<vtkProp*> props() const;
};

}  // namespace raylab::vis
