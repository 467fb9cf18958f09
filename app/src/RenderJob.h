#pragma once

#include "raylab/core/Image.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/Scene.h"

#include "window/BackgroundTask.h"

#include <QImage>
#include <QObject>

#include <memory>

namespace raylab::app {

/// What a render has reached after one progressive pass.
struct RenderProgress {
  std::shared_ptr<const FloatImage> image;  ///< The image of the passes so far.
  int samplesPerPixel = 0;                  ///< Samples reached in every pixel.
  int samplesWanted = 0;                    ///< Samples the render stops at.
  double seconds = 0.0;                     ///< Wall-clock time since the render began.
  std::uint64_t rays = 0;                   ///< Rays traced so far, every kind.
  /// Samples so far that reached limits::kMaxRaysPerSample (RenderStats::cappedSamples):
  /// their rays past the cap were not traced.
  std::uint64_t cappedSamples = 0;
  QImage picture;  ///< The image's 8-bit picture (toPicture), made on the render thread.
  /// Rays per second so far (0 before any time has passed).
  double raysPerSecond() const { return seconds > 0.0 ? double(rays) / seconds : 0.0; }
};

/**
 * \brief One render at a time, off the UI thread: the window's Render button.
 *
 * start() renders a copy of the scene with core's Renderer as a BackgroundTask job (whose
 * thread runs the renderer's own tile threads), and reports each finished pass with passFinished on
 * the UI thread. Like the original course program's mutex, two renders never run at once:
 * start() while a render runs cancels it and starts the new one as soon as the old one has
 * stopped (the old one's late passes are dropped). cancel() returns at once; the worker
 * stops before its next tile and the passes finished so far stay shown. The destructor
 * cancels and waits for the worker, so no thread outlives the job.
 *
 * The UI thread stays responsive while every core renders (tests/bench/BenchWindow.cpp): the
 * render threads run at a lower priority (nice 10 on Linux), and each pass's 8-bit picture is
 * made on the worker, so the UI thread only shows it.
 */
class RenderJob : public QObject {
  Q_OBJECT

 public:
  explicit RenderJob(QObject* parent = nullptr);
  ~RenderJob() override;

  /// Renders `scene` at its camera's size with `settings` on `threads` threads (0: all).
  void start(std::shared_ptr<const Scene> scene, const RenderSettings& settings, int threads);
  /// Stops the render (and forgets a render waiting to start); the last finished pass
  /// stays the result. Returns at once.
  void cancel();
  /// True from start() until finished() is emitted for the last render asked for.
  bool busy() const { return m_task.busy(); }
  /// True while a worker thread exists (a cancelled one may still be stopping).
  bool threadRunning() const { return m_task.threadRunning(); }
  /// The most render threads that ever ran at the same time in this process, over every
  /// job (for tests: the window must never render twice at once).
  static int mostAtOnce();

 signals:
  /// A pass finished (on the UI thread).
  void passFinished(const raylab::app::RenderProgress& progress);
  /// The render ended: complete, or `cancelled`; `progress` is its last pass.
  void finished(const raylab::app::RenderProgress& progress, bool cancelled);

 private:
  BackgroundTask m_task;
};

}  // namespace raylab::app

Q_DECLARE_METATYPE(raylab::app::RenderProgress)
