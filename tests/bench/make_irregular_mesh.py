#!/usr/bin/env python3
"""Writes the irregular benchmark meshes of the budget benchmark (budget_speed.sh), deterministically.

  make_irregular_mesh.py scan BUNNY.obj OUT.obj   a scan-like mesh of 58,784 triangles: the bunny
      split 1-to-4 twice (flat midpoints), every vertex moved within its surface by up to 0.35 of its
      shortest edge and off it by noise, then a third of the edges flipped where that folds nothing
      (valences 3 to 12, triangles of very different sizes and shapes, as a scanner's mesh has)
  make_irregular_mesh.py mixed U V OUT.obj        a closed torus of 2UV triangles whose rows and columns
      grow geometrically (the largest triangles about 400 times the smallest's edge length): very
      large and very small triangles in one mesh

Plain Python (no numpy), a fixed seed: the same file on every machine.
"""
import math
import random
import sys


def read_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == 'v':
                vertices.append([float(x) for x in w[1:4]])
            elif w[0] == 'f':
                faces.append([int(x.split('/')[0]) - 1 for x in w[1:4]])
    return vertices, faces


def write_obj(path, vertices, faces):
    with open(path, 'w') as f:
        for v in vertices:
            f.write('v %r %r %r\n' % tuple(v))
        for t in faces:
            f.write('f %d %d %d\n' % (t[0] + 1, t[1] + 1, t[2] + 1))


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a):
    return math.sqrt(dot(a, a))


def split_1_to_4(vertices, faces):
    mid = {}
    out = []

    def m(a, b):
        key = (min(a, b), max(a, b))
        if key not in mid:
            mid[key] = len(vertices)
            vertices.append([(vertices[a][i] + vertices[b][i]) / 2 for i in range(3)])
        return mid[key]

    for a, b, c in faces:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        out += [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
    return out


def face_normal(vertices, t):
    return cross(sub(vertices[t[1]], vertices[t[0]]), sub(vertices[t[2]], vertices[t[0]]))


def scan(bunny, out_path):
    rng = random.Random(29)
    vertices, faces = read_obj(bunny)
    for _ in range(2):
        faces = split_1_to_4(vertices, faces)
    # Normals and shortest edges per vertex, for the jitter.
    normal = [[0.0, 0.0, 0.0] for _ in vertices]
    shortest = [math.inf] * len(vertices)
    for t in faces:
        n = face_normal(vertices, t)
        for i in range(3):
            a, b = t[i], t[(i + 1) % 3]
            normal[a] = [normal[a][k] + n[k] for k in range(3)]
            length = norm(sub(vertices[a], vertices[b]))
            shortest[a] = min(shortest[a], length)
            shortest[b] = min(shortest[b], length)
    moved = []
    for v, n, s in zip(vertices, normal, shortest):
        n = [x / (norm(n) or 1.0) for x in n]
        d = [rng.gauss(0, 1) for _ in range(3)]
        d = sub(d, [dot(d, n) * x for x in n])  # within the surface
        d = [x / (norm(d) or 1.0) * s * 0.35 * rng.random() for x in d]
        off = rng.gauss(0, 0.05) * s
        moved.append([v[k] + d[k] + off * n[k] for k in range(3)])
    vertices = moved
    # Edge flips: an edge (a, b) between (a, b, c) and (b, a, d) becomes (c, d) unless (c, d) exists
    # already or a new triangle turns against the old ones.
    edges = {}
    for fi, t in enumerate(faces):
        for i in range(3):
            edges[(t[i], t[(i + 1) % 3])] = fi
    keys = sorted(edges)
    rng.shuffle(keys)
    for a, b in keys:
        if rng.random() > 0.33 or (a, b) not in edges or (b, a) not in edges:
            continue
        f, g = edges[(a, b)], edges[(b, a)]
        c = next(x for x in faces[f] if x not in (a, b))
        d = next(x for x in faces[g] if x not in (a, b))
        if c == d or (c, d) in edges or (d, c) in edges:
            continue
        n_old = face_normal(vertices, faces[f])
        t1, t2 = [c, a, d], [d, b, c]
        n1, n2 = face_normal(vertices, t1), face_normal(vertices, t2)
        if dot(n1, n_old) <= 0 or dot(n2, n_old) <= 0 or dot(n1, n2) <= 0:
            continue
        for t in (faces[f], faces[g]):
            for i in range(3):
                del edges[(t[i], t[(i + 1) % 3])]
        faces[f], faces[g] = t1, t2
        for fi in (f, g):
            t = faces[fi]
            for i in range(3):
                edges[(t[i], t[(i + 1) % 3])] = fi
    write_obj(out_path, vertices, faces)


def mixed(u, v, out_path):
    # Cumulative angles whose steps grow geometrically by `ratio` over the rows: the torus closes
    # with its finest row next to its coarsest.
    def angles(n, ratio):
        steps = [ratio ** (i / (n - 1)) for i in range(n)]
        total = sum(steps)
        acc, out = 0.0, []
        for s in steps:
            out.append(2 * math.pi * acc / total)
            acc += s
        return out

    au, av = angles(u, 400.0), angles(v, 20.0)
    vertices = []
    for a in au:
        for b in av:
            bump = 0.08 * math.sin(5 * a + 3 * b) + 0.05 * math.cos(11 * a - 7 * b)
            r = 1.0 + (0.4 + bump) * math.cos(b)
            vertices.append([r * math.cos(a), r * math.sin(a), (0.4 + bump) * math.sin(b)])
    faces = []
    for i in range(u):
        for j in range(v):
            p, q = i * v + j, ((i + 1) % u) * v + j
            r, s = ((i + 1) % u) * v + (j + 1) % v, i * v + (j + 1) % v
            faces += [[p, q, r], [p, r, s]]
    write_obj(out_path, vertices, faces)


if __name__ == '__main__':
    if len(sys.argv) == 4 and sys.argv[1] == 'scan':
        scan(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 5 and sys.argv[1] == 'mixed':
        mixed(int(sys.argv[2]), int(sys.argv[3]), sys.argv[4])
    else:
        sys.exit(__doc__)
