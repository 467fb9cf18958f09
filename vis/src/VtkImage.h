#pragma once

#include "raylab/vis/Image.h"

#include <vtkImageData.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>

namespace raylab::vis::detail {

/// VTK image data with the same pixels (unsigned char RGB). VTK's rows run bottom-up,
/// SrgbImage's top-down, so the rows are flipped. Private to vis.
vtkSmartPointer<vtkImageData> toVtkImage(const SrgbImage& image);

/// The back buffer of `window` (already rendered at width x height) as an SrgbImage, rows
/// flipped to top-down. Private to vis: every offscreen picture is read through here.
SrgbImage grabWindow(vtkRenderWindow* window, int width, int height);

}  // namespace raylab::vis::detail
