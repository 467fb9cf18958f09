#include "raylab/core/Comparison.h"

#include "raylab/core/Limits.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/ReferenceCache.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace raylab {

namespace {

using ojson = nlohmann::ordered_json;

/// The sRGB curve of [0, 1] sampled at kCurveSteps + 1 points, for displayRmse: linear
/// interpolation between them is within 2e-5 of the curve (its worst bend, just above
/// the linear toe at 0.0031), and a table lookup is ~20x cheaper than pow per channel.
constexpr int kCurveSteps = 4096;

const std::vector<float>& srgbTable() {
  static const std::vector<float> table = [] {
    std::vector<float> t(kCurveSteps + 2);
    for (int i = 0; i <= kCurveSteps; ++i)
      t[std::size_t(i)] = float(imageio::srgbFromLinear(double(i) / kCurveSteps));
    t[kCurveSteps + 1] = t[kCurveSteps];  // so that v = 1 can read its right neighbour
    return t;
  }();
  return table;
}

/// The display value of a linear radiance: clamp to [0, 1] (NaN as 0), then sRGB.
float displayValue(float linear, const std::vector<float>& table) {
  if (!(linear > 0.0f)) return 0.0f;
  if (linear >= 1.0f) return 1.0f;
  const float x = linear * kCurveSteps;
  const int i = int(x);
  const float f = x - float(i);
  return table[std::size_t(i)] + f * (table[std::size_t(i) + 1] - table[std::size_t(i)]);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ojson raysJson(const RayCounts& rays) {
  ojson out;
  for (int k = 0; k < kRayKindCount; ++k) out[toString(static_cast<RayKind>(k))] = rays.byKind[k];
  out["total"] = rays.total();
  return out;
}

}  // namespace

double displayRmse(const FloatImage& image, const FloatImage& reference) {
  if (image.width != reference.width || image.height != reference.height ||
      image.pixels.size() != reference.pixels.size())
    throw std::invalid_argument("displayRmse: images differ in size (" +
                                std::to_string(image.width) + "x" + std::to_string(image.height) +
                                " vs " + std::to_string(reference.width) + "x" +
                                std::to_string(reference.height) + ")");
  if (image.pixels.empty()) return 0.0;
  const std::vector<float>& table = srgbTable();
  double sum = 0.0;
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(displayValue(image.pixels[i][c], table)) -
                       double(displayValue(reference.pixels[i][c], table));
      sum += d * d;
    }
  return std::sqrt(sum / (3.0 * double(image.pixels.size())));
}

int ComparisonSettings::defaultReferenceSpp() const {
  if (equalTime()) return 256;
  // Sixteen times the samples, within the spp limit (16 x 2^31 overflowed an int).
  return int(
      std::min<std::int64_t>(16 * std::int64_t(samplesPerPixel), limits::kMaxSamplesPerPixel));
}

int ComparisonSettings::referenceSpp() const {
  return referenceSamplesPerPixel > 0 ? referenceSamplesPerPixel : defaultReferenceSpp();
}

std::string ComparisonSettings::toString() const {
  std::ostringstream out;
  out << "ComparisonSettings[";
  for (std::size_t i = 0; i < algorithms.size(); ++i)
    out << (i ? "," : "") << raylab::toString(algorithms[i]);
  out << ", spp=" << samplesPerPixel << ", seconds=" << secondsPerAlgorithm
      << ", referenceSpp=" << referenceSpp() << ", threads=" << threads << "]";
  return out.str();
}

bool referenceTooNoisy(const ComparisonResult& result) {
  if (!result.reference.file.empty() || result.reference.samplesPerPixel <= 0) return false;
  for (const AlgorithmFigures& figures : result.algorithms)
    if (figures.algorithm == Algorithm::PathTracing &&
        16LL * figures.stats.samplesPerPixel > result.reference.samplesPerPixel)
      return true;
  return false;
}

