#include "commands/AnimateCommand.h"

#include "commands/ExitCodes.h"
#include "commands/TraceCommand.h"

#include "raylab/core/Lesson.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayWords.h"

#include "raylab/core/AtomicFolder.h"
#include "raylab/core/Exception.h"
#include "raylab/vis/BounceAnimation.h"
#include "raylab/vis/Display.h"
#include "raylab/vis/ImageIO.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

namespace raylab::app {

namespace {

/// A failure of the animation's output (folder, encoder).
class AnimateError : public Exception {
 public:
  using Exception::Exception;
};

struct AnimateOptions {
  RayTreeOptions tree;
  std::string frames;    ///< --frames A:B (inclusive); empty = all.
  int every = 1;         ///< --every N.
  std::string video;     ///< --video F.mp4; empty = none.
  int fps = 24;          ///< --fps of the video.
  bool captions = true;  ///< --captions: the narration of each frame along its bottom.
};

/// The caption of a frame in language `lang` (vis::stepCaption), the scene's names as a
/// reader of that language sees them.
std::function<std::string(int)> captionsIn(const std::string& lang, const Scene& scene,
                                           const PixelTrace& trace,
                                           const vis::AnimationSettings& animation) {
  const Language language = parseLanguage(lang).value_or(Language::English);
  return [&trace, animation, language, names = sceneNames(scene, language)](int frame) {
    return vis::stepCaption(trace, animation, frame, names, language);
  };
}

/// Parses "A:B" (A <= B, both >= 0); nothing when malformed.
std::optional<std::pair<int, int>> parseRange(const std::string& text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 >= text.size()) return std::nullopt;
  const std::string a = text.substr(0, colon), b = text.substr(colon + 1);
  const auto digits = [](const std::string& s) {
    return s.size() <= 9 && s.find_first_not_of("0123456789") == std::string::npos;
  };
  if (!digits(a) || !digits(b)) return std::nullopt;
  const int first = std::stoi(a), last = std::stoi(b);
  if (first > last) return std::nullopt;
  return std::make_pair(first, last);
}

/// The absolute path of `program` found on PATH, or "" when it is not there.
std::string findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(dir) / program;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) &&
        (std::filesystem::status(candidate, ec).permissions() &
         std::filesystem::perms::owner_exec) != std::filesystem::perms::none)
      return candidate.string();
  }
  return {};
}

/// Single-quotes `text` for /bin/sh.
std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// The prefix of the new videos made beside `target`: ".STEM.raylab-new-"; the process id
/// and the extension follow.
std::string newVideoPrefix(const std::filesystem::path& target) {
  return "." + target.stem().string() + ".raylab-new-";
}

/// Removes the new videos beside `target` whose process no longer runs (killed with -9 while
/// ffmpeg wrote): half a video nobody will finish.
void removeStaleVideos(const std::filesystem::path& target) {
  namespace fs = std::filesystem;
  const std::string prefix = newVideoPrefix(target);
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string entry = it->path().filename().string();
    std::error_code ignored;
    if (entry.rfind(prefix, 0) != 0 || it->symlink_status(ignored).type() != fs::file_type::regular)
      continue;  // not ours (a frames folder beside it has its own cleaning)
    const long pid = std::strtol(entry.c_str() + prefix.size(), nullptr, 10);
    if (pid <= 0 || (::kill(pid_t(pid), 0) != 0 && errno == ESRCH)) fs::remove(it->path(), ignored);
  }
}

/// How ffmpeg ended, for a message: "exit status N" or "stopped by signal N" (Ctrl-C: 2).
std::string howItEnded(int status) {
  if (status == -1) return "could not be started";
  if (WIFSIGNALED(status)) return "stopped by signal " + std::to_string(WTERMSIG(status));
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  // The shell between says 128 + N for a program stopped by signal N.
  if (code > 128 && code <= 128 + 64) return "stopped by signal " + std::to_string(code - 128);
  return "exit status " + std::to_string(code);
}

