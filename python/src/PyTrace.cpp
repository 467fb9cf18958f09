// raylab.trace and raylab.Stepper: one pixel sample's ray tree with every field of
// `raylab trace --json`, as Python objects and as NumPy arrays, and the engine stepped one
// ray at a time from Python.

#include "Bindings.h"

#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/RayWords.h"
#include "raylab/core/Tracer.h"

#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace raylab::python {

namespace {

/// One segment of a shared trace.
struct SegmentRef {
  std::shared_ptr<const TraceData> data;
  int index = 0;
  const RaySegment& get() const { return data->trace.tree.segments[std::size_t(index)]; }
};

std::string objectName(const TraceData& data, int object) {
  const auto& objects = data.scene->objects;
  return object >= 0 && object < int(objects.size()) ? objects[std::size_t(object)].name
                                                     : std::string();
}

/// The segment under the keys of the JSON dump (RayTreeJson::forEachField), vectors as
/// tuples.
py::dict segmentDict(const TraceData& data, const RaySegment& s) {
  py::dict j;
  RayTreeJson::forEachField(s, *data.scene, [&j](const char* key, const auto& value) {
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, Vec3>)
      j[key] = toTuple(value);
    else
      j[key] = value;
  });
  return j;
}

py::dict countsDict(const RayCounts& counts) {
  py::dict out;
  for (int k = 0; k < kRayKindCount; ++k) out[toString(RayKind(k))] = counts.byKind[std::size_t(k)];
  return out;
}

/// An N x 3 array of one vector field of every segment (a copy: no view into the tree).
template <typename Field>
py::array_t<double> vectors(const RayTree& tree, Field field) {
  py::array_t<double> out({py::ssize_t(tree.segments.size()), py::ssize_t(3)});
  double* p = out.mutable_data();
  for (const RaySegment& s : tree.segments) {
    const Vec3 v = field(s);
    *p++ = v.x;
    *p++ = v.y;
    *p++ = v.z;
  }
  return out;
}

template <typename T, typename Field>
py::array_t<T> scalars(const RayTree& tree, Field field) {
  py::array_t<T> out(py::ssize_t(tree.segments.size()));
  T* p = out.mutable_data();
  for (const RaySegment& s : tree.segments) *p++ = T(field(s));
  return out;
}

py::dict treeArrays(const TraceData& data) {
  const RayTree& tree = data.trace.tree;
  py::list kinds, reasons;
  for (const RaySegment& s : tree.segments) {
    kinds.append(toString(s.kind));
    reasons.append(RayTreeJson::endReasonName(s.endReason));
  }
  const py::object asarray = py::module_::import("numpy").attr("asarray");
  py::dict out;
  out["origins"] = vectors(tree, [](const RaySegment& s) { return s.origin; });
  out["ends"] = vectors(tree, [](const RaySegment& s) { return s.endPoint; });
  out["directions"] = vectors(tree, [](const RaySegment& s) { return s.direction; });
  out["normals"] = vectors(tree, [](const RaySegment& s) { return s.normal; });
  out["weights"] = vectors(tree, [](const RaySegment& s) { return s.weight; });
  out["throughputs"] = vectors(tree, [](const RaySegment& s) { return s.throughput; });
  out["emitted"] = vectors(tree, [](const RaySegment& s) { return s.emitted; });
  out["radiances"] = vectors(tree, [](const RaySegment& s) { return s.radiance; });
  out["energies"] = scalars<double>(tree, [](const RaySegment& s) { return s.energy(); });
  out["pdfs"] = scalars<double>(tree, [](const RaySegment& s) { return s.pdf; });
  out["times"] = scalars<double>(tree, [](const RaySegment& s) { return s.time; });
  out["parents"] = scalars<int>(tree, [](const RaySegment& s) { return s.parent; });
  out["depths"] = scalars<int>(tree, [](const RaySegment& s) { return s.depth; });
  out["objects"] = scalars<int>(tree, [](const RaySegment& s) { return s.object; });
  out["hits"] = scalars<bool>(tree, [](const RaySegment& s) { return s.hit; });
  out["kinds"] = asarray(kinds);
  out["end_reasons"] = asarray(reasons);
  return out;
}