Comparison::Comparison(const Scene& scene, const RenderSettings& settings,
                       const ComparisonSettings& compare)
    : m_scene(scene), m_settings(settings), m_compare(compare) {
  if (m_compare.algorithms.empty()) throw Error("comparison: no algorithm to compare");
  if (m_compare.samplesPerPixel < 1)
    throw Error("comparison: samples per pixel must be at least 1, not " +
                std::to_string(m_compare.samplesPerPixel));
  if (!(m_compare.secondsPerAlgorithm >= 0.0) || !std::isfinite(m_compare.secondsPerAlgorithm))
    throw Error("comparison: the time per algorithm must be a positive number of seconds");
  if (m_compare.referenceSamplesPerPixel < 0)
    throw Error("comparison: reference samples per pixel must be positive");
  if (scene.camera.width < 1 || scene.camera.height < 1)
    throw Error("comparison: the image size must be positive");
}

std::uint64_t Comparison::referenceSeed(std::uint64_t seed) {
  // Any fixed bijection that moves every seed works; this is a 64-bit LCG step.
  return seed * 6364136223846793005ULL + 1442695040888963407ULL;
}

void Comparison::setReference(FloatImage image, const std::string& file) {
  const std::string name = file.empty() ? std::string("the reference image") : file;
  if (image.width != m_scene.camera.width || image.height != m_scene.camera.height)
    throw Error(name + ": the reference is " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + " but the scene renders at " +
                std::to_string(m_scene.camera.width) + "x" + std::to_string(m_scene.camera.height) +
                "; render the reference at the same size (or pass that --size)");
  m_reference = ComparisonReference{};
  m_reference.image = std::move(image);
  m_reference.file = file;
  m_hasReference = true;
}

RenderSettings Comparison::referenceSettings(const RenderSettings& settings,
                                             const ComparisonSettings& compare) {
  RenderSettings reference = settings;
  reference.algorithm = Algorithm::PathTracing;
  reference.samplesPerPixel = compare.referenceSpp();
  reference.seed = referenceSeed(settings.seed);
  return reference;
}

void Comparison::setReferenceCache(std::optional<ReferenceCache> cache) {
  m_cache = cache ? std::make_shared<const ReferenceCache>(std::move(*cache)) : nullptr;
}

void Comparison::cancel() {
  std::lock_guard<std::mutex> lock(m_activeMutex);
  m_cancelled = true;
  if (m_active != nullptr) m_active->cancel();
}

FloatImage Comparison::renderCancellably(Renderer& renderer) {
  {
    std::lock_guard<std::mutex> lock(m_activeMutex);
    if (m_cancelled) renderer.cancel();
    m_active = &renderer;
  }
  struct Release {
    Comparison& self;
    ~Release() {
      std::lock_guard<std::mutex> lock(self.m_activeMutex);
      self.m_active = nullptr;
    }
  } release{*this};
  return renderer.render();
}

std::optional<ComparisonReference> Comparison::cachedReference(std::string& key,
                                                               std::string& note) {
  if (!m_cache) return std::nullopt;
  const RenderSettings settings = referenceSettings(m_settings, m_compare);
  try {
    key = ReferenceCache::key(m_scene, settings);
  } catch (const Exception& e) {
    note = std::string("the reference cache cannot key this scene: ") + e.what();
    return std::nullopt;
  }
  ReferenceCache::Lookup lookup = m_cache->load(m_scene, settings);
  if (lookup.reference) return std::move(lookup.reference);
  note = lookup.problem;
  return std::nullopt;
}

ComparisonReference Comparison::renderReference(
    const std::string& key, std::string note,
    const std::function<void(double, int, const FloatImage&)>& report) {
  // Path tracing at high spp with its own seed, stored for the next time.
  const RenderSettings settings = referenceSettings(m_settings, m_compare);
  ComparisonReference reference;
  reference.cacheNote = std::move(note);
  Renderer renderer(m_scene, settings);
  renderer.setThreads(m_compare.threads);
  renderer.setProgress([&](double fraction, const FloatImage& image) {
    report(fraction, renderer.stats().samplesPerPixel, image);
  });
  reference.image = renderCancellably(renderer);
  reference.samplesPerPixel = renderer.stats().samplesPerPixel;
  reference.seed = settings.seed;
  reference.seconds = renderer.stats().seconds;
  if (!key.empty() && !renderer.stats().cancelled) {
    if (auto problem = m_cache->store(m_scene, settings, reference)) {
      reference.cacheNote += (reference.cacheNote.empty() ? "" : "; ") + *problem;
    } else {
      reference.cacheFile = m_cache->imagePath(key);
    }
  }
  return reference;
}

