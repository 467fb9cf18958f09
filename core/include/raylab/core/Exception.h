#pragma once

#include <stdexcept>
#include <string>

namespace raylab {

/// Base of every error RayLab reports about its input (scene files, meshes, the command
/// line, the window). Each thrower nests its own subtype (e.g. `MeshIO::ReadError`);
/// `what()` names the file, the place and the problem.
class Exception : public std::runtime_error {
 public:
  explicit Exception(const std::string& message) : std::runtime_error(message) {}
};

/// Thrown by lesson code that is left for the student. Never return black instead.
class NotImplemented : public Exception {
 public:
  explicit NotImplemented(const std::string& what) : Exception("not implemented: " + what) {}
};

}  // namespace raylab
