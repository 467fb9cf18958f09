#pragma once

#include "raylab/vis/Image.h"

#include <vtkImageData.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>

namespace raylab::detail {

/// VTK image data with the same pixels (unsigned char RGB). VTK's rows run bottom-up,
/// Image's top-down, so the rows are flipped. Private to vis.
vtkSmartPointer<vtkImageData> toVtkImage(const Image& image);

/// The back buffer of `window` (already rendered at width x height) as an Image, rows
/// flipped to top-down. Private to vis: every offscreen picture is read through here.
Image grabWindow(vtkRenderWindow* window, int width, int height);

}  // namespace raylab::detail
