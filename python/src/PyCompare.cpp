// raylab.compare: the four algorithms on one scene against a path-traced reference (core's
// Comparison), as a dict of images, figures and convergence series (NumPy arrays).

#include "Bindings.h"

#include "raylab/core/Comparison.h"
#include "raylab/core/Image.h"
#include "raylab/core/Limits.h"

#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <optional>
#include <vector>

namespace raylab::python {
namespace {

/// Thrown from the comparison's progress callback to stop it. The callback runs on the
/// renderer's calling thread after a pass (Renderer::Progress); the renderer stops its
/// workers and lets the exception through once they have left, so it unwinds through
/// Comparison::run without leaving work behind.
struct ComparisonStopped {};

py::dict seriesDict(const std::vector<ConvergencePoint>& series) {
  const py::ssize_t n = py::ssize_t(series.size());
  py::array_t<int> spp(n);
  py::array_t<double> seconds(n), rmse(n), rmseLinear(n);
  py::array_t<std::uint64_t> rays(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const ConvergencePoint& p = series[std::size_t(i)];
    spp.mutable_at(i) = p.samplesPerPixel;
    seconds.mutable_at(i) = p.seconds;
    rays.mutable_at(i) = p.rays;
    rmse.mutable_at(i) = p.rmse;
    rmseLinear.mutable_at(i) = p.rmseLinear;
  }
  py::dict out;
  out["spp"] = spp;
  out["seconds"] = seconds;
  out["rays"] = rays;
  out["rmse"] = rmse;
  out["rmse_linear"] = rmseLinear;
  return out;
}

py::dict resultDict(ComparisonResult result, const py::dtype& dtype) {
  py::dict out;
  out["scene"] = result.sceneName;
  out["width"] = result.width;
  out["height"] = result.height;
  out["mode"] = result.compare.equalTime() ? "equal time" : "equal samples";
  out["seed"] = result.settings.seed;
  out["json"] = comparisonJson(result);
  py::dict reference;
  reference["spp"] = result.reference.samplesPerPixel;
  reference["seed"] = result.reference.seed;
  reference["file"] = result.reference.file;
  reference["seconds"] = result.reference.seconds;
  reference["too_noisy"] = referenceTooNoisy(result);
  reference["image"] = imageToArray(std::move(result.reference.image), dtype);
  out["reference"] = reference;
  py::list algorithms;
  for (AlgorithmFigures& figures : result.algorithms) {
    py::dict a;
    a["algorithm"] = toString(figures.algorithm);
    a["title"] = algorithmTitle(figures.algorithm);
    a["stats"] = statsDict(figures.stats);
    a["rmse"] = figures.rmse;
    a["rmse_linear"] = figures.rmseLinear;
    a["series"] = seriesDict(figures.series);
    a["image"] = imageToArray(std::move(figures.image), dtype);
    algorithms.append(a);
  }
  out["algorithms"] = algorithms;
  return out;
}

/// compare()'s keyword arguments as the comparison's settings (the default algorithms when
/// none are named).
ComparisonSettings comparisonSettings(int spp, double seconds,
                                      const std::optional<std::vector<std::string>>& algorithms,
                                      int referenceSpp, int threads) {
  ComparisonSettings compare;
  compare.samplesPerPixel = spp;
  compare.secondsPerAlgorithm = seconds;
  compare.referenceSamplesPerPixel = referenceSpp;
  compare.threads = threads;
  if (algorithms) {
    compare.algorithms.clear();
    for (const std::string& name : *algorithms) compare.algorithms.push_back(algorithmNamed(name));
  }
  return compare;
}

/// The reference compare() was given: a PFM path, an array (finite numbers only), or None
/// (the comparison renders one).
void setReference(Comparison& comparison, const py::object& reference) {
  if (py::isinstance<py::str>(reference)) {
    const std::string file = reference.cast<std::string>();
    comparison.setReference(imageio::readPfm(file), file);
  } else if (!reference.is_none()) {
    FloatImage image = arrayToImage(reference, "reference");
    // A NaN or infinite reference gave finite error figures (issue 38).
    for (const glm::vec3& p : image.pixels)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw py::value_error("reference must hold finite numbers (it holds NaN or inf)");
    comparison.setReference(std::move(image), "array");
  }
}

}  // namespace

void bindCompare(py::module_& m) {
  m.def(
      "compare",
      [](const SceneHandle& handle, int spp, double seconds,
         std::optional<std::vector<std::string>> algorithms, const py::object& reference,
         int referenceSpp, int threads, std::optional<std::uint64_t> seed,
         std::optional<int> maxDepth, const py::object& progress, const py::object& dtype) {
        checkRange("spp", spp, 1, limits::kMaxSamplesPerPixel);
        checkRange("reference_spp", referenceSpp, 0, limits::kMaxSamplesPerPixel);
        checkRange("threads", threads, 0, limits::kMaxThreads);
        const std::shared_ptr<const Scene> scene = handle.scene;
        const RenderSettings settings = settingsFor(
            *scene, {std::nullopt, std::nullopt, seed, maxDepth, std::nullopt, std::nullopt});
        warnAbout(*scene);
        const ComparisonSettings compare =
            comparisonSettings(spp, seconds, algorithms, referenceSpp, threads);
        const py::dtype type = py::dtype::from_args(dtype);
        Comparison comparison(*scene, settings, compare);
        setReference(comparison, reference);

        // Progress: the comparison's thread queues its reports here for this thread.
        std::mutex mutex;
        std::vector<std::tuple<std::string, double, int>> reports;
        std::atomic<bool> stop{false};
        comparison.setProgress([&](const std::string& stage, double fraction, int samples) {
          if (stop) throw ComparisonStopped{};
          const std::lock_guard<std::mutex> lock(mutex);
          reports.emplace_back(stage, fraction, samples);
        });
        ComparisonResult result;
        runInterruptible(
            [&] {
              try {
                result = comparison.run();
              } catch (const ComparisonStopped&) {
              }
            },
            [&] {
              std::vector<std::tuple<std::string, double, int>> waiting;
              {
                const std::lock_guard<std::mutex> lock(mutex);
                waiting.swap(reports);
              }
              if (progress.is_none()) return;
              for (const auto& [stage, fraction, samples] : waiting)
                progress(stage, fraction, samples);
            },
            [&] { stop = true; });
        return resultDict(std::move(result), type);
      },
      py::arg("scene"), py::kw_only(), py::arg("spp") = 16, py::arg("seconds") = 0.0,
      py::arg("algorithms") = py::none(), py::arg("reference") = py::none(),
      py::arg("reference_spp") = 0, py::arg("threads") = 0, py::arg("seed") = py::none(),
      py::arg("max_depth") = py::none(), py::arg("progress") = py::none(),
      py::arg("dtype") = "float32",
      R"(The side-by-side comparison (raylab compare): each algorithm at `spp` samples (or for
`seconds` each: equal time) against a path-traced reference (rendered at reference_spp,
0 = the default rule, or given as an array or a PFM path). Returns a dict: scene, width,
height, mode, seed, json (raylab compare --json's text), reference {image, spp, seed, file,
seconds, too_noisy} and algorithms, a list of {algorithm, title, image, stats, rmse,
rmse_linear, series} where series holds the convergence curve as arrays (spp, seconds,
rays, rmse, rmse_linear), one point per pass. progress(stage, fraction, spp) is called on
this thread after every pass of every stage; Ctrl-C or an exception from it stops the comparison. The GIL is released.)");
}

}  // namespace raylab::python
