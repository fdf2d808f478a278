#!/usr/bin/python3
"""Helpers of editor_dense_mesh_window_test.sh (Debian's python3: numpy), independent of rgbsub's code:
  torus N M OUT.obj       a bumped torus of 2*N*M triangles, as tests/app/small_meshes.cpp writes it
  on_mesh DENSE.obj SAVED.obj
                          every vertex of SAVED lies on DENSE's triangles: prints the largest closest-point
                          distance over the bounding-box diagonal of DENSE, fails above 1e-6
  same_mesh A.obj B.obj   the same vertex positions (exactly) and faces, in the same order
  grab OUT.png            the whole X screen ($DISPLAY) as a PNG, to look at
"""
import ctypes
import struct
import sys
import zlib

import numpy as np


def read_obj(path):
    vertices, faces = [], []
    with open(path) as lines:
        for line in lines:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                vertices.append([float(w) for w in words[1:4]])
            elif words[0] == "f":
                faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])
    return np.array(vertices), np.array(faces, dtype=np.int64)


def torus(n, m, out):
    # The same bumps as small_meshes.cpp's write_torus, so that a cage has detail to keep.
    u = 2.0 * np.pi * np.repeat(np.arange(n), m) / n
    v = 2.0 * np.pi * np.tile(np.arange(m), n) / m
    r = 0.3 + 0.01 * np.sin(7.0 * u) * np.sin(5.0 * v)
    points = np.stack([(1.0 + r * np.cos(v)) * np.cos(u), (1.0 + r * np.cos(v)) * np.sin(u), r * np.sin(v)], axis=1)
    i, j = np.repeat(np.arange(n), m), np.tile(np.arange(m), n)
    vid = lambda i, j: (i % n) * m + j % m + 1
    faces = np.stack([vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j), vid(i + 1, j + 1), vid(i, j + 1)], axis=1).reshape(-1, 3)
    with open(out, "w") as obj:
        obj.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in points.tolist())
        obj.writelines(f"f {a} {b} {c}\n" for a, b, c in faces.tolist())


def closest_distances(points, a, b, c):
    """Distance from each point to the nearest of the triangles (a, b, c): Ericson's closest point on a
    triangle (Real-Time Collision Detection 5.1.5), every point against every triangle, in chunks."""
    ab, ac = b - a, c - a
    best = np.full(len(points), np.inf)
    for start in range(0, len(points), 64):
        p = points[start:start + 64, None, :]
        ap, bp, cp = p - a, p - b, p - c
        d1, d2 = (ab * ap).sum(-1), (ac * ap).sum(-1)
        d3, d4 = (ab * bp).sum(-1), (ac * bp).sum(-1)
        d5, d6 = (ab * cp).sum(-1), (ac * cp).sum(-1)
        va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
        with np.errstate(divide="ignore", invalid="ignore"):
            denominator = va + vb + vc
            v_in, w_in = vb / denominator, vc / denominator
            t_ab, t_ac = d1 / (d1 - d3), d2 / (d2 - d6)
            t_bc = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        # Regions in Ericson's order: the first that applies wins.
        cases = [
            ((d1 <= 0) & (d2 <= 0), 0.0, 0.0),
            ((d3 >= 0) & (d4 <= d3), 1.0, 0.0),
            ((vc <= 0) & (d1 >= 0) & (d3 <= 0), t_ab, 0.0),
            ((d6 >= 0) & (d5 <= d6), 0.0, 1.0),
            ((vb <= 0) & (d2 >= 0) & (d6 <= 0), 0.0, t_ac),
            ((va <= 0) & ((d4 - d3) >= 0) & ((d5 - d6) >= 0), 1.0 - t_bc, t_bc),
        ]
        v, w = v_in, w_in
        for condition, cv, cw in reversed(cases):
            v = np.where(condition, cv, v)
            w = np.where(condition, cw, w)
        closest = a + ab * v[..., None] + ac * w[..., None]
        best[start:start + 64] = np.sqrt(((p - closest) ** 2).sum(-1)).min(axis=1)
    return best


