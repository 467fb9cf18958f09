#pragma once

#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RayWords.h"

#include <string>
#include <vector>

/// \file BounceAnimation.h
/// The bounce animation: which part of a recorded ray tree frame N shows, and the caption
/// that tells what happens in it. Pure C++ (no VTK): the window's ray-tree panel calls
/// both (the picture and the status line), `raylab animate` and `trace --frame` draw the
/// same frames with revealFrame.

namespace raylab::vis {

/// In which order the bounce animation reveals a tree.
enum class RevealOrder {
  Processing,  ///< The engine's processing order (segment ids), `raysPerStep` at a time.
  Depth,       ///< Depth by depth: every ray of depth d travels at once.
};
const char* toString(RevealOrder order);

/// Settings of the bounce animation.
struct AnimationSettings {
  RevealOrder order = RevealOrder::Depth;
  int framesPerStep = 12;  ///< Frames for a ray front to travel its segment.
  int raysPerStep = 1;     ///< Processing order: segments that start together.
};

/**
 * \brief What frame `frame` of the animation shows: a pure function of (tree, settings,
 * frame), never of the clock, so any frame renders offscreen the same every time.
 *
 * `fraction[i]` is how much of segment i is drawn from its origin: 0 hidden, 1 whole,
 * in between the ray front is travelling (drawn at origin + fraction * (end - origin)).
 * Frame 0 shows nothing; frameCount() - 1 shows the whole tree.
 */
struct RevealFrame {
  std::vector<float> fraction;
  int step = 0;       ///< Step being played (processing: first ray id / raysPerStep;
                      ///< depth: the depth travelling).
  bool done = false;  ///< Every segment is whole.
};

/// Number of frames of the animation of `tree` (at least 1).
int frameCount(const RayTree& tree, const AnimationSettings& settings);
/// Frame `frame` (clamped to [0, frameCount - 1]).
RevealFrame revealFrame(const RayTree& tree, const AnimationSettings& settings, int frame);

/**
 * \brief What happens in frame `frame`, in `language`: a sentence for the status line, the
 * video caption and the lesson text, e.g. "Step 3 of 9: reflection ray #2 hit 'glass ball'
 * and spawned 2 rays (#4..#5)." in processing order, "Depth 1 of 3: 4 rays travel (2
 * reflection, 2 shadow)." depth by depth. Narrates the trace's steps (what the engine did
 * with each ray, RayWords.h) with the objects and lights named from `names`. Frame 0 says
 * nothing is revealed yet; the last frame adds that the whole tree is shown.
 */
std::string stepCaption(const PixelTrace& trace, const AnimationSettings& settings, int frame,
                        const SceneNames& names, Language language = Language::English);

}  // namespace raylab::vis
