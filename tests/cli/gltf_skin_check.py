#!/usr/bin/env python3
"""A skinned glTF stays skinned through `refine` and `lods`, read back by hand (json/struct, no glTF
library) against this script's own Loop subdivision of the weights:

- the input, made here: an octahedron (every vertex of valence 4) skinned to a chain of six joint
  nodes under a "rig" node; vertex i weighs a_i on joint i and 1 - a_i on joint i + 1 (JOINTS_0 as
  unsigned bytes), inverse bind matrices the inverse of each joint's bind placement;
- `refine --level 1 -o .glb`: the skin is carried (joint nodes by name, their translations, the
  hierarchy, the inverse bind matrices, every level's node skinned), and every vertex's weights are
  those of one step of Loop's rules (even vertices 1 - 4b, b = 31/256 for valence 4; edge vertices
  3/8, 3/8, 1/8, 1/8) applied to the per-joint weights, of which the four heaviest are kept over their
  sum (a vertex takes weight from up to six joints here, so the cut is exercised). Vertices are
  matched by their positions, which this Loop step gives as well;
- `lods --levels 1,0 -o .glb` (limit positions): every level skinned by the one skin; in every written
  vertex the float weights sum to 1 (within float rounding), at most four are non-zero, and their
  joints exist.

usage: gltf_skin_check.py PATH/TO/rgbsub
"""
import base64
import json
import math
import os
import struct
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "io"))
from gltf_export_check import expect, load_glb  # noqa: E402

POSITIONS = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
FACES = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
JOINTS = 6
SHARE = [0.87, 0.66, 0.64, 0.81, 0.57, 0.84]  # vertex i's weight on joint i; the rest on joint i + 1
JOINT_NAMES = ["hip", "spine", "chest", "neck", "head", "crown"]
STEP = [0.0, 0.25, 0.5, 0.25, 0.5, 0.25]  # each joint's translation (y) from its parent
TYPES = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
CODES = {5121: "B", 5123: "H", 5125: "I", 5126: "f"}


def input_weights():
    """Per vertex, its dense weight per joint."""
    weights = []
    for i in range(len(POSITIONS)):
        w = [0.0] * JOINTS
        w[i] = SHARE[i]
        w[(i + 1) % JOINTS] += 1 - SHARE[i]
        weights.append(w)
    return weights


def skinned_gltf():
    """The input file's JSON, its buffer embedded."""
    parts, views, accessors = [], [], []

    def add(data, component, kind, count, target=None):
        views.append({"buffer": 0, "byteOffset": sum(len(p) for p in parts), "byteLength": len(data)})
        if target:
            views[-1]["target"] = target
        parts.append(data)
        accessors.append({"bufferView": len(views) - 1, "componentType": component, "type": kind, "count": count})
        return len(accessors) - 1

    position = add(struct.pack("<18f", *[c for p in POSITIONS for c in p]), 5126, "VEC3", 6, 34962)
    accessors[position].update({"min": [-1, -1, -1], "max": [1, 1, 1]})
    indices = add(struct.pack("<24I", *[i for f in FACES for i in f]), 5125, "SCALAR", 24, 34963)
    joints = add(bytes(j for i in range(6) for j in (i, (i + 1) % JOINTS, 0, 0)), 5121, "VEC4", 6, 34962)
    weights = add(struct.pack("<24f", *[w for i in range(6) for w in (SHARE[i], 1 - SHARE[i], 0, 0)]), 5126, "VEC4", 6, 34962)
    bind_y = [sum(STEP[:j + 1]) for j in range(JOINTS)]  # the chain's joints lie on the y axis
    matrices = [x for y in bind_y for x in (1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -y, 0, 1)]
    inverse_bind = add(struct.pack("<96f", *matrices), 5126, "MAT4", 6)
    data = b"".join(parts)
    nodes = [{"name": "body", "mesh": 0, "skin": 0}, {"name": "rig", "children": [2], "scale": [1, 1, 1]}]
    for j in range(JOINTS):
        nodes.append({"name": JOINT_NAMES[j], "translation": [0, STEP[j], 0]})
        if j + 1 < JOINTS:
            nodes[-1]["children"] = [len(nodes)]
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": nodes,
        "meshes": [{"primitives": [{"attributes": {"POSITION": position, "JOINTS_0": joints, "WEIGHTS_0": weights},
                                    "indices": indices}]}],
        "skins": [{"name": "chain", "joints": list(range(2, 2 + JOINTS)), "skeleton": 2, "inverseBindMatrices": inverse_bind}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    }


def read(doc, buffer, index):
    accessor = doc["accessors"][index]
    view = doc["bufferViews"][accessor["bufferView"]]
    n, code = TYPES[accessor["type"]], CODES[accessor["componentType"]]
    values = struct.unpack_from("<%d%s" % (n * accessor["count"], code), buffer, view.get("byteOffset", 0) + accessor.get("byteOffset", 0))
    return [tuple(values[i:i + n]) for i in range(0, len(values), n)]


