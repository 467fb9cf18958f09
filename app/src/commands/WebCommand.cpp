// `raylab web`: every lesson as a static, self-contained site (issue 34; doc/web-data.md),
// written beside DIR and swapped in whole.
#include "commands/WebCommand.h"

#include "commands/ExitCodes.h"
#include "commands/InstalledData.h"
#include "commands/WebLesson.h"
#include "commands/WebSite.h"

#include "raylab/core/AtomicFolder.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/LessonAliases.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/Text.h"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

namespace raylab::app {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// The zip while it is made: inside the new folder (so an interrupt removes it with the
/// folder), moved beside DIR once the site is in place.
constexpr const char* kZipInside = ".raylab-site.zip";

struct WebCommandOptions {
  std::vector<std::string> lessons;  ///< Files or ids; empty: every lesson in `dir`.
  std::string dir = lessonsFolder();
  std::string out;
  std::string lang = "both";
  std::string bundle;  ///< Folder of raylab-web.js/.css; empty: the build's or installed.
  bool student = false;
  bool zip = false;
  int maxSpp = 0;
  int maxSizeMb = 512;
};

/// The page's bundle: --bundle, else <bin>/../share/raylab/web, else the build tree's.
std::string bundleFolder(const std::string& given) {
  if (!given.empty()) return given;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path() / ".." / "share" / "raylab" / "web";
    if (fs::is_regular_file(installed / "raylab-web.js", ec)) return installed.string();
  }
  return RAYLAB_WEB_BUNDLE_DIR;
}

/// The files of a site: nothing else may be in a folder the export replaces.
bool siteFile(const std::string& name) {
  static const std::set<std::string> kNames = {"index.html",     "course.js", "raylab-web.js",
                                               "raylab-web.css", "lessons",   "imsmanifest.xml",
                                               kZipInside};
  return kNames.count(name) > 0;
}

