#pragma once

/// \file RayKind.h
/// Why a ray was spawned: the one word the materials (a BSDF sample's lobe), the tracer and
/// the ray tree share. Its own header, so that the materials need not include the ray tree.

namespace raylab {

/// Why a ray was spawned (the colour-by-kind legend of the ray-tree view).
enum class RayKind { Camera, Reflection, Refraction, Diffuse, Glossy, Shadow };
constexpr int kRayKindCount = 6;
const char* toString(RayKind kind);

}  // namespace raylab
