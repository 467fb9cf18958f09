// The compiled part of the Python package `raylab`: its exceptions, the conversions the
// binding files share, and the waiting loop that lets Ctrl-C stop long C++ work.

#include "Bindings.h"

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Comparison.h"
#include "raylab/core/Exception.h"
#include "raylab/core/Limits.h"
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Shape.h"
#include "raylab/core/Text.h"
#include "raylab/vis/ImageIO.h"

#include <pybind11/stl.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace raylab::python {

Algorithm algorithmNamed(const std::string& name) {
  if (std::optional<Algorithm> algorithm = parseAlgorithm(name)) return *algorithm;
  throw py::value_error("unknown algorithm '" + name + "': use " + algorithmWordList());
}

void checkRange(const char* name, long long value, long long lowest, long long highest) {
  if (value < lowest || value > highest)
    throw py::value_error(std::string(name) + " must be in " + std::to_string(lowest) + ".." +
                          std::to_string(highest) + ", not " + std::to_string(value));
}

RenderSettings settingsFor(const Scene& scene, const SettingsOverrides& overrides) {
  RenderSettings settings = scene.render;
  if (overrides.algorithm) settings.algorithm = algorithmNamed(*overrides.algorithm);
  if (overrides.spp) {
    checkRange("spp", *overrides.spp, 1, limits::kMaxSamplesPerPixel);
    settings.samplesPerPixel = *overrides.spp;
  }
  if (overrides.seed) settings.seed = *overrides.seed;
  if (overrides.maxDepth) {
    checkRange("max_depth", *overrides.maxDepth, 0, limits::kMaxDepth);
    settings.maxDepth = *overrides.maxDepth;
  }
  if (overrides.nextEventEstimation) settings.nextEventEstimation = *overrides.nextEventEstimation;
  if (overrides.multipleImportance) settings.multipleImportance = *overrides.multipleImportance;
  return settings;
}

py::tuple toTuple(const Vec3& v) { return py::make_tuple(v.x, v.y, v.z); }

Vec3 toVec3(const py::handle& value, const char* what) {
  try {
    const std::vector<double> numbers = value.cast<std::vector<double>>();
    if (numbers.size() == 3) return Vec3(numbers[0], numbers[1], numbers[2]);
  } catch (const py::cast_error&) {
  }
  throw py::value_error(std::string(what) + " must be three numbers (x, y, z), not " +
                        py::repr(value).cast<std::string>());
}

py::array imageToArray(FloatImage image, const py::dtype& dtype) {
  const std::vector<py::ssize_t> shape{image.height, image.width, 3};
  if (dtype.is(py::dtype::of<float>())) {
    // The pixels move into a capsule the array keeps alive: no copy, no dangling view.
    auto* owned = new FloatImage(std::move(image));
    py::capsule owner(owned, [](void* p) { delete static_cast<FloatImage*>(p); });
    return py::array_t<float>(shape, reinterpret_cast<const float*>(owned->pixels.data()), owner);
  }
  if (dtype.is(py::dtype::of<double>())) {
    py::array_t<double> array(shape);
    double* out = array.mutable_data();
    for (const glm::vec3& p : image.pixels) {
      *out++ = p.r;
      *out++ = p.g;
      *out++ = p.b;
    }
    return std::move(array);
  }
  throw py::value_error("dtype must be float32 or float64, not " +
                        py::repr(py::object(dtype)).cast<std::string>());
}

void warnAbout(const Scene& scene) {
  for (const std::string& warning : sceneWarnings(scene))
    if (PyErr_WarnEx(PyExc_UserWarning, ("raylab: " + warning).c_str(), 2) != 0)
      throw py::error_already_set();
}

FloatImage arrayToImage(const py::array& array, const char* what) {
  if (array.ndim() != 3 || array.shape(2) != 3)
    throw py::value_error(std::string(what) + " must be an H x W x 3 array, not of shape " +
                          py::str(py::getattr(array, "shape")).cast<std::string>());
  const auto floats = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!floats) throw py::value_error(std::string(what) + " must hold numbers");
  FloatImage image(int(array.shape(1)), int(array.shape(0)));
  const float* in = floats.data();
  for (glm::vec3& p : image.pixels) {
    p = glm::vec3(in[0], in[1], in[2]);
    in += 3;
  }
  return image;
}

void runInterruptible(const std::function<void()>& work, const std::function<void()>& poll,
                      const std::function<void()>& cancel) {
  std::mutex mutex;
  std::condition_variable finishedSignal;
  bool finished = false;
  std::exception_ptr workError;
  std::thread worker([&] {
    try {
      work();
    } catch (...) {
      workError = std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(mutex);
    finished = true;
    finishedSignal.notify_all();
  });
  for (;;) {
    bool done = false;
    {
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(mutex);
      finishedSignal.wait_for(lock, std::chrono::milliseconds(20), [&] { return finished; });
      done = finished;
    }
    try {
      // Ctrl-C sets a flag that only the main thread's signal check turns into
      // KeyboardInterrupt; a progress callback may raise too.
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      poll();
    } catch (...) {
      cancel();
      {
        py::gil_scoped_release release;
        worker.join();
      }
      throw;
    }
    if (done) break;
  }
  worker.join();
  if (workError) std::rethrow_exception(workError);
}

}  // namespace raylab::python

