#!/usr/bin/env python3
"""Writes the instanced scene of more than 10^9 spheres (issue 11 item 7, docs/instancing.md).

One group, a sphereflake of depth 6 (sum of 9^i for i = 0..6 = 597 871 spheres, stored once), placed
N x N times on a grid by Embree instances: N = 41 gives 1681 instances, 1 005 021 151 spheres.
Each instance is turned about the vertical by a different angle so the grid is not a repeated
picture. Usage: scripts/billion_spheres.py [N] > /tmp/billion.json; rayo render /tmp/billion.json
"""
import json
import sys

DEPTH = 6
SPHERES_PER_FLAKE = sum(9**i for i in range(DEPTH + 1))


def scene(n: int) -> dict:
    spacing = 2.6
    half = (n - 1) * spacing / 2
    instances = []
    for j in range(n):
        for i in range(n):
            instances.append({
                "type": "instance", "of": "flake",
                "transform": {"translate": [round(i * spacing - half, 3), 0, round(j * spacing - half, 3)],
                              "rotate": [0, (37 * (i * n + j)) % 120, 0]}})
    extent = half + spacing
    return {
        "rayo": 1,
        "camera": {"eye": [0, 0.75 * extent, 1.1 * extent], "look_at": [0, -2, -0.25 * extent],
                   "vfov": 50, "width": 1024, "height": 1024},
        "render": {"max_depth": 2},
        "background": [0.078, 0.361, 0.753],
        "ambient_light": 0.1,
        "materials": {
            "floor": {"kd": [0.8, 0.6, 0.264], "ka": [0.1, 0.075, 0.033]},
            "ball": {"kd": [0.5, 0.45, 0.35], "ka": [0.1, 0.09, 0.07], "ks": 0.5,
                     "shininess": 3.0827, "reflect": 0.5},
        },
        "lights": [{"type": "point", "position": [0.4 * extent, 0.8 * extent, 0.6 * extent]},
                   {"type": "point", "position": [-0.6 * extent, 0.5 * extent, 0.2 * extent],
                    "color": 0.5}],
        "groups": {"flake": [{"type": "sphereflake", "center": [0, 0, 0], "radius": 0.5,
                              "depth": DEPTH, "axis": [0, 1, 0], "material": "ball"}]},
        "objects": [{"type": "polygon", "material": "floor",
                     "vertices": [[-extent, -0.55, -extent], [-extent, -0.55, extent],
                                  [extent, -0.55, extent], [extent, -0.55, -extent]]}]
                   + instances,
    }


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 41
    json.dump(scene(n), sys.stdout, indent=None, separators=(",", ":"))
    sys.stdout.write("\n")
    print(f"{n * n} instances x {SPHERES_PER_FLAKE} spheres = {n * n * SPHERES_PER_FLAKE} spheres",
          file=sys.stderr)


if __name__ == "__main__":
    main()
