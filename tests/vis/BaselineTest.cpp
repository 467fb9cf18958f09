#include "BaselineTest.h"

#include "raylab/vis/ImageIO.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace raylab::testing {

using namespace raylab::vis;  // the tests speak vis's types unqualified

void expectMatchesBaseline(const SrgbImage& image, const std::string& name, double threshold) {
  const std::filesystem::path baseline =
      std::filesystem::path(RAYLAB_BASELINE_DIR) / (name + ".png");
  const std::filesystem::path output = std::filesystem::path(RAYLAB_TEMP_DIR) / (name + ".png");
  std::filesystem::create_directories(output.parent_path());

  // Step 1: no baseline yet: keep the output for a human to look at and bless.
  if (!std::filesystem::exists(baseline)) {
    vis::writePng(image, output.string());
    ADD_FAILURE() << "no baseline " << baseline << "; wrote " << output
                  << ". Look at it; if it is right, copy it to tests/baselines/ and commit it.";
    return;
  }

  // Step 2: compare on compareImages' scale; keep the output when it differs too much.
  const SrgbImage expected = vis::readPng(baseline.string());
  const double error = compareImages(image, expected);
  if (error > threshold) {
    vis::writePng(image, output.string());
    ADD_FAILURE() << "rendering differs from baseline " << baseline << ": error " << error
                  << " > threshold " << threshold << "; output " << image.width << "x"
                  << image.height << ", baseline " << expected.width << "x" << expected.height
                  << "; output written to " << output;
  }
}

}  // namespace raylab::testing
