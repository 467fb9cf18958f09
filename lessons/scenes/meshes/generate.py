#!/usr/bin/env python3
"""Writes the meshes of the lesson scenes into this folder.

Run from anywhere: python3 lessons/scenes/meshes/generate.py. The files are committed; this
script documents how they were made and regenerates them byte for byte.

  icosphere-80.obj     icosahedron subdivided once, unit radius: 42 vertices, 80 triangles
                       (lesson 2: a closed, watertight mesh whose triangles share edges)
  icosphere-1280.obj   subdivided three times: 642 vertices, 1280 triangles
                       (lesson 8: enough triangles for a bounding volume hierarchy to matter)
  icosphere-80-normals.obj  icosphere-80.obj with a vertex normal per vertex (vn, the exact
                       sphere normal) and faces v//vn: smooth shading from the file
                       (smooth-shading.json)

Both are closed and counter-clockwise seen from outside (normals point outward); every
edge is shared by exactly two triangles through the same two vertex indices.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


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


def obj(vertices, faces, title):
    lines = ["# RayLab lesson mesh: " + title]
    lines += ["v %.9g %.9g %.9g" % p for p in vertices]
    lines += ["f %d %d %d" % tuple(i + 1 for i in face) for face in faces]
    return "\n".join(lines) + "\n"


def obj_with_normals(vertices, faces, title):
    # On a unit sphere the normal at a vertex is the vertex itself.
    lines = ["# RayLab lesson mesh: " + title]
    lines += ["v %.9g %.9g %.9g" % p for p in vertices]
    lines += ["vn %.9g %.9g %.9g" % p for p in vertices]
    lines += ["f %d//%d %d//%d %d//%d" % tuple(i + 1 for i in face for _ in (0, 1))
              for face in faces]
    return "\n".join(lines) + "\n"


def main():
    for subdivisions in (1, 3):
        v, f = icosphere(subdivisions)
        name = "icosphere-%d.obj" % len(f)
        with open(os.path.join(HERE, name), "w") as out:
            out.write(obj(v, f, "unit icosphere, %d triangles" % len(f)))
    v, f = icosphere(1)
    with open(os.path.join(HERE, "icosphere-80-normals.obj"), "w") as out:
        out.write(obj_with_normals(v, f, "unit icosphere, 80 triangles, vertex normals"))


if __name__ == "__main__":
    main()
