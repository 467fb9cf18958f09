#pragma once

#include "raylab/core/Scene.h"
#include "raylab/vis/BvhStyle.h"

#include <vtkActor.h>
#include <vtkSmartPointer.h>

class vtkRenderer;

namespace raylab::vis {

/// The actors of a BvhStyle (BvhStyle.h): wireframe boxes in three line widths (level
/// boxes, boxes a ray entered, boxes it missed or culled). Private to vis; SceneView owns
/// one and rebuilds it when the style or the scene changes.
struct BvhActors {
  BvhStyle style;
  vtkSmartPointer<vtkActor> levels;   ///< Boxes of the levels (no ray), per-box colours.
  vtkSmartPointer<vtkActor> entered;  ///< Boxes the ray entered, thick, per-box colours.
  vtkSmartPointer<vtkActor> skipped;  ///< Boxes the ray missed or culled, thin, greys.
  BvhSummary summary;                 ///< What is drawn, counted.

  BvhActors();
  /// Adds the actors to `renderer` (once per scene: SceneView::setScene clears props).
  void addTo(vtkRenderer* renderer) const;
  /// Rebuilds the boxes of `style` for `scene`; an object that is not a mesh draws nothing.
  void build(const Scene& scene, const BvhStyle& newStyle);
};

}  // namespace raylab::vis
