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
    "short-vertex-line": (ply_header("ascii", 100) + b"0 0\n" + ASCII_ROWS.split(b"\n", 1)[1], "vertex 0 has only 2 numbers"),
    "faces-without-xyz": (ply_header("ascii", 3, "property float a\nproperty float b\n", 1) + b"0 0\n1 0\n0 1\n3 0 1 2\n",
                          "no scalar 'x'"),
    "only-x": (ply_header("ascii", 3, "property float x\n", 1) + b"0\n1\n2\n3 0 1 2\n", "no scalar 'y'"),
    "truncated-binary": (ply_header("binary_little_endian", 100) + BINARY_ROWS[:601], "50 of the 100 vertex"),
    "truncated-binary-faces": (ply_header("binary_little_endian", 100, faces=8) + BINARY_ROWS + TETRA_FACES,
                               "4 of the 8 face"),
    "no-magic": (b"solid cube\n", "does not start with the line 'ply'"),
    # vtkPLYReader reads the points a face names without a bounds check (found by bench/fuzz: a crash)
    "face-index-beyond-vertices": (ply_header("binary_little_endian", 100, faces=4) + BINARY_ROWS +
                                   struct.pack("<Biii", 3, 0, 1, 2) * 3 + struct.pack("<Biii", 3, 0, 134217729, 2),
                                   "face 3 names vertex 134217729, but there are 100 vertices"),
    "negative-face-index-ascii": (ply_header("ascii", 100, faces=1) + ASCII_ROWS + b"3 0 -1 2\n",
                                  "face 0 names vertex -1"),
    "faces-without-vertex-indices": (ply_header("binary_little_endian", 100).replace(
        b"end_header", b"element face 1\nproperty list uchar int vertex_ids\nend_header") + BINARY_ROWS +
        struct.pack("<Biii", 3, 0, 1, 2), "its faces have no 'vertex_indices' list"),
    # VTK's header parser reads this as a face element without properties, then crashes (bench/fuzz)
    "header-words-run-together": (ply_header("binary_big_endian", 100).replace(
        b"end_header", b"element face 0Jproperty list uchar int vertex_indices\nend_header") + BINARY_ROWS,
        "bad element in header line"),
    "element-without-property": (ply_header("ascii", 100).replace(b"end_header", b"element edge 0\nend_header") +
                                 ASCII_ROWS, "the element 'edge' has no property"),
    "blank-line-in-data": (ply_header("ascii", 100) + b"0 0 0\n\n" + ASCII_ROWS.split(b"\n", 1)[1],
                           "a blank line where vertex 1 was expected"),
    "nul-bytes-in-ascii-data": (ply_header("ascii", 100, faces=1) + ASCII_ROWS + b"3 0 1 2\0\0\0 7\n",
                                "binary data (a NUL byte) in a text line, in face 0"),
    "vertex-element-twice": (ply_header("ascii", 100).replace(b"end_header", b"element vertex 0\nproperty float x\nend_header")
                             + ASCII_ROWS, "the element 'vertex' is declared twice"),
    "no-final-line-end": (ply_header("ascii", 100) + ASCII_ROWS.rstrip(b"\n"), "the line of vertex 99 has no line end"),
    "blank-line-in-header": (ply_header("ascii", 100).replace(b"element vertex", b"\t\nelement vertex") + ASCII_ROWS,
                             "a blank line in the header, at line 3"),
    "element-before-vertices": (ply_header("binary_little_endian", 100).replace(
        b"element vertex", b"element scan 1\nproperty int id\nelement vertex") + b"\0\0\0\0" + BINARY_ROWS,
        "its element 'scan' is out of place"),
    "incomplete-face-ascii": (ply_header("ascii", 100, faces=1) + ASCII_ROWS + b"3 0 1\n", "face 0 is incomplete"),
    # VTK's parser splits words at blanks only: "3-0" is one word, and the fourth word is missing (bench/fuzz)
    # vtkPLYReader stores a list where it asked for a number: an assertion in vtkPLY::store_item (bench/fuzz)
    "vertex-property-list": (ply_header("ascii", 100, "property float x\nproperty float y\nproperty float z\n"
                             "property list uchar float normal\n") + b"".join(
                             b"%g %g %g 0\n" % p for p in CORNERS), "the vertex property 'normal' is a list"),
    "property-declared-twice": (ply_header("ascii", 100, "property float x\nproperty float y\nproperty float z\n"
                                "property float x\n") + b"".join(b"%g %g %g 0\n" % p for p in CORNERS),
                                "the property 'x' of the element 'vertex' is declared twice"),
    "second-format-line": (ply_header("ascii", 100).replace(b"element vertex", b"format binary_little_endian 1.0\n"
                           b"element vertex") + ASCII_ROWS, "a second 'format' line"),
    "face-color-list": (ply_header("binary_little_endian", 100, faces=1).replace(
        b"end_header", b"property list uchar uchar red\nend_header") + BINARY_ROWS +
        struct.pack("<BiiiB", 3, 0, 1, 2, 0), "the face property 'red' must be a number"),
    "face-words-run-together": (ply_header("ascii", 100, faces=1) + ASCII_ROWS + b"3-0 1 2\n",
                                "'3-0' is not a number, in face 0"),
}


def garbage(n=4000):
    return bytes((k * 37 + 11) % 256 for k in range(n))
