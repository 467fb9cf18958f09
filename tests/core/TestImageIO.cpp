// Image files of the renderer: PFM (linear, round trip), PPM (tone mapped), the sRGB curve
// and the RMSE used by the convergence figures.
#include "raylab/core/Image.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace raylab {
namespace {

using ::testing::HasSubstr;

std::filesystem::path freshDir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(RAYLAB_TEMP_DIR) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/// A 3 x 2 image whose every channel is different.
FloatImage testImage() {
  FloatImage image(3, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) image.at(x, y) = glm::vec3(x + 10 * y, 0.5f * x, -1.0f * y);
  image.at(2, 1) = glm::vec3(1e-30f, 3.4e38f, 1.0f / 3.0f);
  return image;
}

TEST(ImageIO, 01_PfmRoundTripIsExact) {
  const auto dir = freshDir("imageio_pfm");
  const FloatImage image = testImage();
  imageio::writePfm(image, (dir / "a.pfm").string());
  const FloatImage back = imageio::readPfm((dir / "a.pfm").string());
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 2);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) EXPECT_EQ(back.pixels[i], image.pixels[i]);
  // Nothing but the file itself is left in the folder.
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
}

TEST(ImageIO, 02_PfmLayoutIsLittleEndianBottomRowFirst) {
  const auto dir = freshDir("imageio_pfm_layout");
  const FloatImage image = testImage();
  imageio::writePfm(image, (dir / "a.pfm").string());
  const std::string bytes = readBytes(dir / "a.pfm");
  const std::string header = "PF\n3 2\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 3 * 2 * 12);
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  // The first pixel stored is the bottom-left one: (0, 1) = (10, 0, -1).
  const unsigned char* data = reinterpret_cast<const unsigned char*>(bytes.data() + header.size());
  const std::uint32_t ten = 0x41200000;  // 10.0f
  EXPECT_EQ(data[0], ten & 0xff);
  EXPECT_EQ(data[3], ten >> 24);
  float red = 0.0f;
  std::memcpy(&red, data, 4);  // the test machine is little-endian
  EXPECT_EQ(red, 10.0f);
}

TEST(ImageIO, 03_ReadsBigEndianPfm) {
  const auto dir = freshDir("imageio_pfm_big");
  // 1 x 1, scale +1 (big-endian): 1.0f = 3f 80 00 00, 0.5f = 3f 00 00 00, -2 = c0 00 00 00.
  std::string bytes = "PF\n1 1\n1.0\n";
  const unsigned char data[] = {0x3f, 0x80, 0, 0, 0x3f, 0x00, 0, 0, 0xc0, 0x00, 0, 0};
  bytes.append(reinterpret_cast<const char*>(data), sizeof(data));
  std::ofstream(dir / "big.pfm", std::ios::binary) << bytes;
  const FloatImage image = imageio::readPfm((dir / "big.pfm").string());
  EXPECT_EQ(image.at(0, 0), glm::vec3(1.0f, 0.5f, -2.0f));
}

TEST(ImageIO, 04_ReadErrorsNameTheFile) {
  const auto dir = freshDir("imageio_errors");
  const auto message = [](const std::string& path) -> std::string {
    try {
      imageio::readPfm(path);
    } catch (const imageio::ReadError& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string missing = (dir / "missing.pfm").string();
  EXPECT_THAT(message(missing), HasSubstr(missing + ": cannot open"));
  std::ofstream(dir / "grey.pfm", std::ios::binary) << "Pf\n1 1\n-1.0\n1234";
  EXPECT_THAT(message((dir / "grey.pfm").string()), HasSubstr("not a colour PFM"));
  std::ofstream(dir / "short.pfm", std::ios::binary) << "PF\n2 2\n-1.0\n12345678";
  EXPECT_THAT(message((dir / "short.pfm").string()), HasSubstr("truncated"));
  std::ofstream(dir / "size.pfm", std::ios::binary) << "PF\n0 2\n-1.0\n";
  EXPECT_THAT(message((dir / "size.pfm").string()), HasSubstr("bad PFM header"));
}

TEST(ImageIO, 05_WriteErrorsLeaveNothingBehind) {
  const auto dir = freshDir("imageio_write_errors");
  const std::string path = (dir / "no" / "such" / "dir.pfm").string();
  try {
    imageio::writePfm(testImage(), path);
    FAIL() << "no error";
  } catch (const imageio::WriteError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path));
  }
  EXPECT_THROW(imageio::writePpm(FloatImage(), (dir / "empty.ppm").string()), imageio::WriteError);
  EXPECT_FALSE(std::filesystem::exists(dir / "empty.ppm"));
}

