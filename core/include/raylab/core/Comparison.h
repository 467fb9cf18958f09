#pragma once

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Exception.h"
#include "raylab/core/Image.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/Scene.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

/**
 * \brief Parameters of a side-by-side comparison of the algorithms on one scene.
 *
 * | field | default | meaning |
 * | --- | --- | --- |
 * | algorithms | all four | which algorithms, in this order |
 * | samplesPerPixel | 4 | equal samples: every algorithm's spp; equal time: the cap |
 * | secondsPerAlgorithm | 0 | > 0: equal time, each algorithm renders this long |
 * | referenceSamplesPerPixel | 0 | spp of the rendered reference; 0 = defaultReferenceSpp() |
 * | threads | 0 | worker threads, 0 = all |
 */
struct ComparisonSettings {
  std::vector<Algorithm> algorithms{kAllAlgorithms.begin(), kAllAlgorithms.end()};
  int samplesPerPixel = 4;           ///< Equal samples: spp of each; equal time: the cap.
  double secondsPerAlgorithm = 0.0;  ///< Equal-time budget per algorithm, s; 0 = equal spp.
  int referenceSamplesPerPixel = 0;  ///< Reference spp; 0 = defaultReferenceSpp().
  int threads = 0;                   ///< Worker threads; 0 = all hardware threads.

  /// True in equal-time mode.
  bool equalTime() const { return secondsPerAlgorithm > 0.0; }
  /// The rule for the rendered reference: 16 x samplesPerPixel with equal samples (its own
  /// noise then adds about 3% to the path tracer's error, and referenceTooNoisy is false),
  /// 256 with equal time (the spp reached is not known beforehand: see referenceTooNoisy).
  int defaultReferenceSpp() const;
  /// referenceSamplesPerPixel, or the default rule when it is 0.
  int referenceSpp() const;
  std::string toString() const;
};

/**
 * \brief How far an image is from the reference, as displayed: the root-mean-square
 * difference of the two pictures after clamping radiance to [0, 1] and applying the sRGB
 * curve, over all pixels and channels. 0 = identical, 1 = black against white.
 *
 * Chosen over linear RMSE for the lessons: linear radiance is unbounded, so a few pixels
 * on the edge of a bright light (radiance 15 in the Cornell box) and the path tracer's
 * fireflies outweigh the whole rest of the picture. Both are reported.
 */
double displayRmse(const FloatImage& image, const FloatImage& reference);

/// The error of one progressive pass: one point of a convergence curve.
struct ConvergencePoint {
  int samplesPerPixel = 0;  ///< Samples per pixel after the pass.
  double seconds = 0.0;     ///< Render time to the end of the pass, s (error
                            ///< measurement excluded).
  std::uint64_t rays = 0;   ///< Rays traced so far, all kinds.
  double rmse = 0.0;        ///< displayRmse against the reference.
  double rmseLinear = 0.0;  ///< imageio::rmse (linear radiance) against the reference.
};

/// What one algorithm achieved: its image and its figures.
struct AlgorithmFigures {
  Algorithm algorithm = Algorithm::PathTracing;
  FloatImage image;   ///< The final image, linear radiance.
  RenderStats stats;  ///< Rays by kind, spp reached, seconds (error measurement
                      ///< excluded), time limit reached.
  /// displayRmse of the final image against the path-traced reference. Ray casting,
  /// Whitted and distributed tracing converge to other images than path tracing (no
  /// diffuse interreflection), so theirs levels off above 0.
  double rmse = 0.0;
  double rmseLinear = 0.0;               ///< imageio::rmse (linear radiance), same images.
  std::vector<ConvergencePoint> series;  ///< One point per progressive pass.
};

/// The reference every error is measured against: path tracing at high spp.
struct ComparisonReference {
  FloatImage image;         ///< Linear radiance.
  int samplesPerPixel = 0;  ///< Its spp (0 when read from a file that does not say).
  std::uint64_t seed = 0;   ///< Seed it was rendered with (0 for a file).
  std::string file;         ///< PFM it was read from; empty when rendered.
  double seconds = 0.0;     ///< Time to render it, s (0 for a file); for a cached one, the
                            ///< time it took when it was rendered.
  bool cached = false;      ///< True when read from the ReferenceCache instead of rendered.
  std::string cacheFile;    ///< The cache's PFM read or written; empty without a cache.
  std::string cacheNote;    ///< What went wrong with the cache (an entry ignored as corrupt,
                            ///< a folder not writable), for a note; empty when all went well.
};