namespace {

/// A comparison's result before any stage ran: the scene and the settings it compares.
ComparisonResult emptyResult(const Scene& scene, const RenderSettings& settings,
                             const ComparisonSettings& compare) {
  ComparisonResult result;
  result.sceneName = scene.name;
  result.sceneNameZh = scene.nameZh;
  result.width = scene.camera.width;
  result.height = scene.camera.height;
  result.settings = settings;
  result.compare = compare;
  return result;
}

/// The reference's share of the progress, one stage (algorithm) counting 1: its spp over the
/// algorithms' with equal samples, as much as all the algorithms with equal time.
double referenceStageWeight(const ComparisonSettings& compare) {
  if (compare.equalTime()) return double(compare.algorithms.size());
  return double(compare.referenceSpp()) / double(compare.samplesPerPixel);
}

/// One point of an algorithm's convergence curve: its image after a pass against the
/// reference, `seconds` into its render (time spent measuring left out).
ConvergencePoint measurePass(const RenderStats& stats, const FloatImage& image,
                             const FloatImage& reference, double seconds) {
  ConvergencePoint point;
  point.samplesPerPixel = stats.samplesPerPixel;
  point.seconds = seconds;
  point.rays = stats.rays.total();
  point.rmse = displayRmse(image, reference);
  point.rmseLinear = imageio::rmse(image, reference);
  return point;
}

/// One point of a convergence curve before the reference is in: its error still unknown.
ConvergencePoint unmeasuredPass(const RenderStats& stats, double seconds) {
  ConvergencePoint point;
  point.samplesPerPixel = stats.samplesPerPixel;
  point.seconds = seconds;
  point.rays = stats.rays.total();
  point.rmse = point.rmseLinear = std::numeric_limits<double>::quiet_NaN();
  return point;
}

/// An algorithm's figures as they stand after the pass measured as `point`.
void setFromPass(AlgorithmFigures& figures, const FloatImage& image, const RenderStats& stats,
                 const ConvergencePoint& point) {
  figures.image = image;
  figures.stats = stats;
  figures.stats.seconds = point.seconds;
  figures.rmse = point.rmse;
  figures.rmseLinear = point.rmseLinear;
}

}  // namespace

bool Comparison::renderAlgorithm(int index, ComparisonResult& result,
                                 const std::function<double(double)>& fractionOf,
                                 std::vector<FloatImage>* passes) {
  const Algorithm algorithm = m_compare.algorithms[std::size_t(index)];
  RenderSettings settings = m_settings;
  settings.algorithm = algorithm;
  settings.samplesPerPixel = m_compare.samplesPerPixel;
  Renderer renderer(m_scene, settings);
  renderer.setThreads(m_compare.threads);
  if (m_compare.equalTime()) renderer.setTimeLimit(m_compare.secondsPerAlgorithm);

  result.algorithms.emplace_back();
  AlgorithmFigures& figures = result.algorithms.back();
  figures.algorithm = algorithm;
  // Every pass measured against the reference (or, without one yet, kept to measure
  // later); the time spent measuring and in the callbacks is taken out of the times.
  double measuring = 0.0;
  const auto start = std::chrono::steady_clock::now();
  renderer.setProgress([&](double fraction, const FloatImage& image) {
    const auto measureStart = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(measureStart - start).count() - measuring;
    ConvergencePoint point;
    if (passes) {
      passes->push_back(image);
      point = unmeasuredPass(renderer.stats(), seconds);
    } else {
      point = measurePass(renderer.stats(), image, m_reference.image, seconds);
    }
    figures.series.push_back(point);
    const double stageFraction =
        std::min(1.0, m_compare.equalTime()
                          ? std::max(fraction, point.seconds / m_compare.secondsPerAlgorithm)
                          : fraction);
    if (m_progress)
      m_progress(toString(algorithm), fractionOf(stageFraction), point.samplesPerPixel);
    if (m_passCallback) {
      // The algorithm as it stands after this pass.
      setFromPass(figures, image, renderer.stats(), point);
      m_passCallback(result, index, fractionOf(stageFraction));
    }
    measuring += secondsSince(measureStart);
  });
  figures.image = renderCancellably(renderer);
  figures.stats = renderer.stats();
  figures.stats.seconds = std::max(0.0, figures.stats.seconds - measuring);
  if (figures.stats.samplesPerPixel == 0) {
    // Cancelled before its first pass: nothing of it to show.
    result.algorithms.pop_back();
    return false;
  }
  if (passes) {
    figures.rmse = figures.rmseLinear = std::numeric_limits<double>::quiet_NaN();
  } else {
    figures.rmse = displayRmse(figures.image, m_reference.image);
    figures.rmseLinear = imageio::rmse(figures.image, m_reference.image);
  }
  return true;
}

