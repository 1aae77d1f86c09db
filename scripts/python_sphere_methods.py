#!/usr/bin/python3
"""The mission's chart from Python (docs/python.md): an SPD scene rendered with each sphere
method, error against time. The reference is brute force in double precision; the error is the
RMS difference of the linear RGB. Prints the table; with Matplotlib installed (Debian
python3-matplotlib), also draws the chart.

usage: PYTHONPATH=build/python /usr/bin/python3 scripts/python_sphere_methods.py [SIZE] [WIDTH] [OUT.png]
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

import rayo

size = int(sys.argv[1]) if len(sys.argv) > 1 else 3
width = int(sys.argv[2]) if len(sys.argv) > 2 else 512
chart = sys.argv[3] if len(sys.argv) > 3 else "sphere_methods.png"
# The rayo executable: $RAYO_CLI, else the build tree's (beside build/python), else on PATH.
cli = os.path.join(os.path.dirname(rayo.__file__), "..", "rayo")
cli = os.environ.get("RAYO_CLI", cli if os.path.exists(cli) else "rayo")

with tempfile.TemporaryDirectory() as folder:
    # The SPD's balls (sphereflake) as NFF, from rayo's own generator.
    subprocess.run([cli, "bench", "suite", "--write-nff", "--scenes", "balls", "--size",
                    str(size), "-o", folder], check=True, capture_output=True)
    scene = rayo.load(os.path.join(folder, f"balls_{size}.nff"))

reference, _ = rayo.render(scene, width=width, sphere_method="bruteforce", sphere_math="double")
rows = []
for method in ["user", "bruteforce", "embree-point", "mesh:1", "mesh:2", "mesh:3", "mesh:4"]:
    for math in ["stable", "seed"]:
        image, stats = rayo.render(scene, width=width, sphere_method=method, sphere_math=math)
        seconds = stats["bvh_seconds"] + stats["render_seconds"]
        rmse = float(np.sqrt(np.mean((image[..., :3] - reference[..., :3]) ** 2)))
        rows.append((method, math, seconds, rmse))
        print(f"{method:13s} {math:7s} {seconds * 1e3:9.1f} ms  rmse {rmse:.3e}")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("(no Matplotlib: table only)")
    sys.exit(0)
figure, axes = plt.subplots(figsize=(7, 4.5))
for method, math, seconds, rmse in rows:
    axes.scatter(seconds * 1e3, max(rmse, 1e-7), marker="o" if math == "stable" else "x")
    axes.annotate(f"{method}/{math}", (seconds * 1e3, max(rmse, 1e-7)), fontsize=7)
axes.set_xlabel("BVH build + render, ms")
axes.set_ylabel("RMS error against bruteforce/double")
axes.set_yscale("log")
axes.set_title(f"balls size {size}, {width} px wide: speed against accuracy")
figure.savefig(chart, dpi=120, bbox_inches="tight")
print(f"chart: {chart}")
