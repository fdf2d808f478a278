#!/usr/bin/python3
"""`rgbsub refine -o OUT.ply|.stl|.vtu|.msh` and `rgbsub lods`, read back by independent readers:
meshio (Debian's python3-meshio) for STL, VTU and MSH, numpy for PLY (meshio 5.0 reads a binary PLY's
face properties column by column, not face by face, so it misreads any face element with properties
besides the vertex list), Python's json/struct for glTF (tests/io/gltf_export_check.py), plain text
for OBJ.

The input is an octahedron with vertex colours, refined to level 3 in a ball around one corner, so that
faces of levels 0 to 3 and of all three colours meet. Against the plain OBJ refine writes for the same
request (its v and f lines, read with Python's float(), which rounds correctly):
MSH both as ASCII and, with --msh-binary, as binary (file-type 1, data-size 8, the int 1 after the
format line), each checked as below:
- PLY, VTU, MSH: every position bit for bit (they store doubles); STL: as 32-bit floats (it stores
  floats), triangle by triangle;
- the triangles, in the OBJ's order, as index triples (PLY, VTU, MSH) or position triples (STL);
- cell data: the levels and colours counted as `rgbsub info` on the saved OBJ counts them; quality
  (aspect ratio) and min_angle recomputed here from the positions with numpy (law of cosines and
  Heron's area), to 1e-9; PLY's vertex colours as bytes of the OBJ's colours.
`rgbsub lods`: levels and budgets as one OBJ per level, nested by position (each coarser level's v
lines among the finer's); a .glb set whose node 0 names the other levels through MSFT_lod, with
MSFT_screencoverage not increasing and ending at 0, each level its own mesh with indexed primitives
and the positions of the OBJ level as floats; --msh-binary levels as binary MSH files, at the OBJ
levels' positions bit for bit and with their triangles; --msh-binary with an output other than .msh is
a usage error (exit 1).

usage: formats_check.py PATH/TO/rgbsub
"""
import os
import re
import subprocess
import sys
import tempfile

import meshio
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "io"))
from gltf_export_check import expect, load_glb, read_accessor  # noqa: E402

OCTAHEDRON = """v 1 0 0 1 0 0
v -1 0 0 0 1 0
v 0 1 0 0 0 1
v 0 -1 0 1 1 0
v 0 0 1 0 1 1
v 0 0 -1 1 0 1
f 1 3 5
f 3 2 5
f 2 4 5
f 4 1 5
f 3 1 6
f 2 3 6
f 4 2 6
f 1 4 6
"""


def run(rgbsub, *args):
    return subprocess.run([rgbsub, *args], check=True, capture_output=True, text=True)


def read_obj(path):
    positions, colours, triangles = [], [], []
    with open(path, encoding="utf-8") as f:
        for line in f:
            words = line.split()
            if words and words[0] == "v":
                positions.append([float(x) for x in words[1:4]])
                if len(words) == 7:
                    colours.append([float(x) for x in words[4:7]])
            elif words and words[0] == "f":
                triangles.append([int(w.split("/")[0]) - 1 for w in words[1:4]])
    return np.array(positions), np.array(colours), np.array(triangles)


def info_counts(rgbsub, path):
    """Triangles per colour (0 green, 1 red, 2 blue) and per level, as `rgbsub info` prints them."""
    text = run(rgbsub, "info", path).stdout
    green, red, blue = map(int, re.search(r"triangles per colour: green (\d+), red (\d+), blue (\d+)", text).groups())
    levels = re.search(r"triangles per level:((?: \d+:\d+)+)", text).group(1).split()
    return {0: green, 1: red, 2: blue}, {int(a): int(b) for a, b in (x.split(":") for x in levels)}


def counts(values):
    keys, numbers = np.unique(np.asarray(values).astype(int), return_counts=True)
    return {int(k): int(n) for k, n in zip(keys, numbers) if n > 0}


def quality(positions, triangles):
    """Aspect ratio and smallest angle (degrees) per triangle: law of cosines, Heron's area."""
    p = positions[triangles]
    a = np.linalg.norm(p[:, 1] - p[:, 2], axis=1)
    b = np.linalg.norm(p[:, 2] - p[:, 0], axis=1)
    c = np.linalg.norm(p[:, 0] - p[:, 1], axis=1)
    s = (a + b + c) / 2
    area = np.sqrt(s * (s - a) * (s - b) * (s - c))
    aspect = np.maximum(np.maximum(a, b), c) * (a + b + c) / (4 * np.sqrt(3) * area)
    cosines = [(b * b + c * c - a * a) / (2 * b * c), (c * c + a * a - b * b) / (2 * c * a), (a * a + b * b - c * c) / (2 * a * b)]
    angles = np.degrees(np.arccos(np.clip(np.array(cosines), -1, 1)))
    return aspect, angles.min(axis=0)


