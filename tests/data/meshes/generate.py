#!/usr/bin/env python3
"""Writes the small test meshes of tests/core/TestMeshIO.cpp into this folder.

Run from anywhere: python3 tests/data/meshes/generate.py. The files are committed; this
script documents how they were made and regenerates them byte for byte.

Good meshes (all closed, counter-clockwise seen from outside):
  cube.obj               unit cube [0,1]^3 as 6 quads (tests triangulation) -> 12 triangles
  tetrahedron.off        ASCII OFF, 4 vertices, 4 triangles
  icosphere.ply          ASCII PLY, icosphere (1 subdivision, radius 1): 42 vertices, 80 triangles
  icosphere_binary.ply   the same, binary little endian
  cube_ascii.stl         ASCII STL triangle soup of the unit cube (12 facets)
  cube_binary.stl        the same, binary
Broken meshes:
  empty.obj              0 bytes
  vertices_only.obj      vertices but no faces
  garbage.obj            line 6 is not OBJ ("hello world")
  bad_index.off          face on line 8 uses vertex 7 of 4
  truncated.stl          binary STL announcing 12 facets but holding 5
  nonmanifold.obj        three triangles sharing one edge
  mesh.xyz               a valid OBJ body under an unknown extension
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

CUBE_V = [(x, y, z) for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)]
# index = 4x + 2y + z; quads counter-clockwise seen from outside
CUBE_QUADS = [
    (0, 1, 3, 2),  # x = 0
    (4, 6, 7, 5),  # x = 1
    (0, 4, 5, 1),  # y = 0
    (2, 3, 7, 6),  # y = 1
    (0, 2, 6, 4),  # z = 0
    (1, 5, 7, 3),  # z = 1
]
CUBE_TRIS = [t for q in CUBE_QUADS for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]

TET_V = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
TET_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def icosphere(subdivisions):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
         (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    norm = lambda p: tuple(c / math.sqrt(sum(d * d for d in p)) for c in p)
    v = [norm(p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        cache = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                v.append(norm(tuple((p + q) / 2 for p, q in zip(v[a], v[b]))))
                cache[key] = len(v) - 1
            return cache[key]

        finer = []
        for a, b, c in f:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = finer
    return v, f


def write(name, data, mode="w"):
    with open(os.path.join(HERE, name), mode + ("b" if isinstance(data, bytes) else "")) as out:
        out.write(data)


def fmt(x):
    return repr(float(x))


def obj(vertices, faces):
    lines = ["# RayLab test mesh"] + ["v %s %s %s" % tuple(map(fmt, p)) for p in vertices]
    lines += ["f " + " ".join(str(i + 1) for i in face) for face in faces]
    return "\n".join(lines) + "\n"


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    length = math.sqrt(sum(x * x for x in n))
    return tuple(x / length for x in n)


def stl_binary(vertices, faces, announced=None, keep=None):
    data = b"RayLab binary STL test mesh".ljust(80, b" ")
    data += struct.pack("<I", len(faces) if announced is None else announced)
    for face in faces[: keep if keep is not None else len(faces)]:
        p = [vertices[i] for i in face]
        data += struct.pack("<3f", *normal(*p))
        for q in p:
            data += struct.pack("<3f", *q)
        data += struct.pack("<H", 0)
    return data


def main():
    write("cube.obj", obj(CUBE_V, CUBE_QUADS))
    off = ["OFF", "# RayLab test mesh", "%d %d 0" % (len(TET_V), len(TET_F))]
    off += ["%s %s %s" % tuple(map(fmt, p)) for p in TET_V]
    off += ["3 %d %d %d" % f for f in TET_F]
    write("tetrahedron.off", "\n".join(off) + "\n")

    v, f = icosphere(1)
    header = ["ply", "format %s 1.0", "comment RayLab test mesh",
              "element vertex %d" % len(v), "property double x", "property double y",
              "property double z", "element face %d" % len(f),
              "property list uchar int vertex_indices", "end_header"]
    ascii_body = ["%s %s %s" % tuple(map(fmt, p)) for p in v] + ["3 %d %d %d" % t for t in f]
    write("icosphere.ply", "\n".join(header).replace("%s", "ascii") + "\n" +
          "\n".join(ascii_body) + "\n")
    binary = ("\n".join(header).replace("%s", "binary_little_endian") + "\n").encode()
    for p in v:
        binary += struct.pack("<3d", *p)
    for t in f:
        binary += struct.pack("<B3i", 3, *t)
    write("icosphere_binary.ply", binary)

    stl = ["solid cube"]
    for face in CUBE_TRIS:
        p = [CUBE_V[i] for i in face]
        stl.append("  facet normal %s %s %s" % tuple(map(fmt, normal(*p))))
        stl.append("    outer loop")
        stl += ["      vertex %s %s %s" % tuple(map(fmt, q)) for q in p]
        stl.append("    endloop")
        stl.append("  endfacet")
    stl.append("endsolid cube")
    write("cube_ascii.stl", "\n".join(stl) + "\n")
    write("cube_binary.stl", stl_binary(CUBE_V, CUBE_TRIS))

    write("empty.obj", "")
    write("vertices_only.obj", obj(TET_V, []))
    garbage = obj(TET_V, TET_F).splitlines()
    garbage.insert(5, "hello world")
    write("garbage.obj", "\n".join(garbage) + "\n")
    bad = ["OFF", "4 4 0"] + ["%s %s %s" % tuple(map(fmt, p)) for p in TET_V]
    bad += ["3 0 2 1", "3 0 1 7", "3 0 3 2", "3 1 2 3"]
    write("bad_index.off", "\n".join(bad) + "\n")
    write("truncated.stl", stl_binary(CUBE_V, CUBE_TRIS, announced=12, keep=5))
    # Three triangles hinged on the edge (0,0,0)-(0,0,1): an edge with three faces.
    write("nonmanifold.obj", obj([(0, 0, 0), (0, 0, 1), (1, 0, 0), (0, 1, 0), (-1, -1, 0)],
                                 [(0, 1, 2), (1, 0, 3), (0, 1, 4)]))
    write("mesh.xyz", obj(TET_V, TET_F))


if __name__ == "__main__":
    main()
