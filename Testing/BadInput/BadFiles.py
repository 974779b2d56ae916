"""Bad input files for the bad-input suite (BadInputCases.py): each function returns the bytes of one file."""
import math
import struct


def rows(points, fmt="%.9f %.9f %.9f\n"):
    return "".join(fmt % tuple(p) for p in points).encode()


def sphere_points(n=400):
    """Golden-angle points on the unit sphere."""
    out = []
    for k in range(n):
        z = -1 + 2 * (k + 0.5) / n
        r = math.sqrt(1 - z * z)
        out.append((r * math.cos(2.4 * k), r * math.sin(2.4 * k), z))
    return out


def sphere(n=400):
    return rows(sphere_points(n))


def with_line(n, k, line):
    lines = sphere(n).decode().splitlines(True)
    lines[k] = line
    return "".join(lines).encode()


def tilted_disc():
    """A filled disc in the plane x + y + z = 0, written with 6 decimals (off the plane by rounding only)."""
    u = (1 / math.sqrt(2), -1 / math.sqrt(2), 0.0)
    v = (1 / math.sqrt(6), 1 / math.sqrt(6), -2 / math.sqrt(6))
    pts = []
    for i in range(30):
        for j in range(30):
            a, b = -1 + 2 * i / 29, -1 + 2 * j / 29
            if a * a + b * b <= 1:
                pts.append(tuple(a * u[c] + b * v[c] for c in range(3)))
    return rows(pts, "%.6f %.6f %.6f\n")


def ply_header(fmt, n, props="property float x\nproperty float y\nproperty float z\n", faces=0):
    face = "element face %d\nproperty list uchar int vertex_indices\n" % faces if faces else ""
    return ("ply\nformat %s 1.0\nelement vertex %d\n%s%send_header\n" % (fmt, n, props, face)).encode()


CORNERS = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)] * 25
ASCII_ROWS = "".join("%g %g %g\n" % p for p in CORNERS).encode()
BINARY_ROWS = b"".join(struct.pack("<fff", *p) for p in CORNERS)
TETRA_FACES = struct.pack("<Biii", 3, 0, 1, 2) * 4

DAMAGED_PLY = {
    "truncated-ascii": (ply_header("ascii", 100) + ASCII_ROWS[: len(ASCII_ROWS) // 2], "50 of the 100 vertex"),
    "short-vertex-line": (ply_header("ascii", 100) + b"0 0\n" + ASCII_ROWS.split(b"\n", 1)[1], "vertex 0 has 2 numbers"),
    "faces-without-xyz": (ply_header("ascii", 3, "property float a\nproperty float b\n", 1) + b"0 0\n1 0\n0 1\n3 0 1 2\n",
                          "no scalar 'x'"),
    "only-x": (ply_header("ascii", 3, "property float x\n", 1) + b"0\n1\n2\n3 0 1 2\n", "no scalar 'y'"),
    "truncated-binary": (ply_header("binary_little_endian", 100) + BINARY_ROWS[:601], "50 of the 100 vertex"),
    "truncated-binary-faces": (ply_header("binary_little_endian", 100, faces=8) + BINARY_ROWS + TETRA_FACES,
                               "4 of the 8 face"),
    "no-magic": (b"solid cube\n", "does not start with the line 'ply'"),
}


def garbage(n=4000):
    return bytes((k * 37 + 11) % 256 for k in range(n))
