#!/usr/bin/env python3
"""Prints a fingerprint of each OBJ's surface that no storage order reaches: its triangles as triples
of vertex lines (the `v` text, so positions to the bit), each turned to start at its least corner
(orientation kept), sorted. Two outputs of rgbsub with the same fingerprint are the same mesh, even
where the vertex and face order in the file differ (a run over a mesh with detail reuses the slots
the removals freed, so its file lists them in another order).

  canonical_obj.py FILE.obj...      one line per file: sha256 of the canonical form, then the name
"""
import hashlib
import sys

for path in sys.argv[1:]:
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith('v '):
                vertices.append(line.strip())
            elif line.startswith('f '):
                corners = [vertices[int(w.split('/')[0]) - 1] for w in line.split()[1:]]
                least = corners.index(min(corners))
                faces.append('|'.join(corners[least:] + corners[:least]))
    faces.sort()
    print(hashlib.sha256('\n'.join(faces).encode()).hexdigest(), path)
