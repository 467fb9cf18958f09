// raylab.render: whole images with core's Renderer, without the GIL, with a progress
// callback and cancellation (Ctrl-C, a callback returning False); image files and errors.

#include "Bindings.h"

#include "raylab/core/Comparison.h"
#include "raylab/core/FilePaths.h"
#include "raylab/core/Image.h"
#include "raylab/core/Limits.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/Renderer.h"
#include "raylab/vis/ImageIO.h"

#include <pybind11/stl.h>

#include <mutex>
#include <optional>

namespace raylab::python {
namespace {

/// The last progress report of the rendering thread, waiting to be handed to Python.
struct ProgressSlot {
  std::mutex mutex;
  bool fresh = false;
  double fraction = 0.0;
  FloatImage image;
};

}  // namespace

py::dict statsDict(const RenderStats& stats) {
  py::dict byKind;
  for (int k = 0; k < kRayKindCount; ++k)
    byKind[toString(RayKind(k))] = stats.rays.byKind[std::size_t(k)];
  py::dict out;
  out["rays"] = stats.rays.total();
  out["rays_by_kind"] = byKind;
  out["spp"] = stats.samplesPerPixel;
  out["seconds"] = stats.seconds;
  out["cancelled"] = stats.cancelled;
  out["time_limit_reached"] = stats.timeLimitReached;
  out["non_finite_samples"] = stats.nonFiniteSamples;
  out["capped_samples"] = stats.cappedSamples;
  return out;
}

namespace {

/// raylab.render: the scene camera's image with one algorithm.
void bindRenderFunction(py::module_& m) {
  m.def(
      "render",
      [](const SceneHandle& handle, std::optional<std::string> algorithm, std::optional<int> spp,
         std::optional<std::uint64_t> seed, int threads, std::optional<int> maxDepth,
         std::optional<bool> nee, std::optional<bool> mis, double timeLimit,
         const py::object& progress, const py::object& dtype, bool withStats) -> py::object {
        const RenderSettings settings =
            settingsFor(*handle.scene, {algorithm, spp, seed, maxDepth, nee, mis});
        warnAbout(*handle.scene);
        const py::dtype type = py::dtype::from_args(dtype);
        checkRange("threads", threads, 0, limits::kMaxThreads);
        // The renderer keeps a reference to the scene: hold the snapshot for the whole run.
        const std::shared_ptr<const Scene> scene = handle.scene;
        Renderer renderer(*scene, settings);
        renderer.setThreads(threads);
        renderer.setTimeLimit(timeLimit);
        ProgressSlot slot;
        const bool report = !progress.is_none();
        if (report)
          renderer.setProgress([&slot](double fraction, const FloatImage& image) {
            const std::lock_guard<std::mutex> lock(slot.mutex);
            slot.fresh = true;
            slot.fraction = fraction;
            slot.image = image;
          });
        FloatImage image;
        runInterruptible([&] { image = renderer.render(); },
                         [&] {
                           if (!report) return;
                           FloatImage latest;
                           double fraction = 0.0;
                           {
                             const std::lock_guard<std::mutex> lock(slot.mutex);
                             if (!slot.fresh) return;
                             slot.fresh = false;
                             fraction = slot.fraction;
                             latest = std::move(slot.image);
                           }
                           const py::object answer =
                               progress(fraction, imageToArray(std::move(latest), type));
                           if (py::isinstance<py::bool_>(answer) && !answer.cast<bool>())
                             renderer.cancel();
                         },
                         [&] { renderer.cancel(); });
        py::array array = imageToArray(std::move(image), type);
        if (!withStats) return std::move(array);
        return py::make_tuple(array, statsDict(renderer.stats()));
      },
      py::arg("scene"), py::kw_only(), py::arg("algorithm") = py::none(),
      py::arg("spp") = py::none(), py::arg("seed") = py::none(), py::arg("threads") = 0,
      py::arg("max_depth") = py::none(), py::arg("next_event_estimation") = py::none(),
      py::arg("multiple_importance") = py::none(), py::arg("time_limit") = 0.0,
      py::arg("progress") = py::none(), py::arg("dtype") = "float32", py::arg("with_stats") = false,
      R"(Renders the scene with core's Renderer: an H x W x 3 array of linear radiance, rows
from the top (float32: the renderer's own floats; dtype='float64' converts).

Settings not given come from the scene's render block. Deterministic: the same scene,
settings and seed give the same floats whatever `threads` is (0 = all). The GIL is
released while rendering. progress(fraction, image_so_far) is called on this thread as
progressive passes (1, 1, 2, 4, ... samples) end, with the latest one (passes ending within
the same 20 ms are reported once; the last report has fraction 1); returning False stops the render, which
then returns the image of the last complete pass. Ctrl-C stops it too and raises
KeyboardInterrupt. with_stats=True returns (image, stats) with the rays by kind, the spp
reached, the seconds, and whether it was cancelled.)");
}

/// The image helpers: display_rmse, rmse, write_image, read_pfm, to_srgb.
void bindImageFunctions(py::module_& m) {
  m.def(
      "display_rmse",
      [](const py::array& image, const py::array& reference) {
        return displayRmse(arrayToImage(image, "image"), arrayToImage(reference, "reference"));
      },
      py::arg("image"), py::arg("reference"),
      "The comparison's error: RMS difference as displayed (clamped to [0, 1], sRGB curve).");
  m.def(
      "rmse",
      [](const py::array& image, const py::array& reference) {
        return imageio::rmse(arrayToImage(image, "image"), arrayToImage(reference, "reference"));
      },
      py::arg("image"), py::arg("reference"), "RMS difference of linear radiance.");
  m.def(
      "write_image",
      [](const py::array& image, const std::string& path) {
        // 8-bit pictures (view_image, to_srgb) are already sRGB: written as they are. Read
        // as radiance, 128 would be 128 times white.
        if (image.dtype().is(py::dtype::of<std::uint8_t>())) {
          if (image.ndim() != 3 || image.shape(2) != 3)
            throw py::value_error("image must be an H x W x 3 array, not of shape " +
                                  py::str(py::getattr(image, "shape")).cast<std::string>());
          if (lowerExtension(path) != ".png")
            throw py::value_error(path +
                                  ": an 8-bit sRGB picture (uint8, as view_image and to_srgb "
                                  "give) is written as .png; .ppm and .pfm take linear "
                                  "radiance (floats)");
          const auto bytes =
              py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(image);
          SrgbImage srgb(int(image.shape(1)), int(image.shape(0)));
          std::copy(bytes.data(), bytes.data() + srgb.rgb.size(), srgb.rgb.begin());
          vis::writePng(srgb, path);
          return;
        }
        if (image.dtype().kind() != 'f')
          throw py::type_error(
              "image must hold floats (linear radiance, as render gives) or uint8 (an sRGB "
              "picture, as view_image gives), not " +
              py::str(py::object(image.dtype())).cast<std::string>());
        vis::writeImage(arrayToImage(image, "image"), path);
      },
      py::arg("image"), py::arg("path"),
      "Writes an H x W x 3 image: floats are linear radiance, written as .png / .ppm (sRGB) or "
      ".pfm (floats), as raylab render does; uint8 is an sRGB picture (view_image, to_srgb), "
      "written to .png as it is. Never leaves a half-written file.");
  m.def(
      "read_pfm",
      [](const std::string& path) {
        return imageToArray(imageio::readPfm(path), py::dtype::of<float>());
      },
      py::arg("path"), "A PFM file (e.g. from raylab render --out F.pfm) as an H x W x 3 array.");
  m.def(
      "to_srgb",
      [](const py::array& image) {
        const SrgbImage srgb = imageio::toSrgb(arrayToImage(image, "image"));
        py::array_t<std::uint8_t> out({srgb.height, srgb.width, 3});
        std::copy(srgb.rgb.begin(), srgb.rgb.end(), out.mutable_data());
        return out;
      },
      py::arg("image"), "The 8-bit sRGB picture of a linear image (as PNG files hold it).");
}

}  // namespace

void bindRender(py::module_& m) {
  bindRenderFunction(m);
  bindImageFunctions(m);
}

}  // namespace raylab::python