/// Everything a comparison measured: what ComparisonView draws and the JSON reports.
struct ComparisonResult {
  std::string sceneName;       ///< Scene::name.
  std::string sceneNameZh;     ///< Scene::nameZh, its Chinese title (empty: sceneName).
  int width = 0, height = 0;   ///< Image size, pixels.
  RenderSettings settings;     ///< Shared settings (algorithm field unused).
  ComparisonSettings compare;  ///< Mode and budgets.
  ComparisonReference reference;
  std::vector<AlgorithmFigures> algorithms;  ///< In compare.algorithms' order.
  /// True when Comparison::cancel stopped the run: `algorithms` then holds those started,
  /// the last one at the last pass it finished (its stats.cancelled set), and when it
  /// stopped while rendering the reference, no algorithm and the reference's finished
  /// passes (never stored in the cache).
  bool cancelled = false;
  /// True while the errors are not yet final (Comparison::setPicturesFirst): the
  /// algorithms are rendered before the reference, and until it is complete each rmse is
  /// measured against the reference's passes so far (reference.samplesPerPixel of
  /// compare.referenceSpp()), or is NaN while it has none. A cancelled run can end so.
  bool provisional = false;
};

/// True when the rendered reference has fewer than 16 times the samples path tracing
/// reached, so that its own noise visibly adds to path tracing's error (a file reference,
/// whose spp is unknown, never counts as too noisy).
bool referenceTooNoisy(const ComparisonResult& result);

class ReferenceCache;

/**
 * \brief Renders one scene under several algorithms with the core Renderer and measures
 * each against a converged reference: the side-by-side comparison of the lessons.
 *
 * Equal samples: every algorithm renders samplesPerPixel. Equal time: each renders
 * progressive passes until secondsPerAlgorithm is used (Renderer::setTimeLimit), and the
 * spp it reached is reported. In both modes, every pass's image is measured against the
 * reference, giving the convergence series (spp 1, 2, 4, 8, ... with equal samples).
 *
 * The reference is path tracing — the algorithm that solves the rendering equation — at
 * referenceSpp(), with another seed than the compared renders (so the path tracer's error
 * is not shrunk by sharing its first samples with the reference), or an image given with
 * setReference. Images are deterministic for a given spp; times are wall-clock. With a
 * ReferenceCache (setReferenceCache), a reference rendered before for the same scene and
 * settings is read back instead of rendered, and a rendered one is stored.
 *
 * Progressive and cancellable, for a window that runs it on a worker thread: the pass
 * callback delivers, after every pass of every algorithm, the comparison so far (each
 * algorithm's image and figures up to that pass); cancel() from any thread stops the run
 * within one tile of rendering, keeping the passes finished so far.
 */
class Comparison {
 public:
  /// Input errors: a reference image of the wrong size, bad settings.
  class Error : public Exception {
   public:
    using Exception::Exception;
  };

  /// Called on the rendering thread: `stage` is "reference" or the algorithm's name,
  /// `fraction` the part of the whole comparison done (0..1), `samples` the stage's spp.
  using Progress =
      std::function<void(const std::string& stage, double fraction, int samplesPerPixel)>;
  /// Called on the rendering thread after each pass of algorithm `index` (into
  /// compare.algorithms) with everything so far: `soFar.reference` complete, the
  /// algorithms before `index` final, algorithm `index` at this pass (its image, stats with
  /// the spp, rays and seconds so far, rmse and series to this pass). `fraction` is the
  /// part of the whole comparison done (0..1). Copy what you keep: the reference is valid
  /// only during the call. With setPicturesFirst, `soFar.provisional` is true until the
  /// reference is in, and each pass of the reference is delivered too, with `index` -1:
  /// every algorithm final but its errors measured against the reference so far.
  using PassCallback =
      std::function<void(const ComparisonResult& soFar, int index, double fraction)>;

