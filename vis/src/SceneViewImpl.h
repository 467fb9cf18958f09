#pragma once

// SceneView's private parts, shared by its files (SceneView.cpp: actors and overlays;
// ScenePicking.cpp: what is under a point of the picture).

#include "BvhActors.h"
#include "RayTreeActors.h"

#include "raylab/vis/SceneView.h"

#include <vtkNew.h>
#include <vtkProp.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <vector>

namespace raylab::vis {

/// The 3D view's background (linear RGB).
constexpr double kBackground[3] = {0.12, 0.13, 0.16};

struct SceneView::Impl {
  vtkNew<vtkRenderer> renderer;
  std::vector<vtkSmartPointer<vtkActor>> objects;     ///< One per scene object.
  std::vector<vtkSmartPointer<vtkActor>> highlights;  ///< Hidden outlines, one per object.
  vtkSmartPointer<vtkRenderWindow> offscreen;         ///< Created on first offscreen render.
  RayTreeActors rays{Vec3(kBackground[0], kBackground[1], kBackground[2])};  ///< Ray tree.
  BvhActors bvh;               ///< A mesh's BVH boxes.
  std::vector<bool> oneSided;  ///< Per object: drawn one-sided (culled from behind).
  std::vector<vtkSmartPointer<vtkProp>> crossings;  ///< setCrossings' line and marks.
  int crossingCount = 0;
  std::vector<int> crossed;  ///< Solids the crossings' ray passes through (drawn see-through).
  std::vector<vtkSmartPointer<vtkProp>> cloud;  ///< setSampleCloud's props; empty = scene.
  vtkSmartPointer<vtkTextActor> caption;        ///< setCaption's text; null when none.
  std::string captionText;  ///< setCaption's text as given (drawn wrapped to the width).
  Point3 inside{0.0};       ///< The room's inside, which one-sided surfaces face.

  ~Impl() {
    if (offscreen) {
      offscreen->RemoveRenderer(renderer);
      offscreen->Finalize();
    }
  }
};

}  // namespace raylab::vis