def cell_data(mesh, name):
    return np.concatenate([np.asarray(block) for block in mesh.cell_data[name]])


def triangles_of(mesh):
    if isinstance(mesh, PlyMesh):
        return mesh.triangles
    expect("cell blocks", [block.type for block in mesh.cells], ["triangle"])
    return np.asarray(mesh.cells[0].data)


class PlyMesh:
    """A binary little-endian PLY as rgbsub writes it, read with numpy's structured dtypes from its
    header, in meshio's shape (points, cells, cell_data, point_data)."""
    TYPES = {"double": "<f8", "float": "<f4", "uchar": "u1", "uint": "<u4", "int": "<i4"}

    def __init__(self, path):
        with open(path, "rb") as f:
            data = f.read()
        end = data.index(b"end_header\n") + len(b"end_header\n")
        header = data[:end].decode("ascii").split("\n")
        expect("ply format", header[1], "format binary_little_endian 1.0")
        elements = []
        for line in header:
            words = line.split()
            if words[:1] == ["element"]:
                elements.append((words[1], int(words[2]), []))
            elif words[:2] == ["property", "list"]:
                expect("list types", words[2:4], ["uchar", "uint"])
                elements[-1][2].append((words[4], "list"))
            elif words[:1] == ["property"]:
                elements[-1][2].append((words[2], self.TYPES[words[1]]))
        (vname, vcount, vprops), (fname, fcount, fprops) = elements
        expect("elements", (vname, fname), ("vertex", "face"))
        vertices = np.frombuffer(data, dtype=[(n, t) for n, t in vprops], count=vcount, offset=end)
        offset = end + vertices.nbytes
        face_dtype = [x for n, t in fprops for x in ((("count", "u1"), (n, "<u4", 3)) if t == "list" else ((n, t),))]
        faces = np.frombuffer(data, dtype=face_dtype, count=fcount, offset=offset)
        expect("ply size", offset + faces.nbytes, len(data))
        assert (faces["count"] == 3).all()
        self.points = np.column_stack([vertices["x"], vertices["y"], vertices["z"]])
        self.point_data = {n: vertices[n] for n, _ in vprops if n not in "xyz"}
        self.triangles = faces["vertex_indices"]
        self.cell_data = {n: [faces[n]] for n, t in fprops if t != "list"}


def check_cells(name, mesh, positions, triangles, colour_counts, level_counts, with_quality):
    expect(name + ": triangles", triangles_of(mesh).tolist(), triangles.tolist())
    expect(name + ": levels", counts(cell_data(mesh, "level")), level_counts)
    expect(name + ": colours", counts(cell_data(mesh, "rgb_colour")), colour_counts)
    if with_quality:
        aspect, min_angle = quality(positions, triangles)
        assert np.allclose(cell_data(mesh, "quality"), aspect, rtol=1e-9, atol=0), name + ": quality"
        assert np.allclose(cell_data(mesh, "min_angle"), min_angle, rtol=1e-9, atol=1e-9), name + ": min_angle"


def check_formats(rgbsub, path):
    run(rgbsub, "refine", path("in.obj"), "--level", "3", "--sphere", "0.8,0.2,0.2,0.3", "-o", path("ref.obj"), "--plain")
    run(rgbsub, "refine", path("in.obj"), "--level", "3", "--sphere", "0.8,0.2,0.2,0.3", "-o", path("state.obj"))
    positions, colours, triangles = read_obj(path("ref.obj"))
    colour_counts, level_counts = info_counts(rgbsub, path("state.obj"))
    assert len(level_counts) == 4 and len(colour_counts) == 3, (level_counts, colour_counts)
    for ext, extra in (("ply", []), ("PLY", []), ("vtu", []), ("msh", []), ("msh", ["--msh-binary"]), ("stl", [])):
        out = path("out%s.%s" % ("_binary" if extra else "", ext))
        note = run(rgbsub, "refine", path("in.obj"), "--level", "3", "--sphere", "0.8,0.2,0.2,0.3", "-o", out, *extra).stderr
        assert "note: the adaptive state is kept only in OBJ files" in note, note
        if ext == "msh":
            with open(out, "rb") as f:
                head = f.read(40)
            binary = b"$MeshFormat\n4.1 1 8\n" + (1).to_bytes(4, sys.byteorder) + b"\n$EndMeshFormat\n"
            assert head.startswith(binary if extra else b"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"), head
        mesh = PlyMesh(out) if ext.lower() == "ply" else meshio.read(out)
        if ext.lower() == "stl":
            # Floats, and meshio merges the facets' corners: compare triangle by triangle.
            got = np.asarray(mesh.points)[triangles_of(mesh)]
            expect("stl positions", got.astype(np.float32).tolist(), positions[triangles].astype(np.float32).tolist())
            print("stl ok")
            continue
        expect(ext + ": positions bit for bit", np.asarray(mesh.points).tolist(), positions.tolist())
        check_cells(ext, mesh, positions, triangles, colour_counts, level_counts, ext in ("vtu", "msh"))
        if ext.lower() == "ply":
            wanted = np.rint(np.clip(colours, 0, 1) * 255).astype(int).tolist()
            got = np.stack([mesh.point_data[c] for c in ("red", "green", "blue")], axis=1).astype(int).tolist()
            expect("ply vertex colours", got, wanted)
        print(ext, *extra, "ok")