/// Encodes dir/frame_*.png to `video` with ffmpeg: into a new file beside it (same
/// extension: ffmpeg picks the format by it), renamed over `video` only when ffmpeg
/// succeeds, so a failed or interrupted encoding leaves an earlier video as it was.
void encodeVideo(const std::string& ffmpeg, const std::filesystem::path& dir, int fps,
                 const std::string& video, const std::string& framesFolder) {
  namespace fs = std::filesystem;
  const fs::path target(video);
  removeStaleVideos(target);
  const fs::path temp =
      target.parent_path() /
      (newVideoPrefix(target) + std::to_string(::getpid()) + target.extension().string());
  const std::string command =
      shellQuote(ffmpeg) + " -y -loglevel error -framerate " + std::to_string(fps) +
      " -pattern_type glob -i " + shellQuote((dir / "frame_*.png").string()) +
      " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -pix_fmt yuv420p " + shellQuote(temp.string());
  const int status = std::system(command.c_str());
  std::error_code ec;
  if (status != 0 || !fs::exists(temp, ec) || std::rename(temp.c_str(), video.c_str()) != 0) {
    fs::remove(temp, ec);
    throw AnimateError(video + ": ffmpeg failed (" + howItEnded(status) +
                       "); the video was not changed; the PNG frames are in " + framesFolder);
  }
}

/// The ffmpeg on PATH that encodes `video`; an error that says how to get it when there is none.
std::string ffmpegFor(const std::string& video) {
  const std::string ffmpeg = findOnPath("ffmpeg");
  if (ffmpeg.empty())
    throw AnimateError("--video " + video +
                       " needs the ffmpeg encoder, which is not on PATH; install it with "
                       "`sudo apt-get install ffmpeg`, or leave out --video to get the PNG "
                       "frames only");
  return ffmpeg;
}

/// Opens `folder`, the new folder beside `out` that takes the frames (frame_*.png); on
/// failure removes the folders the run made (`missing`: the first of them) and throws.
void openFramesFolder(std::optional<AtomicFolder>& folder, const std::string& out,
                      const std::string& missing) {
  try {
    folder.emplace(out, [](const std::string& name) {
      return name.rfind("frame_", 0) == 0 && name.size() > 10 &&
             name.compare(name.size() - 4, 4, ".png") == 0;
    });
  } catch (const AtomicFolder::Error& e) {
    removeFoldersMade(missing);
    throw AnimateError(e.what());
  }
}

/// The frames first..last, every `every`th, and with --every the last one too: the finished
/// tree (or the range's end).
std::vector<int> framesToWrite(int first, int last, int every) {
  std::vector<int> frames;
  for (int f = first; f <= last; f += every) frames.push_back(f);
  if (frames.back() != last) frames.push_back(last);
  return frames;
}

