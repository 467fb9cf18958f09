#pragma once

#include "raylab/core/Lesson.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Types.h"

#include <vtkProp.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

/// \file TeachingOverlays.h
/// Props SceneView draws over (or instead of) the scene for single lesson steps (private
/// to vis): the hits along one ray, and a sampler's directions as a point cloud.

namespace raylab::vis {

/// Colours of the crossing marks: entering a solid, leaving it, crossing an open surface.
constexpr double kEnteringColour[3] = {0.25, 0.85, 0.35};
constexpr double kLeavingColour[3] = {0.95, 0.25, 0.25};
constexpr double kOpenSurfaceColour[3] = {0.95, 0.8, 0.2};
/// Colour of the sample cloud's points.
constexpr double kSampleColour[3] = {1.0, 0.55, 0.1};

/// The ray from `origin` along `direction` drawn on through its last crossing, and a ball
/// of radius `markRadius` at each crossing, coloured entering / leaving / open surface.
std::vector<vtkSmartPointer<vtkProp>> crossingProps(const std::vector<SceneCrossing>& crossings,
                                                    const Point3& origin, const Vec3& direction,
                                                    double markRadius);

/// Unit directions drawn as points on the unit hemisphere over a grey disk (the surface),
/// with the normal (+z) as an arrow, named `axisLabel` in `language` at its tip (nothing
/// when empty); `fullSphere` draws the whole sphere's outline.
/// Local z is drawn as z: look with view-up (0, 0, 1) (sampleCloudCamera).
std::vector<vtkSmartPointer<vtkProp>> sampleCloudProps(const std::vector<Vec3>& directions,
                                                       bool fullSphere,
                                                       const std::string& axisLabel = {},
                                                       Language language = Language::English);

}  // namespace raylab::vis
