#pragma once

#include "raylab/core/TriangleMesh.h"

#include <string>

/// \file MeshCache.h
/// The meshes read last, kept while their files are unchanged: a lesson's steps with scene
/// changes read their scene again, one step after another, and each read reloaded its
/// meshes (40 steps over a 200,000-triangle mesh took 32 s, issue 38). Private to core.

namespace raylab::meshcache {

/**
 * \brief The mesh of file `path` as MeshIO::load(path) reads it, from the cache when the
 * file has the size, modification time and inode it had when it was read. At most four
 * meshes and 4,000,000 triangles are kept (the oldest dropped first); thread-safe. Throws
 * MeshIO::ReadError as MeshIO::load does (errors are not cached).
 */
TriangleMesh load(const std::string& path);

}  // namespace raylab::meshcache