def obj_vertex_set(path):
    positions, _, triangles = read_obj(path)
    return {tuple(p) for p in positions.tolist()}, len(triangles)


def check_lods(rgbsub, path):
    for option, values, lods in (("--levels", "1,3,2", 3), ("--budgets", "300,60,1000", 3)):
        printed = run(rgbsub, "lods", path("in.obj"), "-o", path("lv.obj"), option, values).stdout
        finer = None
        sizes = []
        for i in range(lods):
            vertices, faces = obj_vertex_set(path("lv_LOD%d.obj" % i))
            assert re.search(r"lv_LOD%d\.obj: LOD%d \(\S+\): %d triangles" % (i, i, faces), printed), printed
            if finer is not None:
                assert vertices <= finer, "%s LOD%d not nested" % (option, i)
                assert "nested in LOD%d" % (i - 1) in printed and "not nested" not in printed, printed
            finer = vertices
            sizes.append(faces)
        assert sizes == sorted(sizes, reverse=True) and len(set(sizes)) == lods, sizes
        print("lods", option, "ok")
    # A glTF set against the OBJ levels of the same request.
    run(rgbsub, "lods", path("in.obj"), "-o", path("set.glb"), "--levels", "2,0,1")
    run(rgbsub, "lods", path("in.obj"), "-o", path("lv.obj"), "--levels", "2,0,1")
    doc, buffer = load_glb(path("set.glb"))
    expect("scene nodes", doc["scenes"][doc["scene"]]["nodes"], [0])
    expect("extensionsUsed", doc["extensionsUsed"], ["MSFT_lod"])
    expect("MSFT_lod ids", doc["nodes"][0]["extensions"]["MSFT_lod"]["ids"], [1, 2])
    coverage = doc["nodes"][0]["extras"]["MSFT_screencoverage"]
    expect("coverage count", len(coverage), 3)
    assert coverage == sorted(coverage, reverse=True) and coverage[-1] == 0 and coverage[0] <= 1, coverage
    expect("meshes", len(doc["meshes"]), 3)
    for i in range(3):
        expect("node mesh", doc["nodes"][i]["mesh"], i)
        positions, _, triangles = read_obj(path("lv_LOD%d.obj" % i))
        primitive, = doc["meshes"][i]["primitives"]
        got = np.array(read_accessor(doc, buffer, primitive["attributes"]["POSITION"]), dtype=np.float32)
        indices = np.array(read_accessor(doc, buffer, primitive["indices"])).reshape(-1, 3)
        expect("glb LOD%d triangles" % i, got[indices].tolist(), positions[triangles].astype(np.float32).tolist())
    print("lods glb ok")
    # Binary MSH levels against the OBJ levels of the same request (written just above).
    run(rgbsub, "lods", path("in.obj"), "-o", path("lv.msh"), "--levels", "2,0,1", "--msh-binary")
    for i in range(3):
        positions, _, triangles = read_obj(path("lv_LOD%d.obj" % i))
        with open(path("lv_LOD%d.msh" % i), "rb") as f:
            assert f.read(20) == b"$MeshFormat\n4.1 1 8\n", i
        mesh = meshio.read(path("lv_LOD%d.msh" % i))
        expect("msh LOD%d positions bit for bit" % i, np.asarray(mesh.points).tolist(), positions.tolist())
        expect("msh LOD%d triangles" % i, triangles_of(mesh).tolist(), triangles.tolist())
    refused = subprocess.run([rgbsub, "lods", path("in.obj"), "-o", path("no.obj"), "--levels", "1", "--msh-binary"],
                             capture_output=True, text=True)
    assert refused.returncode == 1 and "--msh-binary" in refused.stderr and "no.obj" in refused.stderr, refused
    assert not os.path.exists(path("no_LOD0.obj"))
    print("lods msh binary ok")


def main():
    with tempfile.TemporaryDirectory() as folder:
        def path(name):
            return os.path.join(folder, name)
        with open(path("in.obj"), "w", encoding="utf-8") as f:
            f.write(OCTAHEDRON)
        check_formats(sys.argv[1], path)
        check_lods(sys.argv[1], path)


if __name__ == "__main__":
    main()
