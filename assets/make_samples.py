#!/usr/bin/env python3
"""Writes the two appearance samples, each a rounded box (a cube-sphere, 4 x 4 quads per cube face, 192
triangles) that looks good once Loop-subdivided:

  textured.obj  texture coordinates (`vt`: every cube face maps onto the whole image) and
                `mtllib textured.mtl`, whose material `bricks` has `map_Kd textured.png`, a 64 x 64
                brick pattern this script draws (an 8-bit RGB PNG, written with zlib alone)
  coloured.obj  vertex colours (`v x y z r g b`): each vertex coloured by its direction from the
                centre, (1 + direction) / 2, so opposite sides show opposite colours

Open them in the editor and choose Display > diffuse texture or vertex colours. Standard library
only; run once from this folder, the outputs are committed."""
import math
import struct
import zlib

N = 4        # quads per cube face side
SIDE = 64    # texture pixels per side
BRICK_W, BRICK_H, MORTAR = 16, 8, 1

# Cube faces as (origin, u, v) with u x v pointing outwards, so quads are counter-clockwise outside.
FACES = [((1, -1, 1), (0, 0, -2), (0, 2, 0)), ((-1, -1, -1), (0, 0, 2), (0, 2, 0)),
         ((-1, 1, 1), (2, 0, 0), (0, 0, -2)), ((-1, -1, -1), (2, 0, 0), (0, 0, 2)),
         ((-1, -1, 1), (2, 0, 0), (0, 2, 0)), ((1, -1, -1), (-2, 0, 0), (0, 2, 0))]


def cube_sphere():
    """Positions (shared between cube faces), and per triangle its three (vertex, (s, t)) corners."""
    positions, index, triangles = [], {}, []

    def vertex(p):
        key = tuple(round(c, 6) for c in p)
        if key not in index:
            index[key] = len(positions)
            r = math.sqrt(sum(c * c for c in p))
            # Half way between the cube and the sphere: a rounded box.
            positions.append(tuple(0.5 * c + 0.5 * c / r for c in p))
        return index[key]

    for origin, u, v in FACES:
        def corner(i, j):
            p = tuple(origin[k] + u[k] * i / N + v[k] * j / N for k in range(3))
            return vertex(p), (i / N, j / N)
        for i in range(N):
            for j in range(N):
                a, b, c, d = corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1)
                # Alternate the diagonal so the cage has no preferred direction.
                triangles += [(a, b, c), (a, c, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, c, d)]
    return positions, triangles


def png(width, height, pixel):
    """An 8-bit RGB PNG; pixel(x, y) gives (r, g, b) with y = 0 the top row."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")


def brick(x, y):
    row = y // BRICK_H
    shifted = x + (BRICK_W // 2 if row % 2 else 0)
    if y % BRICK_H < MORTAR or shifted % BRICK_W < MORTAR:
        return (215, 210, 200)  # mortar
    shade = ((shifted // BRICK_W) * 7 + row * 3) % 4  # neighbouring bricks differ a little
    return (150 + 12 * shade, 60 + 6 * shade, 40 + 4 * shade)


positions, triangles = cube_sphere()

with open("textured.png", "wb") as out:
    out.write(png(SIDE, SIDE, brick))
with open("textured.mtl", "w") as out:
    out.write("# rgbsub sample material, made by assets/make_samples.py\n"
              "newmtl bricks\nKd 0.8 0.4 0.3\nmap_Kd textured.png\n")
with open("textured.obj", "w") as out:
    out.write("# rgbsub sample: a rounded box with texture coordinates and a diffuse texture, made by\n"
              "# assets/make_samples.py. Display > diffuse texture shows it.\n"
              "mtllib textured.mtl\n")
    for p in positions:
        out.write("v %.6f %.6f %.6f\n" % p)
    uvs = sorted({uv for t in triangles for _, uv in t})
    uv_index = {uv: i for i, uv in enumerate(uvs)}
    for uv in uvs:
        out.write("vt %.6f %.6f\n" % uv)
    out.write("usemtl bricks\n")
    for t in triangles:
        out.write("f %s\n" % " ".join("%d/%d" % (v + 1, uv_index[uv] + 1) for v, uv in t))

with open("coloured.obj", "w") as out:
    out.write("# rgbsub sample: a rounded box with vertex colours (each vertex's direction from the\n"
              "# centre, as (1 + direction) / 2), made by assets/make_samples.py. Display > vertex colours\n"
              "# shows them.\n")
    for p in positions:
        r = math.sqrt(sum(c * c for c in p))
        out.write("v %.6f %.6f %.6f %.6f %.6f %.6f\n" % (p + tuple((1 + c / r) / 2 for c in p)))
    for t in triangles:
        out.write("f %d %d %d\n" % tuple(v + 1 for v, _ in t))
print(len(positions), "vertices", len(triangles), "triangles")
