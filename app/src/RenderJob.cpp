#include "RenderJob.h"

#include "ImageView.h"

#include <atomic>
#include <chrono>

namespace raylab::app {

namespace {
std::atomic<int> g_running{0};  ///< Render threads running now, in every job.
std::atomic<int> g_most{0};     ///< The most that ever ran at once.

/// The figures of `renderer` now, and `image` with its 8-bit picture (made here, on the
/// render thread, not on the UI thread).
RenderProgress progressOf(const Renderer& renderer, const FloatImage& image, int wanted) {
  const RenderStats& stats = renderer.stats();
  RenderProgress progress;
  progress.samplesWanted = wanted;
  progress.samplesPerPixel = stats.samplesPerPixel;
  progress.rays = stats.rays.total();
  progress.cappedSamples = stats.cappedSamples;
  if (stats.samplesPerPixel > 0) {
    progress.image = std::make_shared<const FloatImage>(image);
    progress.picture = toPicture(image);
  }
  return progress;
}

}  // namespace

RenderJob::RenderJob(QObject* parent) : QObject(parent) { qRegisterMetaType<RenderProgress>(); }

RenderJob::~RenderJob() = default;

int RenderJob::mostAtOnce() { return g_most.load(); }

void RenderJob::cancel() { m_task.cancel(); }

void RenderJob::start(std::shared_ptr<const Scene> scene, const RenderSettings& settings,
                      int threads) {
  auto renderer = std::make_shared<Renderer>(*scene, settings);
  renderer->setThreads(threads);
  const int wanted = settings.samplesPerPixel;
  BackgroundTask::Job job;
  job.stop = [renderer, scene] {  // the scene outlives the renderer
    renderer->cancel();
  };
  job.run = [this, scene, renderer, wanted](const BackgroundTask::Post& post) {
    const auto begin = std::chrono::steady_clock::now();
    Renderer* r = renderer.get();
    renderer->setProgress([this, r, wanted, begin, post](double, const FloatImage& image) {
      RenderProgress progress = progressOf(*r, image, wanted);
      if (!progress.image) {  // a pass always shows its image
        progress.image = std::make_shared<const FloatImage>(image);
        progress.picture = toPicture(image);
      }
      progress.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
      post([this, progress] { emit passFinished(progress); });
    });
    const int running = ++g_running;
    for (int most = g_most.load();
         running > most && !g_most.compare_exchange_weak(most, running);) {
    }
    RenderProgress last;
    last.samplesWanted = wanted;
    bool cancelled = true;
    try {
      const FloatImage image = renderer->render();
      last = progressOf(*renderer, image, wanted);
      last.seconds = renderer->stats().seconds;
      cancelled = renderer->stats().cancelled;
    } catch (const std::exception&) {
      // Renderer only throws for an empty image or spp < 1, which the loader refuses;
      // report it as a render that produced nothing.
    }
    --g_running;
    return std::function<void()>([this, last, cancelled] { emit finished(last, cancelled); });
  };
  m_task.start(std::move(job));
}

}  // namespace raylab::app
