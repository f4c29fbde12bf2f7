#!/usr/bin/env python3
"""Writes scenes/textures/sky.pfm: a 64x32 lat-long environment map (docs/scene-format.md)
of a procedural sky with a bright sun, for scenes/envmap.json. Linear radiance, float RGB.

The sky grades from a pale horizon to a blue zenith; the ground below the horizon is a dim
brown; the sun is a patch of about 4 texels at 35 degrees elevation toward -x (the left of
photon's default camera, which looks down -z), holding about three times the sky's
irradiance on a horizontal surface.

PFM (Netpbm float map): header "PF", width height, scale (negative: little-endian), then
rows bottom to top. Run from anywhere: python3 scripts/make_sky_map.py
"""
import math
import os
import struct

WIDTH, HEIGHT = 64, 32
SUN_ELEVATION = math.radians(35)
SUN_AZIMUTH_U = 0.25  # u = 1/4 faces -x (lat-long convention of docs/scene-format.md)
SUN_RADIUS = math.radians(4.5)
SUN = (150.0, 140.0, 120.0)


def direction(u, v):
    """The lat-long convention: theta = pi v from +y, phi = 2 pi u."""
    theta, phi = math.pi * v, 2 * math.pi * u
    return (-math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))


def radiance(u, v):
    d = direction(u, v)
    sun = direction(SUN_AZIMUTH_U, 0.5 - SUN_ELEVATION / math.pi)
    if math.acos(max(-1.0, min(1.0, sum(a * b for a, b in zip(d, sun))))) < SUN_RADIUS:
        return SUN
    if d[1] < 0:
        return (0.12, 0.10, 0.08)
    t = d[1] ** 0.5  # 0 at the horizon, 1 at the zenith
    horizon, zenith = (0.85, 0.88, 0.92), (0.22, 0.38, 0.80)
    return tuple(h + (z - h) * t for h, z in zip(horizon, zenith))


def main():
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    path = os.path.join(root, "scenes", "textures", "sky.pfm")
    data = bytearray(b"PF\n%d %d\n-1.0\n" % (WIDTH, HEIGHT))
    for row in reversed(range(HEIGHT)):  # PFM stores the bottom row first
        for column in range(WIDTH):
            data += struct.pack("<3f", *radiance((column + 0.5) / WIDTH, (row + 0.5) / HEIGHT))
    with open(path, "wb") as f:
        f.write(data)
    print(path, len(data), "bytes")


if __name__ == "__main__":
    main()