/// ValueError unless (x, y) is a pixel of the scene's image and sample >= 0.
void checkPixel(const Scene& scene, int x, int y, int sample) {
  const CameraSpec& c = scene.camera;
  if (x < 0 || y < 0 || x >= c.width || y >= c.height)
    throw py::value_error("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                          ") is outside the " + std::to_string(c.width) + "x" +
                          std::to_string(c.height) + " image");
  if (sample < 0) throw py::value_error("sample must be 0 or more, not " + std::to_string(sample));
}

std::pair<int, int> pixelOf(const py::handle& pixel) {
  // Two whole numbers: a string, floats or another length is named, not pybind11's cast error.
  const auto problem = [&pixel] {
    return py::value_error("pixel must be (x, y), two integers, not " +
                           py::repr(pixel).cast<std::string>());
  };
  if (py::isinstance<py::str>(pixel) || !py::isinstance<py::sequence>(pixel)) throw problem();
  const auto items = pixel.cast<py::sequence>();
  if (items.size() != 2) throw problem();
  std::vector<int> xy;
  for (const py::handle item : items) {
    // Integers, NumPy's too (both have __index__); not floats, not True / False.
    if (py::isinstance<py::bool_>(item) || !py::hasattr(item, "__index__")) throw problem();
    try {
      xy.push_back(item.attr("__index__")().cast<int>());
    } catch (const std::exception&) {  // beyond int's range
      throw problem();
    }
  }
  return {xy[0], xy[1]};
}

/// The engine stepped from Python: the scene snapshot and the tracer the stepper points into.
struct StepperHandle {
  std::shared_ptr<const Scene> scene;
  std::unique_ptr<Tracer> tracer;
  std::unique_ptr<Stepper> stepper;
  std::vector<StepEvent> steps;  ///< By ray id, as tracePixel keeps them.

  bool step() {
    if (!stepper->step()) return false;
    const StepEvent& event = stepper->lastEvent();
    if (event.ray >= 0) {
      if (std::size_t(event.ray) >= steps.size()) steps.resize(std::size_t(event.ray) + 1);
      steps[std::size_t(event.ray)] = event;
    }
    return true;
  }
};

/// What each step of `trace` did, in English words (the phrase table's narration).
std::vector<std::string> stepTexts(const PixelTrace& trace, const Scene& scene) {
  const SceneNames names = sceneNames(scene, Language::English);
  std::vector<std::string> texts;
  for (const StepEvent& e : trace.steps) texts.push_back(narrateStep(e, names, Language::English));
  return texts;
}

py::dict eventDict(const StepEvent& e, const Scene& scene) {
  py::dict out;
  out["ray"] = e.ray;
  out["end_reason"] = RayTreeJson::endReasonName(e.end);
  out["spawned"] = e.spawned;
  out["text"] = narrateStep(e, sceneNames(scene, Language::English), Language::English);
  return out;
}

py::dict queuedDict(const QueuedRay& q) {
  py::dict out;
  out["id"] = q.id;
  out["parent"] = q.parent;
  out["kind"] = toString(q.kind);
  out["depth"] = q.depth;
  out["origin"] = toTuple(q.ray.origin);
  out["direction"] = toTuple(q.ray.direction);
  out["weight"] = toTuple(q.weight);
  out["throughput"] = toTuple(q.throughput);
  out["pdf"] = q.pdf;
  return out;
}

}  // namespace

