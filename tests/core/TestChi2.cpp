// Chi-square goodness-of-fit tests of every sampler against its density, in the manner of
// Nori's chi2test and Mitsuba's ChiSquareTest: draw N samples, histogram them on a 2D grid,
// integrate the claimed density over each cell numerically to get the expected counts,
// pool cells expecting fewer than 5 samples, and compute the p-value of the chi-square
// statistic. A sampler fails when p < alpha, where alpha is 1% Sidak-corrected over the
// kPositiveTests tests of this file (so the whole file has a 1% false-alarm rate).
// Each family also has a negative control — a sampler checked against a wrong density —
// which must be rejected, so we know the test has teeth.
//
// Directions are binned in spherical coordinates (theta or cos theta, phi) around a chosen
// axis; points on a disk in (r^2, phi). Where a density has a feature, the grid is chosen
// to resolve it: theta bins for sharp Phong lobes, and for a sphere light a cone around
// it with cells uniform in sqrt(cos theta - cos theta_max), so that the 1/cos singularity
// of area sampling at the silhouette becomes smooth.
#include "raylab/core/Bsdf.h"
#include "raylab/core/Camera.h"
#include "raylab/core/Microfacet.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sampler.h"
#include "raylab/core/Sampling.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Sphere.h"

#include <gtest/gtest.h>
#include <boost/math/special_functions/gamma.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace raylab {
namespace {

/// Number of chi-square tests below that must pass (the Sidak correction's m).
constexpr int kPositiveTests = 36;
/// Overall significance level of the file.
constexpr double kSignificance = 0.01;
/// Per-test level: 1 - (1 - 0.01)^(1/18) = 5.58e-4.
const double kAlpha = 1.0 - std::pow(1.0 - kSignificance, 1.0 / kPositiveTests);
/// Cells expecting fewer samples than this are pooled (the usual rule for chi-square).
constexpr double kMinExpected = 5.0;

/// Where samples fell on a grid over [0, 1)^2.
struct Histogram {
  int nx = 0, ny = 0;
  std::vector<double> counts;  ///< Row-major, nx * ny.
  long long outside = 0;       ///< Samples outside the domain, where the density is 0.
  long long rejected = 0;      ///< Sampler returned nothing (lost mass, allowed).
};

/// A sample's grid coordinates, nothing for a rejected sample; coordinates outside
/// [0, 1]^2 mean "outside the domain".
using SampleFn = std::function<std::optional<Vec2>()>;
/// The claimed density with respect to grid coordinates (density x Jacobian).
using DensityFn = std::function<double(double x, double y)>;

Histogram histogram(int nx, int ny, long long n, const SampleFn& sample) {
  Histogram h;
  h.nx = nx;
  h.ny = ny;
  h.counts.assign(std::size_t(nx) * ny, 0.0);
  for (long long i = 0; i < n; ++i) {
    const std::optional<Vec2> g = sample();
    if (!g) {
      ++h.rejected;
      continue;
    }
    if (!(g->x >= 0.0 && g->x <= 1.0 && g->y >= 0.0 && g->y <= 1.0)) {
      ++h.outside;
      continue;
    }
    const int ix = std::min(int(g->x * nx), nx - 1);
    const int iy = std::min(int(g->y * ny), ny - 1);
    h.counts[std::size_t(iy) * nx + ix] += 1.0;
  }
  return h;
}

/// Probability of each cell: the density integrated by a composite Gauss-Legendre rule,
/// `sub` x `sub` sub-cells per cell with 2 x 2 or 4 x 4 nodes each (never at the cell
/// edges, where densities may be singular or discontinuous).
std::vector<double> integrate(int nx, int ny, const DensityFn& density, int sub, bool order4) {
  static const double x2[] = {-0.5773502691896257, 0.5773502691896257};
  static const double w2[] = {1.0, 1.0};
  static const double x4[] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                              0.8611363115940526};
  static const double w4[] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                              0.3478548451374538};
  const double* xs = order4 ? x4 : x2;
  const double* ws = order4 ? w4 : w2;
  const int order = order4 ? 4 : 2;
  std::vector<double> p(std::size_t(nx) * ny, 0.0);
  const double hx = 1.0 / (nx * sub), hy = 1.0 / (ny * sub);
  for (int iy = 0; iy < ny; ++iy)
    for (int ix = 0; ix < nx; ++ix) {
      double sum = 0.0;
      for (int sy = 0; sy < sub; ++sy)
        for (int sx = 0; sx < sub; ++sx) {
          // Centre of the sub-cell, then the Gauss nodes around it.
          const double cx = (ix * sub + sx + 0.5) * hx, cy = (iy * sub + sy + 0.5) * hy;
          for (int a = 0; a < order; ++a)
            for (int b = 0; b < order; ++b)
              sum += ws[a] * ws[b] * density(cx + 0.5 * hx * xs[a], cy + 0.5 * hy * xs[b]);
        }
      p[std::size_t(iy) * nx + ix] = sum * 0.25 * hx * hy;
    }
  return p;
}

struct Chi2Result {
  double statistic = 0.0;
  int dof = 0;
  double pValue = 0.0;
  std::string failure;  ///< Set when the test failed outright (sample where none expected).
};

