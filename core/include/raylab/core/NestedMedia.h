#pragma once

#include "raylab/core/Types.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

/// \file NestedMedia.h
/// Overlapping glass volumes by priority (C. M. Schmidt and B. Budge, "Simple nested
/// dielectrics in ray traced images", JGT 7(2), 2002). A material with `priority` >= 1 makes
/// its (closed) object a volume of index `ior`. Each ray carries the volumes it is inside,
/// in the order it entered them; the medium filling a point is the volume of highest
/// priority among them (ties: the one entered first). A surface where that medium does not
/// change is a false interface: the ray goes straight on, only the list changes. Elsewhere
/// the surface refracts and reflects with the index pair (medium before, medium after).
/// Priority 0 keeps the per-interface rule (each surface names ior and ior_outside).
///
/// Worked example (TestNestedMedia): a glass ball G (n 1.5, priority 2) overlapping a water
/// ball W (n 1.33, priority 1), a ray entering G first: air -> G is 1 -> 1.5; W's surface
/// inside G is false (G keeps the overlap); leaving G into W is 1.5 -> 1.33; leaving W is
/// 1.33 -> 1.

namespace raylab {

struct Scene;

/// The volumes a ray is inside, as object indices (Scene::objects) in the order it entered
/// them; unused places hold -1. At most kCapacity: a fifth volume entered is not tracked.
struct MediumStack {
  static constexpr int kCapacity = 4;
  std::array<std::int16_t, kCapacity> objects{{-1, -1, -1, -1}};

  /// Number of volumes held.
  int size() const;
  bool empty() const { return objects[0] < 0; }
  bool contains(int object) const;
  /// This list with `object` added at the end (unchanged when full or already there).
  MediumStack with(int object) const;
  /// This list without `object`.
  MediumStack without(int object) const;
  bool operator==(const MediumStack& o) const { return objects == o.objects; }
  bool operator!=(const MediumStack& o) const { return !(*this == o); }
};

/// What a ray meets at the surface of a nested volume.
struct MediumCrossing {
  bool real = true;             ///< False interface: the medium does not change, no refraction.
  double etaIncident = 1.0;     ///< Index of the medium the ray arrives in.
  double etaTransmitted = 1.0;  ///< Index of the medium beyond the surface.
  MediumStack after;            ///< The volumes the ray is inside once through.
};

/// The scene's nested volumes: each object's priority and index, looked up per crossing.
class NestedMedia {
 public:
  NestedMedia() = default;
  explicit NestedMedia(const Scene& scene);

  /// Whether any object is a nested volume (priority >= 1); when not, tracers skip all this.
  bool active() const { return m_active; }
  /// Whether object `object` is a nested volume.
  bool isVolume(int object) const;
  /// The volume that fills a point inside all of `stack`'s: highest priority, ties to the one
  /// entered first; -1 when the stack is empty.
  int filling(const MediumStack& stack) const;
  /// Index of refraction inside all of `stack`'s volumes; `outside` when it is empty.
  double ior(const MediumStack& stack, double outside) const;
  /// Crossing the surface of volume `object`, into it when `entering`, from inside `before`.
  MediumCrossing cross(const MediumStack& before, int object, bool entering) const;
  /// The volumes that contain point `p` (a camera inside water), in object order.
  MediumStack volumesAt(const Scene& scene, const Point3& p) const;

 private:
  std::vector<int> m_priority;    ///< Per object; 0 for objects that are not volumes.
  std::vector<double> m_ior;      ///< Per object: its material's ior.
  std::vector<double> m_outside;  ///< Per object: its material's ior_outside.
  bool m_active = false;
};

}  // namespace raylab
