#!/usr/bin/env python3
"""Reads gltf_levels_example's refined meshes back by hand (the glTF with json/base64/struct: no glTF
library) and checks that each glTF has the triangles of the mesh in memory corner for corner, as the
example took them from the core (its .corners file, no writer of ours in between): position, exact
texture coordinate (v flipped to 1 - v) and vertex colour, as 32-bit floats, with one glTF vertex per
distinct (vertex, UV) pair of the mesh (vertices split along UV seams).

usage: gltf_levels_check.py PATH/TO/gltf_levels_example
"""
import collections
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_export_check import expect, f32, load_glb, load_gltf, read_accessor  # noqa: E402


def canonical(triangle):
    """The triangle rotated to start at its smallest corner (keeps its orientation)."""
    first = min(range(3), key=lambda i: triangle[i])
    return tuple(triangle[(first + i) % 3] for i in range(3))


def mesh_triangles(path):
    """The mesh's triangles as corners (position, (u, 1 - v), colour), its number of vertices and of
    distinct (vertex, UV) pairs."""
    triangles, vertices, pairs, corners = [], set(), set(), []
    with open(path, encoding="utf-8") as f:
        for line in f:
            words = line.split()
            assert len(words) == 9, line
            slot, numbers = int(words[0]), [float(x) for x in words[1:]]
            u, v = numbers[3], numbers[4]
            vertices.add(slot)
            pairs.add((slot, u, v))
            corners.append((tuple(f32(x) for x in numbers[0:3]), (f32(u), f32(1 - v)), tuple(f32(x) for x in numbers[5:8])))
            if len(corners) == 3:
                triangles.append(canonical(corners))
                corners = []
    assert not corners, path
    return collections.Counter(triangles), len(vertices), len(pairs)


def gltf_triangles(doc, buffer, coloured):
    """The glTF's triangles as mesh_triangles gives them, and its number of vertices."""
    primitive = doc["meshes"][0]["primitives"]
    attributes = primitive[0]["attributes"]
    expect("attributes", sorted(attributes), ["COLOR_0"] * coloured + ["NORMAL", "POSITION", "TEXCOORD_0"])
    positions = read_accessor(doc, buffer, attributes["POSITION"])
    texcoords = read_accessor(doc, buffer, attributes["TEXCOORD_0"])
    colours = [None] * len(positions)
    if coloured:
        expect("COLOR_0 type", doc["accessors"][attributes["COLOR_0"]]["type"], "VEC3")
        colours = read_accessor(doc, buffer, attributes["COLOR_0"])
    triangles = []
    for p in primitive:
        indices = read_accessor(doc, buffer, p["indices"])
        for i in range(0, len(indices), 3):
            triangles.append(canonical([(positions[k], texcoords[k], colours[k]) for k in indices[i:i + 3]]))
    return collections.Counter(triangles), len(positions)


def same_triangles(name, got, wanted):
    if got != wanted:
        raise AssertionError("%s: %d triangles differ from the mesh's (e.g. %r)" %
                             (name, sum((got - wanted).values()), next(iter(got - wanted), None)))


def main():
    with tempfile.TemporaryDirectory() as folder:
        subprocess.run([sys.argv[1], folder], check=True)
        for stem in ("adaptive", "limit"):
            wanted, vertices, pairs = mesh_triangles(os.path.join(folder, stem + ".corners"))
            # Refined past level 0 (the grid has 20 vertices and 24 triangles), with seams to split.
            assert vertices > 100 and sum(wanted.values()) > 24 * 4, (stem, vertices)
            assert pairs > vertices, (stem, pairs, vertices)
            for name, load in ((stem + ".gltf", load_gltf), (stem + ".glb", load_glb)):
                got, gltf_vertices = gltf_triangles(*load(os.path.join(folder, name)), True)
                expect(name + " vertices (one per (v, vt) pair)", gltf_vertices, pairs)
                same_triangles(name, got, wanted)
                print(name, "ok:", sum(got.values()), "triangles,", gltf_vertices, "vertices")


if __name__ == "__main__":
    main()
