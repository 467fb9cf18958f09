#pragma once

#include "raylab/core/Scene.h"
#include "raylab/vis/BvhStyle.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <array>

class vtkRenderer;

namespace raylab::vis {

/// The actors of a BvhStyle (BvhStyle.h): wireframe boxes in three line widths (level
/// boxes, boxes a ray entered, boxes it missed or culled), and their legend in the view's
/// top right corner (the ray tree's is in the top left: the colours of both overlap).
/// Private to vis; SceneView owns one and rebuilds it when the style or the scene changes.
struct BvhActors {
  BvhStyle style;
  vtkSmartPointer<vtkActor> levels;   ///< Boxes of the levels (no ray), per-box colours.
  vtkSmartPointer<vtkActor> entered;  ///< Boxes the ray entered, thick, per-box colours.
  vtkSmartPointer<vtkActor> skipped;  ///< Boxes the ray missed or culled, thin, greys.
  BvhSummary summary;                 ///< What is drawn, counted.
  /// The legend: a title, then up to 8 level colours and, with a ray, two greys.
  static constexpr int kLegendRows = 11;
  std::array<vtkSmartPointer<vtkTextActor>, kLegendRows> legend;
  Vec3 background{0.0};  ///< The view's background, behind the legend's words.

  BvhActors();
  ~BvhActors();
  BvhActors(const BvhActors&) = delete;
  BvhActors& operator=(const BvhActors&) = delete;
  /// Adds the actors to `renderer` (once per scene: SceneView::setScene clears props), and
  /// lays the legend out before each of its renders.
  void addTo(vtkRenderer* renderer);
  /// Places the legend for a view of `width` x `height` pixels.
  void layoutLegend(int width, int height);
  /// Rebuilds the boxes of `style` for `scene`; an object that is not a mesh draws nothing.
  void build(const Scene& scene, const BvhStyle& newStyle);

 private:
  vtkSmartPointer<vtkCallbackCommand> m_layout;
  vtkRenderer* m_observed = nullptr;
  unsigned long m_observer = 0;
};

}  // namespace raylab::vis
