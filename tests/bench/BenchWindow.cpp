// Window benchmarks (Google Benchmark), the performance figures of issue 11:
//   ColdStart         `raylab` (the window, default scene, a fresh XDG_CONFIG_HOME) run as a
//                     process, from its start to the first frame its 3D view put on the screen
//                     (the window reports it with RAYLAB_REPORT_FIRST_FRAME and closes);
//                     counter exit_ms: to the end of the process.
//   UiLatency         the window's UI thread while the Image tab path-traces the default scene
//                     (320x240, 16 spp) on 2 threads: the gaps between successive timeouts of
//                     a 1 ms timer, i.e. between event-loop iterations, until the render ends;
//                     counters max_gap_ms and p99_gap_ms (the target: under 50 ms),
//                     gaps_over_50ms, passes. The loop sleeps between timeouts as when waiting
//                     for input (a 0 ms timer would spin the UI thread, which then takes a core
//                     from the render threads and measures itself).
//   FirstPass/A       the progressive preview of the Cornell box at 320x240 with algorithm A,
//                     as the window's Image tab runs it (RenderJob, 2 threads): from start() to
//                     the first full pass (1 spp) arriving on the UI thread.
// Needs an X server (the window): run by hand, e.g.
//   xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" build/release/tests/bench/raylab_bench_window
//       --benchmark_counters_tabular=true --benchmark_repetitions=5   (one line)
#include "MainWindow.h"
#include "RenderJob.h"
#include "RenderPanel.h"

#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"
#include "raylab/core/SceneIO.h"

#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QDir>
#include <QEventLoop>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTimer>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace raylab::app {
namespace {

using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

/// Lets Qt show, lay out and paint.
void settle() {
  for (int i = 0; i < 20; ++i) QApplication::processEvents();
}

/// This process's environment with `changes` ("NAME=value") replacing or adding variables.
std::vector<std::string> environmentWith(const std::vector<std::string>& changes) {
  std::vector<std::string> result;
  for (char** e = environ; *e; ++e) {
    const std::string entry(*e);
    const std::string name = entry.substr(0, entry.find('='));
    const bool replaced = std::any_of(changes.begin(), changes.end(), [&](const std::string& c) {
      return c.compare(0, name.size() + 1, name + "=") == 0;
    });
    if (!replaced) result.push_back(entry);
  }
  result.insert(result.end(), changes.begin(), changes.end());
  return result;
}

void ColdStart(benchmark::State& state) {
  double totalFirst = 0.0, totalExit = 0.0;
  for (auto _ : state) {
    QTemporaryDir dir;  // the fresh configuration (no last scene, no layout) and the report
    const std::string report = dir.filePath(QStringLiteral("first-frame")).toStdString();
    std::vector<std::string> env =
        environmentWith({"XDG_CONFIG_HOME=" + dir.filePath(QStringLiteral("config")).toStdString(),
                         "RAYLAB_REPORT_FIRST_FRAME=" + report, "QT_QPA_PLATFORM=xcb"});
    std::vector<char*> envp;
    for (std::string& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    std::string program = RAYLAB_EXECUTABLE;
    char* argv[] = {program.data(), nullptr};

    const Clock::time_point start = Clock::now();
    pid_t pid = 0;
    if (posix_spawn(&pid, program.c_str(), nullptr, nullptr, argv, envp.data()) != 0) {
      state.SkipWithError("cannot start " RAYLAB_EXECUTABLE);
      return;
    }
    int status = 0;
    waitpid(pid, &status, 0);
    const Clock::time_point end = Clock::now();
    long long firstFrameNs = 0;
    std::ifstream(report) >> firstFrameNs;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || firstFrameNs <= 0) {
      state.SkipWithError("raylab did not report its first frame (is there an X display?)");
      return;
    }
    const Clock::time_point first{std::chrono::nanoseconds(firstFrameNs)};
    const double firstMs = msBetween(start, first);
    totalFirst += firstMs;
    totalExit += msBetween(start, end);
    state.SetIterationTime(firstMs * 1e-3);
  }
  const double n = double(state.iterations());
  state.counters["first_frame_ms"] = totalFirst / n;
  state.counters["exit_ms"] = totalExit / n;
}
BENCHMARK(ColdStart)->UseManualTime()->Unit(benchmark::kMillisecond);

/// The value below which `fraction` of the sorted `values` lie.
double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto index = std::size_t(std::ceil(fraction * double(values.size()))) - 1;
  return values[std::min(index, values.size() - 1)];
}

