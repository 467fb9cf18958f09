#pragma once

#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Sphere.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace raylab {

/// `ls` from a point `s` sampled uniformly in area on a light's surface, seen from `ref`: its
/// direction, distance and density converted to solid angle (d omega = cos_light dA / d^2).
/// False when the point is at ref or faces away from it (only the outside emits).
inline bool lightSampleFromArea(const ShapeSample& s, const Vec3& ref, LightSample& ls) {
  const Vec3 toLight = s.p - ref;
  const double distance2 = glm::dot(toLight, toLight);
  if (!(distance2 > 0.0)) return false;
  ls.distance = std::sqrt(distance2);
  ls.wi = toLight * (1.0 / ls.distance);  // one division, not three
  const double cosLight = -glm::dot(s.n, ls.wi);
  if (!(cosLight > 0.0)) return false;
  ls.p = s.p;
  ls.n = s.n;
  ls.pdf = s.pdfArea * distance2 / cosLight;
  return true;
}

/**
 * \brief Next-event estimation for a round sphere light: points on the light sampled by
 * solid angle from the shading point, restricted to the part of the light that no other
 * sphere separates from it. Private to core; SceneIntersector owns one per sphere light.
 *
 * 1. Cone sampling (pbrt's Sphere::Sample(ref)): a light of radius R whose centre is at
 *    distance d from ref subtends the cone of half-angle theta_max, sin theta_max = R / d.
 *    A direction uniform in that cone (pdf 1 / (2 pi (1 - cos theta_max))) is followed to
 *    its first hit on the light. Unlike area sampling, no sample lands on the far side.
 * 2. Separating spheres: a shadow ray is blocked by every surface it crosses, so a light
 *    point can only be reached from ref if every closed sphere has both on the same side
 *    (inside or outside). Each other static round sphere S that cuts the light splits its
 *    surface into two caps: the part inside S and the part outside. Only the cap on ref's
 *    side can be visible; a light entirely on the other side of S is not visible at all.
 *    Samples outside the allowed caps are dropped before any shadow ray is traced, and
 *    the direction is drawn from the narrowest of the cones that contain a visible point:
 *    the light's own cone or the cone of the ball around an allowed cap (a cap smaller
 *    than a hemisphere lies in the ball through its rim circle). This is exact, not a
 *    heuristic: the sampled set still contains every light point ref can see, and pdf()
 *    reports the density of the same rule. It matters where lights are mostly buried in
 *    other objects, as in smallpt, whose light is a sphere of radius 600 of which only a
 *    cap about 25 units across pokes below the ceiling (itself a sphere of radius 1e5).
 * 3. The cap by area: a cap's ball contains the cap, but seen obliquely a flat cap fills
 *    little of the ball's cone (smallpt's cap is 0.27 high and 36 across: from a wall
 *    beside it most of the cone's directions pass beside the cap and were dropped). When
 *    the narrowest cone is a cap's ball and ref sees the cap at an angle phi from its
 *    axis with cos phi below 0.9 (kConeMinCos2; about that share of the cone reaches the
 *    cap), points are drawn uniformly in area on that cap (1 - cos theta uniform in
 *    [0, its height], phi uniform) and their density is converted to solid angle
 *    (d^2 / (area cos_light)). The cap contains every point ref can see (it is the
 *    allowed side of one separator), so this too samples every visible point; points
 *    that face away from ref or that another separator hides are dropped, and pdf()
 *    applies the same choice of mode and cap.
 * 4. Fallback: when ref is inside (or on) the light, uniform area sampling, as for every
 *    other shape (nothing is visible from inside: lights emit outwards).
 *
 * Everything is in the light's own frame: a moving light is sampled by SceneIntersector
 * with ref moved back by time * velocity. Separating spheres are used only when the
 * light and the separating sphere are both static.
 */
class SphereLightSampler {
 public:
  /// For emitter `object` of `scene`, which must be a round Sphere (Sphere::isRound).
  SphereLightSampler(const Scene& scene, int object);

  /// A light point seen from `ref` for u in [0,1)^2, with its solid-angle pdf (without
  /// the light's pick probability), into `ls` (p, n, wi, distance, pdf; the rest is left
  /// as it was). False when the sample falls outside the visible part of the light or the
  /// light cannot be seen from ref at all (`ls` is then partly written).
  bool sample(const Point3& ref, const Vec2& u, LightSample& ls) const;
  /// Solid-angle density with which sample() returns the light point `p` with outward
  /// normal `n` from `ref` (0 where sample() never goes: back side, separated caps).
  double pdf(const Point3& ref, const Point3& p, const Normal3& n) const;

