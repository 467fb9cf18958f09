#include "Subcommand.h"

#include "SceneSource.h"
#include "raylab/core/Limits.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <iostream>

#include <unistd.h>

namespace raylab::app {

namespace {

/// Length of the well-formed UTF-8 sequence starting at text[i] (2 to 4 bytes), or 0 when
/// the bytes there are not one (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF).
std::size_t utf8Length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) {
    return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u;
  };
  const unsigned c = byte(i);
  const auto cont = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xbf) {
    return byte(k) >= lo && byte(k) <= hi;
  };
  if (c >= 0xc2 && c <= 0xdf) return cont(i + 1) ? 2 : 0;
  if (c == 0xe0) return cont(i + 1, 0xa0) && cont(i + 2) ? 3 : 0;
  if ((c >= 0xe1 && c <= 0xec) || c == 0xee || c == 0xef) return cont(i + 1) && cont(i + 2) ? 3 : 0;
  if (c == 0xed) return cont(i + 1, 0x80, 0x9f) && cont(i + 2) ? 3 : 0;
  if (c == 0xf0) return cont(i + 1, 0x90) && cont(i + 2) && cont(i + 3) ? 4 : 0;
  if (c >= 0xf1 && c <= 0xf3) return cont(i + 1) && cont(i + 2) && cont(i + 3) ? 4 : 0;
  if (c == 0xf4) return cont(i + 1, 0x80, 0x8f) && cont(i + 2) && cont(i + 3) ? 4 : 0;
  return 0;
}

}  // namespace

std::string cappedSamplesWarning(std::uint64_t count) {
  return std::to_string(count) + (count == 1 ? " sample" : " samples") + " reached the cap of " +
         std::to_string(limits::kMaxRaysPerSample) +
         " rays per sample: their rays past it were not traced, so those pixels miss some "
         "light (fewer glossy or shadow samples, or a smaller max depth, avoid it)";
}

// printable: see Subcommand.h.
/// `text` as valid UTF-8 without terminal controls: control bytes and bytes that are not
/// UTF-8 (a file name in another encoding, a scene file's stray byte) are written as \xNN,
/// C1 controls as \u00NN, so a message never recolours the terminal, moves its cursor or
/// carries broken text (issue 14). Newlines, tabs and UTF-8 letters pass through.
std::string printable(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    char escaped[8];
    if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) {
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    } else if (c < 0x80) {
      out += char(c);
    } else if (const std::size_t length = utf8Length(text, i); length == 0) {
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    } else if (c == 0xc2 && static_cast<unsigned char>(text[i + 1]) <= 0x9f) {
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned char>(text[i + 1]));
      out += escaped;
      ++i;
    } else {
      out.append(text, i, length);
      i += length - 1;
    }
  }
  return out;
}

namespace {
constexpr int kMinSize = 16;
constexpr int kMaxSize = limits::kMaxImageSide;
}  // namespace

std::optional<std::pair<int, int>> parseSize(const std::string& text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos || x == 0 || x + 1 >= text.size()) return std::nullopt;
  const std::string w = text.substr(0, x);
  const std::string h = text.substr(x + 1);
  const auto digitsOnly = [](const std::string& s) {
    return s.size() <= 5 && s.find_first_not_of("0123456789") == std::string::npos;
  };
  if (!digitsOnly(w) || !digitsOnly(h)) return std::nullopt;
  const int width = std::stoi(w);
  const int height = std::stoi(h);
  if (width < kMinSize || width > kMaxSize || height < kMinSize || height > kMaxSize) {
    return std::nullopt;
  }
  if (std::int64_t(width) * height > limits::kMaxImagePixels) return std::nullopt;
  return std::make_pair(width, height);
}

std::string checkSize(const std::string& text) {
  if (parseSize(text)) return {};
  return "expected WIDTHxHEIGHT with each side in " + std::to_string(kMinSize) + ".." +
         std::to_string(kMaxSize) + " and at most 4096x4096 pixels in all, e.g. 300x300";
}

void CommonOptions::add(CLI::App* command, const std::string& outHelp, const std::string& sizeHelp,
                        bool outRequired, bool withAlgorithm) {
  CLI::Option* outOption = command->add_option("--out,-o", out, outHelp);
  if (outRequired) outOption->required();
  command->add_option("--scene", scene, "Scene file (default: the built-in scene)");
  if (withAlgorithm) {
    m_algorithmOption =
        command
            ->add_option("--algorithm,-a", m_algorithmText,
                         "raycast, whitted, distributed or path (default: the scene's)")
            ->check(CLI::IsMember({"raycast", "whitted", "distributed", "path"}));
  }
  // A negative seed is a mistake, not 2^64 - 1 (issue 14).
  m_seedOption = command->add_option("--seed", m_seedValue, "Random seed (default: the scene's)")
                     ->check(CLI::NonNegativeNumber);
  m_sizeOption =
      command->add_option("--size", m_sizeText, sizeHelp)->check(CLI::Validator(checkSize, "WxH"));
  command->final_callback([this] { finish(); });
}

void CommonOptions::finish() {
  if (m_algorithmOption && *m_algorithmOption) algorithm = parseAlgorithm(m_algorithmText);
  if (m_seedOption && *m_seedOption) seed = m_seedValue;
  if (m_sizeOption && *m_sizeOption) size = parseSize(m_sizeText);
}

Scene CommonOptions::loadScene(const std::string& topLevelScene) const {
  Scene loaded = loadSceneOrDefault(scene.empty() ? topLevelScene : scene);
  if (size) {
    loaded.camera.width = size->first;
    loaded.camera.height = size->second;
  }
  return loaded;
}

RenderSettings CommonOptions::settings(const Scene& loaded) const {
  RenderSettings result = loaded.render;
  if (algorithm) result.algorithm = *algorithm;
  if (seed) result.seed = *seed;
  return result;
}

ProgressBar::ProgressBar(std::string label)
    : m_label(std::move(label)), m_terminal(::isatty(STDERR_FILENO) == 1) {}

void ProgressBar::update(double fraction, const std::string& detail) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  const int percent = static_cast<int>(fraction * 100.0 + 0.5);
  if (m_terminal) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth + 0.5);
    std::cerr << "\r" << m_label << " [" << std::string(filled, '#')
              << std::string(kWidth - filled, '.') << "] " << std::setw(3) << percent << "% "
              << detail << "\033[K" << std::flush;
    if (fraction >= 1.0) std::cerr << "\n";
  } else {
    if (percent == m_lastPercent) return;
    std::cerr << m_label << ": " << percent << "%";
    if (!detail.empty()) std::cerr << " (" << detail << ")";
    std::cerr << std::endl;
  }
  m_lastPercent = percent;
}

}  // namespace raylab::app
