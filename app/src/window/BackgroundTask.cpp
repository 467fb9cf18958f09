#include "BackgroundTask.h"

#include <QMetaObject>

#include <mutex>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace raylab::app {

namespace {

/// Held while a call is posted and before it is read. Qt's event queue synchronises the
/// two threads with a lock ThreadSanitizer cannot see in a Qt not built with it, so without
/// this it reports the posted data as a race; with it the order is explicit: the worker
/// posts under the lock, the UI thread takes the lock before it reads anything of the call,
/// even the captured `this` (so the lock is not a member).
std::mutex g_handOff;

/// The nice value workers run at: below the UI thread, so that on a machine whose every
/// core renders the UI still runs as soon as it has work (a pass to show, a click).
constexpr int kWorkerNice = 10;

}  // namespace

void lowerThreadPriority() {
#ifdef __linux__
  const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
  const int now = ::getpriority(PRIO_PROCESS, tid);
  if (now < kWorkerNice) ::setpriority(PRIO_PROCESS, tid, kWorkerNice);
#endif
}

BackgroundTask::BackgroundTask(QObject* parent) : QObject(parent) {}

BackgroundTask::~BackgroundTask() {
  m_waiting.reset();
  if (m_running) {
    m_running->stop();
    m_running->thread.join();
  }
}

bool BackgroundTask::current(int generation) const {
  return generation == m_generation && generation >= m_firstShown && !m_waiting;
}

void BackgroundTask::start(Job job) {
  if (m_running) {
    // One job at a time: stop the running one; this one starts when it has ended.
    m_running->stop();
    m_waiting = std::move(job);
    return;
  }
  launch(std::move(job));
}

void BackgroundTask::cancel() {
  m_waiting.reset();
  if (m_running) m_running->stop();
}

void BackgroundTask::drop() {
  cancel();
  m_firstShown = m_generation + 1;
}

void BackgroundTask::launch(Job job) {
  const int generation = ++m_generation;
  // The worker posts to this object; the destructor joins the worker first, so `this` is
  // alive whenever a call is posted, and Qt drops the calls still queued when it is gone.
  Post post = [this, generation](std::function<void()> call) {
    std::lock_guard<std::mutex> posting(g_handOff);
    QMetaObject::invokeMethod(
        this,
        [this, generation, call = std::move(call)] {
          { std::lock_guard<std::mutex> posted(g_handOff); }
          if (current(generation)) call();
        },
        Qt::QueuedConnection);
  };
  Running running;
  running.stop = job.stop;
  running.generation = generation;
  running.thread = std::thread([this, generation, run = std::move(job.run), post] {
    lowerThreadPriority();
    std::function<void()> end = run(post);
    std::lock_guard<std::mutex> posting(g_handOff);
    QMetaObject::invokeMethod(
        this,
        [this, generation, end = std::move(end)] {
          { std::lock_guard<std::mutex> posted(g_handOff); }
          workerDone(generation, end);
        },
        Qt::QueuedConnection);
  });
  m_running = std::move(running);
}

void BackgroundTask::workerDone(int generation, const std::function<void()>& end) {
  if (!m_running || m_running->generation != generation) return;
  m_running->thread.join();  // it has posted its last call: it ends at once
  m_running.reset();
  if (m_waiting) {
    Job next = std::move(*m_waiting);
    m_waiting.reset();
    launch(std::move(next));
    return;
  }
  if (end && current(generation)) end();
}

}  // namespace raylab::app
