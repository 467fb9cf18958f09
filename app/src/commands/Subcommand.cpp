#include "commands/Subcommand.h"

#include "commands/SceneSource.h"
#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/AtomicFile.h"
#include "raylab/core/Exception.h"
#include "raylab/core/FilePaths.h"
#include "raylab/core/Limits.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/SceneEdit.h"
#include "raylab/core/Text.h"
#include "raylab/vis/Display.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include <unistd.h>

namespace raylab::app {

std::string cappedSamplesWarning(std::uint64_t count) {
  return std::to_string(count) + (count == 1 ? " sample" : " samples") + " reached the cap of " +
         std::to_string(limits::kMaxRaysPerSample) +
         " rays per sample: their rays past it were not traced, so those pixels miss some "
         "light (fewer glossy or shadow samples, or a smaller max depth, avoid it)";
}

std::string printable(const std::string& text) { return printableText(text); }

CLI::Validator endsIn(const std::string& extension) {
  return CLI::Validator(
      [extension](const std::string& path) {
        return lowerExtension(path) == extension ? std::string()
                                                 : "the file name must end in " + extension;
      },
      "FILE");
}

void checkWritable(const std::string& path) {
  if (const auto problem = cannotWrite(path)) throw Exception(path + ": " + *problem);
}

std::string firstMissingFolder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path missing = fs::absolute(dir, ec);
  if (ec || fs::exists(missing, ec)) return {};
  while (missing.has_parent_path() && missing.parent_path() != missing &&
         !fs::exists(missing.parent_path(), ec))
    missing = missing.parent_path();
  return missing.string();
}

void removeFoldersMade(const std::string& missing) {
  std::error_code ec;
  if (!missing.empty()) std::filesystem::remove_all(missing, ec);
}

void requireDisplayAfterFolder(const std::string& missing) {
  try {
    vis::requireDisplay();
  } catch (...) {
    removeFoldersMade(missing);
    throw;
  }
}

namespace {
constexpr int kMinSize = 16;
constexpr int kMaxSize = limits::kMaxImageSide;
}  // namespace

CLI::Option* addFaultOption(CLI::App* command, std::optional<Fault>& fault) {
  std::vector<std::string> words{"list"};
  std::string names;
  for (int i = 1; i < kFaultCount; ++i) {
    words.push_back(toString(Fault(i)));
    names += (i > 1 ? ", " : "") + words.back();
  }
  return command
      ->add_option_function<std::string>(
          "--fault",
          [&fault](const std::string& text) {
            if (text == "list") {
              for (int i = 1; i < kFaultCount; ++i)
                std::cout << toString(Fault(i)) << "\n  "
                          << phrase("fault." + std::string(toString(Fault(i))), Language::English)
                          << "\n  "
                          << phrase("fault." + std::string(toString(Fault(i))), Language::Chinese)
                          << "\n";
              throw CLI::Success();
            }
            fault = parseFault(text);
          },
          "Plant a typical student bug in the engine, for a bug hunt: " + names +
              " ('--fault list' says what each does)")
      ->type_name("NAME")
      ->check(CLI::IsMember(words));
}

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
    m_algorithmOption = command
                            ->add_option("--algorithm,-a", m_algorithmText,
                                         algorithmWordList() + " (default: the scene's)")
                            ->check(CLI::IsMember(algorithmWords()));
  }
  // A negative seed is a mistake, not 2^64 - 1 (issue 14).
  // Digits only, and at most 2^64 - 1: a larger one was clamped silently, and CLI11's own
  // message quoted a 300-digit number back (issue 38).
  m_seedOption =
      command->add_option("--seed", m_seedValue, "Random seed (default: the scene's)")
          ->check(CLI::Validator(
              [](const std::string& text) {
                const bool digits = !text.empty() && text.size() <= 20 &&
                                    text.find_first_not_of("0123456789") == std::string::npos;
                if (digits && (text.size() < 20 || text <= "18446744073709551615"))
                  return std::string();
                return std::string("expected a whole number from 0 to 18446744073709551615");
              },
              "SEED"));
  m_sizeOption =
      command->add_option("--size", m_sizeText, sizeHelp)->check(CLI::Validator(checkSize, "WxH"));
  command
      ->add_option("--set", sets,
                   "Change a value of the scene for this run, e.g. --set max_depth=1 (a key of "
                   "the render block) or --set /camera/aperture=0.2 (any place of the scene "
                   "file); repeatable")
      ->type_name("PLACE=VALUE")
      ->check(CLI::Validator(
          [](const std::string& text) {
            const auto eq = text.find('=');
            return eq == std::string::npos || eq == 0
                       ? std::string(
                             "expected PLACE=VALUE, e.g. max_depth=1 or "
                             "/camera/aperture=0.2")
                       : std::string();
          },
          "PLACE=VALUE"));
  command->final_callback([this] { finish(); });
}

void CommonOptions::finish() {
  if (m_algorithmOption && *m_algorithmOption) algorithm = parseAlgorithm(m_algorithmText);
  if (m_seedOption && *m_seedOption) seed = m_seedValue;
  if (m_sizeOption && *m_sizeOption) size = parseSize(m_sizeText);
}

Scene CommonOptions::loadScene(const std::string& topLevelScene) const {
  Scene loaded = loadWithSets(topLevelScene);
  if (size) {
    loaded.camera.width = size->first;
    loaded.camera.height = size->second;
  }
  return loaded;
}

Scene CommonOptions::loadWithSets(const std::string& topLevelScene) const {
  const std::string path = scene.empty() ? topLevelScene : scene;
  Scene loaded = loadSceneOrDefault(path);
  for (const std::string& set : sets) {
    const auto eq = set.find('=');
    std::string place = set.substr(0, eq);
    if (place.front() != '/') place = "/render/" + place;
    std::string value = set.substr(eq + 1);
    // JSON as typed; a bare word (whitted, sah) as the string it means.
    // (Bytes that are not UTF-8 become U+FFFD: dump() would throw on them, issue 38.)
    if (!nlohmann::json::accept(value))
      value = nlohmann::json(value).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    loaded = edit::setValue(
        loaded, place, value,
        (path.empty() ? std::string("the built-in scene") : path) + " (--set " + set + ")");
  }
  return loaded;
}

RenderSettings CommonOptions::settings(const Scene& loaded) const {
  RenderSettings result = loaded.render;
  if (algorithm) result.algorithm = *algorithm;
  if (seed) result.seed = *seed;
  if (fault) result.fault = *fault;
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
