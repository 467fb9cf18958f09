#pragma once

#include "commands/Subcommand.h"

#include <CLI/CLI.hpp>

namespace raylab::app {

/**
 * \brief `raylab diff THEIRS.json [--scene S] [--pixel X Y] [--out PNG]`: reads a ray tree
 * written by a student's own tracer in RayLab's ray tree JSON (doc/ray-tree-json.md), traces
 * the same pixel sample with the engine (the tree's algorithm and seed unless --algorithm /
 * --seed say otherwise), and names the first ray that differs (which ray, which field, both
 * values) in English and Chinese. With --out, draws both trees in the 3D view: the engine's
 * solid, theirs dashed: green where they agree, the differing ray red, the rays after it orange.
 * Exit 0 when the trees agree within kTreeDiffTolerance, 1 when they differ or the file is not a
 * ray tree (file, JSON place and problem), 2 on a usage error.
 */
Subcommand addDiffCommand(CLI::App& cli);

}  // namespace raylab::app
