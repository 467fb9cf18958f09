#pragma once

#include "raylab/core/Exception.h"
#include "raylab/core/TriangleMesh.h"

#include <string>
#include <vector>

namespace raylab {

/**
 * \brief Reads triangle meshes from OBJ, PLY, OFF and STL files (ASCII and binary PLY and
 * STL) with CGAL's polygon-soup readers, then repairs, orients and triangulates them.
 *
 * The pipeline (CGAL Polygon Mesh Processing, "Polygon soups"):
 *  1. `CGAL::IO::read_polygon_soup` reads points and polygons (format from the extension,
 *     case-insensitive);
 *  2. `repair_polygon_soup` merges duplicate points, drops degenerate and duplicate
 *     polygons and unused points;
 *  3. `orient_polygon_soup` gives all polygons a consistent orientation;
 *  4. polygons with more than three vertices are triangulated (CGAL's constrained
 *     triangulation of each face, so non-convex faces work too);
 *  5. a closed mesh (every edge in exactly two triangles) with a negative signed volume
 *     is flipped, so its normals point outward as TriangleMesh::inside expects;
 *  6. vertex normals, when the file gives them (OBJ: `vn` lines and faces `v//vn` or
 *     `v/vt/vn`; PLY: the vertex properties `nx ny nz`), become the mesh's corner normals
 *     (smooth shading, TriangleMesh::setNormals): each final triangle takes them from the
 *     file's face it came from, matched by position, so repair, orientation and
 *     triangulation keep them; an OBJ face without normal indices shades flat.
 * Positions and normals are taken as world space, unchanged.
 *
 * Every failure throws ReadError; its message starts with the path (and ":line" where the
 * line is known) and says what is wrong:
 *  - the file does not exist or cannot be opened;
 *  - the extension is none of .obj .off .ply .stl;
 *  - the file has no faces (empty file, only vertices, or every face degenerate);
 *  - the file cannot be parsed (CGAL's own report is included; for OBJ and OFF the first
 *    offending line is located), or a face refers to a vertex that does not exist;
 *  - a normal is malformed, zero or not finite, an OBJ face's normal index refers to no
 *    `vn` (with the line), or a PLY file has only some of nx, ny, nz;
 *  - the surface is non-manifold beyond repair (unless Options::allowNonManifold): after
 *    repair, `orient_polygon_soup` could only orient the soup by duplicating vertices,
 *    i.e. some edge is shared by more than two faces, faces meet at a vertex without
 *    sharing an edge around it, or the surface is not orientable (a Moebius strip); or
 *    the soup is still not a valid polygon mesh (`is_polygon_soup_a_polygon_mesh`).
 */
class MeshIO {
 public:
  /// A mesh file that cannot be read; what() names the file and the problem.
  class ReadError : public Exception {
   public:
    using Exception::Exception;
  };

  /// Loading options.
  struct Options {
    bool allowNonManifold = false;  ///< Keep non-manifold input (vertices duplicated by
                                    ///< orientation) instead of throwing.
  };

  /// Loads, repairs, orients and triangulates the mesh in `path`.
  static TriangleMesh load(const std::string& path, const Options& options);
  /// Same with default options.
  static TriangleMesh load(const std::string& path) { return load(path, Options{}); }

  /// The extensions load() accepts, lower case with the dot: ".obj", ".off", ".ply", ".stl".
  static std::vector<std::string> supportedExtensions();
};

}  // namespace raylab
