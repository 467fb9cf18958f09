// The yardstick of RayLab's path sample (issue 16): a minimal explicit path tracer that
// follows Kevin Beason's smallpt algorithm on smallpt's nine spheres, written for these
// benchmarks (smallpt itself is not a dependency). What it keeps of smallpt, as the cost it
// measures is smallpt's:
//   - the scene: nine spheres in double precision, each diffuse, mirror or glass (index 1.5),
//     the light a sphere of radius 600 poking through the ceiling with radiance 12;
//   - the intersection: every sphere tested in a flat loop, the nearest root beyond 1e-4;
//   - the estimator: radiance only from emission (no light sampling), a cosine-weighted
//     diffuse bounce, an ideal mirror, Fresnel-weighted glass (Schlick) that follows both
//     branches up to depth 2 and one chosen with probability 1/4 + Re/2 after it; Russian
//     roulette after depth 5 with the surface colour's largest component; no depth limit;
//   - the camera: eye (50, 52, 295.6), direction (0, -0.042612, -1), the film's half-width
//     0.5135 w / h and half-height 0.5135 (vertical field of view 28.8 degrees), each ray
//     starting 140 units along its unit direction (lessons/scenes/smallpt.json's near
//     sphere);
//   - the random numbers: erand48, one stream per image row.
// What it changes, so that it converges to the very image RayLab computes and the error of
// both can be measured against one reference: each sample is uniform over the pixel (a box
// filter, as RayLab's film samples) instead of smallpt's tent filter over 2x2 subpixels, and
// nothing is clamped (smallpt clamps each subpixel's mean to [0, 1]). Neither changes the
// cost of a sample: one camera ray and its path, i.e. one call of radiance().
#pragma once

#include "raylab/core/Image.h"

#include <stdlib.h>  // erand48 (POSIX)

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <thread>
#include <vector>

namespace raylab::yardstick {

struct V {
  double x = 0.0, y = 0.0, z = 0.0;
  V() = default;
  V(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  V operator+(const V& o) const { return {x + o.x, y + o.y, z + o.z}; }
  V operator-(const V& o) const { return {x - o.x, y - o.y, z - o.z}; }
  V operator*(double s) const { return {x * s, y * s, z * s}; }
  V times(const V& o) const { return {x * o.x, y * o.y, z * o.z}; }
  double dot(const V& o) const { return x * o.x + y * o.y + z * o.z; }
  V cross(const V& o) const { return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x}; }
  V unit() const { return *this * (1.0 / std::sqrt(dot(*this))); }
};

enum class Surface { Diffuse, Mirror, Glass };

struct Ball {
  double radius;
  V centre, emission, colour;
  Surface surface;