namespace {

/// raylab.Segment: one ray of a traced tree, every field of its record.
void bindSegment(py::module_& m) {
  py::class_<SegmentRef>(m, "Segment", R"(One ray of a traced tree, with every field of the
JSON dump (raylab trace --json) under the same names. It keeps its trace alive.)")
      .def_property_readonly("id", [](const SegmentRef& r) { return r.get().id; })
      .def_property_readonly("parent", [](const SegmentRef& r) { return r.get().parent; })
      .def_property_readonly("first_child", [](const SegmentRef& r) { return r.get().firstChild; })
      .def_property_readonly("child_count", [](const SegmentRef& r) { return r.get().childCount; })
      .def_property_readonly("kind", [](const SegmentRef& r) { return toString(r.get().kind); })
      .def_property_readonly("depth", [](const SegmentRef& r) { return r.get().depth; })
      .def_property_readonly("origin", [](const SegmentRef& r) { return r.get().origin; })
      .def_property_readonly("direction", [](const SegmentRef& r) { return r.get().direction; })
      .def_property_readonly("time", [](const SegmentRef& r) { return r.get().time; })
      .def_property_readonly("hit", [](const SegmentRef& r) { return r.get().hit; })
      .def_property_readonly("end_point", [](const SegmentRef& r) { return r.get().endPoint; })
      .def_property_readonly("light_point", [](const SegmentRef& r) { return r.get().lightPoint; })
      .def_property_readonly("object", [](const SegmentRef& r) { return r.get().object; })
      .def_property_readonly(
          "object_name", [](const SegmentRef& r) { return objectName(*r.data, r.get().object); })
      .def_property_readonly(
          "light_object", [](const SegmentRef& r) { return r.get().lightObject; },
          "Shadow rays to an area light: its object index; -1 otherwise.")
      .def_property_readonly(
          "point_light", [](const SegmentRef& r) { return r.get().pointLight; },
          "Shadow rays to a point light: its index among the point lights; -1 otherwise.")
      .def_property_readonly(
          "light_name", [](const SegmentRef& r) { return lightNameOf(r.get(), *r.data->scene); },
          "Shadow rays: the light aimed at (an area light's object name or a point light's "
          "name); '' for other rays.")
      .def_property_readonly("normal", [](const SegmentRef& r) { return r.get().normal; })
      .def_property_readonly("weight", [](const SegmentRef& r) { return r.get().weight; })
      .def_property_readonly("pdf", [](const SegmentRef& r) { return r.get().pdf; })
      .def_property_readonly("throughput", [](const SegmentRef& r) { return r.get().throughput; })
      .def_property_readonly("emitted", [](const SegmentRef& r) { return r.get().emitted; })
      .def_property_readonly("radiance", [](const SegmentRef& r) { return r.get().radiance; })
      .def_property_readonly(
          "end_reason",
          [](const SegmentRef& r) { return RayTreeJson::endReasonName(r.get().endReason); })
      .def_property_readonly(
          "energy", [](const SegmentRef& r) { return r.get().energy(); },
          "Luminance of throughput * radiance: the share of the pixel's light.")
      .def_property_readonly(
          "step_text",
          [](const SegmentRef& r) {
            return narrateStep(r.data->trace.steps[std::size_t(r.index)],
                               sceneNames(*r.data->scene, Language::English), Language::English);
          },
          "What the engine's step of this ray did, in words.")
      .def_property_readonly("children",
                             [](const SegmentRef& r) {
                               std::vector<SegmentRef> out;
                               const RaySegment& s = r.get();
                               for (int c = 0; c < s.childCount; ++c)
                                 out.push_back({r.data, s.firstChild + c});
                               return out;
                             })
      .def(
          "to_dict", [](const SegmentRef& r) { return segmentDict(*r.data, r.get()); },
          "Every field under the JSON dump's keys.")
      .def("__repr__", [](const SegmentRef& r) {
        const RaySegment& s = r.get();
        return "<raylab.Segment #" + std::to_string(s.id) + " " + toString(s.kind) + " depth " +
               std::to_string(s.depth) + ", " + RayTreeJson::endReasonName(s.endReason) + ">";
      });
}

/// raylab.Trace: one traced pixel sample, its tree and figures.
void bindTraceClass(py::module_& m) {
  py::class_<TraceData, std::shared_ptr<TraceData>>(m, "Trace", R"(One traced pixel sample: its
ray tree (every ray, propagated), the text of each step, the rays by kind and the estimate.
Made by raylab.trace or Stepper.tree().)")
      .def_property_readonly("algorithm",
                             [](const TraceData& d) { return toString(d.trace.algorithm); })
      .def_property_readonly(
          "pixel", [](const TraceData& d) { return py::make_tuple(d.trace.x, d.trace.y); })
      .def_property_readonly("sample", [](const TraceData& d) { return d.trace.sample; })
      .def_property_readonly("seed", [](const TraceData& d) { return d.settings.seed; })
      .def_property_readonly(
          "estimate", [](const TraceData& d) { return d.trace.estimate; },
          "The sample's radiance: the renderer's value when the whole tree was traced; past the "
          "ray budget (or after a cancel) the radiance of the rays traced.")
      .def_property_readonly(
          "tree_estimate", [](const TraceData& d) { return d.trace.tree.estimate(); },
          "The recorded tree's estimate: the JSON dump's 'estimate'.")
      .def_property_readonly("rays_by_kind",
                             [](const TraceData& d) { return countsDict(d.trace.counts); })
      .def_property_readonly("depth", [](const TraceData& d) { return d.trace.depth(); })
      .def_property_readonly("truncated", [](const TraceData& d) { return d.trace.tree.truncated; })
      .def_property_readonly(
          "message",
          [](const TraceData& d) { return stopWords(d.trace.tree.stop, Language::English); },
          "Why the trace stopped early, in English ('' when it did not).")
      .def_property_readonly("step_texts",
                             [](const TraceData& d) { return stepTexts(d.trace, *d.scene); })
      .def_property_readonly("segments",
                             [](const std::shared_ptr<TraceData>& d) {
                               std::vector<SegmentRef> out;
                               for (std::size_t i = 0; i < d->trace.tree.segments.size(); ++i)
                                 out.push_back({d, int(i)});
                               return out;
                             })
      .def("__len__", [](const TraceData& d) { return d.trace.tree.segments.size(); })
      .def("__getitem__",
           [](const std::shared_ptr<TraceData>& d, int i) {
             const int n = int(d->trace.tree.segments.size());
             if (i < 0) i += n;
             if (i < 0 || i >= n) throw py::index_error("segment index out of range");
             return SegmentRef{d, i};
           })
      .def("summary", [](const TraceData& d) { return traceSummary(d.trace, Language::English); })
      .def(
          "to_json",
          [](const TraceData& d) {
            return RayTreeJson::serialize(d.trace.tree, *d.scene, d.settings);
          },
          "The JSON dump, byte for byte what raylab trace --json writes for this tree.")
      .def(
          "save_json",
          [](const TraceData& d, const std::string& path) {
            RayTreeJson::save(d.trace.tree, *d.scene, d.settings, path);
          },
          py::arg("path"))
      .def("arrays", &treeArrays, R"(NumPy arrays of the tree for plotting (copies): origins,
ends, directions, normals, weights, throughputs, emitted, radiances (N x 3); energies, pdfs,
times, parents, depths, objects, hits (N); kinds and end_reasons (N strings).)")
      .def("__repr__", [](const TraceData& d) {
        return "<raylab.Trace " + std::string(toString(d.trace.algorithm)) + " pixel (" +
               std::to_string(d.trace.x) + ", " + std::to_string(d.trace.y) +
               "): " + traceSummary(d.trace, Language::English) + ">";
      });
}

/// raylab.trace: a pixel sample (or one given ray) traced with the real algorithm.
void bindTraceFunction(py::module_& m) {
  m.def(
      "trace",
      [](const SceneHandle& handle, const py::object& pixel, int sample,
         std::optional<std::string> algorithm, std::optional<int> spp,
         std::optional<std::uint64_t> seed, std::optional<int> maxDepth, std::optional<bool> nee,
         std::optional<bool> mis, std::optional<Ray> ray) {
        const auto [x, y] = pixelOf(pixel);
        checkPixel(*handle.scene, x, y, sample);
        auto data = std::make_shared<TraceData>();
        data->scene = handle.scene;
        data->settings = settingsFor(*handle.scene, {algorithm, spp, seed, maxDepth, nee, mis});
        {
          py::gil_scoped_release release;
          data->trace = ray ? traceRay(*data->scene, data->settings, *ray, x, y, sample)
                            : tracePixel(*data->scene, data->settings, x, y, sample);
        }
        return data;
      },
      py::arg("scene"), py::arg("pixel") = py::make_tuple(0, 0), py::arg("sample") = 0,
      py::kw_only(), py::arg("algorithm") = py::none(), py::arg("spp") = py::none(),
      py::arg("seed") = py::none(), py::arg("max_depth") = py::none(),
      py::arg("next_event_estimation") = py::none(), py::arg("multiple_importance") = py::none(),
      py::arg("ray") = py::none(),
      R"(Traces sample `sample` of pixel (x, y) (y down) with the real algorithm, recording its
ray tree (core's tracePixel, as raylab trace and the window do). Settings not given come
from the scene's render block; `spp` matters too: film and lens samples are stratified over
the pixel's spp, so sample s equals sample s of a render with the same spp and seed. With
`ray` (a raylab.Ray), that ray is traced in place of the pixel's camera ray (core's
traceRay, raylab trace --ray), e.g. one exactly tangent to a sphere; the pixel then only
chooses the random numbers. The GIL is released.)");
}

/// raylab.Stepper: the engine advanced one ray at a time.
/// Stepper.tree(): the tree so far as a Trace, a snapshot later steps do not change.
std::shared_ptr<TraceData> treeSoFar(const StepperHandle& h) {
  auto data = std::make_shared<TraceData>();
  data->scene = h.scene;
  data->settings = h.tracer->settings();
  PixelTrace& t = data->trace;
  t.algorithm = data->settings.algorithm;
  t.tree = h.stepper->tree();
  t.x = t.tree.pixelX;
  t.y = t.tree.pixelY;
  t.sample = t.tree.sample;
  // The steps taken; a ray still queued is told from the tree (it waits).
  t.steps = h.steps;
  t.steps.resize(t.tree.segments.size());
  for (const RaySegment& s : t.tree.segments)
    if (t.steps[std::size_t(s.id)].ray != s.id) t.steps[std::size_t(s.id)] = stepEventOf(s);
  t.counts = h.stepper->counts();
  t.estimate = h.stepper->estimate();
  return data;
}

void bindStepper(py::module_& m) {
  py::class_<StepperHandle>(m, "Stepper", R"(The engine of the four algorithms for one pixel
sample, advanced one ray at a time: the real algorithm, not a replay (core's Stepper).)")
      .def(py::init([](const SceneHandle& handle, const py::object& pixel, int sample,
                       std::optional<std::string> algorithm, std::optional<int> spp,
                       std::optional<std::uint64_t> seed, std::optional<int> maxDepth) {
             const auto [x, y] = pixelOf(pixel);
             checkPixel(*handle.scene, x, y, sample);
             auto h = std::make_unique<StepperHandle>();
             h->scene = handle.scene;
             h->tracer = std::make_unique<Tracer>(
                 *h->scene, settingsFor(*handle.scene, {algorithm, spp, seed, maxDepth,
                                                        std::nullopt, std::nullopt}));
             h->stepper = std::make_unique<Stepper>(*h->tracer, x, y, sample);
             return h;
           }),
           py::arg("scene"), py::arg("pixel"), py::arg("sample") = 0, py::kw_only(),
           py::arg("algorithm") = py::none(), py::arg("spp") = py::none(),
           py::arg("seed") = py::none(), py::arg("max_depth") = py::none())
      .def("step", &StepperHandle::step,
           "Processes the first ray of the queue; False when the queue was already empty.")
      .def(
          "run_to_end",
          [](StepperHandle& h) {
            py::gil_scoped_release release;
            while (h.step()) {
            }
          },
          "Steps until every ray is processed (the tree is then propagated).")
      .def(
          "reset",
          [](StepperHandle& h) {
            h.stepper->reset();
            h.steps.clear();
          },
          "Back to before the first step (same pixel, sample and seed).")
      .def_property_readonly("done", [](const StepperHandle& h) { return h.stepper->done(); })
      .def_property_readonly(
          "last_event",
          [](const StepperHandle& h) { return eventDict(h.stepper->lastEvent(), *h.scene); },
          "What the last step did: ray, end_reason, spawned, text.")
      .def_property_readonly(
          "queue",
          [](const StepperHandle& h) {
            py::list out;
            for (const QueuedRay& q : h.stepper->queue()) out.append(queuedDict(q));
            return out;
          },
          "The rays waiting, first in front (copies).")
      .def_property_readonly("estimate",
                             [](const StepperHandle& h) { return h.stepper->estimate(); })
      .def_property_readonly("rays_by_kind",
                             [](const StepperHandle& h) { return countsDict(h.stepper->counts()); })
      .def("tree", &treeSoFar,
           "The tree so far, as a Trace (a snapshot: later steps do not change it).")
      .def("__iter__", [](py::object self) { return self; })
      .def("__next__", [](StepperHandle& h) {
        if (!h.step()) throw py::stop_iteration();
        return eventDict(h.stepper->lastEvent(), *h.scene);
      });
}

}  // namespace

void bindTrace(py::module_& m) {
  bindSegment(m);
  bindTraceClass(m);
  bindTraceFunction(m);
  bindStepper(m);
}

}  // namespace raylab::python