std::vector<Lesson> loadLessons(const WebCommandOptions& o) {
  std::vector<std::string> paths;
  if (o.lessons.empty()) paths = LessonIO::list(o.dir);
  for (const std::string& l : o.lessons) paths.push_back(resolveLessonFile(l, o.dir));
  if (paths.empty()) throw WebError(o.dir + ": no lesson files (NN-topic.json) to export");
  std::vector<Lesson> lessons;
  std::set<std::string> ids;
  for (const std::string& path : paths) {
    lessons.push_back(LessonIO::load(path));  // LoadError names the file and the place
    if (!ids.insert(fileId(lessons.back().id)).second)
      throw WebError(path + ": a second lesson with the id \"" + lessons.back().id + "\"");
  }
  return lessons;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw WebError(path +
                   ": the page's bundle is missing; build it (cmake --build build "
                   "--target raylab_web_bundle) or give --bundle DIR");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The course's words and lessons (course.js).
json courseData(const std::vector<json>& lessons, const WebOptions& o) {
  json phrases = json::object();
  for (const std::string& key : phraseKeys()) {
    const bool page = key.rfind("web.", 0) == 0 || key.rfind("ray_kind.", 0) == 0 ||
                      key.rfind("end_reason.", 0) == 0 || key.rfind("legend.", 0) == 0 ||
                      key.rfind("algorithm.", 0) == 0;
    if (page)
      phrases[key] = localJson({phrase(key, Language::English), phrase(key, Language::Chinese)}, o);
  }
  json list = json::array();
  for (const json& l : lessons)
    list.push_back({{"id", l["id"]},
                    {"page", "lessons/" + l["id"].get<std::string>() + ".html"},
                    {"title", l["title"]},
                    {"summary", l["summary"]},
                    {"steps", l["steps"].size()},
                    {"minutes", l["minutes"]}});
  json languages = json::array();
  for (Language l : o.languages) languages.push_back(languageTag(l));
  return {{"version", 1},           {"student", o.student},
          {"languages", languages}, {"defaultLanguage", languages[0]},
          {"phrases", phrases},     {"lessons", list}};
}

/// Zips the site folder `site` into `zip`, a name inside it (Debian's zip, run there).
void zipSite(const std::string& site, const std::string& zip) {
  const pid_t child = ::fork();
  if (child == 0) {
    if (::chdir(site.c_str()) != 0) ::_exit(127);
    const int devnull = ::open("/dev/null", O_WRONLY);
    if (devnull >= 0) ::dup2(devnull, STDOUT_FILENO);
    ::execlp("zip", "zip", "-q", "-r", "-X", zip.c_str(), ".", "-x", zip.c_str(),
             static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  if (child < 0 || ::waitpid(child, &status, 0) < 0 || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0)
    throw WebError(zip + ": cannot be written (`zip` failed" +
                   (WIFEXITED(status) && WEXITSTATUS(status) == 127
                        ? std::string("; install Debian's zip")
                        : std::string()) +
                   ")");
}

std::string megabytes(std::size_t bytes) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << double(bytes) / (1024.0 * 1024.0) << " MB";
  return out.str();
}

/// Writes the pages and data of every lesson into `out`.
std::vector<json> writeLessons(const std::vector<Lesson>& lessons, const WebOptions& o,
                               WebOutput& out) {
  std::vector<json> data;
  fs::create_directories(fs::path(out.siteDir) / "lessons");
  const Language first = o.languages.front();
  for (const Lesson& lesson : lessons) {
    data.push_back(lessonData(lesson, o, out));
    const std::string id = data.back()["id"];
    const fs::path base = fs::path(out.siteDir) / "lessons" / id;
    writeSiteFile(base.string() + ".js", scriptCall("lesson", data.back()), out.written, o.limits);
    writeSiteFile(base.string() + ".html",
                  pageShell(id, lesson.title.in(first), phrase("web.noscript", first)), out.written,
                  o.limits);
    out.files.push_back("lessons/" + id + ".js");
    out.files.push_back("lessons/" + id + ".html");
    std::cout << printable(lesson.id) << ": " << lesson.steps.size() << " steps" << std::endl;
  }
  return data;
}

int runWeb(const WebCommandOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  WebOptions options;
  if (o.lang == "en") options.languages = {Language::English};
  if (o.lang == "zh") options.languages = {Language::Chinese};
  options.student = o.student;
  options.maxSpp = o.maxSpp;
  options.limits.siteBytes = std::size_t(o.maxSizeMb) << 20;
  const std::vector<Lesson> lessons = loadLessons(o);
  const std::string bundleDir = bundleFolder(o.bundle);
  const std::string script = readFile((fs::path(bundleDir) / "raylab-web.js").string());
  const std::string style = readFile((fs::path(bundleDir) / "raylab-web.css").string());
  const std::string missing = firstMissingFolder(o.out);
  std::optional<AtomicFolder> folder;
  try {
    folder.emplace(o.out, siteFile);
  } catch (const AtomicFolder::Error& e) {
    removeFoldersMade(missing);
    throw WebError(e.what());
  }
  requireDisplayAfterFolder(missing);
  WebOutput out;
  out.siteDir = folder->path();
  const std::vector<json> data = writeLessons(lessons, options, out);
  const Language first = options.languages.front();
  const std::string title = phrase("web.course_title", first);
  writeSiteFile(folder->file("course.js"), scriptCall("course", courseData(data, options)),
                out.written, options.limits);
  writeSiteFile(folder->file("index.html"), pageShell("", title, phrase("web.noscript", first)),
                out.written, options.limits);
  writeSiteFile(folder->file("raylab-web.js"), script, out.written, options.limits);
  writeSiteFile(folder->file("raylab-web.css"), style, out.written, options.limits);
  for (const char* f : {"course.js", "index.html", "raylab-web.js", "raylab-web.css"})
    out.files.push_back(f);
  writeSiteFile(folder->file("imsmanifest.xml"), imsManifest(title, out.files), out.written,
                options.limits);
  // The zip is made beside DIR from the new folder, then both are put in place.
  fs::path site = fs::path(o.out).lexically_normal();
  if (!site.has_filename()) site = site.parent_path();  // "out/" is "out"
  const std::string zipPath = site.string() + ".zip";
  if (o.zip) zipSite(folder->path(), kZipInside);
  folder->commit();
  if (o.zip && std::rename((site / kZipInside).c_str(), zipPath.c_str()) != 0)
    throw WebError(zipPath + ": cannot be written (" + std::strerror(errno) + "; the site " +
                   o.out + " was)");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << printable(o.out) << ": " << lessons.size() << " lessons, " << megabytes(out.written)
            << ", " << std::fixed << std::setprecision(1) << seconds << " s"
            << (o.zip ? "; " + printable(zipPath) : std::string()) << std::endl;
  return kExitOk;
}

}  // namespace

Subcommand addWebCommand(CLI::App& cli) {
  auto o = std::make_shared<WebCommandOptions>();
  CLI::App* command = cli.add_subcommand(
      "web", "Write the lessons as a static web site that opens from file:// (or in Moodle)");
  command->footer(
      "Examples:\n"
      "  raylab web --out site\n"
      "  raylab web --out site-04 --lang zh --student 04-whitted\n"
      "  raylab web --out course --zip      (also course.zip with imsmanifest.xml for Moodle)\n"
      "Open DIR/index.html in a browser; no server and no network are needed. DIR is\n"
      "written beside itself and replaced whole when complete: an error, a full disk or\n"
      "Ctrl-C leave an earlier site as it was.\n"
      "Pictures need an X server, also headless: run under xvfb-run -a.\n"
      "Exit codes: 0 ok, 1 a lesson does not load, a step cannot be exported or DIR cannot be\n"
      "            written (the message names which), 2 usage error, 3 internal error.");
  command->add_option("LESSON", o->lessons, "Lessons to export (files or ids; default: all)");
  command->add_option("--out", o->out, "The site's folder")->required();
  command->add_option("--lang", o->lang, "Languages of the site: en, zh or both")
      ->check(CLI::IsMember({"en", "zh", "both"}))
      ->capture_default_str();
  command->add_flag("--student", o->student,
                    "The student's site: no teacher's notes, answers or explanations");
  command->add_flag("--zip", o->zip, "Also write DIR.zip (with imsmanifest.xml, IMS CP 1.1)");
  command->add_option("--dir", o->dir, "Folder of the lesson files")->capture_default_str();
  command->add_option("--bundle", o->bundle,
                      "Folder of raylab-web.js and raylab-web.css (default: the built one)");
  command
      ->add_option("--max-spp", o->maxSpp,
                   "Most samples per pixel of image, comparison and plot pictures")
      ->check(CLI::Range(1, 1 << 16));
  command->add_option("--max-size", o->maxSizeMb, "Refuse to write a site larger than this (MB)")
      ->check(CLI::Range(1, 1 << 16))
      ->capture_default_str();
  return {command, [o](const std::string&) { return runWeb(*o); }};
}

}  // namespace raylab::app
