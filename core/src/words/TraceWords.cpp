#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/RayWords.h"

#include <iomanip>
#include <sstream>

namespace raylab {

namespace {

/// "1.5": bytes as mebibytes, 3 significant digits.
std::string mebibytes(std::size_t bytes) {
  std::ostringstream out;
  out << std::setprecision(3) << double(bytes) / double(1 << 20);
  return out.str();
}

std::string algorithmWords(Algorithm algorithm, Language language) {
  return algorithmTitle(algorithm, language, AlgorithmName::Long);
}

}  // namespace

std::string stopWords(const TreeStop& stop, Language language) {
  switch (stop.cause) {
    case StopCause::None:
      return {};
    case StopCause::Budget:
      return phrase("trace.stop.budget", language,
                    {{"rays", std::to_string(stop.rays)},
                     {"mib", mebibytes(stop.budgetBytes)},
                     {"max", std::to_string(stop.maxRays)}});
    case StopCause::Cancelled:
      return phrase("trace.stop.cancelled", language, {{"rays", std::to_string(stop.rays)}});
  }
  return {};
}

std::string stopWords(const GridStop& stop, Language language) {
  if (stop.cause == StopCause::None) return {};
  const std::string key =
      std::string(stop.cause == StopCause::Cancelled ? "grid.stop.cancelled" : "grid.stop.budget") +
      (stop.samples ? ".samples" : ".pixels");
  return phrase(key, language,
                {{"done", std::to_string(stop.done)},
                 {"of", std::to_string(stop.of)},
                 {"mib", std::to_string(stop.budgetBytes >> 20)}});
}

std::string vectorWords(const Vec3& v) {
  std::ostringstream out;
  out << "(" << std::setprecision(6) << v.x << ", " << v.y << ", " << v.z << ")";
  return out.str();
}

std::string traceHeading(const PixelTrace& trace, Language language) {
  const std::string algorithm = algorithmWords(trace.algorithm, language);
  const std::string heading = trace.root
                                  ? phrase("trace.info.ray", language,
                                           {{"algorithm", algorithm},
                                            {"origin", vectorWords(trace.root->origin)},
                                            {"direction", vectorWords(trace.root->direction)}})
                                  : phrase("trace.info.pixel", language,
                                           {{"algorithm", algorithm},
                                            {"x", std::to_string(trace.x)},
                                            {"y", std::to_string(trace.y)},
                                            {"sample", std::to_string(trace.sample)}});
  return heading + "\n" + traceSummary(trace, language);
}

std::string gridHeading(Algorithm algorithm, int across, int down, const GridTrace& grid,
                        Language language) {
  return phrase("trace.info.grid", language,
                {{"algorithm", algorithmWords(algorithm, language)},
                 {"across", std::to_string(across)},
                 {"down", std::to_string(down)},
                 {"pixels", std::to_string(grid.traces.size())},
                 {"rays", std::to_string(grid.combined.segments.size())}});
}

std::string bundleHeading(Algorithm algorithm, int x, int y, int first, const GridTrace& bundle,
                          Language language) {
  return phrase("trace.info.bundle", language,
                {{"algorithm", algorithmWords(algorithm, language)},
                 {"x", std::to_string(x)},
                 {"y", std::to_string(y)},
                 {"first", std::to_string(first)},
                 {"last", std::to_string(first + int(bundle.traces.size()) - 1)},
                 {"rays", std::to_string(bundle.combined.segments.size())}});
}

}  // namespace raylab
