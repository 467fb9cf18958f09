#include "RenderJob.h"

#include "ImageView.h"

#include <QMetaObject>
#include <QPointer>

#include <atomic>
#include <chrono>
#include <mutex>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace raylab::app {

RenderJob::RenderJob(QObject* parent) : QObject(parent) { qRegisterMetaType<RenderProgress>(); }

RenderJob::~RenderJob() {
  m_pending.reset();
  if (m_worker) {
    m_worker->renderer->cancel();
    m_worker->thread.join();
  }
}

void RenderJob::start(std::shared_ptr<const Scene> scene, const RenderSettings& settings,
                      int threads) {
  Request request{std::move(scene), settings, threads};
  if (m_worker) {
    // One render at a time: stop the running one; this one starts when it has stopped.
    m_worker->renderer->cancel();
    m_pending = std::move(request);
    return;
  }
  launch(std::move(request));
}

void RenderJob::cancel() {
  m_pending.reset();
  if (m_worker) m_worker->renderer->cancel();
}

namespace {
std::atomic<int> g_running{0};  ///< Render threads running now, in every job.
std::atomic<int> g_most{0};     ///< The most that ever ran at once.
std::mutex g_handOff;           ///< Held while a pass is posted and before it is read.

/// The nice value render threads run at: below the UI thread, so that on a machine whose
/// every core renders the UI still runs as soon as it has work (a pass to show, a click).
constexpr int kRenderNice = 10;

}  // namespace

void lowerThreadPriority() {
#ifdef __linux__
  const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
  const int now = ::getpriority(PRIO_PROCESS, tid);
  if (now < kRenderNice) ::setpriority(PRIO_PROCESS, tid, kRenderNice);
#endif
}

int RenderJob::mostAtOnce() { return g_most.load(); }

void RenderJob::launch(Request request) {
  const int generation = ++m_generation;
  auto renderer = std::make_shared<Renderer>(*request.scene, request.settings);
  renderer->setThreads(request.threads);
  const int wanted = request.settings.samplesPerPixel;
  const auto begin = std::chrono::steady_clock::now();
  // The worker posts to this object through a QPointer-free queued call: the destructor
  // joins the worker first, so `this` is alive whenever a call is posted.
  //
  // The hand-off also holds g_handOff: Qt's event queue synchronises the two threads with a
  // lock ThreadSanitizer cannot see in a Qt not built with it, so without this it reports
  // the posted pass (its copy and its image) as a race; with it the order is explicit:
  // the worker posts under the lock, the UI thread takes the lock before it reads anything
  // of the call, even the captured `this` (so the lock is not a member).
  auto post = [this, generation](const RenderProgress& progress, std::optional<bool> end) {
    std::lock_guard<std::mutex> posting(g_handOff);
    QMetaObject::invokeMethod(
        this,
        [this, generation, progress, end] {
          { std::lock_guard<std::mutex> posted(g_handOff); }
          if (end)
            workerDone(generation, progress, *end);
          else if (generation == m_generation && !m_pending)
            emit passFinished(progress);
        },
        Qt::QueuedConnection);
  };
  Renderer* r = renderer.get();
  renderer->setProgress([r, wanted, begin, post](double, const FloatImage& image) {
    RenderProgress progress;
    progress.image = std::make_shared<const FloatImage>(image);
    progress.picture = toPicture(image);  // here, not on the UI thread
    progress.samplesPerPixel = r->stats().samplesPerPixel;
    progress.samplesWanted = wanted;
    progress.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    progress.rays = r->stats().rays.total();
    progress.cappedSamples = r->stats().cappedSamples;
    post(progress, std::nullopt);
  });
  Worker worker;
  worker.renderer = renderer;
  worker.generation = generation;
  worker.thread = std::thread([scene = request.scene, renderer, wanted, post] {
    lowerThreadPriority();
    const int running = ++g_running;
    for (int most = g_most.load();
         running > most && !g_most.compare_exchange_weak(most, running);) {
    }
    RenderProgress last;
    last.samplesWanted = wanted;
    bool cancelled = true;
    try {
      FloatImage image = renderer->render();
      const RenderStats& stats = renderer->stats();
      last.samplesPerPixel = stats.samplesPerPixel;
      last.seconds = stats.seconds;
      last.rays = stats.rays.total();
      last.cappedSamples = stats.cappedSamples;
      if (stats.samplesPerPixel > 0) {
        last.image = std::make_shared<const FloatImage>(image);
        last.picture = toPicture(image);
      }
      cancelled = stats.cancelled;
    } catch (const std::exception&) {
      // Renderer only throws for an empty image or spp < 1, which the loader refuses;
      // report it as a render that produced nothing.
    }
    --g_running;
    post(last, cancelled);
  });
  m_worker = std::move(worker);
}

void RenderJob::workerDone(int generation, const RenderProgress& last, bool cancelled) {
  if (!m_worker || m_worker->generation != generation) return;
  m_worker->thread.join();  // it has posted its last call: it ends at once
  m_worker.reset();
  if (m_pending) {
    Request next = std::move(*m_pending);
    m_pending.reset();
    launch(std::move(next));
    return;
  }
  emit finished(last, cancelled);
}

}  // namespace raylab::app
