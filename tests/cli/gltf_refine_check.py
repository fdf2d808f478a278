#!/usr/bin/env python3
"""`rgbsub refine -o OUT.glb|OUT.gltf` read back by hand (the json/base64/struct readers of
tests/io/gltf_export_check.py, no glTF library), against what the input says:

- a flat 4x4 grid, two materials by column half (Kd from its .mtl), refined uniformly to level 2: 32 * 16
  triangles, 256 per material; a triangle's material is the one of the cell its centroid lies in (Loop
  keeps the flat grid's lines straight away from its corners); every normal is +z; the positions are
  those of the OBJ refine writes for the same request (float32);
- the same grid at level 0 with texture coordinates: each glTF vertex is an input corner (position, u,
  1 - v); refined, each glTF triangle has the corners (position, exact texture coordinate) of the OBJ
  refine writes for the same request, and rgbsub warns of nothing.

usage: gltf_refine_check.py PATH/TO/rgbsub
"""
import collections
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "io"))
from gltf_export_check import expect, f32, load_glb, load_gltf, read_accessor  # noqa: E402
from gltf_levels_check import canonical, gltf_triangles, same_triangles  # noqa: E402

CELLS = 4


def obj_triangles(path):
    """The OBJ's triangles as corners (position, (u, 1 - v), colour or None), its number of v lines
    and of distinct (v, vt) pairs."""
    positions, colours, texcoords, triangles, pairs = [], [], [], [], set()
    with open(path, encoding="utf-8") as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                assert len(words) in (4, 7), line
                positions.append(tuple(f32(float(x)) for x in words[1:4]))
                colours.append(tuple(f32(float(x)) for x in words[4:7]) if len(words) == 7 else None)
            elif words[0] == "vt":
                u, v = float(words[1]), float(words[2])
                texcoords.append((f32(u), f32(1 - v)))
            elif words[0] == "f":
                assert len(words) == 4, line
                corners = []
                for corner in words[1:]:
                    v, t = (int(i) - 1 for i in corner.split("/")[:2])
                    pairs.add((v, t))
                    corners.append((positions[v], texcoords[t], colours[v]))
                triangles.append(canonical(corners))
    return collections.Counter(triangles), len(positions), len(pairs)


def grid_obj(with_uvs):
    lines = ["mtllib grid.mtl"]
    for y in range(CELLS + 1):
        for x in range(CELLS + 1):
            lines.append("v %d %d 0" % (x, y))
            if with_uvs:
                lines.append("vt %g %g" % (x / CELLS, y / CELLS))
    for y in range(CELLS):
        for x in range(CELLS):
            a = y * (CELLS + 1) + x + 1
            b, c, d = a + 1, a + CELLS + 2, a + CELLS + 1
            lines.append("usemtl " + ("left" if x < CELLS // 2 else "right"))
            for t in ((a, b, c), (a, c, d)):
                lines.append("f " + " ".join("%d/%d" % (i, i) if with_uvs else str(i) for i in t))
    return "\n".join(lines) + "\n"


MTL = "newmtl left\nKd 1 0 0\nnewmtl right\nKd 0 0.5 1\n"


def obj_positions(path):
    with open(path, encoding="utf-8") as f:
        return [tuple(f32(float(x)) for x in line.split()[1:4]) for line in f if line.startswith("v ")]


def run(rgbsub, *args):
    return subprocess.run([rgbsub, *args], check=True, capture_output=True, text=True)


def check_refined(doc, buffer, obj_vertices):
    primitives = doc["meshes"][0]["primitives"]
    attributes = primitives[0]["attributes"]
    expect("no texture coordinates", "TEXCOORD_0" in attributes, False)
    positions = read_accessor(doc, buffer, attributes["POSITION"])
    expect("positions (those of the OBJ export)", sorted(positions), sorted(obj_vertices))
    normals = read_accessor(doc, buffer, attributes["NORMAL"])
    expect("normals", set(normals), {(0.0, 0.0, 1.0)})
    names = [m["name"] for m in doc["materials"]]
    expect("materials", names, ["left", "right"])
    expect("left colour", doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"], [1.0, 0.0, 0.0, 1.0])
    expect("right colour", doc["materials"][1]["pbrMetallicRoughness"]["baseColorFactor"], [0.0, 0.5, 1.0, 1.0])
    total = 0
    for p in primitives:
        indices = read_accessor(doc, buffer, p["indices"])
        expect("triangles of " + names[p["material"]], len(indices) // 3, 2 * CELLS * CELLS // 2 * 16)
        for t in range(0, len(indices), 3):
            x = sum(positions[i][0] for i in indices[t:t + 3]) / 3
            expect("side of a triangle", "left" if x < CELLS / 2 else "right", names[p["material"]])
        total += len(indices) // 3
    expect("triangles", total, 2 * CELLS * CELLS * 16)


def check_level0(doc, buffer):
    attributes = doc["meshes"][0]["primitives"][0]["attributes"]
    positions = read_accessor(doc, buffer, attributes["POSITION"])
    uvs = read_accessor(doc, buffer, attributes["TEXCOORD_0"])
    for (x, y, _), (u, v) in zip(positions, uvs):
        expect("texture coordinate of (%g, %g)" % (x, y), (u, v), (f32(x / CELLS), f32(1 - y / CELLS)))
    expect("vertices", len(positions), (CELLS + 1) ** 2)


def main():
    rgbsub = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        def path(name):
            return os.path.join(folder, name)
        with open(path("grid.mtl"), "w", encoding="utf-8") as f:
            f.write(MTL)
        with open(path("grid.obj"), "w", encoding="utf-8") as f:
            f.write(grid_obj(False))
        with open(path("textured.obj"), "w", encoding="utf-8") as f:
            f.write(grid_obj(True))
        run(rgbsub, "refine", path("grid.obj"), "--level", "2", "-o", path("refined.obj"), "--plain")
        obj_vertices = obj_positions(path("refined.obj"))
        for name, load in (("refined.glb", load_glb), ("refined.gltf", load_gltf)):
            run(rgbsub, "refine", path("grid.obj"), "--level", "2", "-o", path(name))
            check_refined(*load(path(name)), obj_vertices)
            print(name, "ok")
        run(rgbsub, "refine", path("textured.obj"), "--level", "0", "-o", path("level0.glb"))
        check_level0(*load_glb(path("level0.glb")))
        print("level0.glb ok")
        run(rgbsub, "refine", path("textured.obj"), "--level", "1", "-o", path("level1.obj"), "--plain")
        wanted, _, pairs = obj_triangles(path("level1.obj"))
        warned = run(rgbsub, "refine", path("textured.obj"), "--level", "1", "-o", path("level1.glb")).stderr
        expect("warnings", warned, "")
        got, vertices = gltf_triangles(*load_glb(path("level1.glb")), False)
        expect("vertices (one per (v, vt) pair)", vertices, pairs)
        same_triangles("level1.glb", got, wanted)
        print("level1.glb ok")


if __name__ == "__main__":
    main()
