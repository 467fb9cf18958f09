#pragma once

#include "raylab/core/Image.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Types.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>

/// \file Bindings.h
/// What the files of the Python module share: the scene handle every call takes, the
/// conversions between glm vectors, images and Python values, and one bind function per
/// file (Module.cpp calls them in order).

namespace pybind11::detail {

/// glm::dvec2 / dvec3 (Vec2, Point3, Vec3, Normal3) to and from Python: any sequence of
/// numbers of the right length in, a tuple of floats out.
template <glm::length_t N>
struct type_caster<glm::vec<N, double, glm::defaultp>> {
  using Vector = glm::vec<N, double, glm::defaultp>;
  PYBIND11_TYPE_CASTER(Vector, const_name("tuple[float, ...]"));

  bool load(handle source, bool convert) {
    if (!isinstance<sequence>(source) || isinstance<str>(source)) return false;
    const sequence items = reinterpret_borrow<sequence>(source);
    if (items.size() != std::size_t(N)) return false;
    for (glm::length_t i = 0; i < N; ++i) {
      make_caster<double> number;
      if (!number.load(items[std::size_t(i)], convert)) return false;
      value[i] = cast_op<double>(number);
    }
    return true;
  }
  static handle cast(const Vector& v, return_value_policy, handle) {
    tuple out(N);
    for (glm::length_t i = 0; i < N; ++i) out[std::size_t(i)] = float_(v[i]);
    return out.release();
  }
};

}  // namespace pybind11::detail

namespace raylab::python {

namespace py = pybind11;

/**
 * \brief A scene as Python holds it: an immutable snapshot and the name its messages
 * start with.
 *
 * Edits (PyScene.cpp) replace the snapshot with the edited scene, so a render or trace
 * that took the old snapshot keeps it alive and unchanged while it runs without the GIL.
 */
struct SceneHandle {
  std::shared_ptr<const Scene> scene;  ///< Never null.
  std::string origin;  ///< The file, or "untitled.json" (as the window's unsaved scene).
};

/// A traced pixel sample and what it was traced in (raylab.Trace). Trace and Segment
/// objects share it, so a segment taken from a trace stays valid after the trace is gone.
struct TraceData {
  std::shared_ptr<const Scene> scene;
  RenderSettings settings;
  PixelTrace trace;
};

/// The render settings of `scene`'s render block with the keyword arguments that are given.
struct SettingsOverrides {
  std::optional<std::string> algorithm;  ///< an algorithm's word (AlgorithmInfo.h, kAllAlgorithms)
  std::optional<int> spp;
  std::optional<std::uint64_t> seed;
  std::optional<int> maxDepth;
  std::optional<bool> nextEventEstimation;
  std::optional<bool> multipleImportance;
};
/// ValueError "NAME must be in LOWEST..HIGHEST, not VALUE" when value is outside (counts
/// from Python are checked against Limits.h before any work, issue 38).
void checkRange(const char* name, long long value, long long lowest, long long highest);
/// The scene's settings with `overrides` applied; an unknown algorithm or a non-positive
/// spp raises ValueError naming the value.
RenderSettings settingsFor(const Scene& scene, const SettingsOverrides& overrides);
/// The algorithm named `name`; ValueError listing the four names otherwise.
Algorithm algorithmNamed(const std::string& name);
/// Python's UserWarning for each of sceneWarnings(scene) (a scene that renders black or
/// empty), as the command line warns on stderr; an error when warnings are errors.
void warnAbout(const Scene& scene);

/// (x, y, z) as a Python tuple of floats.
py::tuple toTuple(const Vec3& v);
/// A sequence of three numbers as a vector; ValueError naming `what` otherwise.
Vec3 toVec3(const py::handle& value, const char* what);

/// The image as an H x W x 3 array of `dtype` (float32: the renderer's own floats, moved
/// into the array without a copy; float64: converted). Rows from the top.
py::array imageToArray(FloatImage image, const py::dtype& dtype);
/// An H x W x 3 array (any float or integer type) as a FloatImage; ValueError otherwise.
FloatImage arrayToImage(const py::array& array, const char* what);
/// A render's figures as a dict: rays, rays_by_kind, spp, seconds, cancelled,
/// time_limit_reached, non_finite_samples, capped_samples (render() and the comparison's
/// algorithms).
py::dict statsDict(const RenderStats& stats);

/**
 * \brief Runs `work` on a worker thread while the calling thread, without the GIL, waits
 * for it: every 20 ms it takes the GIL back to run Python's signal handlers
 * (PyErr_CheckSignals, so Ctrl-C in a terminal or a notebook arrives) and `poll` (which
 * delivers progress to Python callbacks on the calling thread).
 *
 * When a signal handler or `poll` raises, `cancel` is called, the worker is waited for and
 * the Python error is raised. An exception thrown by `work` is rethrown here.
 */
void runInterruptible(const std::function<void()>& work, const std::function<void()>& poll,
                      const std::function<void()>& cancel);

void bindGeometry(py::module_& m);
void bindScene(py::module_& m);
void bindRender(py::module_& m);
void bindTrace(py::module_& m);
void bindCompare(py::module_& m);
void bindVis(py::module_& m);
void bindStudent(py::module_& m);

}  // namespace raylab::python
