#!/usr/bin/env python3
"""Writes machined_part.obj: an L-shaped bracket, 4 x 3 units in plan and 2 high, with a 45-degree
chamfer on its outer corner (86 triangles). Every wall meets the caps and its neighbours at 90 degrees,
the chamfer meets its two walls at 45 degrees, and every other edge is flat, so sharp-angle tagging
has a known answer: 44 edges above 30 degrees (14 upright edges at 7 corners, 2 x 15 rim edges), 40
above 60 degrees, none above 90. Run once; the output is committed."""

HEIGHT, LAYERS = 2.0, 2
corners = []  # triangles as three (x, y, z) points; numbered once all are known


# The profile, counter-clockwise seen from +z, with a point at every unit step.
profile = [(0.5, 0), (1, 0), (2, 0), (3, 0), (4, 0), (4, 1), (3, 1), (2, 1), (1, 1), (1, 2), (1, 3), (0, 3),
           (0, 2), (0, 1), (0, 0.5)]
# The plan as cells (counter-clockwise polygons) fanned from their first point: unit squares, and the
# chamfered corner cell.
cells = [[(1, 1), (0, 1), (0, 0.5), (0.5, 0), (1, 0)]]
cells += [[(x, 0), (x + 1, 0), (x + 1, 1), (x, 1)] for x in range(1, 4)]
cells += [[(0, y), (1, y), (1, y + 1), (0, y + 1)] for y in range(1, 3)]

levels = [HEIGHT * j / LAYERS for j in range(LAYERS + 1)]
for cell in cells:
    for z, up in ((0.0, False), (HEIGHT, True)):
        points = [(float(x), float(y), z) for x, y in cell]
        for k in range(1, len(points) - 1):
            t = (points[0], points[k], points[k + 1])
            corners.append(t if up else (t[0], t[2], t[1]))
for i, (x0, y0) in enumerate(profile):
    x1, y1 = profile[(i + 1) % len(profile)]
    for j in range(LAYERS):
        a, b = (float(x0), float(y0), levels[j]), (float(x1), float(y1), levels[j])
        c, d = (float(x1), float(y1), levels[j + 1]), (float(x0), float(y0), levels[j + 1])
        corners += [(a, b, c), (a, c, d)]

# Every point is a sum of halves, exact in binary, so equal points compare equal.
vertices = sorted({p for t in corners for p in t})
number = {p: i + 1 for i, p in enumerate(vertices)}
with open("machined_part.obj", "w") as out:
    out.write("# machined_part.obj: an L-shaped bracket with a chamfered corner (assets/make_machined_part.py)\n")
    for p in vertices:
        out.write("v %g %g %g\n" % p)
    for t in corners:
        out.write("f %d %d %d\n" % tuple(number[p] for p in t))
