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
  ls.wi = toLight / ls.distance;
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
 * 3. Fallback: when ref is inside (or on) the light, uniform area sampling, as for every
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
  };

  /// What to sample from one reference point.
  struct Plan {
    enum class Mode { Invisible, Area, Cone } mode = Mode::Invisible;
    Vec3 axis{0.0};            ///< Cone: unit axis from ref.
    double cosThetaMax = 0.0;  ///< Cone: cosine of its half-angle.
    Vec3 centreOffset{0.0};    ///< Cone: ref minus the light's centre.
    double c = 0.0;            ///< Cone: |centreOffset|^2 - radius^2 (> 0: ref is outside).
    /// Bit i: ref is inside separator i (for the first 64 separators; visibleSide
    /// recomputes the rest).
    std::uint64_t inside = 0;
  };

  Plan plan(const Point3& ref) const;
  /// True when the light point with outward normal n is on ref's side of every separator
  /// (`plan` is plan(ref)).
  bool visibleSide(const Plan& plan, const Point3& ref, const Normal3& n) const;
  static bool isInside(const Separator& s, const Point3& ref) {
    const Vec3 f = ref - s.centre;
    return glm::dot(f, f) < s.radius2;
  }

  const Sphere* m_sphere;
  Point3 m_centre;
  double m_radius;
  std::vector<Separator> m_separators;
  /// The first 64 separators: centres and squared radii as columns, and bit i set in
  /// m_disjoint / m_encloses by relation, in m_capInside / m_capOutside when the cap on
  /// that side has a ball (capRadius2 >= 0); m_cuts lists the Cuts separators.
  std::vector<double> m_sepX, m_sepY, m_sepZ, m_sepRadius2;
  std::uint64_t m_disjoint = 0, m_encloses = 0, m_capInside = 0, m_capOutside = 0;
  std::vector<int> m_cuts;
};

}  // namespace raylab
