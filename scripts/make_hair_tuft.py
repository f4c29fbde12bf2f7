#!/usr/bin/python3
"""Writes scenes/meshes/tuft.hair: a tuft of 1,500 hairs for scenes/hair.json.

Each hair is one cubic Bezier segment (4 points, a HAIR file strand of 3 segments read with
"basis": "bezier"): it leaves the top of a sphere of radius 0.5 at (0, 0.5, 0) along the
normal and falls under gravity, so its points lie on the scalp, a little out along the normal,
further out and down, and below. Its thickness runs from 0.004 at the root to 0.001 at the tip.
The random numbers are Python's seeded Mersenne Twister: the file is the same on every run.

Usage: make_hair_tuft.py [OUTPUT]   (default: scenes/meshes/tuft.hair beside this script's folder)
"""
import math
import pathlib
import random
import struct
import sys

HAIRS = 1500


def hair(rng):
    # A root on the cap within 50 degrees of the top, uniform in area.
    cos_theta = rng.uniform(math.cos(math.radians(50)), 1.0)
    sin_theta = math.sqrt(1 - cos_theta * cos_theta)
    phi = rng.uniform(0, 2 * math.pi)
    n = (sin_theta * math.cos(phi), cos_theta, sin_theta * math.sin(phi))
    root = tuple(0.5 * c + (0.5 if i == 1 else 0.0) for i, c in enumerate(n))
    length = rng.uniform(0.7, 1.0)
    out = (n[0], 0.0, n[2])
    norm = math.hypot(out[0], out[2]) or 1.0
    out = (out[0] / norm, 0.0, out[2] / norm)
    p1 = tuple(root[i] + n[i] * 0.15 * length for i in range(3))
    p2 = tuple(root[i] + n[i] * 0.2 * length + out[i] * 0.25 * length - (0.15 * length if i == 1 else 0) for i in range(3))
    p3 = tuple(root[i] + out[i] * 0.35 * length - (0.75 * length if i == 1 else 0) + rng.uniform(-0.03, 0.03)
               for i in range(3))
    return [root, p1, p2, p3]


def main():
    here = pathlib.Path(__file__).resolve().parent.parent
    output = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here / "scenes" / "meshes" / "tuft.hair"
    rng = random.Random(1)
    strands = [hair(rng) for _ in range(HAIRS)]
    points = [p for s in strands for p in s]
    thickness = [0.004 - 0.003 * i / 3 for _ in strands for i in range(4)]
    # cyHairFile's header: signature, hair count, point count, arrays (segments, points,
    # thickness), default segments, thickness, transparency, colour, 88 bytes of info.
    header = b"HAIR" + struct.pack("<IIII", len(strands), len(points), 1 | 2 | 4, 0)
    header += struct.pack("<ff3f", 0, 0, 0, 0, 0) + b"photon tuft".ljust(88, b"\0")
    body = b"".join(struct.pack("<H", 3) for _ in strands)
    body += b"".join(struct.pack("<3f", *p) for p in points)
    body += b"".join(struct.pack("<f", t) for t in thickness)
    output.write_bytes(header + body)


if __name__ == "__main__":
    main()
