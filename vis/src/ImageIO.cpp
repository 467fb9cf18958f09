#include "raylab/vis/ImageIO.h"

#include "VtkImage.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkSmartPointer.h>

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace raylab {

Image ImageIO::readPng(const std::string& path) {
  // Step 1: refuse what is not a readable PNG before VTK prints its own warnings.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw Error(path + ": no such file");
  }
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str())) {
    throw Error(path + ": not a PNG file");
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* data = reader->GetOutput();
  int dims[3] = {0, 0, 0};
  data->GetDimensions(dims);
  const int channels = data->GetNumberOfScalarComponents();
  if (dims[0] <= 0 || dims[1] <= 0 || data->GetScalarType() != VTK_UNSIGNED_CHAR || channels < 1 ||
      channels > 4) {
    throw Error(path + ": unsupported PNG (need 8-bit grey, grey+alpha, RGB or RGBA)");
  }

  // Step 2: copy, flipping VTK's bottom-up rows and dropping alpha / expanding grey.
  Image image(dims[0], dims[1]);
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

void ImageIO::writePng(const Image& image, const std::string& path) {
  if (image.empty()) throw Error(path + ": cannot write an empty image");

  // Step 1: VTK image data, rows bottom-up.
  const vtkSmartPointer<vtkImageData> data = detail::toVtkImage(image);

  // Step 2: write beside the target, then rename, so a failure leaves no half file.
  const std::filesystem::path target(path);
  const std::filesystem::path parent = target.has_parent_path() ? target.parent_path() : ".";
  std::error_code ec;
  if (!std::filesystem::is_directory(parent, ec)) {
    throw Error(path + ": cannot write: folder " + parent.string() + " does not exist");
  }
  const std::string temporary = path + ".part.png";
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(temporary.c_str());
  writer->SetInputData(data);
  writer->Write();
  if (writer->GetErrorCode() != 0 || !std::filesystem::is_regular_file(temporary, ec) ||
      std::filesystem::file_size(temporary, ec) == 0) {
    std::filesystem::remove(temporary, ec);
    throw Error(path + ": cannot write the PNG file (permissions or disk space?)");
  }
  std::filesystem::rename(temporary, target, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw Error(path + ": cannot write: " + ec.message());
  }
}

}  // namespace raylab