def on_mesh(dense_path, saved_path):
    dense, faces = read_obj(dense_path)
    saved, _ = read_obj(saved_path)
    diagonal = np.linalg.norm(dense.max(axis=0) - dense.min(axis=0))
    distances = closest_distances(saved, dense[faces[:, 0]], dense[faces[:, 1]], dense[faces[:, 2]]) / diagonal
    worst = distances.max()
    print(f"{len(saved)} vertices of {saved_path}: largest distance to {dense_path} {worst:.3g} of its diagonal")
    return worst <= 1e-6


def same_mesh(a_path, b_path):
    (a, a_faces), (b, b_faces) = read_obj(a_path), read_obj(b_path)
    same = a.shape == b.shape and a_faces.shape == b_faces.shape and (a == b).all() and (a_faces == b_faces).all()
    print(f"{a_path} ({len(a)} vertices, {len(a_faces)} faces) and {b_path} ({len(b)}, {len(b_faces)}): "
          + ("the same mesh" if same else "different"))
    return same


def screen():
    """The X screen as an array of rows of RGB bytes (24-bit TrueColor)."""
    class XImage(ctypes.Structure):
        _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("xoffset", ctypes.c_int), ("format", ctypes.c_int),
                    ("data", ctypes.POINTER(ctypes.c_ubyte)), ("byte_order", ctypes.c_int), ("bitmap_unit", ctypes.c_int),
                    ("bitmap_bit_order", ctypes.c_int), ("bitmap_pad", ctypes.c_int), ("depth", ctypes.c_int),
                    ("bytes_per_line", ctypes.c_int), ("bits_per_pixel", ctypes.c_int)]
    xlib = ctypes.cdll.LoadLibrary("libX11.so.6")
    xlib.XOpenDisplay.restype = ctypes.c_void_p
    xlib.XOpenDisplay.argtypes = [ctypes.c_char_p]
    xlib.XDefaultRootWindow.restype = ctypes.c_ulong
    xlib.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
    xlib.XDisplayWidth.argtypes = xlib.XDisplayHeight.argtypes = [ctypes.c_void_p, ctypes.c_int]
    xlib.XGetImage.restype = ctypes.POINTER(XImage)
    xlib.XGetImage.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int, ctypes.c_uint, ctypes.c_uint,
                               ctypes.c_ulong, ctypes.c_int]
    display = xlib.XOpenDisplay(None)
    if not display:
        sys.exit("dense_mesh_window.py: cannot open the display")
    width, height = xlib.XDisplayWidth(display, 0), xlib.XDisplayHeight(display, 0)
    image = xlib.XGetImage(display, xlib.XDefaultRootWindow(display), 0, 0, width, height, 0xFFFFFFFF, 2).contents
    if image.bits_per_pixel != 32 or image.byte_order != 0:
        sys.exit("dense_mesh_window.py: expects a 24-bit little-endian TrueColor screen")
    raw = np.ctypeslib.as_array(image.data, shape=(height, image.bytes_per_line))
    return raw[:, :4 * width].reshape(height, width, 4)[:, :, 2::-1].copy()  # BGRX to RGB


def grab(out):
    pixels = screen()
    height, width, _ = pixels.shape
    rows = b"".join(b"\0" + pixels[y].tobytes() for y in range(height))
    chunk = lambda kind, data: struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    with open(out, "wb") as png:
        png.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                  + chunk(b"IDAT", zlib.compress(rows, 6)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    command, args = sys.argv[1], sys.argv[2:]
    if command == "torus":
        torus(int(args[0]), int(args[1]), args[2])
        ok = True
    elif command == "on_mesh":
        ok = on_mesh(*args)
    elif command == "same_mesh":
        ok = same_mesh(*args)
    elif command == "grab":
        grab(args[0])
        ok = True
    else:
        sys.exit(__doc__)
    sys.exit(0 if ok else 1)
