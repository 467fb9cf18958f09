#include "raylab/vis/ImageIO.h"

#include "VtkImage.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/FilePaths.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <filesystem>
#include <system_error>

namespace raylab::vis {

SrgbImage readPng(const std::string& path) {
  // Step 1: refuse what is not a readable PNG before VTK prints its own warnings.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw ImageError(path + ": no such file");
  }
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str())) {
    throw ImageError(path + ": not a PNG file");
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* data = reader->GetOutput();
  int dims[3] = {0, 0, 0};
  data->GetDimensions(dims);
  const int channels = data->GetNumberOfScalarComponents();
  if (dims[0] <= 0 || dims[1] <= 0 || data->GetScalarType() != VTK_UNSIGNED_CHAR || channels < 1 ||
      channels > 4) {
    throw ImageError(path + ": unsupported PNG (need 8-bit grey, grey+alpha, RGB or RGBA)");
  }

  // Step 2: copy, flipping VTK's bottom-up rows and dropping alpha / expanding grey.
  SrgbImage image(dims[0], dims[1]);
  const auto* in = static_cast<const std::uint8_t*>(data->GetScalarPointer());
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* row =
        in + static_cast<std::size_t>(image.height - 1 - y) * image.width * channels;
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = row + static_cast<std::size_t>(x) * channels;
      if (channels >= 3) {
        image.set(x, y, {p[0], p[1], p[2]});
      } else {
        image.set(x, y, {p[0], p[0], p[0]});
      }
    }
  }
  return image;
}

void writePng(const SrgbImage& image, const std::string& path) {
  if (image.empty()) throw ImageError(path + ": cannot write an empty image");

  // Step 1: encode in memory (VTK image data has its rows bottom-up).
  const vtkSmartPointer<vtkImageData> data = detail::toVtkImage(image);
  vtkNew<vtkPNGWriter> writer;
  writer->WriteToMemoryOn();
  writer->SetInputData(data);
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  if (writer->GetErrorCode() != 0 || !bytes || bytes->GetNumberOfValues() == 0)
    throw ImageError(path + ": cannot encode the PNG image");

  // Step 2: write it beside the target, then rename: never a half-written file.
  const std::string encoded(reinterpret_cast<const char*>(bytes->GetPointer(0)),
                            std::size_t(bytes->GetNumberOfValues()));
  if (const auto problem = writeFileAtomically(path, encoded))
    throw ImageError(path + ": " + *problem);
}

bool isImageFile(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".png" || ext == ".ppm" || ext == ".pfm";
}

void writeImage(const FloatImage& image, const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".pfm") {
    imageio::writePfm(image, path);
  } else if (ext == ".ppm") {
    imageio::writePpm(image, path);
  } else if (ext == ".png") {
    writePng(imageio::toSrgb(image), path);
  } else {
    throw ImageError(path + ": unknown image format '" + ext +
                     "' (the file name must end in .png, .ppm or .pfm)");
  }
}

}  // namespace raylab::vis
