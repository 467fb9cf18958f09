#pragma once

#include <string>

/// \file FilePaths.h
/// File-name helpers shared by the loaders, the writers and the command line.

namespace raylab {

/// The extension of `path`'s file name in lower case, with its dot (".png"), or "" when
/// the file name has none. A dot in a folder name does not count.
std::string lowerExtension(const std::string& path);

/// `path` with its extension (see lowerExtension) replaced by `extension` (".json"), or
/// with `extension` appended when it has none.
std::string replaceExtension(const std::string& path, const std::string& extension);

}  // namespace raylab
