#pragma once

#include "raylab/core/Material.h"
#include "raylab/core/Types.h"

#include <sstream>
#include <string>

/// \file InspectorFormat.h
/// How the ray inspector writes numbers, materials and its "label  value" lines: one
/// format for the inspection and the oracle check. Private to core/src/inspect/.

namespace raylab::inspect {

/// "(x, y, z)" with 4 significant digits: readable on a projector, precise enough to
/// recognise a scene's numbers (the oracle block prints t in full).
std::string vec(const Vec3& v);
/// `x` with `digits` significant digits.
std::string number(double x, int digits = 6);
/// The parameters a material's scattering model reads, e.g. "albedo (0.7, 0.1, 0.1)".
std::string materialParameters(const Material& m);
/// One "label  value" line of the inspector text, labels padded to one column.
void line(std::ostringstream& out, const char* label, const std::string& value);

}  // namespace raylab::inspect
