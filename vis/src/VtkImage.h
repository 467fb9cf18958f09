#pragma once

#include "raylab/vis/Image.h"

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

namespace raylab::detail {

/// VTK image data with the same pixels (unsigned char RGB). VTK's rows run bottom-up,
/// Image's top-down, so the rows are flipped. Private to vis.
vtkSmartPointer<vtkImageData> toVtkImage(const Image& image);

}  // namespace raylab::detail
