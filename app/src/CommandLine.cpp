#include "CommandLine.h"

#include "ExitCodes.h"
#include "RenderCommand.h"
#include "SnapshotCommand.h"

#if RAYLAB_WITH_GUI
#include "WindowCommand.h"
#endif

#include <CLI/CLI.hpp>

#include <cstdint>
#include <iostream>

namespace raylab::app {

namespace {

constexpr int kMinSize = 16;
constexpr int kMaxSize = 8192;

const char* const kFooter =
    "Exit codes: 0 ok, 1 runtime error (bad scene file, unwritable output),\n"
    "            2 usage error, 3 internal error (please report it).\n"
    "Rendering needs an X server, also headless: run under xvfb-run -a.";

/// CLI11 check for --size.
std::string checkSize(const std::string& text) {
  if (parseSize(text)) return {};
  return "expected WIDTHxHEIGHT with each side in " + std::to_string(kMinSize) + ".." +
         std::to_string(kMaxSize) + ", e.g. 300x300";
}

}  // namespace

std::optional<std::pair<int, int>> parseSize(const std::string& text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos || x == 0 || x + 1 >= text.size()) return std::nullopt;
  const std::string w = text.substr(0, x);
  const std::string h = text.substr(x + 1);
  const auto digitsOnly = [](const std::string& s) {
    return s.size() <= 5 && s.find_first_not_of("0123456789") == std::string::npos;
  };
  if (!digitsOnly(w) || !digitsOnly(h)) return std::nullopt;
  const int width = std::stoi(w);
  const int height = std::stoi(h);
  if (width < kMinSize || width > kMaxSize || height < kMinSize || height > kMaxSize) {
    return std::nullopt;
  }
  return std::make_pair(width, height);
}

int runCommandLine(int argc, char** argv) {
  CLI::App cli{
      "RayLab: watch rays being traced, bounce by bounce, in 3D.\n"
      "With no subcommand, opens the window on the scene.",
      "raylab"};
  cli.footer(kFooter);
  cli.set_version_flag("--version", std::string("raylab ") + RAYLAB_VERSION);

  // The window (no subcommand).
  std::string windowScene;
  cli.add_option("--scene", windowScene, "Scene file to open (default: the built-in scene)");
  int quitAfterMs = -1;
  std::string screenshot;
  cli.add_option("--quit-after-ms", quitAfterMs,
                 "Close the window by itself this many ms after it is shown (tests)")
      ->group("Testing")
      ->check(CLI::Range(0, 3600000));
  cli.add_option("--screenshot", screenshot,
                 "Save a picture of the whole window to this PNG, then quit (tests)")
      ->group("Testing");
  std::string select;
  cli.add_option("--select", select, "Select this object (by name) when the window opens");

  // raylab snapshot
  SnapshotOptions snapshot;
  std::string size = "300x300";
  CLI::App* snapshotCommand =
      cli.add_subcommand("snapshot", "Render the window's 3D view offscreen to a PNG file");
  snapshotCommand->add_option("--out,-o", snapshot.out, "PNG file to write")->required();
  snapshotCommand->add_option("--scene", snapshot.scene,
                              "Scene file (default: the built-in scene)");
  snapshotCommand->add_option("--size", size, "Picture size WIDTHxHEIGHT")
      ->check(CLI::Validator(checkSize, "WxH"))
      ->capture_default_str();

  // raylab render
  RenderOptions render;
  std::string renderSize;
  std::string renderAlgorithm;
  int renderSpp = 0;
  std::uint64_t renderSeed = 0;
  CLI::App* renderCommand = cli.add_subcommand(
      "render", "Render the scene with a ray-tracing algorithm to an image file (no display)");
  renderCommand->footer(
      "Exit codes: 0 ok, 1 runtime error (bad scene file, unwritable output),\n"
      "            2 usage error, 3 internal error (please report it).\n"
      "Needs no display: the image is ray traced on the CPU. Progress goes to stderr.");
  renderCommand->add_option("--out,-o", render.out, "Image to write: .png, .ppm or .pfm (linear)")
      ->required()
      ->check(CLI::Validator(
          [](const std::string& path) {
            return isRenderOutput(path) ? std::string()
                                        : "the file name must end in .png, .ppm or .pfm";
          },
          "FILE"));
  renderCommand->add_option("--scene", render.scene, "Scene file (default: the built-in scene)");
  CLI::Option* algorithmOption =
      renderCommand
          ->add_option("--algorithm,-a", renderAlgorithm,
                       "raycast, whitted, distributed or path (default: the scene's)")
          ->check(CLI::IsMember({"raycast", "whitted", "distributed", "path"}));
  CLI::Option* sppOption =
      renderCommand->add_option("--spp", renderSpp, "Samples per pixel (default: the scene's)")
          ->check(CLI::Range(1, 1 << 20));
  CLI::Option* seedOption =
      renderCommand->add_option("--seed", renderSeed, "Random seed (default: the scene's)");
  renderCommand->add_option("--threads", render.threads, "Worker threads, 0 = all")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  CLI::Option* renderSizeOption =
      renderCommand
          ->add_option("--size", renderSize, "Image size WIDTHxHEIGHT (default: the scene's)")
          ->check(CLI::Validator(checkSize, "WxH"));

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version come here too, with CLI11's success code.
    return cli.exit(e) == 0 ? kExitOk : kExitUsage;
  }

  if (*snapshotCommand) {
    const auto wh = parseSize(size);
    snapshot.width = wh->first;
    snapshot.height = wh->second;
    if (snapshot.scene.empty()) snapshot.scene = windowScene;  // raylab --scene F snapshot
    return runSnapshot(snapshot);
  }

  if (*renderCommand) {
    if (*algorithmOption) render.algorithm = renderAlgorithm;
    if (*sppOption) render.spp = renderSpp;
    if (*seedOption) render.seed = renderSeed;
    if (*renderSizeOption) {
      const auto wh = parseSize(renderSize);
      render.width = wh->first;
      render.height = wh->second;
    }
    if (render.scene.empty()) render.scene = windowScene;  // raylab --scene F render
    return runRender(render);
  }

#if RAYLAB_WITH_GUI
  WindowOptions window;
  window.scene = windowScene;
  window.quitAfterMs = quitAfterMs;
  window.screenshot = screenshot;
  window.select = select;
  return runWindow(argc, argv, window);
#else
  std::cerr << "raylab: this build has no window (configured with RAYLAB_BUILD_GUI=OFF); "
               "use a subcommand, see raylab --help\n";
  return kExitUsage;
#endif
}

}  // namespace raylab::app