/// Pearson's chi-square test of the histogram against n * probabilities, with the cells
/// of low expectation pooled (Nori's chi2test).
Chi2Result chi2Test(const Histogram& h, const std::vector<double>& probability, long long n) {
  Chi2Result r;
  if (h.outside > 0) {
    r.failure = std::to_string(h.outside) + " samples outside the density's domain";
    return r;
  }
  // Sort the cells by expected count so low-expectation cells are pooled first.
  std::vector<std::pair<double, double>> cells;  // (expected, observed)
  for (std::size_t i = 0; i < h.counts.size(); ++i)
    cells.emplace_back(probability[i] * double(n), h.counts[i]);
  std::sort(cells.begin(), cells.end());
  double pooledExpected = 0.0, pooledObserved = 0.0;
  for (const auto& [expected, observed] : cells) {
    if (expected <= 0.0) {
      if (observed > 0.0) {
        r.failure = std::to_string(long(observed)) + " samples in a cell of zero density";
        return r;
      }
    } else if (expected < kMinExpected || (pooledExpected > 0.0 && pooledExpected < kMinExpected)) {
      // Too few expected: into the pool (and the pool into the next cell until it is big
      // enough).
      pooledExpected += expected;
      pooledObserved += observed;
    } else {
      r.statistic += (observed - expected) * (observed - expected) / expected;
      ++r.dof;
    }
  }
  if (pooledExpected > 0.0) {
    r.statistic +=
        (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
    ++r.dof;
  }
  // One degree of freedom is lost to the fixed total.
  r.dof -= 1;
  if (r.dof < 1) {
    r.failure = "too few cells for a chi-square test";
    return r;
  }
  r.pValue = boost::math::gamma_q(0.5 * r.dof, 0.5 * r.statistic);
  return r;
}

/// Runs one test and prints its figures.
Chi2Result runChi2(const std::string& name, int nx, int ny, long long n, const SampleFn& sample,
                   const DensityFn& density, int sub = 4, bool order4 = true) {
  const Histogram h = histogram(nx, ny, n, sample);
  const std::vector<double> p = integrate(nx, ny, density, sub, order4);
  double total = 0.0;
  for (double v : p) total += v;
  const Chi2Result r = chi2Test(h, p, n);
  std::printf("chi2 %-44s statistic=%10.1f dof=%5d p=%.4g%s (integral %.6f, rejected %lld)\n",
              name.c_str(), r.statistic, r.dof, r.pValue,
              r.failure.empty() ? "" : (" FAILED: " + r.failure).c_str(), total, h.rejected);
  ::testing::Test::RecordProperty("p_" + name, std::to_string(r.pValue));
  return r;
}

void expectAccepted(const Chi2Result& r, const std::string& name) {
  EXPECT_TRUE(r.failure.empty()) << name << ": " << r.failure;
  EXPECT_GE(r.pValue, kAlpha) << name << ": chi2 = " << r.statistic << ", dof = " << r.dof;
}

void expectRejected(const Chi2Result& r, const std::string& name) {
  EXPECT_TRUE(!r.failure.empty() || r.pValue < kAlpha)
      << name << " (negative control) was accepted: p = " << r.pValue;
}

/// How the polar coordinate of a direction maps to the grid's x.
enum class Polar {
  Cos,       ///< x uniform in cos theta, from 1 down to cMin.
  Theta,     ///< x uniform in theta, from 0 to acos(cMin).
  SqrtEdge,  ///< x uniform in 1 - sqrt((cos theta - cMin) / (1 - cMin)): smooth at a
             ///< 1/sqrt singularity on the cone's edge.
};

/// Directions around an axis, as grid coordinates (x: polar, y: phi / 2 pi).
struct SphereGrid {
  Frame frame;
  Polar polar = Polar::Cos;
  double cMin = -1.0;  ///< Cosine of the domain's largest polar angle.

  Vec2 toGrid(const Vec3& w) const {
    const Vec3 l = frame.toLocal(w);
    double c = glm::clamp(l.z, -1.0, 1.0);
    // Rounding may put a sample on the cone's edge just outside it.
    if (c < cMin - 1e-9) return {-1.0, -1.0};
    c = std::max(c, cMin);
    double x = 0.0;
    switch (polar) {
      case Polar::Cos:
        x = (1.0 - c) / (1.0 - cMin);
        break;
      case Polar::Theta:
        x = std::acos(c) / std::acos(cMin);
        break;
      case Polar::SqrtEdge:
        x = 1.0 - std::sqrt((c - cMin) / (1.0 - cMin));
        break;
    }
    double phi = std::atan2(l.y, l.x);
    if (phi < 0.0) phi += 2.0 * kPi;
    return {x, phi / (2.0 * kPi)};
  }

  /// The direction at grid point (x, y) and the Jacobian d omega / (dx dy).
  std::pair<Vec3, double> at(double x, double y) const {
    double c = 0.0, dcdx = 0.0;
    switch (polar) {
      case Polar::Cos:
        c = 1.0 - (1.0 - cMin) * x;
        dcdx = 1.0 - cMin;
        break;
      case Polar::Theta: {
        const double thetaMax = std::acos(cMin);
        c = std::cos(thetaMax * x);
        dcdx = thetaMax * std::sin(thetaMax * x);
        break;
      }
      case Polar::SqrtEdge:
        c = cMin + (1.0 - cMin) * (1.0 - x) * (1.0 - x);
        dcdx = 2.0 * (1.0 - cMin) * (1.0 - x);
        break;
    }
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    const double phi = 2.0 * kPi * y;
    return {frame.toWorld({s * std::cos(phi), s * std::sin(phi), c}), dcdx * 2.0 * kPi};
  }

  DensityFn density(std::function<double(const Vec3&)> pdf) const {
    return [this, pdf](double x, double y) {
      const auto [w, jacobian] = at(x, y);
      return pdf(w) * jacobian;
    };
  }
};

/// A disk point as grid coordinates (r^2, phi / 2 pi); outside the unit disk is outside.
Vec2 diskToGrid(const Vec2& p) {
  const double r2 = glm::dot(p, p);
  if (r2 > 1.0 + 1e-12) return {-1.0, -1.0};
  double phi = std::atan2(p.y, p.x);
  if (phi < 0.0) phi += 2.0 * kPi;
  return {std::min(r2, 1.0), phi / (2.0 * kPi)};
}

/// Area element of the (r^2, phi / 2 pi) grid: dA = r dr dphi = pi dx dy.
constexpr double kDiskJacobian = kPi;

const Normal3 kNormal = glm::normalize(Vec3(0.3, -0.2, 0.9));

TEST(Chi2, 01_CosineHemisphere) {
  Sampler rng(1, 0, 0, 0);
  const Frame f(kNormal);
  SphereGrid grid{f, Polar::Cos, -1.0};
  auto sample = [&]() -> std::optional<Vec2> {
    return grid.toGrid(f.toWorld(sampleCosineHemisphere(rng.next2D())));
  };
  const auto r = runChi2(
      "cosine hemisphere", 40, 80, 1000000, sample,
      grid.density([&](const Vec3& w) { return cosineHemispherePdf(glm::dot(w, kNormal)); }));
  expectAccepted(r, "cosine hemisphere");
  // Negative control: cosine samples claimed to be uniform over the hemisphere.
  Sampler rng2(2, 0, 0, 0);
  auto sample2 = [&]() -> std::optional<Vec2> {
    return grid.toGrid(f.toWorld(sampleCosineHemisphere(rng2.next2D())));
  };
  expectRejected(runChi2("NEGATIVE cosine as uniform hemisphere", 40, 80, 1000000, sample2,
                         grid.density([&](const Vec3& w) {
                           return glm::dot(w, kNormal) > 0.0 ? 1.0 / (2.0 * kPi) : 0.0;
                         })),
                 "cosine as uniform");
}

TEST(Chi2, 02_UniformSphere) {
  Sampler rng(3, 0, 0, 0);
  SphereGrid grid{Frame(kNormal), Polar::Cos, -1.0};
  auto sample = [&]() -> std::optional<Vec2> {
    return grid.toGrid(sampleUniformSphere(rng.next2D()));
  };
  expectAccepted(runChi2("uniform sphere", 40, 80, 1000000, sample,
                         grid.density([](const Vec3&) { return uniformSpherePdf(); })),
                 "uniform sphere");
  // Negative control: a 10% tilt of the claimed density along the axis.
  Sampler rng2(4, 0, 0, 0);
  auto sample2 = [&]() -> std::optional<Vec2> {
    return grid.toGrid(sampleUniformSphere(rng2.next2D()));
  };
  expectRejected(runChi2("NEGATIVE uniform sphere as (1 + 0.1 z) / 4pi", 40, 80, 1000000, sample2,
                         grid.density([](const Vec3& w) {
                           return (1.0 + 0.1 * glm::dot(w, kNormal)) / (4.0 * kPi);
                         })),
                 "tilted sphere");
}

TEST(Chi2, 03_PhongLobeWarp) {
  // samplePhongLobe itself, exponent 20, binned in theta around the lobe's axis.
  Sampler rng(5, 0, 0, 0);
  const Frame f(kNormal);
  SphereGrid grid{f, Polar::Theta, -1.0};
  auto sample = [&]() -> std::optional<Vec2> {
    return grid.toGrid(f.toWorld(samplePhongLobe(rng.next2D(), 20.0)));
  };
  expectAccepted(
      runChi2("phong lobe warp n=20", 60, 60, 1000000, sample, grid.density([&](const Vec3& w) {
        return phongLobePdf(glm::dot(w, kNormal), 20.0);
      })),
      "phong warp");
}

/// Glossy material at incidence `degrees` from the normal kNormal, as a sampler and pdf.
struct GlossySetup {
  Material m;
  SurfaceInteraction si;
  Vec3 wo;
  GlossySetup(double exponent, double degrees) {
    m.type = MaterialType::Glossy;
    m.colour = Vec3(0.5, 0.6, 0.7);
    m.specular = 0.7;
    m.exponent = exponent;
    const Frame f(kNormal);
    const double a = radians(degrees);
    wo = f.toWorld({std::sin(a), 0.0, std::cos(a)});
    si.n = kNormal;
    si.frontFace = true;
  }
};

TEST(Chi2, 04_GlossyMaterialSampling) {
  // bsdf::sample against bsdf::pdf for the Glossy material (Phong lobe + Lambert mixture),
  // exponents 1, 10, 100 at incidence 0, 45 and 80 degrees. Samples below the surface are
  // rejected by the sampler; pdf is 0 there, so none may land there. Theta bins around
  // the normal (3 degrees) resolve even the n = 100 lobe; the horizon is a cell edge.
  for (double exponent : {1.0, 10.0, 100.0})
    for (double degrees : {0.0, 45.0, 80.0}) {
      const GlossySetup g(exponent, degrees);
      Sampler rng(6, int(exponent), int(degrees), 0);
      SphereGrid grid{Frame(kNormal), Polar::Theta, -1.0};
      auto sample = [&]() -> std::optional<Vec2> {
        const auto s = bsdf::sample(g.m, g.si, g.wo, rng);
        if (!s) return std::nullopt;
        return grid.toGrid(s->wi);
      };
      char name[64];
      std::snprintf(name, sizeof name, "glossy n=%g at %g deg", exponent, degrees);
      expectAccepted(runChi2(name, 60, 60, 1000000, sample, grid.density([&](const Vec3& w) {
                       return bsdf::pdf(g.m, g.si, g.wo, w);
                     })),
                     name);
    }
  // Negative control: samples of exponent 10 against the density of exponent 13.
  const GlossySetup g(10.0, 45.0), wrong(13.0, 45.0);
  Sampler rng(7, 0, 0, 0);
  SphereGrid grid{Frame(kNormal), Polar::Theta, -1.0};
  auto sample = [&]() -> std::optional<Vec2> {
    const auto s = bsdf::sample(g.m, g.si, g.wo, rng);
    if (!s) return std::nullopt;
    return grid.toGrid(s->wi);
  };
  expectRejected(runChi2("NEGATIVE glossy n=10 as n=13", 60, 60, 1000000, sample,
                         grid.density([&](const Vec3& w) {
                           return bsdf::pdf(wrong.m, wrong.si, wrong.wo, w);
                         })),
                 "glossy n=10 as n=13");
}

/// One emissive object seen from the origin.
Scene lightScene(std::unique_ptr<Shape> light) {
  Scene scene;
  Material m;
  m.name = "light";
  m.emission = Vec3(1.0, 2.0, 0.5);
  scene.materials.push_back(m);
  scene.objects.emplace_back("light", std::move(light), 0);
  return scene;
}

/// smallpt in miniature (Chi2.10, Chi2.15): a light of radius 2.5 centred at (0, 3, 0) poking
/// 0.3 below the top of a "room", the inside of a sphere of radius 10.8 centred at (0, -10, 0).
Scene smallptLightScene() {
  Scene scene = lightScene(std::make_unique<Sphere>(Point3(0, 3, 0), 2.5));
  Material wall;
  wall.name = "wall";
  scene.materials.push_back(wall);
  scene.objects.emplace_back("room", std::make_unique<Sphere>(Point3(0, -10, 0), 10.8), 1);
  return scene;
}

/// Solid-angle density of the intersector's light sampling towards w, from `ref` (the
/// origin unless given): lightPdf at the first hit along w, 0 when that is not a light.
double lightDensity(const SceneIntersector& si, const Vec3& w, const Point3& ref = Point3(0.0)) {
  const auto hit = si.intersect(Ray::make(ref, w));
  if (!hit) return 0.0;
  return si.lightPdf(ref, hit->object, hit->si);
}

TEST(Chi2, 05_SphereLightSampling) {
  // A sphere of radius 0.8 at distance 2 (centre (0.6, 1.8, -0.6) away): a round sphere light
  // is sampled uniformly in the cone of half-angle asin(0.8 / 2) it subtends. Grid: that
  // cone, cells uniform in sqrt(cos theta - cos theta_max) (fine at the silhouette, where
  // the negative control's density is singular).
  const Point3 centre(0.6, 1.8, -0.6);
  const double radius = 0.8;
  const Scene scene = lightScene(std::make_unique<Sphere>(centre, radius));
  const SceneIntersector si(scene);
  const double d = glm::length(centre);
  SphereGrid grid{Frame(centre / d), Polar::SqrtEdge, std::sqrt(1.0 - (radius / d) * (radius / d))};
  Sampler rng(8, 0, 0, 0);
  auto sample = [&]() -> std::optional<Vec2> {
    const auto ls = si.sampleLight(Point3(0.0), rng.next2D(), rng.next1D());
    if (!ls) return std::nullopt;
    return grid.toGrid(ls->wi);
  };
  expectAccepted(runChi2("sphere light (solid angle)", 30, 40, 1000000, sample,
                         grid.density([&](const Vec3& w) { return lightDensity(si, w); })),
                 "sphere light");
  // Negative control: the density of area sampling without its 1 / cos_light, i.e. the
  // cone's density times cos_light.
  Sampler rng2(9, 0, 0, 0);
  auto sample2 = [&]() -> std::optional<Vec2> {
    const auto ls = si.sampleLight(Point3(0.0), rng2.next2D(), rng2.next1D());
    if (!ls) return std::nullopt;
    return grid.toGrid(ls->wi);
  };
  expectRejected(runChi2("NEGATIVE sphere light without 1/cos", 30, 40, 1000000, sample2,
                         grid.density([&](const Vec3& w) {
                           const auto hit = si.intersect(Ray::make(Point3(0.0), w));
                           if (!hit) return 0.0;
                           const double cosLight = -glm::dot(hit->si.n, w);
                           return si.lightPdf(Point3(0.0), hit->object, hit->si) * cosLight;
                         })),
                 "sphere light without cos");
}

TEST(Chi2, 06_QuadLightSampling) {
  // A tilted 1.5 x 1 rectangle facing the origin; the grid is a cone around its centre
  // that contains it, so cells straddle its edges: many sub-cells per cell keep the
  // integration error there far below the statistical one.
  auto quad =
      std::make_unique<Quad>(Point3(-0.5, 2.0, -0.8), Vec3(1.5, 0.3, 0.0), Vec3(0.0, 0.4, 1.0));
  if (glm::dot(glm::cross(quad->edgeU(), quad->edgeV()), Vec3(0, 1, 0)) > 0.0)
    quad =
        std::make_unique<Quad>(Point3(-0.5, 2.0, -0.8), Vec3(0.0, 0.4, 1.0), Vec3(1.5, 0.3, 0.0));
  const Point3 centre = quad->corner() + 0.5 * (quad->edgeU() + quad->edgeV());
  const Vec3 axis = glm::normalize(centre);
  double cMin = 1.0;
  for (Vec3 corner :
       {quad->corner(), quad->corner() + quad->edgeU(), quad->corner() + quad->edgeV(),
        quad->corner() + quad->edgeU() + quad->edgeV()})
    cMin = std::min(cMin, glm::dot(glm::normalize(corner), axis));
  cMin -= 0.02;
  const Scene scene = lightScene(std::move(quad));
  const SceneIntersector si(scene);
  SphereGrid grid{Frame(axis), Polar::Cos, cMin};
  Sampler rng(10, 0, 0, 0);
  auto sample = [&]() -> std::optional<Vec2> {
    const auto ls = si.sampleLight(Point3(0.0), rng.next2D(), rng.next1D());
    if (!ls) return std::nullopt;
    return grid.toGrid(ls->wi);
  };
  const auto r =
      runChi2("quad light (solid angle)", 30, 60, 1000000, sample,
              grid.density([&](const Vec3& w) { return lightDensity(si, w); }), 24, false);
  expectAccepted(r, "quad light");
}

TEST(Chi2, 07_LensSampling) {
  // The concentric disk mapping, and the thin-lens camera's ray origins (which must be
  // uniform on the lens), on a (r^2, phi) grid.
  Sampler rng(11, 0, 0, 0);
  auto sample = [&]() -> std::optional<Vec2> {
    return diskToGrid(sampleUniformDisk(rng.next2D()));
  };
  const DensityFn uniform = [](double, double) { return uniformDiskPdf() * kDiskJacobian; };
  expectAccepted(runChi2("uniform disk", 40, 40, 1000000, sample, uniform), "uniform disk");

  CameraSpec spec;
  spec.position = {1, 2, 3};
  spec.lookAt = {0, 0, 0};
  spec.aperture = 0.25;
  const Camera camera(spec);
  const Vec3 forward = glm::normalize(spec.lookAt - spec.position);
  const Vec3 right = glm::normalize(glm::cross(forward, spec.up));
  const Vec3 up = glm::cross(right, forward);
  Sampler rng2(12, 3, 4, 0);
  auto lens = [&]() -> std::optional<Vec2> {
    const Vec3 o = camera.generateRay({17.5, 99.5}, rng2.next2D(), 0.0).origin - spec.position;
    return diskToGrid(Vec2(glm::dot(o, right), glm::dot(o, up)) / spec.aperture);
  };
  expectAccepted(runChi2("thin lens camera origins", 40, 40, 1000000, lens, uniform), "thin lens");

  // Negative control: the naive polar map (r = u) bunches points at the centre.
  Sampler rng3(13, 0, 0, 0);
  auto naive = [&]() -> std::optional<Vec2> {
    const Vec2 u = rng3.next2D();
    return diskToGrid(u.x * Vec2(std::cos(2 * kPi * u.y), std::sin(2 * kPi * u.y)));
  };
  expectRejected(runChi2("NEGATIVE naive polar disk as uniform", 40, 40, 1000000, naive, uniform),
                 "naive disk");
}

TEST(Chi2, 08_TheCountOfTestsMatchesTheCorrection) {
  // cosine 1 + sphere 1 + phong warp 1 + glossy 9 + sphere light 1 + quad light 1 + disk 2
  // + cone warp 1 + separated sphere light 1 + microfacet normals 2 + visible normals 6
  // + rough conductor 3 + rough dielectric 3 + separated sphere light by area 1 + plastic 3.
  EXPECT_EQ(kPositiveTests, 1 + 1 + 1 + 9 + 1 + 1 + 2 + 1 + 1 + 2 + 6 + 3 + 3 + 1 + 3);
  // 1 - (1 - 0.01)^(1/36).
  EXPECT_NEAR(kAlpha, 2.7914e-04, 1e-7);
}

TEST(Chi2, 09_UniformConeWarp) {
  // sampleUniformCone with a half-angle of 50 degrees, cells uniform in cos theta over the
  // cone: the density is the constant uniformConePdf inside, 0 outside.
  const double cosMax = std::cos(radians(50.0));
  const Frame f(kNormal);
  SphereGrid grid{f, Polar::Cos, cosMax};
  const auto inCone = [&](const Vec3& w) { return glm::dot(w, kNormal) >= cosMax; };
  Sampler rng(14, 0, 0, 0);
  auto sample = [&]() -> std::optional<Vec2> {
    return grid.toGrid(f.toWorld(sampleUniformCone(rng.next2D(), cosMax)));
  };
  expectAccepted(
      runChi2("uniform cone 50 deg", 40, 80, 1000000, sample, grid.density([&](const Vec3& w) {
        return inCone(w) ? uniformConePdf(cosMax) : 0.0;
      })),
      "uniform cone");
  // Negative control: the same samples claimed uniform in theta (density
  // 1 / (2 pi theta_max sin theta)), the naive polar warp.
  Sampler rng2(15, 0, 0, 0);
  auto sample2 = [&]() -> std::optional<Vec2> {
    return grid.toGrid(f.toWorld(sampleUniformCone(rng2.next2D(), cosMax)));
  };
  expectRejected(runChi2("NEGATIVE uniform cone as uniform in theta", 40, 80, 1000000, sample2,
                         grid.density([&](const Vec3& w) {
                           const double c = glm::dot(w, kNormal);
                           const double sinTheta = std::sqrt(std::max(0.0, 1.0 - c * c));
                           return inCone(w) ? 1.0 / (2.0 * kPi * radians(50.0) * sinTheta) : 0.0;
                         })),
                 "cone as uniform in theta");
}

TEST(Chi2, 10_SphereLightCutByASeparatingSphere) {
  // smallpt in miniature: a light of radius R = 2.5 centred at (0, 3, 0) pokes 0.3 below the
  // top of the "room", the inside of a sphere of radius 10.8 centred at (0, -10, 0) (top at
  // y = 0.8). From a point in the room only the cap of the light inside the room can be
  // seen; the sampler draws directions from the cone of the ball around that cap and keeps
  // those whose first hit on the light is in the cap. The claimed density is lightPdf at
  // the first hit of a real ray along w (the room's wall hides the rest of the light), so
  // the test also checks that no sample lands where the room hides the light. Cells
  // straddle the cap's rim, where the density jumps: many sub-cells keep the integration
  // error there small.
  const Scene scene = smallptLightScene();
  const SceneIntersector si(scene);
  const Point3 ref(0.3, -1.2, 0.2);
  // The cap inside the room: n . (-y) >= cos(alpha) with cos(alpha) = (D^2 + R^2 - rho^2) /
  // (2 R D) for the distance D = 13 between the centres; the ball through its rim circle.
  const double D = 13.0, R = 2.5, rho = 10.8;
  const double cosAlpha = (D * D + R * R - rho * rho) / (2.0 * R * D);
  const Point3 rimCentre(0.0, 3.0 - R * cosAlpha, 0.0);
  const double rimRadius = R * std::sqrt(1.0 - cosAlpha * cosAlpha);
  const double distance = glm::length(rimCentre - ref);
  const double cosMax = std::sqrt(1.0 - (rimRadius / distance) * (rimRadius / distance));
  SphereGrid grid{Frame((rimCentre - ref) / distance), Polar::Cos, cosMax};
  Sampler rng(16, 0, 0, 0);
  long long accepted = 0;
  auto sample = [&]() -> std::optional<Vec2> {
    const auto ls = si.sampleLight(ref, rng.next2D(), rng.next1D());
    if (!ls) return std::nullopt;
    ++accepted;
    return grid.toGrid(ls->wi);
  };
  expectAccepted(
      runChi2("sphere light cut by a sphere", 30, 60, 1000000, sample,
              grid.density([&](const Vec3& w) { return lightDensity(si, w, ref); }), 24, false),
      "separated sphere light");
  // Most directions of the cap's cone reach the cap.
  EXPECT_GT(accepted, 500000);
  // Negative control: the same samples against the light's own cone, uniform over every
  // visible direction (what sampling without the separating sphere would give).
  const double toLight = glm::length(Point3(0, 3, 0) - ref);
  const double lightConePdf = uniformConePdf(std::sqrt(1.0 - (R / toLight) * (R / toLight)));
  Sampler rng2(17, 0, 0, 0);
  auto sample2 = [&]() -> std::optional<Vec2> {
    const auto ls = si.sampleLight(ref, rng2.next2D(), rng2.next1D());
    if (!ls) return std::nullopt;
    return grid.toGrid(ls->wi);
  };
  expectRejected(runChi2("NEGATIVE cut sphere light as its whole cone", 30, 60, 1000000, sample2,
                         grid.density([&](const Vec3& w) {
                           return lightDensity(si, w, ref) > 0.0 ? lightConePdf : 0.0;
                         }),
                         24, false),
                 "cut light as whole cone");
}

const char* modelName(MicrofacetModel model) { return toString(model); }

TEST(Chi2, 11_MicrofacetNormals) {
  // sampleNormal against D(h) cos(theta_h), alpha = 0.3, on the upper hemisphere in theta
  // bins (1.5 degrees).
  const Frame up(Vec3(0.0, 0.0, 1.0));
  SphereGrid grid{up, Polar::Theta, 0.0};
  for (MicrofacetModel model : {MicrofacetModel::GGX, MicrofacetModel::Beckmann}) {
    const microfacet::Distribution d{model, 0.3};
    Sampler rng(18, int(model), 0, 0);
    auto sample = [&]() -> std::optional<Vec2> {
      return grid.toGrid(microfacet::sampleNormal(d, rng.next2D()));
    };
    const std::string name = std::string(modelName(model)) + " normals D cos, alpha 0.3";
    expectAccepted(runChi2(name, 60, 40, 1000000, sample, grid.density([&](const Vec3& h) {
                     return microfacet::normalPdf(d, h);
                   })),
                   name);
  }
}

TEST(Chi2, 12_VisibleNormals) {
  // sampleVisibleNormal against visibleD(wo, h), alpha = 0.5, seen at 0, 60 and 85 degrees,
  // on the upper hemisphere around the normal.
  const Frame up(Vec3(0.0, 0.0, 1.0));
  SphereGrid grid{up, Polar::Theta, 0.0};
  for (MicrofacetModel model : {MicrofacetModel::GGX, MicrofacetModel::Beckmann})
    for (double degrees : {0.0, 60.0, 85.0}) {
      const microfacet::Distribution d{model, 0.5};
      const double a = radians(degrees);
      const Vec3 wo(std::sin(a) * std::cos(0.4), std::sin(a) * std::sin(0.4), std::cos(a));
      Sampler rng(19, int(model), int(degrees), 0);
      auto sample = [&]() -> std::optional<Vec2> {
        return grid.toGrid(microfacet::sampleVisibleNormal(d, wo, rng.next2D()));
      };
      char name[80];
      std::snprintf(name, sizeof name, "%s visible normals at %g deg", modelName(model), degrees);
      expectAccepted(runChi2(name, 60, 60, 1000000, sample, grid.density([&](const Vec3& h) {
                       return microfacet::visibleNormalPdf(d, wo, h);
                     })),
                     name);
    }
  // Negative control: visible normals at 60 degrees claimed to follow D cos (the sampler
  // that ignores the view).
  const microfacet::Distribution d{MicrofacetModel::GGX, 0.5};
  const Vec3 wo(std::sin(radians(60.0)), 0.0, 0.5);
  Sampler rng(20, 0, 0, 0);
  auto sample = [&]() -> std::optional<Vec2> {
    return grid.toGrid(microfacet::sampleVisibleNormal(d, wo, rng.next2D()));
  };
  expectRejected(runChi2("NEGATIVE visible normals as D cos", 60, 60, 1000000, sample,
                         grid.density([&](const Vec3& h) { return microfacet::normalPdf(d, h); })),
                 "visible normals as D cos");
}

/// A rough material at incidence `degrees` from kNormal (beyond 90: from inside).
struct RoughSetup {
  Material m;
  SurfaceInteraction si;
  Vec3 wo;
  RoughSetup(MaterialType type, MicrofacetModel model, double alpha, double degrees,
             bool visible = true) {
    m.type = type;
    m.colour = Vec3(0.9, 0.8, 0.7);
    m.distribution = model;
    m.roughness = alpha;
    m.visibleNormals = visible;
    m.ior = 1.5;
    const double a = radians(degrees);
    wo = Frame(kNormal).toWorld({std::sin(a), 0.0, std::cos(a)});
    si.n = kNormal;
    si.frontFace = glm::dot(wo, kNormal) > 0.0;
  }
};

/// bsdf::sample against bsdf::pdf over the whole sphere (theta bins of 3 degrees around
/// the normal), for a rough material.
Chi2Result roughChi2(const std::string& name, const RoughSetup& g, const RoughSetup& claimed,
                     std::uint64_t seed) {
  SphereGrid grid{Frame(kNormal), Polar::Theta, -1.0};
  Sampler rng(seed, 0, 0, 0);
  auto sample = [&]() -> std::optional<Vec2> {
    const auto s = bsdf::sample(g.m, g.si, g.wo, rng);
    if (!s) return std::nullopt;
    return grid.toGrid(s->wi);
  };
  return runChi2(name, 60, 60, 1000000, sample, grid.density([&](const Vec3& w) {
    return bsdf::pdf(claimed.m, claimed.si, claimed.wo, w);
  }));
}

TEST(Chi2, 13_RoughConductorSampling) {
  const RoughSetup cases[] = {
      {MaterialType::RoughConductor, MicrofacetModel::GGX, 0.2, 45.0},
      {MaterialType::RoughConductor, MicrofacetModel::Beckmann, 0.5, 70.0},
      {MaterialType::RoughConductor, MicrofacetModel::GGX, 0.3, 60.0, false}};
  const char* names[] = {"rough conductor ggx 0.2 at 45 deg", "rough conductor beckmann 0.5 at 70",
                         "rough conductor ggx 0.3 D cos at 60"};
  for (int i = 0; i < 3; ++i)
    expectAccepted(roughChi2(names[i], cases[i], cases[i], 22 + i), names[i]);
}

TEST(Chi2, 14_RoughDielectricSampling) {
  // Reflection and transmission together, over the whole sphere: from outside at 45
  // degrees, from inside at 30 degrees (below the critical angle 41.8), Beckmann at 70.
  const RoughSetup cases[] = {
      {MaterialType::RoughDielectric, MicrofacetModel::GGX, 0.3, 45.0},
      {MaterialType::RoughDielectric, MicrofacetModel::GGX, 0.3, 150.0},
      {MaterialType::RoughDielectric, MicrofacetModel::Beckmann, 0.2, 70.0}};
  const char* names[] = {"rough dielectric ggx 0.3 at 45 deg",
                         "rough dielectric ggx 0.3 inside at 30",
                         "rough dielectric beckmann 0.2 at 70"};
  for (int i = 0; i < 3; ++i)
    expectAccepted(roughChi2(names[i], cases[i], cases[i], 26 + i), names[i]);
  // Negative control: alpha 0.3 samples against the density of alpha 0.36.
  const RoughSetup wrong(MaterialType::RoughDielectric, MicrofacetModel::GGX, 0.36, 45.0);
  expectRejected(roughChi2("NEGATIVE rough dielectric 0.3 as 0.36", cases[0], wrong, 30),
                 "rough dielectric 0.3 as 0.36");
}

TEST(Chi2, 15_SphereLightCapByArea) {
  // Chi2.10's light and room, seen from beside the cap (a point 0.45 below the rim's plane
  // and 1.7 from the light's axis): the cap is seen obliquely and fills little of its
  // ball's cone, so the sampler draws points uniformly in area on the cap instead and
  // converts their density to solid angle. The claimed density (lightPdf at the first
  // hit of a real ray) must be the density of the samples; the mean of 1 / pdf over all
  // samples (0 for dropped ones) must be the solid angle the light shows through the room,
  // found by rays; and fewer samples are dropped than the cone would drop.
  const Scene scene = smallptLightScene();
  const SceneIntersector si(scene);
  const Point3 ref(1.6, 0.3, -0.4);
  const double D = 13.0, R = 2.5, rho = 10.8;
  const double cosAlpha = (D * D + R * R - rho * rho) / (2.0 * R * D);
  const Point3 rimCentre(0.0, 3.0 - R * cosAlpha, 0.0);
  const double rimRadius = R * std::sqrt(1.0 - cosAlpha * cosAlpha);
  const double distance = glm::length(rimCentre - ref);
  const double cosMax = std::sqrt(1.0 - (rimRadius / distance) * (rimRadius / distance));
  // The grid: the light's whole cone, fine at its silhouette (SqrtEdge), where the area
  // density converted to solid angle has its 1 / cos_light singularity.
  const Vec3 toLight = Point3(0, 3, 0) - ref;
  const double lightDistance = glm::length(toLight);
  SphereGrid grid{Frame(toLight / lightDistance), Polar::SqrtEdge,
                  std::sqrt(1.0 - (R / lightDistance) * (R / lightDistance))};
  Sampler rng(31, 0, 0, 0);
  long long accepted = 0;
  double inversePdf = 0.0, inversePdf2 = 0.0;
  constexpr long long kSamples = 1000000;
  auto sample = [&]() -> std::optional<Vec2> {
    const auto ls = si.sampleLight(ref, rng.next2D(), rng.next1D());
    if (!ls) return std::nullopt;
    ++accepted;
    inversePdf += 1.0 / ls->pdf;
    inversePdf2 += 1.0 / (ls->pdf * ls->pdf);
    return grid.toGrid(ls->wi);
  };
  expectAccepted(
      runChi2("sphere light cap by area", 60, 60, kSamples, sample,
              grid.density([&](const Vec3& w) { return lightDensity(si, w, ref); }), 24, false),
      "sphere light cap by area");
  // The visible solid angle by rays: directions uniform in the ball's cone, the share whose
  // first hit is the light.
  Sampler rays(32, 0, 0, 0);
  const Frame frame((rimCentre - ref) / distance);
  long long seen = 0;
  constexpr long long kRays = 1000000;
  for (long long i = 0; i < kRays; ++i) {
    const Vec3 w = frame.toWorld(sampleUniformCone(rays.next2D(), cosMax));
    const auto hit = si.intersect(Ray::make(ref, w));
    seen += hit && hit->object == 0;
  }
  const double cone = 2.0 * kPi * (1.0 - cosMax);
  const double byRays = cone * double(seen) / double(kRays);
  const double byRaysError =
      cone * std::sqrt(double(seen) * double(kRays - seen) / double(kRays)) / double(kRays);
  const double mean = inversePdf / double(kSamples);
  const double meanError =
      std::sqrt((inversePdf2 / double(kSamples) - mean * mean) / double(kSamples));
  std::printf(
      "visible solid angle: %.6f +- %.6f by light samples, %.6f +- %.6f by rays; "
      "%.3f of light samples kept, %.3f of the cone's directions reach the light\n",
      mean, meanError, byRays, byRaysError, double(accepted) / double(kSamples),
      double(seen) / double(kRays));
  EXPECT_NEAR(mean, byRays, 5.0 * std::hypot(meanError, byRaysError));
  EXPECT_GT(double(accepted) / double(kSamples), double(seen) / double(kRays) + 0.1);
  // Negative control: the same sampler against the density uniform over the visible
  // directions (what the cap's cone gives), scaled to the same kept share.
  Sampler rng2(33, 0, 0, 0);
  auto sample2 = [&]() -> std::optional<Vec2> {
    const auto ls = si.sampleLight(ref, rng2.next2D(), rng2.next1D());
    if (!ls) return std::nullopt;
    return grid.toGrid(ls->wi);
  };
  const double kept = double(accepted) / double(kSamples);
  expectRejected(runChi2("NEGATIVE cap by area as uniform in angle", 60, 60, kSamples, sample2,
                         grid.density([&](const Vec3& w) {
                           return lightDensity(si, w, ref) > 0.0 ? kept / byRays : 0.0;
                         }),
                         24, false),
                 "cap by area as uniform in angle");
}

TEST(Chi2, 16_PlasticSampling) {
  // The plastic's mixture (coating normals, visible or D cos, and the cosine hemisphere)
  // against its pdf over the whole sphere (nothing may fall below the surface): GGX at
  // 30 degrees, Beckmann at 70, GGX with D cos sampling at 60.
  RoughSetup cases[] = {{MaterialType::Plastic, MicrofacetModel::GGX, 0.2, 30.0},
                        {MaterialType::Plastic, MicrofacetModel::Beckmann, 0.5, 70.0},
                        {MaterialType::Plastic, MicrofacetModel::GGX, 0.3, 60.0, false}};
  const char* names[] = {"plastic ggx 0.2 at 30 deg", "plastic beckmann 0.5 at 70 deg",
                         "plastic ggx 0.3 D cos at 60 deg"};
  for (int i = 0; i < 3; ++i) {
    cases[i].m.colour = Vec3(0.5, 0.3, 0.2);
    expectAccepted(roughChi2(names[i], cases[i], cases[i], 40 + i), names[i]);
  }
  // Negative control: samples of a dark base (more coating rays) against the density of a
  // white one.
  RoughSetup white = cases[0];
  white.m.colour = Vec3(1.0);
  expectRejected(roughChi2("NEGATIVE plastic dark base as white", cases[0], white, 43),
                 "plastic dark base as white");
}

}  // namespace
}  // namespace raylab