  /// `scene` (which must outlive the comparison) rendered with `settings` (algorithm
  /// ignored). Throws Error when `compare` is invalid (no algorithm, spp < 1, ...).
  Comparison(const Scene& scene, const RenderSettings& settings, const ComparisonSettings& compare);

  /// Uses `image` (e.g. a PFM of a long path-traced render) as the reference instead of
  /// rendering one; `file` names it in the figures. Throws Error naming the file when its
  /// size differs from the scene camera's.
  void setReference(FloatImage image, const std::string& file = {});
  void setProgress(Progress progress) { m_progress = std::move(progress); }
  void setPassCallback(PassCallback callback) { m_passCallback = std::move(callback); }
  /// Reads and stores the rendered reference in `cache` (nothing: no cache, the default).
  /// A reference given with setReference is neither read nor stored.
  void setReferenceCache(std::optional<ReferenceCache> cache);
  /**
   * \brief Pictures first (off by default): when the reference has to be rendered (not
   * given, not in the cache), renders the algorithms before it, so that a window shows
   * each picture within its first pass instead of after the long reference. Until the
   * reference is in, the results are provisional (ComparisonResult::provisional); its
   * passes are delivered as it refines. The final result equals the reference-first
   * order's (same images, reference, errors and series): only the times differ.
   */
  void setPicturesFirst(bool on) { m_picturesFirst = on; }

  /// Renders the reference (unless given or cached) and each algorithm; returns the
  /// figures (result.cancelled when cancel() stopped it). Call it once.
  ComparisonResult run();
  /// Stops run() from any thread (also from the callbacks): returns at once; run() returns
  /// after the tiles being rendered, with the passes finished so far. Stays cancelled.
  void cancel();
  /// True once cancel() was called.
  bool cancelled() const { return m_cancelled; }

  /// Seed of the rendered reference for a comparison seeded with `seed`.
  static std::uint64_t referenceSeed(std::uint64_t seed);
  /// The settings the reference of a comparison is rendered with: `settings` with path
  /// tracing, compare.referenceSpp() and referenceSeed(settings.seed).
  static RenderSettings referenceSettings(const RenderSettings& settings,
                                          const ComparisonSettings& compare);

 private:
  const Scene& m_scene;
  RenderSettings m_settings;
  ComparisonSettings m_compare;
  ComparisonReference m_reference;
  bool m_hasReference = false;
  bool m_picturesFirst = false;
  Progress m_progress;
  PassCallback m_passCallback;
  std::shared_ptr<const ReferenceCache> m_cache;
  std::atomic<bool> m_cancelled{false};
  std::mutex m_activeMutex;      ///< Guards m_active against cancel() from other threads.
  Renderer* m_active = nullptr;  ///< The renderer run() is in, for cancel().

  /// The reference's cache entry for this comparison: `key` set when the cache can key
  /// the scene, the verified entry when there is one, else what went wrong in `note`.
  std::optional<ComparisonReference> cachedReference(std::string& key, std::string& note);
  /// Renders with `renderer`, reachable by cancel() meanwhile.
  FloatImage renderCancellably(Renderer& renderer);
  /// Renders the reference (each pass reported with its image) and stores it under `key`.
  ComparisonReference renderReference(
      const std::string& key, std::string note,
      const std::function<void(double, int, const FloatImage&)>& report);
  /// Renders algorithm `index` into a new entry of result.algorithms, each pass measured
  /// against m_reference, or (`passes` given: no reference yet) kept there to measure
  /// later. False when it was cancelled before its first pass (no entry then).
  bool renderAlgorithm(int index, ComparisonResult& result,
                       const std::function<double(double)>& fractionOf,
                       std::vector<FloatImage>* passes);
  /// The pictures-first order: the algorithms, then the reference, then the errors.
  ComparisonResult runPicturesFirst(ComparisonResult result, const std::string& key,
                                    const std::string& note, double referenceWeight);
};

/// The figures as JSON (nlohmann-json, 2-space indent): scene, mode, error metric and
/// what it is measured against, the reference, and per algorithm its time, spp, rays by
/// kind and total, rmse, linear rmse and convergence series.
std::string comparisonJson(const ComparisonResult& result);

}  // namespace raylab
