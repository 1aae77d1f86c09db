#!/usr/bin/env python3
"""Golden values for tests/shading/noise_test.cpp and cellular_test.cpp.

An independent double-precision reimplementation of the definitions documented in
shading/noise.h and shading/cellular.h (not a translation of the optimized C++): lowbias32 as the
hash (core/sampling.h), the chained lattice hash, value noise with the cubic 3t^2 - 2t^3, Perlin's
gradient noise (Perlin 2002: 12 edge gradients padded to 16, quintic fade, scaled by 1/1.0365 and
clamped), fBm and turbulence with per-octave seeds, and Worley's F1..F3 by brute force over the
5x5x5 block of cells. Run it and paste the printed values when a definition changes on purpose.
"""
import math

MASK = 0xFFFFFFFF


def hash_u32(x):  # lowbias32 (Chris Wellons, "Prospecting for hash functions", 2018)
    x &= MASK
    x ^= x >> 16
    x = (x * 0x7FEB352D) & MASK
    x ^= x >> 15
    x = (x * 0x846CA68B) & MASK
    x ^= x >> 16
    return x


def unit_float(h):  # the top 24 bits in [0, 1)
    return (h >> 8) / 16777216.0


def hash_3d(x, y, z, seed):
    return hash_u32(hash_u32(hash_u32(hash_u32(seed) ^ (x & MASK)) ^ (y & MASK)) ^ (z & MASK))


def lerp(a, b, t):
    return a + (b - a) * t


def trilinear(corner, s):  # corner(dx, dy, dz), weights s = (sx, sy, sz)
    def along_x(dy, dz):
        return lerp(corner(0, dy, dz), corner(1, dy, dz), s[0])
    return lerp(lerp(along_x(0, 0), along_x(1, 0), s[1]), lerp(along_x(0, 1), along_x(1, 1), s[1]),
                s[2])


def value_noise_3d(p, seed):
    i = [math.floor(c) for c in p]
    f = [p[k] - i[k] for k in range(3)]
    return trilinear(lambda dx, dy, dz: unit_float(hash_3d(i[0] + dx, i[1] + dy, i[2] + dz, seed)),
                     [t * t * (3 - 2 * t) for t in f])


GRADIENTS = [(1, 1, 0), (-1, 1, 0), (1, -1, 0), (-1, -1, 0), (1, 0, 1), (-1, 0, 1), (1, 0, -1),
             (-1, 0, -1), (0, 1, 1), (0, -1, 1), (0, 1, -1), (0, -1, -1), (1, 1, 0), (1, -1, 0),
             (-1, 1, 0), (0, -1, -1)]


def gradient_noise_3d(p, seed):
    i = [math.floor(c) for c in p]
    f = [p[k] - i[k] for k in range(3)]

    def corner(dx, dy, dz):
        g = GRADIENTS[hash_3d(i[0] + dx, i[1] + dy, i[2] + dz, seed) & 15]
        return g[0] * (f[0] - dx) + g[1] * (f[1] - dy) + g[2] * (f[2] - dz)
    n = trilinear(corner, [t * t * t * (t * (t * 6 - 15) + 10) for t in f])
    return max(-1.0, min(1.0, n / 1.0365))


def octave_seed(seed, octave):
    return hash_u32((seed + 0x9E3779B9 * (octave + 1)) & MASK)


def octaves(p, seed, basis, octaves=6, persistence=0.5, lacunarity=2.0):
    total = norm = 0.0
    for o in range(octaves):
        q = [c * lacunarity ** o for c in p]
        total += persistence ** o * basis(q, octave_seed(seed, o))
        norm += persistence ** o
    return total / norm


def cellular_3d(p, seed):
    cell = [math.floor(c) for c in p]
    found = []
    for dz in range(-2, 3):
        for dy in range(-2, 3):
            for dx in range(-2, 3):
                x, y, z = cell[0] + dx, cell[1] + dy, cell[2] + dz
                h0 = hash_3d(x, y, z, seed)
                h1 = hash_u32(h0 ^ 0x68E31DA4)
                h2 = hash_u32(h1 ^ 0xB5297A4D)
                feature = (x + unit_float(h0), y + unit_float(h1), z + unit_float(h2))
                found.append((math.dist(feature, p), h0))
    found.sort()
    return found[0][0], found[1][0], found[2][0], found[0][1]


if __name__ == "__main__":
    print("hash_u32:", [hash_u32(n) for n in (1, 2, 0xDEADBEEF)])
    print("int_noise_3d(3, -7, 11, 42) = %.9g" % unit_float(hash_3d(3, -7, 11, 42)))
    # Dyadic coordinates: exact in float, so the C++ sees the same points.
    for p in [(0.375, -1.25, 2.625), (-3.5, 0.125, 7.75), (10.0625, -20.5, 0.8125)]:
        print(p)
        print("  value seed 5 %.9g, gradient seed 11 %.9g" %
              (value_noise_3d(p, 5), gradient_noise_3d(p, 11)))
        print("  fbm seed 3 %.9g, turbulence seed 4 %.9g" %
              (octaves(p, 3, gradient_noise_3d),
               octaves(p, 4, lambda q, s: abs(gradient_noise_3d(q, s)))))
        print("  cellular seed 9: F1 %.9g F2 %.9g F3 %.9g cell id %d" % cellular_3d(p, 9))
