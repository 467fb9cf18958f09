#pragma once

#include <QObject>

#include <functional>
#include <optional>
#include <thread>

namespace raylab::app {

/// Lowers the calling thread's scheduling priority below the UI thread's (Linux's nice is
/// per thread, and threads it starts inherit it: a renderer's tile threads), so that with
/// every core rendering the window still answers at once. Best effort: elsewhere nothing.
void lowerThreadPriority();

/**
 * \brief The window's one way to run long work off the UI thread: the render, the
 * comparison (and, for the same reasons, any other job that may take seconds).
 *
 * One job at a time per task, on a worker thread at a lower priority. The job hands its
 * results to the UI thread with `post` (queued calls on this object's thread, in order);
 * when it returns, the call it returns runs on the UI thread after its thread is joined.
 * No event loop is ever spun inside a call: the UI thread only runs what was posted.
 *
 * - start() while a job runs **supersedes** it: the running job is asked to stop, all it
 *   still posts is dropped (its end too), and the new job starts as soon as the old thread
 *   has ended, so two jobs of one task never run at once.
 * - cancel() asks the running job to stop and forgets a waiting one, but keeps what the
 *   running job still posts (a cancelled render shows the passes it finished) and its end.
 * - drop() stops it and drops everything it would still post: its input is gone (another
 *   scene was opened).
 * - The destructor stops the job and joins its thread, so no thread outlives the task and
 *   no posted call reaches a deleted object.
 *
 * Qt's QtConcurrent::run + QFutureWatcher would do the same with a thread pool; a plain
 * thread keeps the renderer's own tile threads the only pool, and the hand-off explicit
 * for ThreadSanitizer (BackgroundTask.cpp).
 */
class BackgroundTask : public QObject {
  Q_OBJECT

 public:
  /// Hands `call` to the UI thread (from the worker); dropped if the job is superseded.
  using Post = std::function<void(std::function<void()> call)>;
  struct Job {
    /// Runs on the worker thread; returns the call that ends the job on the UI thread.
    std::function<std::function<void()>(const Post& post)> run;
    /// Asks `run` to return soon (called on the UI thread while it runs).
    std::function<void()> stop;
  };

  explicit BackgroundTask(QObject* parent = nullptr);
  ~BackgroundTask() override;

  /// Runs `job`: now, or once the running job (asked to stop) has ended.
  void start(Job job);
  /// Asks the running job to stop (what it posts still arrives) and forgets a waiting one.
  void cancel();
  /// Stops the running job and drops everything it still posts, its end included.
  void drop();
  /// True from start() until the last job asked for has ended.
  bool busy() const { return m_running.has_value() || m_waiting.has_value(); }
  /// True while a worker thread exists (a stopped job's thread may still be ending).
  bool threadRunning() const { return m_running.has_value(); }
  /// True when calls posted by job `generation` are shown (it is the newest job, nothing
  /// waits to supersede it, and it was not dropped).
  bool current(int generation) const;

 private:
  struct Running {
    std::thread thread;
    std::function<void()> stop;
    int generation = 0;
  };
  void launch(Job job);
  /// The worker's end, on the UI thread: joins it, then starts a waiting job.
  void workerDone(int generation, const std::function<void()>& end);

  std::optional<Running> m_running;
  std::optional<Job> m_waiting;
  int m_generation = 0;  ///< The newest job's number.
  int m_firstShown = 1;  ///< Jobs before this number were dropped.
};

}  // namespace raylab::app
