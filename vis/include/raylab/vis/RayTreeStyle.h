#pragma once

#include "raylab/core/Language.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/Types.h"

#include <array>
#include <climits>
#include <optional>
#include <string>
#include <vector>

/// \file RayTreeStyle.h
/// How a recorded ray tree is drawn: colouring, filters and the shared energy scale (the
/// bounce animation that reveals it is BounceAnimation.h). Pure C++ (no VTK): the window's
/// controls, the command line and the tests all speak these types; RayTreeActors (private)
/// turns them into VTK data.

namespace raylab::vis {

/// What the colour of a drawn ray means.
enum class RayColouring {
  Energy,   ///< The original course program's convention: light grey low, green medium,
            ///< blue high.
  Kind,     ///< Camera, reflection, refraction, diffuse, glossy, shadow (see kindColour).
  Depth,    ///< Bounces from the camera ray, on a sequential scale.
  Verdict,  ///< A student's code judged ray by ray (issue 35): RayTreeStyle::verdicts, see
            ///< verdictColour; rays without a verdict are grey.
};
const char* toString(RayColouring colouring);

/**
 * \brief The one energy scale of every algorithm's trees.
 *
 * A segment's energy (RaySegment::energy) is the luminance of `throughput * radiance`:
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

/// Colour of a ray kind in the Kind colouring (distinct hues, readable on the dark view).
Vec3 kindColour(RayKind kind);
/// Colour of a depth in the Depth colouring (0 = camera rays), `maxDepth` the deepest drawn.
Vec3 depthColour(int depth, int maxDepth);
/// Colour of a raylab::Verdict (StudentHooks.h, as int) in the Verdict colouring: agrees
/// green, off by ulps yellow-green, the wrong answers from orange to red, exception magenta,
/// not judged grey.
Vec3 verdictColour(int verdict);
/// The legend's words of a verdict ("wrong hit" / "交点错误").
std::string verdictLabel(int verdict, Language language);
/// Colour of the selected object's outline in the 3D view: a pale orchid that no ray
/// colouring uses (kind, energy, depth, verdict, nor the selected ray's magenta), at least
/// 35 CIELAB units from each of them and lighter than the colours nearest to it in hue.
Vec3 selectionOutlineColour();

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
  bool widthFollowsEnergy = true;         ///< Thicker lines for more energy (else all `lineWidth`).
  double lineWidth = 2.0;                 ///< Pixels; with widthFollowsEnergy, the width at low.
  bool showHitPoints = true;              ///< A dot at every hit.
  bool showNormals = false;               ///< The surface normal at every hit.
  bool showArrows = false;                ///< An arrow head at the end of every segment.
  bool showLegend = true;                 ///< The colour legend in a corner of the view.
  Language language = Language::English;  ///< The legend's words (Chinese: a CJK font).
  /// Verdict colouring: per segment id, a raylab::Verdict as int (StudentTrace::verdicts);
  /// segments beyond its end are not judged.
  std::vector<int> verdicts;
};

/// The colouring named `name` ("energy", "kind", "depth" or "verdict"), nothing for another.
std::optional<RayColouring> parseColouring(const std::string& name);
/// The ray kinds of a comma-separated list of kind names ("camera,shadow"), as a filter's
/// `kinds`; an empty list means every kind. The message names the first unknown kind.
struct ParsedKinds {
  std::array<bool, kRayKindCount> kinds{true, true, true, true, true, true};
  std::string error;  ///< Empty when every name is known.
};
ParsedKinds parseRayKinds(const std::string& list);
/// Every ray kind's name, comma-separated, for messages and help texts.
std::string rayKindNames();

}  // namespace raylab::vis