TEST(ImageIO, 06_SrgbCurve) {
  // The curve's ends, and both pieces meeting at the linear/curve boundary 0.0031308,
  // where 12.92 * 0.0031308 = 0.040450 (IEC 61966-2-1).
  EXPECT_EQ(imageio::srgbFromLinear(0.0), 0.0);
  EXPECT_EQ(imageio::srgbFromLinear(1.0), 1.0);
  EXPECT_NEAR(imageio::srgbFromLinear(0.0031308), 0.0404500, 1e-7);
  EXPECT_NEAR(1.055 * std::pow(0.0031308, 1.0 / 2.4) - 0.055, 0.0404500, 1e-6);
  // Continuous across it: no visible step between the two pieces.
  EXPECT_NEAR(imageio::srgbFromLinear(0.0031308 + 1e-10), imageio::srgbFromLinear(0.0031308), 1e-7);
  // 0.5 linear is 0.7354 in sRGB; 0.2140 linear is 0.5.
  EXPECT_NEAR(imageio::srgbFromLinear(0.5), 0.735357, 1e-6);
  EXPECT_NEAR(imageio::srgbFromLinear(0.214041), 0.5, 1e-6);
  // 8 bits: 0 -> 0, 1 -> 255, the boundary -> round(255 * 0.04045) = 10, 0.5 -> 188.
  EXPECT_EQ(imageio::toSrgb8(0.0), 0);
  EXPECT_EQ(imageio::toSrgb8(1.0), 255);
  EXPECT_EQ(imageio::toSrgb8(0.0031308), 10);
  EXPECT_EQ(imageio::toSrgb8(0.5), 188);
  // Clamped: above 1, below 0, NaN and infinity.
  EXPECT_EQ(imageio::toSrgb8(7.5), 255);
  EXPECT_EQ(imageio::toSrgb8(-0.25), 0);
  EXPECT_EQ(imageio::toSrgb8(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(imageio::toSrgb8(std::numeric_limits<double>::infinity()), 255);
}

TEST(ImageIO, 07_PpmIsToneMappedTopRowFirst) {
  const auto dir = freshDir("imageio_ppm");
  FloatImage image(2, 1);
  image.at(0, 0) = glm::vec3(0.0f, 0.5f, 1.0f);
  image.at(1, 0) = glm::vec3(2.0f, -1.0f, 0.0031308f);
  imageio::writePpm(image, (dir / "a.ppm").string());
  const std::string bytes = readBytes(dir / "a.ppm");
  const std::string header = "P6\n2 1\n255\n";
  ASSERT_EQ(bytes.size(), header.size() + 6);
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  const unsigned char expected[] = {0, 188, 255, 255, 0, 10};
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(static_cast<unsigned char>(bytes[header.size() + i]), expected[i]) << i;
  EXPECT_EQ(imageio::toSrgb(image).rgb, std::vector<std::uint8_t>(expected, expected + 6));
}

TEST(ImageIO, 08_Rmse) {
  FloatImage a(2, 1), b(2, 1);
  EXPECT_EQ(imageio::rmse(a, b), 0.0);
  // One channel off by 0.6 of six: sqrt(0.36 / 6).
  b.at(1, 0).g = 0.6f;
  EXPECT_NEAR(imageio::rmse(a, b), std::sqrt(0.36 / 6.0), 1e-7);
  // Every channel off by 1: 1.
  EXPECT_NEAR(imageio::rmse(FloatImage(2, 1),
                            [] {
                              FloatImage c(2, 1);
                              for (auto& p : c.pixels) p = glm::vec3(1.0f);
                              return c;
                            }()),
              1.0, 1e-12);
  EXPECT_THROW(imageio::rmse(a, FloatImage(1, 2)), std::invalid_argument);
}

}  // namespace
}  // namespace raylab
