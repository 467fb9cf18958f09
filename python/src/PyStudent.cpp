// raylab.student's engine side (issue 35): a student's Python functions as the engine's
// StudentHooks, one pixel sample traced with them and judged against the exact oracle, an
// image rendered with them, and the engine's own optics pieces as references.

#include "Bindings.h"

#include "raylab/core/Bsdf.h"
#include "raylab/core/ClassicShading.h"
#include "raylab/core/Fresnel.h"
#include "raylab/core/Limits.h"
#include "raylab/core/RayOffset.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/Sampling.h"
#include "raylab/core/StudentHooks.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/SceneView.h"

#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>

namespace raylab::python {

namespace {

/// A vector as a NumPy array of three floats, what a student's code computes with.
py::array_t<double> vec(const Vec3& v) {
  py::array_t<double> out(3);
  double* p = out.mutable_data();
  p[0] = v.x;
  p[1] = v.y;
  p[2] = v.z;
  return out;
}

/// "ZeroDivisionError: float division by zero (student.py, line 7, in intersect_sphere)":
/// the Python error and the student's line where it was raised.
std::string describe(py::error_already_set& error) {
  std::string text = error.what();
  const std::size_t newline = text.find('\n');
  if (newline != std::string::npos) text.resize(newline);
  try {
    const py::list frames = py::module_::import("traceback").attr("extract_tb")(error.trace());
    if (!frames.empty()) {
      const py::object last = frames[frames.size() - 1];
      text += " (" + last.attr("filename").cast<std::string>() + ", line " +
              std::to_string(last.attr("lineno").cast<int>()) + ", in " +
              last.attr("name").cast<std::string>() + ")";
    }
  } catch (const std::exception&) {
  }
  return text;
}

/**
 * \brief Keeps a Python thread state for a renderer's worker thread for the thread's life:
 * pybind11 otherwise creates and deletes one around every call of a student's function from
 * a thread Python does not know. Does nothing on a thread Python knows (the caller's).
 */
class PinnedThreadState {
 public:
  PinnedThreadState() {
    if (PyGILState_GetThisThreadState() != nullptr) return;
    m_gil = PyGILState_Ensure();
    m_saved = PyEval_SaveThread();
  }
  ~PinnedThreadState() {
    if (!m_saved) return;
    PyEval_RestoreThread(m_saved);
    PyGILState_Release(m_gil);
  }
  PinnedThreadState(const PinnedThreadState&) = delete;
  PinnedThreadState& operator=(const PinnedThreadState&) = delete;

