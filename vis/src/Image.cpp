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

namespace raylab {

Image::Image(int w, int h) : width(std::max(w, 0)), height(std::max(h, 0)) {
  rgb.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 0);
}

Rgb8 Image::at(int x, int y) const {
  RAYLAB_DCHECK(x >= 0 && x < width && y >= 0 && y < height);
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void Image::set(int x, int y, const Rgb8& colour) {
  RAYLAB_DCHECK(x >= 0 && x < width && y >= 0 && y < height);
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  rgb[i] = colour[0];
  rgb[i + 1] = colour[1];
  rgb[i + 2] = colour[2];
}

int Image::distinctColours() const {
  std::unordered_set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
    colours.insert((std::uint32_t{rgb[i]} << 16) | (std::uint32_t{rgb[i + 1]} << 8) |
                   std::uint32_t{rgb[i + 2]});
  }
  return static_cast<int>(colours.size());
}

std::string Image::toString() const {
  return "Image(" + std::to_string(width) + "x" + std::to_string(height) + ")";
}

vtkSmartPointer<vtkImageData> detail::toVtkImage(const Image& image) {
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

double compareImages(const Image& a, const Image& b) {
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

Image detail::grabWindow(vtkRenderWindow* window, int width, int height) {
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
  Image image(width, height);
  const auto* in = static_cast<const std::uint8_t*>(data->GetScalarPointer());
  const std::size_t rowBytes = std::size_t(width) * 3;
  for (int y = 0; y < height; ++y)
    std::memcpy(image.rgb.data() + std::size_t(y) * rowBytes,
                in + std::size_t(height - 1 - y) * rowBytes, rowBytes);
  return image;
}

}  // namespace raylab
