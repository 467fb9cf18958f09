#pragma once

// One lesson of `raylab web` as data (doc/web-data.md's `lesson`), its pictures written.

#include "WebSite.h"

#include "raylab/core/Language.h"
#include "raylab/core/Lesson.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace raylab::app {

/// What an export holds.
struct WebOptions {
  std::vector<Language> languages{Language::English, Language::Chinese};
  bool student = false;  ///< No teacher's notes, no answer key.
  int maxSpp = 0;        ///< Most spp of image, comparison and plot pictures (0: defaults).
  WebLimits limits;
};

/// Where one lesson's files go, and what has been written so far.
struct WebOutput {
  std::string siteDir;             ///< The new site's folder (pictures go under lessons/).
  std::size_t written = 0;         ///< Bytes written into the site.
  std::vector<std::string> files;  ///< Every file written, relative to the site.
};

/// `{en, zh}` of `text`, the languages not exported empty.
nlohmann::json localJson(const LocalText& text, const WebOptions& options);

/// The data of `lesson`, every step staged through the lesson stager; its pictures are
/// written into `out`. Throws WebError naming the lesson and step that failed.
nlohmann::json lessonData(const Lesson& lesson, const WebOptions& options, WebOutput& out);

}  // namespace raylab::app
