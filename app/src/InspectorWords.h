#pragma once

#include "raylab/core/RayTree.h"

#include <QString>

#include <string>
#include <vector>

namespace raylab::app {

/**
 * \brief The ray inspector's text (core RayInspection::rayText + oracleText) in the
 * window's language: in English exactly core's; in Chinese every field name, the words of
 * the values (hit, miss, material kinds, parameters) and the ending translated, numbers,
 * vectors and names kept. `id` is the ray of `tree` the text is about.
 */
QString inspectorText(const std::string& coreText, const RayTree& tree, int id,
                      const std::vector<std::string>& objectNames,
                      const std::vector<std::string>& pointLightNames = {});

}  // namespace raylab::app