ComparisonResult Comparison::run() {
  ComparisonResult result = emptyResult(m_scene, m_settings, m_compare);

  // Step 1: how much of the work each stage is, for the progress fraction: spp with equal
  // samples (the reference counts as its spp), one budget each with equal time. A cached
  // reference turns out to cost nothing: the fraction then jumps past it.
  const int count = static_cast<int>(m_compare.algorithms.size());
  const double referenceWeight = m_hasReference ? 0.0 : referenceStageWeight(m_compare);
  const double totalWeight = referenceWeight + count;
  double doneWeight = 0.0;
  const auto fractionOf = [&](double stageFraction, double weight) {
    return std::clamp((doneWeight + stageFraction * weight) / totalWeight, 0.0, 1.0);
  };

  // Step 2: the reference — path tracing at high spp with its own seed — unless given or
  // cached; rendered after the algorithms when the pictures come first.
  if (!m_hasReference) {
    std::string key, note;
    if (auto cached = cachedReference(key, note)) {
      m_reference = std::move(*cached);
    } else if (m_picturesFirst) {
      return runPicturesFirst(std::move(result), key, note, referenceWeight);
    } else {
      m_reference = renderReference(key, note, [&](double fraction, int spp, const FloatImage&) {
        if (m_progress) m_progress("reference", fractionOf(fraction, referenceWeight), spp);
      });
    }
    doneWeight += referenceWeight;
  }
  result.reference = m_reference;
  if (m_cancelled) {
    result.cancelled = true;
    return result;
  }

  // Step 3: each algorithm, measuring every pass against the reference.
  for (int index = 0; index < count && !m_cancelled; ++index) {
    if (!renderAlgorithm(
            index, result, [&](double f) { return fractionOf(f, 1.0); }, nullptr))
      break;
    doneWeight += 1.0;
  }
  result.cancelled = m_cancelled;
  return result;
}

