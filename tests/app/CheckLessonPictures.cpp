// raylab_check_lesson_pictures: compares the step pictures `raylab lesson FILE --out DIR`
// wrote with the lesson's baselines (the lessons' CTest tests, labels app;lessons;render).
//
//   raylab_check_lesson_pictures LESSON.json DIR BASELINES [--bless | --other-language]
//
// For step N the picture is DIR/step-NN.png and its baseline BASELINES/step-NN.png, kept
// at half the size (2 x 2 pixels averaged: a lesson's baselines take a quarter of the
// space; the picture is halved the same way before it is compared).
//  - Deterministic steps (scene, inspector, samples and image views: the same scene,
//    settings and seed give the same pixels) must match their baseline within
//    vis::compareImages' default threshold of the baseline tests (2e-4, ~18 pixels of a
//    300x300 picture completely wrong; it forgives driver noise).
//  - Comparison and plot steps print measured times (and, at equal time, render as many
//    samples as the time allows), so they are checked for what must hold whatever the
//    timing: the size of the baseline, at most 5% of the pixels far from it (the figures'
//    text and the noise of the pictures move; a missing panel or a wrong colour scale
//    does not pass), and not a blank picture.
// --other-language: the pictures are the lesson in the other language than the baselines
// (Chinese against the English ones): the same pictures but for their words, so the 3D
// views, images and point clouds are checked as timed ones (the words move at most a few
// percent of the pixels); comparisons and plots, mostly words at this size, for their
// size and for not being blank.
// --bless writes every picture, halved, over its baseline (after a deliberate change; look
// at them first). Prints one line per step; exit code 0 when every step passes.
#include "raylab/core/Lesson.h"
#include "raylab/vis/Image.h"
#include "raylab/vis/ImageIO.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace {

using namespace raylab;
namespace fs = std::filesystem;

constexpr double kDeterministicThreshold = 2e-4;
/// Timed views (equal-time comparisons, plots) change with the machine's speed and load:
/// their figures (ms, spp) and the noise of the panels that reach fewer samples in time.
/// On a machine with a load of 13 on 2 cores they were 6.3% far from the idle baseline; a
/// wrong picture (a black or missing panel, wrong colours) is far in well over a quarter.
constexpr double kTimedFarFraction = 0.10;
constexpr int kFar = 48;  ///< A channel this far from the baseline counts as different.

/// `image` at half the size, each pixel the mean of a 2 x 2 block (rounded).
SrgbImage halve(const SrgbImage& image) {
  SrgbImage half(std::max(1, image.width / 2), std::max(1, image.height / 2));
  for (int y = 0; y < half.height; ++y)
    for (int x = 0; x < half.width; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const int sx = std::min(2 * x + dx, image.width - 1);
            const int sy = std::min(2 * y + dy, image.height - 1);
            sum += image.at(sx, sy)[std::size_t(c)];
          }
        half.rgb[3 * (std::size_t(y) * half.width + x) + c] = std::uint8_t((sum + 2) / 4);
      }
  return half;
}

/// Fraction of pixels with some channel more than kFar from the other image's.
double farFraction(const SrgbImage& a, const SrgbImage& b) {
  if (a.width != b.width || a.height != b.height) return 1.0;
  int far = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const Rgb8 p = a.at(x, y), q = b.at(x, y);
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(p[c]) - int(q[c])) > kFar) {
          ++far;
          break;
        }
    }
  return double(far) / (double(a.width) * a.height);
}

/// Fraction of pixels that differ from the top-left pixel (the background).
double contentFraction(const SrgbImage& image) {
  const Rgb8 background = image.at(0, 0);
  int content = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) content += image.at(x, y) != background;
  return double(content) / (double(image.width) * image.height);
}

std::string stepName(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "step-%02zu.png", index + 1);
  return name;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc == 5 ? argv[4] : "";
  if (argc != 4 && !(argc == 5 && (mode == "--bless" || mode == "--other-language"))) {
    std::cerr << "usage: raylab_check_lesson_pictures LESSON.json DIR BASELINES "
                 "[--bless | --other-language]\n";
    return 2;
  }
  const bool bless = mode == "--bless";
  const bool otherLanguage = mode == "--other-language";
  int failures = 0;
  try {
    const Lesson lesson = LessonIO::load(argv[1]);
    const fs::path dir = argv[2], baselines = argv[3];
    if (bless) fs::create_directories(baselines);
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
      const LessonStep& step = lesson.steps[i];
      const std::string name = stepName(i);
      const fs::path picture = dir / name, baseline = baselines / name;
      if (bless) {
        vis::writePng(halve(vis::readPng(picture.string())), baseline.string());
        std::cout << "blessed " << baseline.string() << "\n";
        continue;
      }
      if (!fs::exists(baseline)) {
        std::cout << "FAILED: " << name << ": no baseline " << baseline.string()
                  << " (look at the picture, then run with --bless)\n";
        ++failures;
        continue;
      }
      const SrgbImage got = halve(vis::readPng(picture.string()));
      const SrgbImage want = vis::readPng(baseline.string());
      const bool timed =
          otherLanguage || step.view == LessonView::Compare || step.view == LessonView::Plot;
      bool ok = false;
      std::string what;
      if (!timed) {
        const double error = vis::compareImages(got, want);
        ok = error <= kDeterministicThreshold;
        what = "difference " + std::to_string(error) + " (threshold " +
               std::to_string(kDeterministicThreshold) + ")";
      } else {
        const bool words =
            otherLanguage && (step.view == LessonView::Compare || step.view == LessonView::Plot);
        const double far = words ? 0.0 : farFraction(got, want);
        const double content = contentFraction(got);
        ok = far <= kTimedFarFraction && content > 0.05 && got.width == want.width &&
             got.height == want.height;
        what = "timed view: " + std::to_string(100.0 * far) + "% of the pixels far from the " +
               "baseline (at most " + std::to_string(100.0 * kTimedFarFraction) + "%), " +
               std::to_string(100.0 * content) + "% not background";
      }
      std::cout << (ok ? "ok:     " : "FAILED: ") << name << " (" << toString(step.view)
                << "): " << what << "\n";
      if (!ok) ++failures;
    }
  } catch (const std::exception& e) {
    std::cerr << "raylab_check_lesson_pictures: " << e.what() << "\n";
    return 1;
  }
  return failures == 0 ? 0 : 1;
}