def loop_step(values):
    """One uniform Loop step of per-vertex vectors over the octahedron: {key: vector}, keys a vertex
    index (even) or a sorted edge (odd)."""
    neighbours = {v: set() for v in range(len(values))}
    opposite = {}
    for f in FACES:
        for k in range(3):
            a, b, c = f[k], f[(k + 1) % 3], f[(k + 2) % 3]
            neighbours[a] |= {b, c}
            opposite.setdefault(tuple(sorted((a, b))), []).append(c)
    out = {}
    for v, ring in neighbours.items():
        n = len(ring)
        beta = (5 / 8 - (3 / 8 + math.cos(2 * math.pi / n) / 4) ** 2) / n
        out[v] = [(1 - n * beta) * x + beta * sum(values[u][i] for u in ring) for i, x in enumerate(values[v])]
    for (a, b), (c, d) in opposite.items():
        out[(a, b)] = [3 / 8 * (values[a][i] + values[b][i]) + 1 / 8 * (values[c][i] + values[d][i]) for i in range(len(values[a]))]
    return out


def heaviest_four(weights):
    """The four heaviest (joint, weight) pairs over their sum; checks that the cut is no near-tie."""
    ranked = sorted(((w, j) for j, w in enumerate(weights) if w > 0), key=lambda p: (-p[0], p[1]))
    if len(ranked) > 4:
        assert ranked[3][0] - ranked[4][0] > 1e-9, "the test's weights tie at the cut"
    kept = ranked[:4]
    total = sum(w for w, _ in kept)
    return {j: w / total for w, j in kept}, len(ranked)


def skinned_node_checks(doc, levels):
    skin = doc["skins"][0]
    expect("skins", len(doc["skins"]), 1)
    expect("skin name", skin["name"], "chain")
    names = [doc["nodes"][n]["name"] for n in skin["joints"]]
    expect("joint names", names, JOINT_NAMES)
    for j, n in enumerate(skin["joints"]):
        expect("joint %d translation" % j, doc["nodes"][n].get("translation"), [0, STEP[j], 0])
        if j + 1 < JOINTS:
            expect("joint %d child" % j, doc["nodes"][n].get("children"), [skin["joints"][j + 1]])
    expect("skeleton root", doc["nodes"][skin["skeleton"]]["name"], "hip")
    rig = [n for n, node in enumerate(doc["nodes"]) if node.get("name") == "rig"]
    expect("rig node carried, parent of the chain", [doc["nodes"][n].get("children") for n in rig], [[skin["joints"][0]]])
    expect("scene roots: the mesh and the rig", doc["scenes"][doc.get("scene", 0)]["nodes"], [0, rig[0]])
    for level in range(levels):
        expect("level %d skinned" % level, doc["nodes"][level].get("skin"), 0)
    return skin


def written_influences(doc, buffer, mesh, joint_count):
    """Per written vertex: (position, {joint: weight}); checks the sum, the count and the joints."""
    attributes = doc["meshes"][mesh]["primitives"][0]["attributes"]
    positions = read(doc, buffer, attributes["POSITION"])
    joints = read(doc, buffer, attributes["JOINTS_0"])
    weights = read(doc, buffer, attributes["WEIGHTS_0"])
    expect("JOINTS_0 unsigned short", doc["accessors"][attributes["JOINTS_0"]]["componentType"], 5123)
    out = []
    for p, js, ws in zip(positions, joints, weights):
        assert abs(sum(ws) - 1) <= 2.5e-7, "weights %r sum to %r" % (ws, sum(ws))
        assert all(w >= 0 for w in ws), ws
        assert all(j < joint_count for j in js), js
        used = {j: w for j, w in zip(js, ws) if w > 0}
        assert len(used) == sum(1 for w in ws if w > 0), "a joint named twice: %r" % (js,)
        out.append((p, used))
    return out


def main():
    rgbsub = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        source = os.path.join(folder, "skinned.gltf")
        with open(source, "w", encoding="utf-8") as f:
            json.dump(skinned_gltf(), f)

        refined = os.path.join(folder, "refined.glb")
        run = subprocess.run([rgbsub, "refine", source, "--level", "1", "-o", refined], capture_output=True, text=True)
        expect("refine exit", (run.returncode, run.stderr), (0, ""))
        doc, buffer = load_glb(refined)
        skin = skinned_node_checks(doc, 1)
        matrices = read(doc, buffer, skin["inverseBindMatrices"])
        expect("inverse bind matrices", [m[13] for m in matrices], [-sum(STEP[:j + 1]) for j in range(JOINTS)])
        expected_positions = loop_step([list(p) for p in POSITIONS])
        expected_weights = loop_step(input_weights())
        written = written_influences(doc, buffer, 0, JOINTS)
        expect("vertices", len(written), len(expected_positions))
        cut = 0
        for key, position in expected_positions.items():
            match = [w for p, w in written if max(abs(a - b) for a, b in zip(p, position)) < 1e-6]
            expect("vertices at %r" % (position,), len(match), 1)
            wanted, influences = heaviest_four(expected_weights[key])
            cut += influences > 4
            expect("joints of the vertex at %r" % (position,), sorted(match[0]), sorted(wanted))
            for j, w in wanted.items():
                assert abs(match[0][j] - w) <= 1e-6, "vertex at %r, joint %d: %r, Loop gives %r" % (position, j, match[0][j], w)
        assert cut >= 6, "vertices take weight from more than four joints (%d do)" % cut

        lods = os.path.join(folder, "lods.glb")
        run = subprocess.run([rgbsub, "lods", source, "--levels", "1,0", "-o", lods], capture_output=True, text=True)
        expect("lods exit", (run.returncode, run.stderr), (0, ""))
        doc, buffer = load_glb(lods)
        skinned_node_checks(doc, 2)
        expect("LOD vertices", [len(written_influences(doc, buffer, m, JOINTS)) for m in range(2)], [18, 6])


if __name__ == "__main__":
    main()