ComparisonResult Comparison::runPicturesFirst(ComparisonResult result, const std::string& key,
                                              const std::string& note, double referenceWeight) {
  const int count = static_cast<int>(m_compare.algorithms.size());
  const double totalWeight = referenceWeight + count;
  double doneWeight = 0.0;
  const auto fractionOf = [&](double stageFraction, double weight) {
    return std::clamp((doneWeight + stageFraction * weight) / totalWeight, 0.0, 1.0);
  };

  // Step 1: each algorithm, every pass kept to be measured once the reference is in.
  result.provisional = true;
  std::vector<std::vector<FloatImage>> passes(static_cast<std::size_t>(count));
  for (int index = 0; index < count && !m_cancelled; ++index) {
    if (!renderAlgorithm(
            index, result, [&](double f) { return fractionOf(f, 1.0); },
            &passes[std::size_t(index)]))
      break;
    doneWeight += 1.0;
  }
  if (m_cancelled) {
    result.cancelled = true;
    return result;
  }

  // Step 2: the reference; each of its passes gives the errors so far (provisional).
  m_reference = renderReference(key, note, [&](double fraction, int spp, const FloatImage& image) {
    if (m_progress) m_progress("reference", fractionOf(fraction, referenceWeight), spp);
    result.reference.image = image;
    result.reference.samplesPerPixel = spp;
    for (AlgorithmFigures& figures : result.algorithms) {
      figures.rmse = displayRmse(figures.image, image);
      figures.rmseLinear = imageio::rmse(figures.image, image);
    }
    if (m_passCallback) m_passCallback(result, -1, fractionOf(fraction, referenceWeight));
  });
  result.reference = m_reference;
  if (m_cancelled) {
    result.cancelled = true;
    return result;
  }

  // Step 3: every pass of every algorithm measured against the reference: the figures of
  // the reference-first order.
  for (std::size_t i = 0; i < result.algorithms.size(); ++i) {
    AlgorithmFigures& figures = result.algorithms[i];
    for (std::size_t p = 0; p < figures.series.size() && p < passes[i].size(); ++p) {
      figures.series[p].rmse = displayRmse(passes[i][p], m_reference.image);
      figures.series[p].rmseLinear = imageio::rmse(passes[i][p], m_reference.image);
    }
    figures.rmse = displayRmse(figures.image, m_reference.image);
    figures.rmseLinear = imageio::rmse(figures.image, m_reference.image);
  }
  result.provisional = false;
  return result;
}

std::string comparisonJson(const ComparisonResult& result) {
  ojson out;
  out["raylab"] = "comparison";
  out["version"] = 1;
  out["scene"] = result.sceneName;
  out["width"] = result.width;
  out["height"] = result.height;
  out["seed"] = result.settings.seed;
  out["maxDepth"] = result.settings.maxDepth;
  if (result.compare.equalTime()) {
    out["mode"] = "equal-time";
    out["secondsPerAlgorithm"] = result.compare.secondsPerAlgorithm;
    out["maxSamplesPerPixel"] = result.compare.samplesPerPixel;
  } else {
    out["mode"] = "equal-samples";
    out["samplesPerPixel"] = result.compare.samplesPerPixel;
  }
  // What the error figures measure: the phrase table's words (core writes no sentence of
  // its own), in English, the one language of the JSON files scripts read.
  out["error"] = {{"metric", phrase("compare.json.metric", Language::English)},
                  {"against", phrase("compare.json.against", Language::English)}};
  ojson reference;
  reference["algorithm"] = "path";
  reference["source"] = result.reference.file.empty() ? "rendered" : "file";
  if (!result.reference.file.empty()) reference["file"] = result.reference.file;
  if (result.reference.samplesPerPixel > 0)
    reference["samplesPerPixel"] = result.reference.samplesPerPixel;
  if (result.reference.file.empty()) {
    reference["seed"] = result.reference.seed;
    reference["seconds"] = result.reference.seconds;
  }
  out["reference"] = reference;

  ojson algorithms = ojson::array();
  for (const AlgorithmFigures& figures : result.algorithms) {
    ojson a;
    a["algorithm"] = toString(figures.algorithm);
    a["title"] = algorithmTitle(figures.algorithm);
    a["seconds"] = figures.stats.seconds;
    a["samplesPerPixel"] = figures.stats.samplesPerPixel;
    a["timeLimitReached"] = figures.stats.timeLimitReached;
    a["rays"] = raysJson(figures.stats.rays);
    const double rays = double(figures.stats.rays.total());
    a["raysPerSecond"] = figures.stats.seconds > 0.0 ? rays / figures.stats.seconds : 0.0;
    a["rmse"] = figures.rmse;
    a["rmseLinear"] = figures.rmseLinear;
    a["nonFiniteSamples"] = figures.stats.nonFiniteSamples;
    ojson series = ojson::array();
    for (const ConvergencePoint& p : figures.series)
      series.push_back({{"samplesPerPixel", p.samplesPerPixel},
                        {"seconds", p.seconds},
                        {"rays", p.rays},
                        {"rmse", p.rmse},
                        {"rmseLinear", p.rmseLinear}});
    a["series"] = series;
    algorithms.push_back(a);
  }
  out["algorithms"] = algorithms;
  return out.dump(2) + "\n";
}

}  // namespace raylab
