#!/usr/bin/env python3
"""Writes default.obj: a coarse control cage of a cat-like head (192 triangles) that looks good once
Loop-subdivided. A cube-sphere (4x4 quads per cube face, vertices shared) deformed into a head with a
muzzle, two pointed ears and a flat base. Run once; the output is committed."""
import math

N = 4
vertices, index, triangles = [], {}, []


def vertex(p):
    key = tuple(round(c, 6) for c in p)
    if key not in index:
        index[key] = len(vertices)
        vertices.append(p)
    return index[key]


# Cube faces as (origin, u, v) with u x v pointing outwards, so quads are counter-clockwise outside.
faces = [((1, -1, 1), (0, 0, -2), (0, 2, 0)), ((-1, -1, -1), (0, 0, 2), (0, 2, 0)),
         ((-1, 1, 1), (2, 0, 0), (0, 0, -2)), ((-1, -1, -1), (2, 0, 0), (0, 0, 2)),
         ((-1, -1, 1), (2, 0, 0), (0, 2, 0)), ((1, -1, -1), (-2, 0, 0), (0, 2, 0))]
for origin, u, v in faces:
    grid = [[vertex(tuple(origin[k] + u[k] * i / N + v[k] * j / N for k in range(3))) for j in range(N + 1)]
            for i in range(N + 1)]
    for i in range(N):
        for j in range(N):
            a, b, c, d = grid[i][j], grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1]
            # Alternate the diagonal so the cage has no preferred direction.
            triangles += [(a, b, c), (a, c, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, c, d)]


def shape(p):
    x, y, z = p
    r = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / r, y / r, z / r  # onto the sphere
    x, y, z = 1.05 * x, 0.9 * y, 0.95 * z  # a slightly wide head
    if z > 0.5 and y < 0.2:  # muzzle
        z += 0.45 * (z - 0.5)
    if y < -0.6:  # flat base where the neck would be
        y = -0.6 - 0.3 * (y + 0.6)
    return (x, y, z)


# Ears: the cage vertex nearest each ear direction becomes a tip, pulled far out along it.
def unit(p):
    r = math.sqrt(sum(c * c for c in p))
    return tuple(c / r for c in p)


positions = [shape(p) for p in vertices]
for side in (-1, 1):
    direction = unit((0.6 * side, 0.8, -0.05))
    tip = max(range(len(vertices)), key=lambda i: sum(a * b for a, b in zip(unit(vertices[i]), direction)))
    positions[tip] = tuple(c + 0.9 * d for c, d in zip(positions[tip], direction))

with open("default.obj", "w") as out:
    out.write("# rgbsub default mesh: a coarse control cage of a cat-like head, made by\n"
              "# assets/make_default_mesh.py (a deformed cube-sphere). Subdivide it to see the surface.\n")
    for p in positions:
        out.write("v %.6f %.6f %.6f\n" % p)
    for t in triangles:
        out.write("f %d %d %d\n" % tuple(i + 1 for i in t))
print(len(vertices), "vertices", len(triangles), "triangles")