 private:
  /// How another sphere S constrains the light points visible from a reference point.
  struct Separator {
    enum class Relation {
      Disjoint,  ///< The light lies outside S: invisible from inside S.
      Encloses,  ///< The light lies inside S: invisible from outside S.
      Cuts,      ///< S cuts the light into the cap {n . axis >= cosAlpha} inside S and
                 ///< the rest outside it.
    };
    Relation relation = Relation::Cuts;
    Point3 centre{0.0};     ///< Of S, world space.
    double radius2 = 0.0;   ///< Of S, squared.
    Vec3 axis{0.0};         ///< Cuts: unit direction from the light's centre to S's centre.
    double cosAlpha = 0.0;  ///< Cuts: cosine of the half-angle of the cap inside S.
    /// Cuts: the ball through the rim of the cap on each side ([1]: inside S), which
    /// contains the cap when it is smaller than a hemisphere (capRadius2 < 0 otherwise).
    Point3 capCentre[2] = {Point3(0.0), Point3(0.0)};
    double capRadius2[2] = {-1.0, -1.0};
    /// Cuts, each side with a ball: the cap's own frame (capS, capT and the axis towards
    /// the cap's apex, +-axis), its height 1 - cos(half-angle) on the unit sphere, computed
    /// without cancellation, and its area on the light; for sampling it by area.
    Vec3 capS[2] = {Vec3(0.0), Vec3(0.0)}, capT[2] = {Vec3(0.0), Vec3(0.0)};
    double capHeight[2] = {0.0, 0.0};
    double capArea[2] = {0.0, 0.0};
    /// Cuts, first 64: bit j of within[side][sideJ] is set when this cap (on `side`) lies,
    /// with a margin of 1e-9 radians, within the cap of Cuts separator j on sideJ: points
    /// sampled on it need no check against j from a ref on sideJ of j.
    std::uint64_t within[2][2] = {{0, 0}, {0, 0}};
  };

  /// What to sample from one reference point.
  struct Plan {
    enum class Mode { Invisible, Area, Cone, CapArea } mode = Mode::Invisible;
    Vec3 axis{0.0};            ///< Cone: unit axis from ref.
    double cosThetaMax = 0.0;  ///< Cone: cosine of its half-angle.
    Vec3 centreOffset{0.0};    ///< Cone: ref minus the light's centre.
    double c = 0.0;            ///< Cone: |centreOffset|^2 - radius^2 (> 0: ref is outside).
    int cap = -1;              ///< CapArea: the separator whose cap is sampled,
    int capSide = 0;           ///< and its side (1: inside it).
    /// Bit i: ref is inside separator i (for the first 64 separators; visibleSide
    /// recomputes the rest).
    std::uint64_t inside = 0;
    /// The Cuts separators (first 64) visibleSide checks: all but, for CapArea, those
    /// whose allowed side contains the whole sampled cap.
    std::uint64_t check = 0;
  };

  void classifySeparators(const Scene& scene, int object);
  void cutAlongCircle(Separator& sep, const Vec3& between, double D, double rho) const;
  void packSeparatorColumns();
  void nestCaps();
  /// Bit i: ref is inside separator i (the first 64, m_sepX's columns).
  std::uint64_t insideMask(const Point3& ref) const;
  /// True when `best` (a cap's ball, bestToCentre from ref, at squared distance
  /// bestDistance2) is better sampled by the cap's area than by the ball's cone; then sets
  /// best's CapArea mode and the separators it must check.
  bool preferCapArea(Plan& best, const Vec3& bestToCentre, double bestDistance2) const;
  Plan plan(const Point3& ref) const;
  /// True when the light point with outward normal n is on ref's side of every separator
  /// (`plan` is plan(ref)).
  bool visibleSide(const Plan& plan, const Point3& ref, const Normal3& n) const;
  static bool isInside(const Separator& s, const Point3& ref) {
    const Vec3 f = ref - s.centre;
    return glm::dot(f, f) < s.radius2;
  }

  /// cos^2 of the largest angle from a cap's axis at which its ball's cone is sampled
  /// rather than the cap by area (kConeMinCos = 0.9: the cone keeps about 90% of its
  /// samples). Measured on smallpt (doc/dev/perf/issue-16.md): 0.9 and "always by area" give the
  /// same error at equal time, 0.7 and 0 (the cone wherever ref faces the cap) more.
  static constexpr double kConeMinCos2 = 0.9 * 0.9;
  const Sphere* m_sphere;
  Point3 m_centre;
  double m_radius;
  std::vector<Separator> m_separators;
  /// The first 64 separators: centres and squared radii as columns (padded to an even
  /// count with a separator that holds no point), and bit i set in
  /// m_disjoint / m_encloses by relation, in m_capInside / m_capOutside when the cap on
  /// that side has a ball (capRadius2 >= 0); m_cuts lists the Cuts separators.
  std::vector<double> m_sepX, m_sepY, m_sepZ, m_sepRadius2;
  std::uint64_t m_disjoint = 0, m_encloses = 0, m_capInside = 0, m_capOutside = 0, m_cutsMask = 0;
  std::vector<int> m_cuts;
};

}  // namespace raylab