namespace py = pybind11;
using namespace raylab;
using namespace raylab::python;

namespace {

// The Python types of RayLab's errors (owned by the module, which lives as long as Python).
PyObject* g_error = nullptr;
PyObject* g_notImplemented = nullptr;
PyObject* g_sceneError = nullptr;
PyObject* g_saveError = nullptr;
PyObject* g_geometryError = nullptr;
PyObject* g_comparisonError = nullptr;
PyObject* g_rayTreeError = nullptr;
PyObject* g_imageError = nullptr;

/// The Python type `name` deriving from `base`, for the C++ error E (pybind11 keeps it).
template <typename E>
PyObject* registerError(py::module_& m, const char* name, PyObject* base) {
  return py::register_exception<E>(m, name, base).ptr();
}

/// Raises `type` with the C++ message `what` as the command line prints it (printableText):
/// a message quoting raw bytes that are not UTF-8 (a file name in another encoding, a
/// scene's stray byte) or terminal controls would otherwise become a UnicodeDecodeError
/// instead of the error it reports (issue 14).
void setError(PyObject* type, const char* what) {
  PyErr_SetString(type, printableText(what).c_str());
}

/// pybind11's translation of C++ exceptions (the same Python types), with printable text.
void translateError(std::exception_ptr error) {
  try {
    if (error) std::rethrow_exception(error);
  } catch (const py::error_already_set&) {
    throw;  // a Python error already: pybind11 restores it
  } catch (const py::builtin_exception&) {
    throw;  // py::value_error and its kin carry text RayLab wrote
  } catch (const std::bad_alloc&) {
    throw;  // MemoryError, no text
  } catch (const NotImplemented& e) {
    setError(g_notImplemented, e.what());
  } catch (const SceneIO::LoadError& e) {
    setError(g_sceneError, e.what());
  } catch (const SceneIO::SaveError& e) {
    setError(g_saveError, e.what());
  } catch (const Shape::InvalidGeometry& e) {
    setError(g_geometryError, e.what());
  } catch (const Comparison::Error& e) {
    setError(g_comparisonError, e.what());
  } catch (const RayTreeJson::Error& e) {
    setError(g_rayTreeError, e.what());
  } catch (const vis::ImageError& e) {
    setError(g_imageError, e.what());
  } catch (const Exception& e) {
    setError(g_error, e.what());
  } catch (const std::out_of_range& e) {
    setError(PyExc_IndexError, e.what());
  } catch (const std::overflow_error& e) {
    setError(PyExc_OverflowError, e.what());
  } catch (const std::invalid_argument& e) {
    setError(PyExc_ValueError, e.what());
  } catch (const std::domain_error& e) {
    setError(PyExc_ValueError, e.what());
  } catch (const std::length_error& e) {
    setError(PyExc_ValueError, e.what());
  } catch (const std::range_error& e) {
    setError(PyExc_ValueError, e.what());
  } catch (const std::exception& e) {
    setError(PyExc_RuntimeError, e.what());
  }
}

}  // namespace

PYBIND11_MODULE(_raylab, m) {
  m.doc() = "RayLab's core and vis libraries: scenes, geometry, renders, ray trees, VTK.";

  // Every input error derives from raylab.Error (raylab::Exception); its text is the C++
  // message, which names the file, the place and the problem.
  g_error = registerError<Exception>(m, "Error", PyExc_RuntimeError);
  g_notImplemented = registerError<NotImplemented>(m, "NotImplementedInRayLab", g_error);
  g_sceneError = registerError<SceneIO::LoadError>(m, "SceneError", g_error);
  g_saveError = registerError<SceneIO::SaveError>(m, "SaveError", g_error);
  g_geometryError = registerError<Shape::InvalidGeometry>(m, "GeometryError", g_error);
  g_comparisonError = registerError<Comparison::Error>(m, "ComparisonError", g_error);
  g_rayTreeError = registerError<RayTreeJson::Error>(m, "RayTreeError", g_error);
  g_imageError = registerError<vis::ImageError>(m, "ImageError", g_error);
  // Registered last, so pybind11 tries it first: every C++ message, RayLab's and the
  // standard library's, reaches Python as printable text.
  py::register_exception_translator(&translateError);

  // The algorithms' words, in historical order, from core's one table (AlgorithmInfo.h).
  m.attr("ALGORITHMS") = py::tuple(py::cast(algorithmWords()));

  bindGeometry(m);
  bindScene(m);
  bindRender(m);
  bindTrace(m);
  bindCompare(m);
  bindVis(m);
  bindStudent(m);
}
