"""Writes the seed corpora of the fuzz targets (run.sh): valid and nearly valid inputs."""
import os
import struct
import sys

root = sys.argv[1]
os.makedirs(os.path.join(root, "expression"), exist_ok=True)
for folder in ("cloud", "xyz", "ply"):
    os.makedirs(os.path.join(root, folder), exist_ok=True)
formulas = ["max(1 - x^2 - y^2, 0)", "-2*pi*(y - 0.5)", "(a1^2 + a2^2)/2",
            "hypot(x, y) <= 1 ? (hypot(x, y) - 1)^2 / (2*t) : 0", "clamp(sin(x)*cos(y), -0.5, 0.5) + atan2(y, x)",
            "if(x > 0 && !(y < 1) || z == 2, log(abs(x) + 1e-9), sqrt(fmod(a1, 3)))", "min(a1, a2, a3, -x ** 2 % 7)",
            "2 - y^2/2 + a1", "exp(-((x-0.3)^2 + (y-0.7)^2)/0.01)", "sign(x)*floor(y)+ceil(z)-round(t)+cbrt(a2)"]
for k, f in enumerate(formulas):
    open(os.path.join(root, "expression", "seed%d" % k), "w").write(f)

corners = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (0.5, 0.5, 0.5)]
text = "x,y,z\n" + "".join("%g %g %g 0 0 1\n" % p for p in corners) + "# comment\n1e-3, 2.5; -4\n"
header = "ply\nformat %s 1.0\ncomment seed\nelement vertex 5\nproperty float x\nproperty float y\n" \
         "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
ascii_ply = header % "ascii" + "".join("%g %g %g\n" % p for p in corners) + "3 0 1 2\n3 0 2 3\n"
binary = (header % "binary_little_endian").encode() + b"".join(struct.pack("<fff", *p) for p in corners) + \
         struct.pack("<Biii", 3, 0, 1, 2) + struct.pack("<Biii", 3, 0, 2, 3)
big = (header % "binary_big_endian").encode() + b"".join(struct.pack(">fff", *p) for p in corners) + \
      struct.pack(">Biii", 3, 0, 1, 2) + struct.pack(">Biii", 3, 0, 2, 3)
seeds = [b"\x00" + text.encode(), b"\x01" + ascii_ply.encode(), b"\x01" + binary, b"\x01" + big,
         b"\x01" + (header % "ascii").replace("element face 2\n", "element face 0\n").encode() + b"0 0 0\n" * 5]
for k, s in enumerate(seeds):
    open(os.path.join(root, "cloud", "seed%d" % k), "wb").write(s)  # first byte: the reader
    open(os.path.join(root, "xyz" if s[0] == 0 else "ply", "seed%d" % k), "wb").write(s[1:])