int runAnimate(const AnimateOptions& options, const std::string& topLevelScene) {
  // Step 1: scene, pixel, frames and encoder, all checked before any work.
  const RayTreeOptions& o = options.tree;
  const Scene scene = o.loadScene(topLevelScene);
  if (const auto error = o.usageError(scene)) {
    std::cerr << "raylab animate: " << *error << std::endl;
    return kExitUsage;
  }
  const std::optional<std::pair<int, int>> range =
      options.frames.empty() ? std::nullopt : parseRange(options.frames);
  if (!options.frames.empty() && !range) {
    std::cerr << "raylab animate: --frames " << options.frames
              << ": expected FIRST:LAST frame numbers, e.g. 0:47" << std::endl;
    return kExitUsage;
  }
  const std::string ffmpeg = options.video.empty() ? std::string() : ffmpegFor(options.video);
  const RenderSettings settings = o.common.settings(scene);

  // Step 2: the folder for the frames (its problems first), then the tree, its view and the
  // frames to write (once they can be drawn).
  // The frames go into a new folder beside --out, swapped in when all are written: an
  // error or Ctrl-C leave an earlier run's frames as they were, and the video sees only
  // this run's frames (issue 38).
  const std::filesystem::path dir(o.common.out);
  const std::string missing = firstMissingFolder(o.common.out);
  std::optional<AtomicFolder> folder;
  openFramesFolder(folder, o.common.out, missing);
  requireDisplayAfterFolder(missing);
  const PixelTrace trace = tracePixel(scene, settings, o.pixel.first, o.pixel.second, o.sample);
  const RayTree& tree = trace.tree;
  const vis::AnimationSettings animation = o.animation();
  const int total = vis::frameCount(tree, animation);
  if (range && range->first > total - 1) {
    removeFoldersMade(missing);
    throw AnimateError("--frames " + options.frames + ": this animation has frames 0 to " +
                       std::to_string(total - 1));
  }
  const int first = range ? range->first : 0;
  const int last = range ? std::min(range->second, total - 1) : total - 1;
  const std::vector<int> frames = framesToWrite(first, last, options.every);

  const int digits = std::max(4, int(std::to_string(total - 1).size()));
  const auto frameFile = [&](int frame) {
    std::ostringstream name;
    name << "frame_" << std::setfill('0') << std::setw(digits) << frame << ".png";
    return folder->file(name.str());
  };

  // Step 3: render frame after frame into the same view.
  const auto [width, height] = o.pictureSize();
  const std::unique_ptr<vis::SceneView> view = o.makeView(scene, tree);
  const std::function<std::string(int)> caption = captionsIn(o.lang, scene, trace, animation);
  ProgressBar progress("animate");
  for (std::size_t i = 0; i < frames.size(); ++i) {
    view->setReveal(vis::revealFrame(tree, animation, frames[i]));
    if (options.captions)
      view->setCaption(caption(frames[i]), parseLanguage(o.lang).value_or(Language::English));
    view->renderToPng(frameFile(frames[i]), width, height);
    progress.update(double(i + 1) / double(frames.size()),
                    std::to_string(i + 1) + "/" + std::to_string(frames.size()) + " frames");
  }

  try {
    folder->commit();
  } catch (const AtomicFolder::Error& e) {
    throw AnimateError(e.what());
  }

  // Step 4: the video, when asked for: encoded from the folder, which holds this run's
  // frames only, into a new file renamed over the video when ffmpeg succeeds.
  if (!ffmpeg.empty()) encodeVideo(ffmpeg, dir, options.fps, options.video, o.common.out);

  std::cout << o.common.out << "\n";
  if (!options.video.empty()) std::cout << options.video << "\n";
  std::cout << frames.size() << " of " << total << " frames (" << first << ".." << last
            << (options.every > 1 ? ", every " + std::to_string(options.every) : std::string())
            << "), " << toString(animation.order) << " order, " << toString(settings.algorithm)
            << ": " << traceSummary(trace, Language::English) << std::endl;
  return kExitOk;
}

}  // namespace

Subcommand addAnimateCommand(CLI::App& cli) {
  auto options = std::make_shared<AnimateOptions>();
  CLI::App* command = cli.add_subcommand(
      "animate", "Animate one pixel sample's ray tree bounce by bounce: numbered PNG frames");
  command->footer(
      "Exit codes: 0 ok, 1 runtime error (bad scene file, unwritable folder, no ffmpeg),\n"
      "            2 usage error (e.g. a pixel outside the image), 3 internal error.\n"
      "Frame N is the same picture as `raylab trace --frame N` with the same options, with\n"
      "the narration of that moment along its bottom (--no-captions leaves it out).\n"
      "Rendering needs an X server, also headless: run under xvfb-run -a.");
  options->tree.add(command, "Folder for the frames (frame_0000.png, ...)", "640x480");
  command->add_option("--frames", options->frames, "Only frames FIRST:LAST (inclusive)")
      ->group("Animation");
  command->add_option("--every", options->every, "Write every Nth frame, and the last")
      ->check(CLI::Range(1, 1 << 30))
      ->capture_default_str()
      ->group("Animation");
  command
      ->add_flag("--captions,!--no-captions", options->captions,
                 "Write each frame's narration (which ray travels, what it hit) along its "
                 "bottom, so a video keeps it (default on)")
      ->group("Animation");
  command->add_option("--video", options->video, "Also encode the frames to this video (ffmpeg)");
  command->add_option("--fps", options->fps, "Frames per second of the video")
      ->check(CLI::Range(1, 240))
      ->capture_default_str();
  return {command, [options](const std::string& topLevelScene) {
            return runAnimate(*options, topLevelScene);
          }};
}

}  // namespace raylab::app
