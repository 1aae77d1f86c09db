#!/usr/bin/env python3
"""Writes scenes/data/island.png, the small 16-bit DEM of scenes/heightfield.json: a volcanic
island (a cone with a crater, ridges and fBm-like sine noise), 129 x 129 samples, grey, 16 bits
(docs/heightfields.md). Pure Python (zlib): no image library needed.
Usage: python3 scenes/data/make_dem.py [OUT.png]"""
import math
import struct
import sys
import zlib

N = 129


def height(i, j):
    x = 2.0 * i / (N - 1) - 1.0
    z = 2.0 * j / (N - 1) - 1.0
    r = math.hypot(x, z)
    cone = max(0.0, 1.0 - r / 0.85) ** 1.5
    crater = 0.35 * math.exp(-((r / 0.16) ** 2))
    angle = math.atan2(z, x)
    ridges = 0.08 * math.sin(7.0 * angle + 9.0 * r) * cone
    noise = sum(0.04 / k * math.sin(k * 5.1 * x + 1.7 * k) * math.sin(k * 4.3 * z + 0.9 * k)
                for k in (1, 2, 4, 8))
    return min(1.0, max(0.0, 0.08 + 0.85 * cone - crater + ridges + noise))


def png_16bit_grey(path, rows):
    raw = b"".join(b"\x00" + b"".join(struct.pack(">H", v) for v in row) for row in rows)

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", len(rows[0]), len(rows), 16, 0, 0, 0, 0)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                  chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else __file__.rsplit("/", 1)[0] + "/island.png"
    png_16bit_grey(out, [[round(65535 * height(i, j)) for i in range(N)] for j in range(N)])
