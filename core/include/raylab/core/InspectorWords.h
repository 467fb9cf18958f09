#pragma once

#include "raylab/core/Language.h"
#include "raylab/core/Material.h"
#include "raylab/core/RayInspector.h"

#include <string>
#include <vector>

namespace raylab {

/**
 * \brief The ray inspector's words, from the phrase table (Phrases.h): the facts of a
 * RayInspection as rows of (field, value), and those rows as the text the window's
 * inspector, `raylab trace --inspect` and the handouts show, in English or Chinese.
 */

/// One line of the inspector: a field and its value, both in words of one language.
struct InspectorRow {
  std::string field;  ///< "hit point", "交点".
  std::string value;  ///< "(0, 1, 2)", "'glass ball' (dielectric)".
  bool sub = false;   ///< An indented detail of the row above (the exact t's bounds).
};

/// The rows of the ray itself: geometry, material, what it carried, why it ended.
std::vector<InspectorRow> inspectorRows(const RayInspection& inspection, Language language);
/// The rows of the exact oracle's check, then its notes (as rows with an empty field).
std::vector<InspectorRow> oracleRows(const OracleCheck& check, Language language);

/// The parameters a material's scattering model reads: "albedo (0.7, 0.1, 0.1)".
std::string materialParameters(const Material& material, Language language);

/// "Ray #3: reflection ray, depth 2, child of #1", then one line per row: the ray's lines.
std::string rayText(const RayInspection& inspection, Language language);
/// The exact-oracle block, headed "Exact oracle (CGAL) on 'ball':" (says so when there is
/// no check, or no hit to check).
std::string oracleText(const RayInspection& inspection, Language language);
/// rayText then oracleText: what `raylab trace --inspect` prints.
std::string inspectorText(const RayInspection& inspection, Language language);

/// What the window's inspector says first, one line each: "reflection ray, depth 2", where
/// it went, what it carried (its share of `pixelEnergy`, the camera ray's energy; none when
/// that is 0) and why it stopped; the last line ends with a newline.
std::string inspectionSummary(const RayInspection& inspection, double pixelEnergy,
                              Language language);

/// "t = 7.13  enters 'sphere'" lines, one per crossing, with the objects' names of `scene`.
std::string crossingsText(const Scene& scene, const std::vector<SceneCrossing>& crossings,
                          Language language);

}  // namespace raylab
