#include "raylab/vis/BounceAnimation.h"

#include "raylab/core/Phrases.h"

#include <algorithm>
#include <array>
#include <climits>

namespace raylab::vis {

const char* toString(RevealOrder order) {
  switch (order) {
    case RevealOrder::Processing:
      return "processing";
    case RevealOrder::Depth:
      return "depth";
  }
  return "unknown";
}

namespace {

/// Steps of the animation: processing order groups `raysPerStep` ids, depth order has
/// one step per depth from 0 to the deepest.
int stepCount(const RayTree& tree, const AnimationSettings& settings) {
  const int n = int(tree.segments.size());
  if (n == 0) return 0;
  if (settings.order == RevealOrder::Processing) {
    const int perStep = std::max(1, settings.raysPerStep);
    return (n + perStep - 1) / perStep;
  }
  int deepest = 0;
  for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
  return deepest + 1;
}

}  // namespace

int frameCount(const RayTree& tree, const AnimationSettings& settings) {
  // Frame 0 shows nothing, then each step plays framesPerStep frames.
  const long long frames =
      1LL + static_cast<long long>(stepCount(tree, settings)) * std::max(1, settings.framesPerStep);
  return int(std::min<long long>(frames, INT_MAX));
}

RevealFrame revealFrame(const RayTree& tree, const AnimationSettings& settings, int frame) {
  const int frames = frameCount(tree, settings);
  frame = std::clamp(frame, 0, frames - 1);
  const int perFrame = std::max(1, settings.framesPerStep);
  const int steps = stepCount(tree, settings);

  RevealFrame out;
  out.fraction.assign(tree.segments.size(), 0.0f);
  out.done = frame == frames - 1;
  out.step = steps == 0 ? 0 : std::min(frame / perFrame, steps - 1);

  // How far step s has travelled at this frame: 0 before it starts, 1 once it is over.
  auto progress = [&](int step) {
    const double t = double(frame - step * perFrame) / double(perFrame);
    return float(std::clamp(t, 0.0, 1.0));
  };
  const int perStep = std::max(1, settings.raysPerStep);
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const int step =
        settings.order == RevealOrder::Processing ? int(i) / perStep : tree.segments[i].depth;
    out.fraction[i] = progress(step);
  }
  return out;
}

std::string stepCaption(const PixelTrace& trace, const AnimationSettings& settings, int frame,
                        const SceneNames& names, Language language) {
  const RayTree& tree = trace.tree;
  if (tree.segments.empty()) return phrase("caption.no_tree", language);
  const int perFrame = std::max(1, settings.framesPerStep);
  const int last = frameCount(tree, settings) - 1;
  frame = std::clamp(frame, 0, last);
  const int steps = last / perFrame;
  if (frame == 0) return phrase("caption.frame_zero", language);
  const int step = (frame - 1) / perFrame;

  std::string text;
  if (settings.order == RevealOrder::Processing) {
    // What the engine did with the ray (or the first of the rays) leaving now.
    const int perStep = std::max(1, settings.raysPerStep);
    const int first = step * perStep;
    const int end = std::min(int(tree.segments.size()), first + perStep);
    const std::string what =
        std::size_t(first) < trace.steps.size()
            ? narrateStep(trace.steps[std::size_t(first)], names, language)
            : phrase("caption.step.unrecorded", language, {{"id", std::to_string(first)}});
    text = phrase(end - first == 1 ? "caption.step.one" : "caption.step.many", language,
                  {{"step", std::to_string(step + 1)},
                   {"steps", std::to_string(steps)},
                   {"first", std::to_string(first)},
                   {"last", std::to_string(end - 1)},
                   {"what", what}});
  } else {
    // Every ray of this depth travels at once: count them by kind.
    std::array<int, kRayKindCount> byKind{};
    int count = 0;
    for (const RaySegment& s : tree.segments)
      if (s.depth == step) {
        ++byKind[std::size_t(s.kind)];
        ++count;
      }
    text = phrase(count == 1 ? "caption.depth.one" : "caption.depth.many", language,
                  {{"depth", std::to_string(step)},
                   {"deepest", std::to_string(steps - 1)},
                   {"count", std::to_string(count)},
                   {"kinds", kindCounts(byKind, language, true)}});
  }
  if (frame == last) text += phrase("caption.whole_tree", language);
  return text;
}

}  // namespace raylab::vis
