#!/usr/bin/env python3
"""Writes scenes/data/planet.raw, the small procedural volume of scenes/voxels.json
(docs/voxels.md): a ringed planet, 64 x 32 x 64 voxels of u8 (128 KiB), raw little-endian, x
fastest, then y, then z. Each voxel holds a smooth field that crosses 0.5 (128) on the surface
and rises inward over about two voxels: a ball of radius 0.42 with sine bumps, and a thin ring
(a flattened torus of radius 0.78) in the x-z plane, in a box [-1, 1] x [-0.5, 0.5] x [-1, 1].
Pure Python: no numpy needed.
Usage: python3 scenes/data/make_volume.py [OUT.raw]"""
import math
import sys

NX, NY, NZ = 64, 32, 64
VOXEL = 2.0 / NX  # the box is 2 x 1 x 2: cubic voxels


def signed_distance(x, y, z):
    """Distance to the surface, positive inside (approximately, for the bumps)."""
    r = math.sqrt(x * x + y * y + z * z)
    bumps = 0.025 * math.sin(9.0 * x + 1.3) * math.sin(11.0 * y) * math.sin(8.0 * z + 0.4)
    ball = 0.42 + bumps - r
    # The ring: a torus whose tube is squashed to a thin disk (3 x thinner in y).
    radial = math.hypot(x, z) - 0.78
    ring = 0.1 - math.hypot(radial * 0.8, y * 3.0)
    return max(ball, ring)


def value(i, j, k):
    x = -1.0 + (i + 0.5) * VOXEL
    y = -0.5 + (j + 0.5) * VOXEL
    z = -1.0 + (k + 0.5) * VOXEL
    v = 0.5 + signed_distance(x, y, z) / (4.0 * VOXEL)
    return round(255 * min(1.0, max(0.0, v)))


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else __file__.rsplit("/", 1)[0] + "/planet.raw"
    data = bytes(value(i, j, k) for k in range(NZ) for j in range(NY) for i in range(NX))
    assert len(data) == NX * NY * NZ
    with open(out, "wb") as f:
        f.write(data)
