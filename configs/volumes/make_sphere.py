#!/usr/bin/env python3
"""Writes sphere.nrrd: the sphere phantom (shaders/include/volume_phantom.h's ramp,
density = clamp(0.5 + (0.35 - r) / 0.1, 0, 1) in the unit box) sampled at the texel centres
of a 24 x 24 x 12 uchar grid whose z spacing is twice x's and y's (space directions), so the
samples span a cube and volume_visualize's `box: volume_data` draws a round sphere."""
import math

SIZES = (24, 24, 12)
RADIUS, SHELL = 0.35, 0.1

samples = bytearray()
for k in range(SIZES[2]):
    for j in range(SIZES[1]):
        for i in range(SIZES[0]):
            p = [(n + 0.5) / s - 0.5 for n, s in zip((i, j, k), SIZES)]
            r = math.sqrt(sum(c * c for c in p))
            density = min(max(0.5 + (RADIUS - r) / SHELL, 0.0), 1.0)
            samples.append(round(density * 255))

header = (
    "NRRD0004\n"
    "# the sphere phantom at 24 x 24 x 12 samples spanning a cube (configs/volumes/make_sphere.py)\n"
    "type: uchar\n"
    "dimension: 3\n"
    "space: left-posterior-superior\n"
    f"sizes: {SIZES[0]} {SIZES[1]} {SIZES[2]}\n"
    "space directions: (1,0,0) (0,1,0) (0,0,2)\n"
    "encoding: raw\n"
    "\n"
)
with open("sphere.nrrd", "wb") as f:
    f.write(header.encode("ascii"))
    f.write(bytes(samples))
