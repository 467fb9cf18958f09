#pragma once

#include "raylab/core/Types.h"

#include <string>

/// \file InspectorFormat.h
/// How the ray inspector writes numbers: one format for the inspection, the oracle check
/// and their words (core/src/words/InspectorWords.cpp). Private to core.

namespace raylab::inspect {

/// "(x, y, z)" with 4 significant digits: readable on a projector, precise enough to
/// recognise a scene's numbers (the oracle block prints t in full).
std::string vec(const Vec3& v);
/// `x` with `digits` significant digits.
std::string number(double x, int digits = 6);

}  // namespace raylab::inspect
