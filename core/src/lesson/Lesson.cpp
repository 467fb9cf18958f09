#include "raylab/core/Lesson.h"

#include "io/JsonChecks.h"
#include "lesson/LessonNames.h"
#include "lesson/LessonReader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace raylab {

using lessonfile::kCameraViews;
using lessonfile::kColourings;
using lessonfile::kMeasures;
using lessonfile::kQuantities;
using lessonfile::kSamplers;
using lessonfile::kViews;
using lessonfile::lookup;
using lessonfile::nameOf;
using nlohmann::json;

const char* toString(LessonView view) { return nameOf(kViews, view); }
std::optional<LessonView> parseLessonView(const std::string& name) { return lookup(kViews, name); }
const char* toString(LessonColouring colouring) { return nameOf(kColourings, colouring); }
const char* toString(LessonCameraView view) { return nameOf(kCameraViews, view); }
const char* toString(LessonMeasure measure) { return nameOf(kMeasures, measure); }
const char* toString(LessonSamples::Sampler sampler) { return nameOf(kSamplers, sampler); }
const char* toString(LessonCheck::Quantity quantity) { return nameOf(kQuantities, quantity); }

RenderSettings LessonStep::settings() const {
  RenderSettings s = scene->render;
  s.algorithm = algorithm;
  return s;
}

int Lesson::questionCount() const {
  return static_cast<int>(std::count_if(steps.begin(), steps.end(),
                                        [](const LessonStep& s) { return bool(s.question); }));
}

std::vector<std::string> Lesson::requiredFeatures() const {
  std::vector<std::string> features;
  for (const LessonStep& s : steps)
    for (const std::string& f : s.needs)
      if (std::find(features.begin(), features.end(), f) == features.end()) features.push_back(f);
  return features;
}

Lesson LessonIO::parse(const std::string& text, const std::string& origin) {
  json root;
  if (const auto problem = parseJson(text, origin, root)) throw LoadError(*problem);
  return lessonfile::Reader(origin).lesson(root);
}

Lesson LessonIO::load(const std::string& path) {
  std::string text;
  if (const auto problem = readTextFile(path, "lesson file", text)) throw LoadError(*problem);
  return parse(text, path);
}

LocalText LessonIO::readTitle(const std::string& path) {
  std::string text;
  if (const auto problem = readTextFile(path, "lesson file", text)) throw LoadError(*problem);
  json root;
  if (const auto problem = parseJson(text, path, root)) throw LoadError(*problem);
  return lessonfile::Reader(path).title(root);
}

std::vector<std::string> LessonIO::list(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw LoadError(dir + ": not a folder (of lesson files)");
  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    const bool lessonName = name.size() > 8 && std::isdigit(static_cast<unsigned char>(name[0])) &&
                            std::isdigit(static_cast<unsigned char>(name[1])) && name[2] == '-' &&
                            e.path().extension() == ".json";
    if (lessonName && e.is_regular_file(ec)) files.push_back((fs::path(dir) / name).string());
  }
  if (ec) throw LoadError(dir + ": cannot read the folder: " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace raylab
