#!/usr/bin/env python3
# configs/weather/fronts.png: a tileable 128×128 weather map (docs/clouds.md "Weather map"):
# r coverage multiplier, a front along a diagonal band with a gap of clear sky; g cloud type,
# cumulonimbus in the front's core, stratus at its edges. Periodic in x and y: no seam.
import math, struct, zlib

N = 128

def texel(x, y):
    u, v = x / N, y / N
    band = 0.5 + 0.5 * math.cos(2 * math.pi * (u + v))             # one front across the tile
    gap = 0.5 + 0.5 * math.cos(2 * math.pi * (u - v))              # clear where the front breaks
    r = max(0.0, min(1.0, 1.6 * band * (0.35 + 0.65 * gap) - 0.15))
    g = max(0.0, min(1.0, band ** 3))
    return int(round(r * 255)), int(round(g * 255)), 0

def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

rows = b"".join(b"\0" + bytes(c for x in range(N) for c in texel(x, y)) for y in range(N))
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", N, N, 8, 2, 0, 0, 0)) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")
open(__file__.replace("make_fronts.py", "fronts.png"), "wb").write(png)
