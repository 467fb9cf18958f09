#include "raylab/core/FilePaths.h"

#include <algorithm>
#include <cctype>

namespace raylab {

std::string lowerExtension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string replaceExtension(const std::string& path, const std::string& extension) {
  return path.substr(0, path.size() - lowerExtension(path).size()) + extension;
}

}  // namespace raylab
