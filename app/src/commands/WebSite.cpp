// The site's pieces (WebSite.h): script-safe JSON, HTML shells, the IMS manifest.
#include "WebSite.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace raylab::app {

std::string scriptCall(const std::string& function, const nlohmann::json& data) {
  const std::string json = data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out = "RayLabSite." + function + "(";
  out.reserve(json.size() + out.size() + 16);
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '>') {
      out += "\\u003e";
    } else if (c == '&') {
      out += "\\u0026";
    } else if (c == '\xE2' && i + 2 < json.size() && json[i + 1] == '\x80' &&
               (json[i + 2] == '\xA8' || json[i + 2] == '\xA9')) {
      // U+2028 and U+2029 end a line in older JavaScript.
      out += json[i + 2] == '\xA8' ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += c;
    }
  }
  return out + ");\n";
}

std::string htmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base64(const void* data, std::size_t bytes) {
  static const char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* in = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((bytes + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes; i += 3) {
    const unsigned v = (unsigned(in[i]) << 16) | (unsigned(in[i + 1]) << 8) | in[i + 2];
    for (int shift : {18, 12, 6, 0}) out += kDigits[(v >> shift) & 63];
  }
  if (i < bytes) {
    const bool two = i + 1 < bytes;
    const unsigned v = (unsigned(in[i]) << 16) | (two ? unsigned(in[i + 1]) << 8 : 0u);
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += two ? kDigits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string fileId(const std::string& id) {
  std::string out;
  for (const char c : id) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_';
    out += safe ? c : '_';
  }
  return out.empty() ? "lesson" : out;
}

std::string pageShell(const std::string& lesson, const std::string& title,
                      const std::string& noscript) {
  const bool index = lesson.empty();
  const std::string up = index ? "" : "../";
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>" +
      htmlEscape(title) + "</title>\n<link rel=\"stylesheet\" href=\"" + up +
      "raylab-web.css\">\n</head>\n<body>\n<div id=\"raylab-app\" data-page=\"" +
      (index ? "index\"" : "lesson\" data-lesson=\"" + htmlEscape(lesson) + "\"") +
      "></div>\n<noscript>" + htmlEscape(noscript) + "</noscript>\n<script src=\"" + up +
      "raylab-web.js\"></script>\n<script src=\"" + up + "course.js\"></script>\n";
  if (!index) html += "<script src=\"" + htmlEscape(lesson) + ".js\"></script>\n";
  return html + "</body>\n</html>\n";
}

std::string imsManifest(const std::string& title, const std::vector<std::string>& files) {
  std::string xml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<manifest identifier=\"raylab-course\" version=\"1.1\"\n"
      "  xmlns=\"http://www.imsglobal.org/xsd/imscp_v1p1\"\n"
      "  xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"\n"
      "  xsi:schemaLocation=\"http://www.imsglobal.org/xsd/imscp_v1p1 "
      "http://www.imsglobal.org/xsd/imscp_v1p1.xsd\">\n"
      "  <organizations default=\"raylab-org\">\n"
      "    <organization identifier=\"raylab-org\">\n"
      "      <title>" +
      htmlEscape(title) +
      "</title>\n"
      "      <item identifier=\"raylab-item\" identifierref=\"raylab-site\">\n"
      "        <title>" +
      htmlEscape(title) +
      "</title>\n      </item>\n    </organization>\n  </organizations>\n"
      "  <resources>\n"
      "    <resource identifier=\"raylab-site\" type=\"webcontent\" href=\"index.html\">\n";
  for (const std::string& file : files) xml += "      <file href=\"" + htmlEscape(file) + "\"/>\n";
  return xml + "    </resource>\n  </resources>\n</manifest>\n";
}

void writeSiteFile(const std::string& path, const std::string& text, std::size_t& written,
                   const WebLimits& limits) {
  written += text.size();
  if (written > limits.siteBytes)
    throw WebError(path + ": the site would be larger than " +
                   std::to_string(limits.siteBytes >> 20) + " MB; export fewer lessons");
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) throw WebError(path + ": cannot be written (" + std::strerror(errno) + ")");
  const bool whole = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  const int error = errno;
  const bool closed = std::fclose(file) == 0;
  if (!whole || !closed)
    throw WebError(path + ": cannot be written (" + std::strerror(whole ? errno : error) + ")");
}

}  // namespace raylab::app
