#!/usr/bin/env python3
"""Reads gltf_export_example's .gltf and .glb back by hand (json, base64, struct: no glTF library)
and checks every value against the mesh described in gltf_export_example.cpp.

usage: gltf_export_check.py PATH/TO/gltf_export_example
"""
import base64
import json
import os
import struct
import subprocess
import sys
import tempfile

FLOAT, UINT = 5126, 5125
COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3}


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def load_gltf(path):
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    uri = doc["buffers"][0]["uri"]
    prefix = "data:application/octet-stream;base64,"
    assert uri.startswith(prefix), uri[:60]
    return doc, base64.b64decode(uri[len(prefix):])


def load_glb(path):
    with open(path, "rb") as f:
        data = f.read()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2 and length == len(data), (magic, version, length, len(data))
    json_length, json_type = struct.unpack_from("<I4s", data, 12)
    assert json_type == b"JSON"
    doc = json.loads(data[20:20 + json_length])
    bin_at = 20 + json_length
    bin_length, bin_type = struct.unpack_from("<I4s", data, bin_at)
    assert bin_type == b"BIN\0"
    assert "uri" not in doc["buffers"][0]
    return doc, data[bin_at + 8:bin_at + 8 + bin_length]


def read_accessor(doc, buffer, index):
    accessor = doc["accessors"][index]
    view = doc["bufferViews"][accessor["bufferView"]]
    n = COMPONENTS[accessor["type"]]
    code = {FLOAT: "f", UINT: "I"}[accessor["componentType"]]
    offset = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
    assert view["byteLength"] == 4 * n * accessor["count"]
    values = struct.unpack_from("<%d%s" % (n * accessor["count"], code), buffer, offset)
    return [tuple(values[i:i + n]) if n > 1 else values[i] for i in range(0, len(values), n)]


def expect(name, got, wanted):
    if got != wanted:
        raise AssertionError("%s: got %r, wanted %r" % (name, got, wanted))


def check(doc, buffer):
    expect("asset version", doc["asset"]["version"], "2.0")
    primitives = doc["meshes"][0]["primitives"]
    expect("primitives", len(primitives), 3)
    attributes = primitives[0]["attributes"]
    for p in primitives:
        expect("shared attributes", p["attributes"], attributes)
        expect("mode", p.get("mode", 4), 4)
    # One glTF vertex per (vertex, texture coordinate) corner, in order of first use.
    corners = [(0, 0), (1, 1), (2, 2), (3, 3), (1, 4), (4, 5), (2, 6), (2, None), (4, None), (5, None)]
    positions = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0.5, 0), (2, 1.5, 0)]
    uvs = [(0, 0), (1, 0), (1, 1), (0, 1), (0.25, 0.25), (0.75, 0.5), (0.25, 0.75)]
    expect("POSITION", read_accessor(doc, buffer, attributes["POSITION"]), [tuple(map(f32, positions[v])) for v, _ in corners])
    position = doc["accessors"][attributes["POSITION"]]
    expect("POSITION min", position["min"], [0, 0, 0])
    expect("POSITION max", position["max"], [2, 1.5, 0])
    expect("NORMAL", read_accessor(doc, buffer, attributes["NORMAL"]), [(0.0, 0.0, 1.0)] * len(corners))
    # glTF's texture origin is the top left: v becomes 1 - v; corners without one get (0, 0).
    expect("TEXCOORD_0", read_accessor(doc, buffer, attributes["TEXCOORD_0"]),
           [(f32(uvs[t][0]), f32(1 - uvs[t][1])) if t is not None else (0.0, 0.0) for _, t in corners])
    # Material 0 (triangle 1 4 2), material 1 (0 1 2, 0 2 3), then the triangle without material.
    expect("indices of material 0", read_accessor(doc, buffer, primitives[0]["indices"]), [4, 5, 6])
    expect("indices of material 1", read_accessor(doc, buffer, primitives[1]["indices"]), [0, 1, 2, 0, 2, 3])
    expect("indices without material", read_accessor(doc, buffer, primitives[2]["indices"]), [7, 8, 9])
    expect("primitive materials", [p.get("material") for p in primitives], [0, 1, None])
    painted, skin = doc["materials"]
    expect("material 0 name", painted["name"], "Painted")
    expect("material 0 colour", painted["pbrMetallicRoughness"]["baseColorFactor"], [0.25, 0.5, 0.75, 1.0])
    expect("material 0 metallic", painted["pbrMetallicRoughness"]["metallicFactor"], 0.0)
    expect("material 1 name", skin["name"], "Skin")
    texture = doc["textures"][skin["pbrMetallicRoughness"]["baseColorTexture"]["index"]]
    expect("texture image", doc["images"][texture["source"]]["uri"], "my%20textures/skin%201.png")
    expect("scene", doc["scenes"][doc["scene"]]["nodes"], [0])
    expect("node", doc["nodes"][0]["mesh"], 0)


def main():
    with tempfile.TemporaryDirectory() as folder:
        subprocess.run([sys.argv[1], folder], check=True)
        for name, load in (("out.gltf", load_gltf), ("out.glb", load_glb)):
            check(*load(os.path.join(folder, name)))
            print(name, "ok")


if __name__ == "__main__":
    main()
