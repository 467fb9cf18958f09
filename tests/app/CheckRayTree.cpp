// raylab_check_ray_tree: checks what `raylab trace` and `raylab animate` wrote, for the
// app's CTest tests.
//
//   raylab_check_ray_tree TREE.json SCENE.json RAYS
//       TREE is `raylab trace --json` of SCENE: it has RAYS segments, "rays" and
//       "rays_by_kind" agree with them, the tree is well formed (ids, parents, children),
//       the estimate in the header is the tree's propagated estimate, and it equals the
//       image renderer's value Tracer::trace for the same algorithm, seed, pixel and sample.
//   raylab_check_ray_tree --same A.png B.png
//       The two pictures are the same pixel for pixel.
//   raylab_check_ray_tree --frames DIR COUNT WIDTH HEIGHT
//       DIR holds exactly COUNT files frame_NNNN.png, numbered 0.. COUNT - 1, of that size.
//
// Prints what it measured; exit code 0 when every check passes, 1 otherwise.
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"
#include "raylab/vis/Image.h"
#include "raylab/vis/ImageIO.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace {

using namespace raylab;
using namespace raylab::vis;

int g_failures = 0;

void check(bool ok, const std::string& what) {
  std::cout << (ok ? "ok:     " : "FAILED: ") << what << "\n";
  if (!ok) ++g_failures;
}

bool same(const Vec3& a, const Vec3& b) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(a[c] - b[c]) > 1e-12 * std::max({1.0, std::abs(a[c]), std::abs(b[c])}))
      return false;
  return true;
}

void checkTree(const std::string& path, const std::string& scenePath, std::size_t rays) {
  RayTreeJson::Info info;
  const RayTree tree = RayTreeJson::load(path, &info);
  std::ifstream in(path);
  const auto doc = nlohmann::json::parse(in);
  check(tree.segments.size() == rays,
        std::to_string(tree.segments.size()) + " segments, expected " + std::to_string(rays));
  check(doc.at("rays").get<std::size_t>() == tree.segments.size(), "\"rays\" counts the segments");
  std::size_t byKind = 0;
  for (const auto& [kind, n] : doc.at("rays_by_kind").items()) byKind += n.get<std::size_t>();
  check(byKind == tree.segments.size(), "\"rays_by_kind\" adds up to the segments");
  bool formed = !tree.segments.empty() && tree.segments[0].parent == -1;
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const RaySegment& s = tree.segments[i];
    formed = formed && s.id == int(i) && (i == 0 || (s.parent >= 0 && s.parent < int(i)));
    for (int c = 0; c < s.childCount; ++c) {
      const int child = s.firstChild + c;
      formed = formed && child > int(i) && child < int(tree.segments.size()) &&
               tree.segments[std::size_t(child)].parent == int(i);
    }
  }
  check(formed, "ids, parents and children form a tree");
  RayTree propagated = tree;
  propagated.propagate();
  check(same(info.estimate, propagated.estimate()), "header estimate " + toString(info.estimate) +
                                                        " = propagated " +
                                                        toString(propagated.estimate()));

  const Scene scene = SceneIO::load(scenePath);
  RenderSettings settings = scene.render;
  const auto algorithm = parseAlgorithm(info.algorithm);
  check(algorithm.has_value(), "algorithm '" + info.algorithm + "' is known");
  if (!algorithm) return;
  settings.algorithm = *algorithm;
  settings.seed = info.seed;
  const Tracer tracer(scene, settings);
  const Vec3 rendered = tracer.trace(tree.pixelX, tree.pixelY, tree.sample);
  check(same(info.estimate, rendered),
        "estimate = the renderer's sample value " + toString(rendered));
}

void checkSame(const std::string& a, const std::string& b) {
  const SrgbImage x = vis::readPng(a), y = vis::readPng(b);
  check(x.width == y.width && x.height == y.height,
        "same size " + x.toString() + " " + y.toString());
  if (x.width != y.width || x.height != y.height) return;
  std::size_t differ = 0;
  for (int j = 0; j < x.height; ++j)
    for (int i = 0; i < x.width; ++i) differ += x.at(i, j) != y.at(i, j);
  check(differ == 0, std::to_string(differ) + " pixels differ");
}

/// `captioned` is `plain` with a caption along its bottom: the same size, the same pixels
/// above the bottom third, and over a hundred pixels changed within it (the words). A caption
/// too long for one line wraps onto more lines at its full size (issue 33 item 9: it used to
/// shrink), so at 160 x 120 two lines reach above the bottom fifth.
void checkCaptioned(const std::string& captioned, const std::string& plain) {
  const SrgbImage x = vis::readPng(captioned), y = vis::readPng(plain);
  check(x.width == y.width && x.height == y.height,
        "same size " + x.toString() + " " + y.toString());
  if (x.width != y.width || x.height != y.height) return;
  const int band = x.height - x.height / 3;
  std::size_t above = 0, within = 0;
  for (int j = 0; j < x.height; ++j)
    for (int i = 0; i < x.width; ++i)
      if (x.at(i, j) != y.at(i, j)) (j < band ? above : within)++;
  check(above == 0, std::to_string(above) + " pixels differ above the caption band");
  check(within > 100, std::to_string(within) + " pixels of the caption band differ (> 100)");
}

void checkFrames(const std::string& dir, int count, int width, int height) {
  int found = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    ++found;
    (void)entry;
  }
  check(found == count, std::to_string(found) + " files, expected " + std::to_string(count));
  for (int f = 0; f < count; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", f);
    const std::string path = (std::filesystem::path(dir) / name).string();
    if (!std::filesystem::exists(path)) {
      check(false, path + " exists");
      continue;
    }
    const SrgbImage image = vis::readPng(path);
    if (image.width != width || image.height != height)
      check(false, path + " is " + image.toString());
  }
  check(true, "frames checked");
}

}  // namespace

int main(int argc, char** argv) {
  const std::string usage =
      "usage: raylab_check_ray_tree TREE.json SCENE.json RAYS | --same A.png B.png |"
      " --frames DIR COUNT WIDTH HEIGHT | --captioned CAPTIONED.png PLAIN.png\n"
      "       | --other-caption ZH.png EN.png (one frame, captions in two languages)\n";
  try {
    const std::string first = argc > 1 ? argv[1] : "";
    if (first == "--same" && argc == 4) {
      checkSame(argv[2], argv[3]);
    } else if ((first == "--captioned" || first == "--other-caption") && argc == 4) {
      checkCaptioned(argv[2], argv[3]);
    } else if (first == "--frames" && argc == 6) {
      checkFrames(argv[2], std::stoi(argv[3]), std::stoi(argv[4]), std::stoi(argv[5]));
    } else if (argc == 4 && first.rfind("--", 0) != 0) {
      checkTree(argv[1], argv[2], std::stoul(argv[3]));
    } else {
      std::cerr << usage;
      return 2;
    }
  } catch (const std::exception& e) {
    std::cout << "FAILED: " << e.what() << "\n";
    return 1;
  }
  return g_failures == 0 ? 0 : 1;
}
