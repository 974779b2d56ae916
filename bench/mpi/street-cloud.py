#!/usr/bin/env python3
"""A long synthetic scene for the distributed reconstruction (issue: clouds bigger than one node):
a street of boxes and upright cylinders in a row along z, the axis the slabs cut, every surface
sampled uniformly with the same density. Deterministic (a fixed seed).

    street-cloud.py OUT.xyz [POINTS] [OBJECTS]

Prints the points written and the scene's length. The objects are 0.6-1.0 wide and 0.5 apart
along z: the model is OBJECTS closed pieces of genus 0."""
import math
import random
import sys


def box_points(rng, centre, size, count, out):
    sx, sy, sz = size
    areas = [sy * sz, sy * sz, sx * sz, sx * sz, sx * sy, sx * sy]
    total = sum(areas)
    for _ in range(count):
        u = rng.random() * total
        face = 0
        while u > areas[face]:
            u -= areas[face]
            face += 1
        a, b = rng.random() - 0.5, rng.random() - 0.5
        axis, sign = face // 2, 1.0 if face % 2 else -1.0
        p = [0.0, 0.0, 0.0]
        p[axis] = sign * 0.5 * size[axis]
        others = [k for k in range(3) if k != axis]
        p[others[0]] = a * size[others[0]]
        p[others[1]] = b * size[others[1]]
        out.append((centre[0] + p[0], centre[1] + p[1], centre[2] + p[2]))


def cylinder_points(rng, centre, radius, height, count, out):
    side, cap = 2.0 * math.pi * radius * height, math.pi * radius * radius
    total = side + 2.0 * cap
    for _ in range(count):
        u = rng.random() * total
        if u < side:
            t = rng.random() * 2.0 * math.pi
            out.append((centre[0] + radius * math.cos(t), centre[1] + (rng.random() - 0.5) * height,
                        centre[2] + radius * math.sin(t)))
        else:
            r, t = radius * math.sqrt(rng.random()), rng.random() * 2.0 * math.pi
            y = 0.5 * height if u < side + cap else -0.5 * height
            out.append((centre[0] + r * math.cos(t), centre[1] + y, centre[2] + r * math.sin(t)))


def main():
    path = sys.argv[1]
    points = int(sys.argv[2]) if len(sys.argv) > 2 else 200000
    objects = int(sys.argv[3]) if len(sys.argv) > 3 else 12
    rng = random.Random(7)
    sizes = []
    for k in range(objects):
        if k % 2 == 0:
            sizes.append((0.6 + 0.4 * rng.random(), 0.8 + 0.4 * rng.random(), 0.6 + 0.4 * rng.random()))
        else:
            sizes.append(0.3 + 0.2 * rng.random())
    areas = []
    for k, s in enumerate(sizes):
        areas.append(2.0 * (s[0] * s[1] + s[1] * s[2] + s[0] * s[2]) if k % 2 == 0
                     else 2.0 * math.pi * s * 1.0 + 2.0 * math.pi * s * s)
    density = points / sum(areas)
    out, z = [], 0.0
    for k in range(objects):
        count = int(density * areas[k])
        if k % 2 == 0:
            size = sizes[k]
            box_points(rng, (0.0, 0.0, z + 0.5 * size[2]), size, count, out)
            z += size[2] + 0.5
        else:
            radius = sizes[k]
            cylinder_points(rng, (0.0, 0.0, z + radius), radius, 1.0, count, out)
            z += 2.0 * radius + 0.5
    with open(path, "w") as f:
        for p in out:
            f.write("%.7f %.7f %.7f\n" % p)
    print("%d points, %d objects, length %.2f along z" % (len(out), objects, z - 0.5))


if __name__ == "__main__":
    main()
