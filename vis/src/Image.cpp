#include "raylab/vis/Image.h"

#include "VtkImage.h"

#include "raylab/core/Check.h"

#include <vtkImageData.h>
#include <vtkImageDifference.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cstring>
#include <unordered_set>

namespace raylab::vis {

vtkSmartPointer<vtkImageData> detail::toVtkImage(const SrgbImage& image) {
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<std::uint8_t*>(data->GetScalarPointer());
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 3;
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(out + static_cast<std::size_t>(image.height - 1 - y) * rowBytes,
                image.rgb.data() + static_cast<std::size_t>(y) * rowBytes, rowBytes);
  }
  return data;
}

double compareImages(const SrgbImage& a, const SrgbImage& b) {
  // Step 1: pictures of different sizes are as different as it gets.
  if (a.width != b.width || a.height != b.height) return 1.0;
  if (a.empty()) return 0.0;

  // Step 2: VTK's regression-test difference (shift- and anti-aliasing tolerant).
  vtkNew<vtkImageDifference> difference;
  difference->SetInputData(detail::toVtkImage(a));
  difference->SetImageData(detail::toVtkImage(b));
  difference->SetThreshold(kCompareChannelTolerance);
  difference->Update();

  // Step 3: from a sum over pixels to a mean per pixel, so the scale is size-independent.
  return difference->GetThresholdedError() / (static_cast<double>(a.width) * a.height);
}

SrgbImage detail::grabWindow(vtkRenderWindow* window, int width, int height) {
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkImageData* data = grab->GetOutput();
  int dims[3] = {0, 0, 0};
  data->GetDimensions(dims);
  RAYLAB_CHECK_EQ(dims[0], width);
  RAYLAB_CHECK_EQ(dims[1], height);
  RAYLAB_CHECK_EQ(data->GetNumberOfScalarComponents(), 3);
  SrgbImage image(width, height);
  const auto* in = static_cast<const std::uint8_t*>(data->GetScalarPointer());
  const std::size_t rowBytes = std::size_t(width) * 3;
  for (int y = 0; y < height; ++y)
    std::memcpy(image.rgb.data() + std::size_t(y) * rowBytes,
                in + std::size_t(height - 1 - y) * rowBytes, rowBytes);
  return image;
}

SrgbImage enlargedToFit(const SrgbImage& image, int maxWidth, int maxHeight) {
  if (image.empty()) return image;
  const int k = std::max(1, std::min(maxWidth / image.width, maxHeight / image.height));
  if (k == 1) return image;
  SrgbImage big(image.width * k, image.height * k);
  for (int y = 0; y < big.height; ++y)
    for (int x = 0; x < big.width; ++x) big.set(x, y, image.at(x / k, y / k));
  return big;
}

}  // namespace raylab::vis
