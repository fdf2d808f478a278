#!/usr/bin/env python3
"""Every kind of glTF rgbsub writes passes the Khronos glTF validator (npm gltf-validator, installed
into the build tree by the test fixture gltf_validator) with no errors: `refine -o` .glb and .gltf of
a grid with two materials (one a colour, one a PNG texture) and texture coordinates, refined; of an
octahedron with vertex colours; of a skinned octahedron (gltf_skin_check.py, its input too); and
`lods` sets (MSFT_lod) of all three, as .glb and .gltf.

usage: gltf_validator_check.py PATH/TO/rgbsub PATH/TO/node VALIDATOR_PREFIX
"""
import json
import os
import struct
import subprocess
import sys
import tempfile
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from formats_check import OCTAHEDRON  # noqa: E402
from gltf_refine_check import grid_obj  # noqa: E402
from gltf_skin_check import skinned_gltf  # noqa: E402

MTL = "newmtl left\nKd 1 0 0\nnewmtl right\nKd 1 1 1\nmap_Kd checker.png\n"


def png_2x2():
    """A 2x2 RGB PNG, written by hand (zlib and struct)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    rows = b"".join(b"\0" + row for row in (b"\xff\xff\xff\0\0\0", b"\0\0\0\xff\xff\xff"))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def main():
    rgbsub, node, prefix = sys.argv[1:4]
    with tempfile.TemporaryDirectory() as folder:
        def path(name):
            return os.path.join(folder, name)
        for name, content in (("grid.obj", grid_obj(True)), ("grid.mtl", MTL), ("octahedron.obj", OCTAHEDRON)):
            with open(path(name), "w", encoding="utf-8") as f:
                f.write(content)
        with open(path("checker.png"), "wb") as f:
            f.write(png_2x2())
        with open(path("skinned.gltf"), "w", encoding="utf-8") as f:
            json.dump(skinned_gltf(), f)
        files = [path("skinned.gltf")]
        for mesh in ("grid.obj", "octahedron.obj", "skinned.gltf"):
            for ext in ("glb", "gltf"):
                stem = mesh.split(".")[0]
                single, lods = path("%s_refined.%s" % (stem, ext)), path("%s_lods.%s" % (stem, ext))
                subprocess.run([rgbsub, "refine", path(mesh), "--level", "2", "-o", single], check=True)
                subprocess.run([rgbsub, "lods", path(mesh), "--levels", "2,1,0", "-o", lods], check=True,
                               stdout=subprocess.DEVNULL)
                files += [single, lods]
        result = subprocess.run([node, os.path.join(HERE, "gltf_validate.js"), prefix, *files])
        sys.exit(result.returncode)


if __name__ == "__main__":
    main()
