#pragma once

#include "commands/Subcommand.h"

namespace CLI {
class App;
}

namespace raylab::app {

/// `raylab web --out DIR [--lang en|zh|both] [--student] [--zip] [LESSON...]`: the lessons as
/// a static site that opens from file:// (doc/web-data.md).
Subcommand addWebCommand(CLI::App& cli);

}  // namespace raylab::app
