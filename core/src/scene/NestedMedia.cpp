// Nested dielectrics by priority (NestedMedia.h; Schmidt and Budge 2002).
#include "raylab/core/NestedMedia.h"

#include "raylab/core/Scene.h"

#include <cstdio>

namespace raylab {

int MediumStack::size() const {
  int n = 0;
  while (n < kCapacity && objects[std::size_t(n)] >= 0) ++n;
  return n;
}

bool MediumStack::contains(int object) const {
  for (std::int16_t o : objects)
    if (o >= 0 && o == object) return true;
  return false;
}

MediumStack MediumStack::with(int object) const {
  MediumStack out = *this;
  const int n = size();
  if (n < kCapacity && !contains(object) && object >= 0 && object <= INT16_MAX)
    out.objects[std::size_t(n)] = std::int16_t(object);
  return out;
}

MediumStack MediumStack::without(int object) const {
  MediumStack out;
  int n = 0;
  for (std::int16_t o : objects)
    if (o >= 0 && o != object) out.objects[std::size_t(n++)] = o;
  return out;
}

NestedMedia::NestedMedia(const Scene& scene) {
  const std::size_t count = scene.objects.size();
  m_priority.assign(count, 0);
  m_ior.assign(count, 1.0);
  m_outside.assign(count, 1.0);
  for (std::size_t i = 0; i < count && i <= std::size_t(INT16_MAX); ++i) {
    const int material = scene.objects[i].material;
    if (material < 0 || material >= int(scene.materials.size())) continue;
    const Material& m = scene.materials[std::size_t(material)];
    m_priority[i] = std::max(0, m.priority);
    m_ior[i] = m.ior;
    m_outside[i] = m.iorOutside;
    if (m.priority > 0) m_active = true;
  }
}

bool NestedMedia::isVolume(int object) const {
  return object >= 0 && object < int(m_priority.size()) && m_priority[std::size_t(object)] > 0;
}

int NestedMedia::filling(const MediumStack& stack) const {
  // The highest priority wins; among equals the volume entered first (strictly greater).
  int best = -1;
  for (std::int16_t o : stack.objects) {
    if (o < 0 || !isVolume(o)) continue;
    if (best < 0 || m_priority[std::size_t(o)] > m_priority[std::size_t(best)]) best = o;
  }
  return best;
}

double NestedMedia::ior(const MediumStack& stack, double outside) const {
  const int f = filling(stack);
  return f < 0 ? outside : m_ior[std::size_t(f)];
}

MediumCrossing NestedMedia::cross(const MediumStack& before, int object, bool entering) const {
  MediumCrossing c;
  if (!isVolume(object)) return c;
  // Outside every volume the medium is the one this surface names outside itself.
  const double outside = m_outside[std::size_t(object)];
  const int fillingBefore = filling(before);
  if (entering) {
    c.after = before.with(object);
    // A false interface when the volume entered does not take over the point (a volume of
    // higher or equal priority fills it already), or when it cannot be tracked.
    c.real = c.after.contains(object) && !before.contains(object) &&
             (fillingBefore < 0 ||
              m_priority[std::size_t(object)] > m_priority[std::size_t(fillingBefore)]);
  } else {
    c.after = before.without(object);
    // Leaving a volume the ray was not known to be in (it started inside one unawares):
    // the surface separates this volume from what the list says is around it.
    c.real = !before.contains(object) || fillingBefore == object;
    if (!before.contains(object)) {
      c.etaIncident = m_ior[std::size_t(object)];
      c.etaTransmitted = ior(before, outside);
      return c;
    }
  }
  c.etaIncident = ior(before, outside);
  c.etaTransmitted = ior(c.after, outside);
  return c;
}

MediumStack NestedMedia::volumesAt(const Scene& scene, const Point3& p) const {
  MediumStack stack;
  for (std::size_t i = 0; i < scene.objects.size() && i < m_priority.size(); ++i)
    if (m_priority[i] > 0 && scene.objects[i].shape && scene.objects[i].shape->inside(p))
      stack = stack.with(int(i));
  return stack;
}

}  // namespace raylab
