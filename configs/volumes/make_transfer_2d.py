#!/usr/bin/env python3
"""Writes transfer_2d.png: a 2D transfer table (Kniss, Kindlmann & Hansen 2002) for
volume_visualize's transfer_table, 33 densities (x, 0 to 1) by 9 gradient magnitudes (up the
image, 0 at the bottom row to gradient_max at the top): the colour runs from blue at low
density to orange at high, the opacity rises with the gradient's magnitude, so the
boundaries between materials show and uniform regions stay faint."""
import struct
import zlib

WIDTH, HEIGHT = 33, 9

rows = []
for y in range(HEIGHT):
    gradient = (HEIGHT - 1 - y) / (HEIGHT - 1)  # the top row: gradient_max
    row = bytearray([0])  # PNG filter: none
    for x in range(WIDTH):
        density = x / (WIDTH - 1)
        colour = (0.2 + 0.8 * density, 0.45 + 0.2 * density, 1.0 - 0.8 * density)
        opacity = 0.0 if density < 0.02 else 0.02 + 0.28 * gradient
        row += bytes(round(255 * v) for v in (*colour, opacity))
    rows.append(bytes(row))


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", WIDTH, HEIGHT, 8, 6, 0, 0, 0))
png += chunk(b"IDAT", zlib.compress(b"".join(rows), 9)) + chunk(b"IEND", b"")
with open("transfer_2d.png", "wb") as f:
    f.write(png)
