#pragma once

// The pieces of the site `raylab web` writes (doc/web-data.md): data files that are JSON
// inside a script call, the HTML shells, the IMS content package manifest.

#include "raylab/core/Exception.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace raylab::app {

/// An export beyond its bounds, or a file that cannot be written; the message names it.
class WebError : public Exception {
 public:
  using Exception::Exception;
};

/// The bounds of one export: a hostile lesson cannot make a 10 GB site.
struct WebLimits {
  std::size_t raysPerStep = 20000;                 ///< Rays of one step's tree.
  std::size_t pointsPerMesh = 2000000;             ///< Points of one drawn mesh.
  std::size_t siteBytes = std::size_t(512) << 20;  ///< Every file of the site together.
};

/// `RayLabSite.<function>(<data>);`: the JSON with `<`, `>`, `&`, U+2028 and U+2029
/// written as \u escapes, so no text of a lesson can end the script or start a tag, and
/// invalid UTF-8 replaced (U+FFFD).
std::string scriptCall(const std::string& function, const nlohmann::json& data);
/// `text` for HTML text and attribute values: & < > " ' as character references.
std::string htmlEscape(const std::string& text);
/// Standard base64 (RFC 4648, with padding) of `bytes` bytes at `data`.
std::string base64(const void* data, std::size_t bytes);
/// A lesson id made safe as a file name: [A-Za-z0-9_-] kept, anything else '_'.
std::string fileId(const std::string& id);

/// The HTML shell of a page: the index (`lesson` empty) or a lesson's page, which loads
/// the bundle, course.js and (a lesson) <id>.js; `title` goes into <title>, escaped.
std::string pageShell(const std::string& lesson, const std::string& title,
                      const std::string& noscript);

/// imsmanifest.xml (IMS Content Packaging 1.1) of a site titled `title` whose start page is
/// index.html, listing `files` (paths relative to the site, '/'-separated).
std::string imsManifest(const std::string& title, const std::vector<std::string>& files);

/// Writes `text` to `path`, adding its size to `written`; throws WebError naming the file
/// when it cannot be written whole (a full disk) or the site would exceed `limits`.
void writeSiteFile(const std::string& path, const std::string& text, std::size_t& written,
                   const WebLimits& limits);

}  // namespace raylab::app