 private:
  PyGILState_STATE m_gil{};
  PyThreadState* m_saved = nullptr;
};

/// Calls the student's `fn` for `piece` and reads a t: None, or a real number.
template <typename... Args>
std::optional<double> askT(const py::function& fn, const char* piece, Args&&... args) {
  thread_local PinnedThreadState pinned;
  const py::gil_scoped_acquire gil;
  py::object answer;
  try {
    answer = fn(std::forward<Args>(args)...);
  } catch (py::error_already_set& error) {
    throw StudentHooks::Failure(describe(error));
  }
  if (answer.is_none()) return std::nullopt;
  if (py::isinstance<py::bool_>(answer) || !py::hasattr(answer, "__float__"))
    throw StudentHooks::Failure(std::string(piece) + " returned " +
                                py::repr(answer).cast<std::string>() +
                                ": expected a float t or None (a miss)");
  return answer.attr("__float__")().cast<double>();
}

/// The hooks `use` was given: {"intersect_sphere": fn, ...} (the functions are kept alive
/// by the dict, which outlives the trace or render).
StudentHooks hooksOf(const py::dict& functions) {
  StudentHooks h;
  for (const auto& [key, value] : functions) {
    const std::string name = key.cast<std::string>();
    if (value.is_none()) continue;
    const py::function fn = value.cast<py::function>();
    if (name == "intersect_sphere")
      h.intersectSphere = [fn](const Point3& o, const Vec3& d, const Point3& c, double r,
                               double tMin, double tMax) {
        thread_local PinnedThreadState pinned;
        const py::gil_scoped_acquire gil;
        return askT(fn, "intersect_sphere", vec(o), vec(d), vec(c), r, tMin, tMax);
      };
    else if (name == "intersect_plane")
      h.intersectPlane = [fn](const Point3& o, const Vec3& d, const Point3& p, const Normal3& n,
                              double tMin, double tMax) {
        thread_local PinnedThreadState pinned;
        const py::gil_scoped_acquire gil;
        return askT(fn, "intersect_plane", vec(o), vec(d), vec(p), vec(n), tMin, tMax);
      };
    else if (name == "intersect_box")
      h.intersectBox = [fn](const Point3& o, const Vec3& d, const Point3& lo, const Point3& hi,
                            double tMin, double tMax) {
        thread_local PinnedThreadState pinned;
        const py::gil_scoped_acquire gil;
        return askT(fn, "intersect_box", vec(o), vec(d), vec(lo), vec(hi), tMin, tMax);
      };
    else if (name == "intersect_triangle")
      h.intersectTriangle = [fn](const Point3& o, const Vec3& d, const Point3& a, const Point3& b,
                                 const Point3& c, double tMin, double tMax) {
        thread_local PinnedThreadState pinned;
        const py::gil_scoped_acquire gil;
        return askT(fn, "intersect_triangle", vec(o), vec(d), vec(a), vec(b), vec(c), tMin, tMax);
      };
  }
  return h;
}

/// A traced sample of both engines, as Python reads it.
struct StudentTraceData {
  std::shared_ptr<TraceData> student, reference;
  StudentTrace trace;
};

py::dict callDict(const StudentCall& c) {
  py::dict d;
  d["ray"] = c.ray;
  d["object"] = c.object;
  d["piece"] = c.piece;
  d["origin"] = toTuple(c.query.origin);
  d["direction"] = toTuple(c.query.direction);
  d["t_min"] = c.query.tMin;
  d["t_max"] = c.query.tMax;
  d["student"] = c.student ? py::object(py::float_(*c.student)) : py::none();
  d["reference"] = c.exactHit ? py::object(py::float_(c.exact)) : py::none();
  d["tangent"] = c.tangent;
  d["ulps"] = c.ulps;
  d["error"] = c.error;
  d["verdict"] = toString(c.verdict);
  return d;
}

std::shared_ptr<TraceData> traceData(const std::shared_ptr<const Scene>& scene,
                                     const RenderSettings& settings, PixelTrace trace) {
  auto d = std::make_shared<TraceData>();
  d->scene = scene;
  d->settings = settings;
  d->trace = std::move(trace);
  return d;
}

/// The student's tree coloured by verdict (left) beside the engine's tree coloured by ray
/// kind (right), each `width` x `height`, in one image.
SrgbImage sideBySide(const SceneHandle& scene, const StudentTraceData& data, int width, int height,
                     Language language) {
  if (width < 1 || height < 1) throw py::value_error("width and height must be at least 1");
  vis::RayTreeStyle studentStyle;
  studentStyle.colouring = vis::RayColouring::Verdict;
  studentStyle.language = language;
  for (const RayVerdict& v : data.trace.verdicts) studentStyle.verdicts.push_back(int(v.verdict));
  vis::RayTreeStyle referenceStyle;
  referenceStyle.colouring = vis::RayColouring::Kind;
  referenceStyle.language = language;
  const std::shared_ptr<const Scene> snapshot = scene.scene;
  py::gil_scoped_release release;
  SrgbImage out(2 * width, height);
  for (int side = 0; side < 2; ++side) {
    vis::SceneView view(*snapshot);
    view.resetViewCamera(double(width) / height);
    view.setRayTree(side == 0 ? data.trace.student.tree : data.trace.reference.tree,
                    side == 0 ? studentStyle : referenceStyle);
    const SrgbImage half = view.renderOffscreen(width, height);
    for (int y = 0; y < height; ++y)
      std::memcpy(&out.rgb[(std::size_t(y) * 2 * width + side * width) * 3],
                  &half.rgb[std::size_t(y) * width * 3], std::size_t(width) * 3);
  }
  return out;
}

void bindStudentTrace(py::module_& m) {
  py::class_<StudentTraceData, std::shared_ptr<StudentTraceData>>(
      m, "StudentTrace", "One pixel sample traced with a student's pieces and by the engine.")
      .def_property_readonly("student", [](const StudentTraceData& d) { return d.student; })
      .def_property_readonly("reference", [](const StudentTraceData& d) { return d.reference; })
      .def_property_readonly("calls",
                             [](const StudentTraceData& d) {
                               py::list out;
                               for (const StudentCall& c : d.trace.calls) out.append(callDict(c));
                               return out;
                             })
      .def_property_readonly("verdicts",
                             [](const StudentTraceData& d) {
                               py::list out;
                               for (const RayVerdict& v : d.trace.verdicts)
                                 out.append(toString(v.verdict));
                               return out;
                             })
      .def_property_readonly("deciding_calls",
                             [](const StudentTraceData& d) {
                               py::list out;
                               for (const RayVerdict& v : d.trace.verdicts) out.append(v.call);
                               return out;
                             })
      .def_property_readonly("first_divergent",
                             [](const StudentTraceData& d) { return d.trace.firstDivergent; })
      .def_property_readonly("passes", [](const StudentTraceData& d) { return d.trace.passes(); });
}

void bindReferences(py::module_& m) {
  m.def("ref_reflect", [](const Vec3& d, const Vec3& n) { return bsdf::reflect(-d, n); });
  m.def("ref_refract", [](const Vec3& d, const Vec3& n, double eta) -> std::optional<Vec3> {
    const auto t = bsdf::refract(-d, n, eta);
    return t ? std::optional<Vec3>(*t) : std::nullopt;
  });
  m.def("ref_fresnel", &fresnel::dielectric);
  m.def("ref_schlick", &fresnel::schlickDielectric);
  m.def("ref_phong", &classic::phongHighlight);
  m.def("ref_blinn_phong", &classic::blinnPhongHighlight);
  m.def("ref_sample_cosine_hemisphere", [](double u1, double u2) {
    const Vec3 w = sampleCosineHemisphere(Vec2(u1, u2));
    return py::make_tuple(toTuple(w), cosineHemispherePdf(w.z));
  });
  m.def("ref_cosine_hemisphere_pdf", &cosineHemispherePdf);
  m.def("ref_offset_distance", &rayOffsetDistance);
}

}  // namespace

void bindStudent(py::module_& m) {
  bindStudentTrace(m);

  m.def(
      "student_trace",
      [](const SceneHandle& handle, const py::dict& functions, int x, int y, int sample,
         std::optional<std::string> algorithm, std::optional<int> spp,
         std::optional<std::uint64_t> seed, std::optional<int> maxDepth, std::optional<Ray> ray) {
        const RenderSettings settings = settingsFor(
            *handle.scene, {algorithm, spp, seed, maxDepth, std::nullopt, std::nullopt});
        const StudentHooks hooks = hooksOf(functions);
        auto out = std::make_shared<StudentTraceData>();
        out->trace = traceStudent(*handle.scene, settings, hooks, x, y, sample, ray);
        out->student = traceData(handle.scene, settings, out->trace.student);
        out->reference = traceData(handle.scene, settings, out->trace.reference);
        return out;
      },
      py::arg("scene"), py::arg("functions"), py::arg("x"), py::arg("y"), py::arg("sample"),
      py::arg("algorithm"), py::arg("spp"), py::arg("seed"), py::arg("max_depth"), py::arg("ray"));

  m.def(
      "student_render",
      [](const SceneHandle& handle, const py::dict& functions, std::optional<std::string> algorithm,
         std::optional<int> spp, std::optional<std::uint64_t> seed, std::optional<int> maxDepth,
         int threads) {
        const RenderSettings settings = settingsFor(
            *handle.scene, {algorithm, spp, seed, maxDepth, std::nullopt, std::nullopt});
        checkRange("threads", threads, 0, limits::kMaxThreads);
        const StudentHooks hooks = hooksOf(functions);
        const std::shared_ptr<Scene> scene = studentScene(*handle.scene, hooks, nullptr);
        Renderer renderer(*scene, settings);
        renderer.setThreads(threads);
        FloatImage image;
        runInterruptible([&] { image = renderer.render(); }, [] {}, [&] { renderer.cancel(); });
        return imageToArray(std::move(image), py::dtype::of<float>());
      },
      py::arg("scene"), py::arg("functions"), py::arg("algorithm"), py::arg("spp"), py::arg("seed"),
      py::arg("max_depth"), py::arg("threads"));

  m.def(
      "student_judge_geometry",
      [](const Shape& shape, const Ray& ray, const py::object& student, const std::string& error) {
        StudentCall call;
        call.query = ray;
        call.error = error;
        if (!student.is_none()) call.student = student.cast<double>();
        judgeCall(shape, call);
        return callDict(call);
      },
      py::arg("shape"), py::arg("ray"), py::arg("student"), py::arg("error") = "",
      "One answer of a student's intersection judged against the exact oracle (a dict).");

  m.def(
      "student_save_view",
      [](const std::string& path, const SceneHandle& scene, const StudentTraceData& data, int width,
         int height, const std::string& language) {
        vis::writePng(sideBySide(scene, data, width, height,
                                 language == "zh" ? Language::Chinese : Language::English),
                      path);
      },
      py::arg("path"), py::arg("scene"), py::arg("trace"), py::arg("width") = 400,
      py::arg("height") = 300, py::arg("language") = "en",
      "The student's tree coloured by verdict beside the engine's (by ray kind), as a PNG.");

  bindReferences(m);
}

}  // namespace raylab::python