  /// Distance along the unit direction d from o to the nearest crossing beyond 1e-4, or 0.
  double hit(const V& o, const V& d) const {
    const V toCentre = centre - o;
    const double along = toCentre.dot(d);
    double disc = along * along - toCentre.dot(toCentre) + radius * radius;
    if (disc < 0.0) return 0.0;
    disc = std::sqrt(disc);
    constexpr double kEps = 1e-4;
    if (along - disc > kEps) return along - disc;
    if (along + disc > kEps) return along + disc;
    return 0.0;
  }
};

/// smallpt's scene: left, right, back, front, bottom, top, mirror, glass, light.
inline const Ball kBalls[9] = {
    {1e5, V(1e5 + 1, 40.8, 81.6), V(), V(.75, .25, .25), Surface::Diffuse},
    {1e5, V(-1e5 + 99, 40.8, 81.6), V(), V(.25, .25, .75), Surface::Diffuse},
    {1e5, V(50, 40.8, 1e5), V(), V(.75, .75, .75), Surface::Diffuse},
    {1e5, V(50, 40.8, -1e5 + 170), V(), V(), Surface::Diffuse},
    {1e5, V(50, 1e5, 81.6), V(), V(.75, .75, .75), Surface::Diffuse},
    {1e5, V(50, -1e5 + 81.6, 81.6), V(), V(.75, .75, .75), Surface::Diffuse},
    {16.5, V(27, 16.5, 47), V(), V(.999, .999, .999), Surface::Mirror},
    {16.5, V(73, 16.5, 78), V(), V(.999, .999, .999), Surface::Glass},
    {600, V(50, 681.6 - .27, 81.6), V(12, 12, 12), V(), Surface::Diffuse},
};

/// Nearest ball along the ray (index, distance), or index -1.
inline int nearest(const V& o, const V& d, double& t) {
  int found = -1;
  t = 1e20;
  for (int i = 8; i >= 0; --i) {
    const double ti = kBalls[i].hit(o, d);
    if (ti != 0.0 && ti < t) {
      t = ti;
      found = i;
    }
  }
  return found;
}

/// The radiance arriving at o from direction d (unit): smallpt's recursive estimator.
inline V radiance(const V& o, const V& d, int depth, unsigned short* rng) {
  double t;
  const int id = nearest(o, d, t);
  if (id < 0) return V();
  const Ball& ball = kBalls[id];
  const V x = o + d * t;
  const V n = (x - ball.centre).unit();
  const V towards = n.dot(d) < 0.0 ? n : n * -1.0;  // the normal on the ray's side
  V colour = ball.colour;
  if (++depth > 5) {
    const double survive = std::max({colour.x, colour.y, colour.z});
    if (erand48(rng) >= survive) return ball.emission;
    colour = colour * (1.0 / survive);
  }
  switch (ball.surface) {
    case Surface::Diffuse: {
      // Cosine-weighted direction about `towards`.
      const double phi = 2.0 * M_PI * erand48(rng);
      const double r2 = erand48(rng);
      const double r = std::sqrt(r2);
      const V w = towards;
      const V u = (std::fabs(w.x) > .1 ? V(0, 1, 0) : V(1, 0, 0)).cross(w).unit();
      const V v = w.cross(u);
      const V next =
          (u * (std::cos(phi) * r) + v * (std::sin(phi) * r) + w * std::sqrt(1 - r2)).unit();
      return ball.emission + colour.times(radiance(x, next, depth, rng));
    }
    case Surface::Mirror:
      return ball.emission + colour.times(radiance(x, d - n * (2 * n.dot(d)), depth, rng));
    case Surface::Glass:
      break;
  }
  const V reflected = d - n * (2 * n.dot(d));
  const bool entering = n.dot(towards) > 0;
  constexpr double kOutside = 1.0, kGlass = 1.5;
  const double eta = entering ? kOutside / kGlass : kGlass / kOutside;
  const double cosIn = d.dot(towards);
  const double cos2Out = 1 - eta * eta * (1 - cosIn * cosIn);
  if (cos2Out < 0)  // total internal reflection
    return ball.emission + colour.times(radiance(x, reflected, depth, rng));
  const V refracted =
      (d * eta - n * ((entering ? 1 : -1) * (cosIn * eta + std::sqrt(cos2Out)))).unit();
  const double r0 =
      (kGlass - kOutside) * (kGlass - kOutside) / ((kGlass + kOutside) * (kGlass + kOutside));
  const double c = 1 - (entering ? -cosIn : refracted.dot(n));
  const double fresnel = r0 + (1 - r0) * c * c * c * c * c;
  const double transmitted = 1 - fresnel;
  V incoming;
  if (depth > 2) {
    const double pickReflect = .25 + .5 * fresnel;
    incoming = erand48(rng) < pickReflect
                   ? radiance(x, reflected, depth, rng) * (fresnel / pickReflect)
                   : radiance(x, refracted, depth, rng) * (transmitted / (1 - pickReflect));
  } else {
    incoming = radiance(x, reflected, depth, rng) * fresnel +
               radiance(x, refracted, depth, rng) * transmitted;
  }
  return ball.emission + colour.times(incoming);
}

/// smallpt's picture at width x height with `spp` samples per pixel on `threads` threads, as
/// linear radiance, top row first (RayLab's order). The same seed gives the same image on
/// any number of threads (one random stream per row).
inline FloatImage render(int width, int height, int spp, int threads, unsigned seed = 0) {
  FloatImage image(width, height);
  const V eye(50, 52, 295.6);
  const V forward = V(0, -0.042612, -1).unit();
  const V right(width * .5135 / height, 0, 0);
  const V up = right.cross(forward).unit() * .5135;
  std::atomic<int> nextRow{0};
  const auto worker = [&] {
    for (int row; (row = nextRow.fetch_add(1)) < height;) {
      const int y = height - 1 - row;  // smallpt's y grows upwards
      unsigned short rng[3] = {0, 0, static_cast<unsigned short>(y * y * y ^ seed)};
      rng[1] = static_cast<unsigned short>(seed >> 16);
      for (int x = 0; x < width; ++x) {
        V sum;
        for (int s = 0; s < spp; ++s) {
          const double fx = (x + erand48(rng)) / width - .5;
          const double fy = (y + erand48(rng)) / height - .5;
          const V d = (right * fx + up * fy + forward).unit();
          sum = sum + radiance(eye + d * 140, d, 0, rng);
        }
        sum = sum * (1.0 / spp);
        image.pixels[std::size_t(row) * width + x] =
            glm::vec3(float(sum.x), float(sum.y), float(sum.z));
      }
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return image;
}

}  // namespace raylab::yardstick
