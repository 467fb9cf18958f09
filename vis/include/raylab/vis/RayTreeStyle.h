#pragma once

#include "raylab/core/RayTree.h"
#include "raylab/core/Types.h"

#include <array>
#include <climits>
#include <string>
#include <vector>

/// \file RayTreeStyle.h
/// How a recorded ray tree is drawn and revealed: colouring, filters, the shared energy
/// scale and the bounce animation. Pure C++ (no VTK): the window's controls, the command
/// line and the tests all speak these types; RayTreeActor turns them into VTK data.

namespace raylab {

/// What the colour of a drawn ray means.
enum class RayColouring {
  Energy,  ///< The seed's convention: light grey low, green medium, blue high.
  Kind,    ///< Camera, reflection, refraction, diffuse, glossy, shadow (see kindColour).
  Depth,   ///< Bounces from the camera ray, on a sequential scale.
};
const char* toString(RayColouring colouring);

/**
 * \brief The one energy scale of every algorithm's trees.
 *
 * A segment's energy is the luminance (Rec. 709 weights) of `throughput * radiance`:
 * the share of the pixel's estimate that came back along this ray (the camera ray's
 * energy is the sample's estimate; a path that never reaches a light carries 0). Energies
 * map to [0, 1] on a log scale between `low` and `high` (fixed numbers, the same for the
 * four algorithms, so their trees can be compared by colour): at or below `low` a ray is
 * light grey, at the geometric mean green, at or above `high` blue.
 */
struct EnergyScale {
  /// Energy drawn light grey (and everything below it).
  double low = 1e-4;
  /// Energy drawn full blue (and everything above it). Lit surfaces seen by the camera
  /// bring back about 0.05 to 1 (1 is a white pixel), so camera rays come out blue, shadow
  /// rays and bounces that deliver a few percent of the pixel green, empty paths grey.
  double high = 0.1;
  /// Position of `energy` on the scale, 0 at `low`, 1 at `high`, clamped.
  double position(double energy) const;
  /// Colour of a scale position in [0, 1]: grey -> green -> blue, linear RGB in [0, 1].
  static Vec3 colour(double position);
};

/// Energy of a recorded segment (see EnergyScale).
double segmentEnergy(const RaySegment& segment);
/// Colour of a ray kind in the Kind colouring (distinct hues, readable on the dark view).
Vec3 kindColour(RayKind kind);
/// Colour of a depth in the Depth colouring (0 = camera rays), `maxDepth` the deepest drawn.
Vec3 depthColour(int depth, int maxDepth);

/// Which segments are drawn. A segment is drawn when it passes every filter.
struct RayFilter {
  std::array<bool, kRayKindCount> kinds{true, true, true, true, true, true};  ///< By RayKind.
  int minDepth = 0;                ///< Shallowest depth drawn.
  int maxDepth = INT_MAX;          ///< Deepest depth drawn.
  bool onlyReachingLight = false;  ///< Only rays on a path that delivers light: the
                                   ///< segment or one of its descendants has emitted > 0.
  double minEnergy = 0.0;          ///< Hide rays whose energy is below this.

  /// True when `tree.segments[id]` passes. `reachesLight` is from reachesLight(tree).
  bool passes(const RayTree& tree, int id, const std::vector<bool>& reachesLight) const;
};

/// For each segment: it or a descendant found light (emitted > 0 anywhere below it).
std::vector<bool> reachesLight(const RayTree& tree);

/// Everything about how a tree is drawn besides which part of it is revealed.
struct RayTreeStyle {
  RayColouring colouring = RayColouring::Energy;
  EnergyScale scale;
  RayFilter filter;
  bool widthFollowsEnergy = true;  ///< Thicker lines for more energy (else all `lineWidth`).
  double lineWidth = 2.0;          ///< Pixels; with widthFollowsEnergy, the width at low.
  bool showHitPoints = true;       ///< A dot at every hit.
  bool showNormals = false;        ///< The surface normal at every hit.
  bool showArrows = false;         ///< An arrow head at the end of every segment.
  bool showLegend = true;          ///< The colour legend in a corner of the view.
};

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

}  // namespace raylab
