#!/usr/bin/python3
"""100 renders of a 64 × 64 scene in one Python process against 100 `rayo render` processes
(issue 29; docs/python.md, "One process against a process per render").

    PYTHONPATH=build/python /usr/bin/python3 scripts/python_hundred.py [N] [SCENE]

N renders (100) of SCENE (scenes/glass.json) at --width 64 --height 64, timed four ways: in this
process with rayo.render alone and with rayo.write of a PNG after each, and as N `build/rayo
render` processes writing a PNG and an EXR. The in-process times include `import rayo`. Before
timing, it checks that one render from each side is the same image (the EXR against the array).
Run it on an otherwise idle machine (under /tmp/rayo-build.lock on a shared one)."""

import os
import subprocess
import sys
import tempfile
import time

start = time.perf_counter()
import rayo  # noqa: E402  (timed: part of the one process's cost)

import_seconds = time.perf_counter() - start

import numpy as np  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLI = os.environ.get("RAYO_CLI", os.path.join(REPO, "build", "rayo"))
N = int(sys.argv[1]) if len(sys.argv) > 1 else 100
SCENE = sys.argv[2] if len(sys.argv) > 2 else os.path.join(REPO, "scenes", "glass.json")
SIZE = ["--width", "64", "--height", "64"]


def in_process(folder, write):
    begin = time.perf_counter()
    scene = rayo.load(SCENE)
    for i in range(N):
        image, _ = rayo.render(scene, width=64, height=64)
        if write:
            rayo.write(image, os.path.join(folder, "h.png"))
    return time.perf_counter() - begin


def processes(folder, extension):
    begin = time.perf_counter()
    for i in range(N):
        subprocess.run([CLI, "render", SCENE, *SIZE, "-o", os.path.join(folder, "h" + extension),
                        "--quiet"], check=True)
    return time.perf_counter() - begin


with tempfile.TemporaryDirectory() as folder:
    exr = os.path.join(folder, "same.exr")
    subprocess.run([CLI, "render", SCENE, *SIZE, "-o", exr, "--quiet"], check=True)
    image, stats = rayo.render(rayo.load(SCENE), width=64, height=64)
    if not np.array_equal(image, rayo.read(exr)):
        sys.exit("python_hundred: the module's image differs from the CLI's")
    rows = [
        (f"Python, one process, {N} x rayo.render (+ import rayo {import_seconds:.3f} s)",
         import_seconds + in_process(folder, False)),
        (f"Python, one process, {N} x (rayo.render + rayo.write PNG)", in_process(folder, True)),
        (f"{N} x `rayo render ... -o h.png --quiet`", processes(folder, ".png")),
        (f"{N} x `rayo render ... -o h.exr --quiet`", processes(folder, ".exr")),
    ]
print(f"{N} renders of {os.path.relpath(SCENE, REPO)} at {stats['width']} x {stats['height']}, "
      f"{stats['spp']} spp, {stats['threads']} threads, {os.cpu_count()} cores")
print("| | seconds | ms per render |")
print("|---|---:|---:|")
for label, seconds in rows:
    print(f"| {label} | {seconds:.2f} | {1000 * seconds / N:.1f} |")
