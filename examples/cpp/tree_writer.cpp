// A student's tracer writing its ray tree in RayLab's JSON (doc/ray-tree-json.md): the
// centre pixel (2, 2) of examples/cpp/one-sphere.json, ray casting, no lights.
// Build: c++ -std=c++17 tree_writer.cpp -o tree_writer; then
//   ./tree_writer > mine.json && raylab diff mine.json --scene one-sphere.json
// `./tree_writer far` takes the far root of the quadratic: the student bug raylab diff names.
#include <cmath>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
  const bool far = argc > 1 && std::strcmp(argv[1], "far") == 0;
  const double o[3] = {0, 0, 0}, d[3] = {0, 0, -1};  // the camera ray through the centre
  const double c[3] = {0, 0, -3}, r = 1;             // the sphere "ball" (object 0)
  const double oc[3] = {o[0] - c[0], o[1] - c[1], o[2] - c[2]};
  const double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
  const double disc = b * b - (oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - r * r);
  const double t = far ? -b + std::sqrt(disc) : -b - std::sqrt(disc);
  const double p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
  const double n[3] = {(p[0] - c[0]) / r, (p[1] - c[1]) / r, (p[2] - c[2]) / r};
  std::printf(
      "{\"raylab_ray_tree\": 1, \"scene\": \"one sphere\", \"algorithm\": \"raycast\",\n"
      " \"seed\": 1, \"pixel\": [2, 2], \"sample\": 0, \"segments\": [\n"
      "  {\"id\": 0, \"parent\": -1, \"first_child\": -1, \"child_count\": 0,\n"
      "   \"kind\": \"camera\", \"depth\": 0, \"time\": 0, \"hit\": true, \"object\": 0,\n");
  std::printf("   \"origin\": [%.17g, %.17g, %.17g], \"direction\": [%.17g, %.17g, %.17g],\n", o[0],
              o[1], o[2], d[0], d[1], d[2]);
  std::printf("   \"end_point\": [%.17g, %.17g, %.17g], \"normal\": [%.17g, %.17g, %.17g],\n", p[0],
              p[1], p[2], n[0], n[1], n[2]);
  std::printf(
      "   \"light_point\": [0, 0, 0], \"weight\": [1, 1, 1], \"pdf\": 0,\n"
      "   \"throughput\": [1, 1, 1], \"emitted\": [0, 0, 0], \"radiance\": [0, 0, 0],\n"
      "   \"end_reason\": \"absorbed\"}]}\n");
  return 0;
}