void UiLatency(benchmark::State& state) {
  MainWindow window(defaultScene());
  window.resize(1260, 860);
  window.show();
  settle();
  RenderPanel& panel = *window.renderPanel();
  window.showImageTab(&panel);
  settle();
  panel.setAlgorithm(Algorithm::PathTracing);
  panel.setThreads(2);
  panel.setSamplesPerPixel(16);  // 5 passes, a few seconds on 2 threads
  std::vector<double> gaps;
  int passes = 0;
  QObject::connect(panel.job(), &RenderJob::passFinished, [&passes] { ++passes; });
  for (auto _ : state) {
    QTimer tick;
    tick.setTimerType(Qt::PreciseTimer);
    tick.setInterval(1);
    Clock::time_point last;
    QObject::connect(&tick, &QTimer::timeout, [&] {
      const Clock::time_point now = Clock::now();
      gaps.push_back(msBetween(last, now));
      last = now;
    });
    QEventLoop loop;
    QObject::connect(&panel, &RenderPanel::renderEnded, &loop, &QEventLoop::quit);
    const Clock::time_point begin = Clock::now();
    panel.render();
    last = Clock::now();
    tick.start();
    loop.exec();
    tick.stop();
    state.SetIterationTime(msBetween(begin, Clock::now()) * 1e-3);
  }
  state.counters["max_gap_ms"] = gaps.empty() ? 0.0 : *std::max_element(gaps.begin(), gaps.end());
  state.counters["p99_gap_ms"] = percentile(gaps, 0.99);
  state.counters["gaps_over_50ms"] =
      double(std::count_if(gaps.begin(), gaps.end(), [](double g) { return g > 50.0; }));
  state.counters["passes"] = benchmark::Counter(double(passes), benchmark::Counter::kAvgIterations);
}
BENCHMARK(UiLatency)->UseManualTime()->Unit(benchmark::kMillisecond);

void FirstPass(benchmark::State& state) {
  const auto algorithm = Algorithm(state.range(0));
  state.SetLabel(toString(algorithm));
  Scene cornell = SceneIO::load(RAYLAB_SOURCE_DIR "/lessons/scenes/cornell.json");
  cornell.camera.width = 320;
  cornell.camera.height = 240;
  const auto scene = std::make_shared<const Scene>(std::move(cornell));
  RenderSettings settings = scene->render;
  settings.algorithm = algorithm;
  settings.samplesPerPixel = 1;  // one pass: the first full pass of the preview
  RenderJob job;
  for (auto _ : state) {
    QEventLoop loop;
    Clock::time_point passed{};
    const auto a =
        QObject::connect(&job, &RenderJob::passFinished, [&passed] { passed = Clock::now(); });
    const auto b = QObject::connect(&job, &RenderJob::finished, &loop, &QEventLoop::quit);
    const Clock::time_point begin = Clock::now();
    job.start(scene, settings, 2);
    loop.exec();
    QObject::disconnect(a);
    QObject::disconnect(b);
    if (passed == Clock::time_point{}) {
      state.SkipWithError("the render reported no pass");
      return;
    }
    state.SetIterationTime(msBetween(begin, passed) * 1e-3);
  }
}
BENCHMARK(FirstPass)
    ->ArgName("algorithm")
    ->DenseRange(int(Algorithm::RayCasting), int(Algorithm::PathTracing))
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace raylab::app

int main(int argc, char** argv) {
  // The window's settings in a folder of this run's own, so no layout or last scene of a
  // user's applies; QApplication before any widget, with the surface format VTK needs.
  QTemporaryDir config;
  qputenv("XDG_CONFIG_HOME", config.path().toLocal8Bit());
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "xcb");
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  int qtArgc = 1;
  QApplication application(qtArgc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
