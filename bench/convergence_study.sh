#!/usr/bin/env bash
# Speed against accuracy for global illumination (docs/path-tracing.md, "Convergence"): the
# documented run of `rayo bench convergence` (bench/lab/convergence_study.h) on the built-in
# Cornell box (scenes/cornell_box.json) at SIZE² pixels: the path integrator at 1, 4, 16, 64,
# 256 and 1024 samples per pixel and Whitted + radiosity at patch sizes 240, 120 and 60 (256 spp
# for the antialiasing), each against a path reference of RAYO_REFERENCE_SPP (default 4096)
# samples per pixel, on all cores. Writes docs/figures/convergence.{csv,json,md,gp} and the
# chart docs/figures/convergence.{png,svg}; `gnuplot docs/figures/convergence.gp`, run from the
# repository's root, redraws the chart from the CSV.
# Usage: bench/convergence_study.sh [SIZE]   (default 128)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${RAYO_BUILD_DIR:-$root/build}"
size="${1:-128}"
cd "$root"  # the chart's script names the CSV relative to the root
"$build/rayo" bench convergence -o docs/figures --width "$size" \
  --reference-spp "${RAYO_REFERENCE_SPP:-4096}" --max-spp 1024
