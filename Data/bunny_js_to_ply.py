"""Converts the npm `bunny` package's index.js (exports.positions / exports.cells)
to an ASCII PLY mesh and an XYZ point file. Writes each file whole or not at all."""
import json
import os
import re
import sys

source, ply_path, xyz_path = sys.argv[1:4]
text = open(source).read()
positions = json.loads(re.search(r"exports\.positions\s*=\s*(\[.*?\]\])", text, re.S).group(1))
cells = json.loads(re.search(r"exports\.cells\s*=\s*(\[.*?\]\])", text, re.S).group(1))
assert positions and cells and all(len(p) == 3 for p in positions), "unexpected bunny package layout"


def write(path, body):
    with open(path + ".part", "w") as f:
        f.write(body)
    os.replace(path + ".part", path)


header = ("ply\nformat ascii 1.0\ncomment Stanford bunny via npm package bunny@1.0.1 (public domain)\n"
          "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
          "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(positions), len(cells)))
write(ply_path, header + "".join("%r %r %r\n" % tuple(p) for p in positions)
      + "".join("3 %d %d %d\n" % tuple(c) for c in cells))
write(xyz_path, "".join("%r %r %r\n" % tuple(p) for p in positions))
print("bunny: %d points, %d triangles -> %s" % (len(positions), len(cells), ply_path))
