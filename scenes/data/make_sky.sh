#!/usr/bin/env bash
# Writes scenes/data/sky.exr, the environment of scenes/path_environment.json: 256x128 half-float
# equirectangular (docs/path-tracing.md, "The environment"): rows 0-63 a sky graded from
# (0.25, 0.45, 0.9) at the zenith to (0.8, 0.85, 0.95) at the horizon, rows 64-127 a dark ground
# (0.12, 0.11, 0.09), and a 6x6-texel sun of radiance (150, 140, 125) at column 180, row 40.
# Needs oiiotool (Debian openimageio-tools, which scripts/setup.sh installs).
# Usage: scenes/data/make_sky.sh [OUT.exr]
set -euo pipefail
out="${1:-$(dirname "${BASH_SOURCE[0]}")/sky.exr}"
oiiotool --pattern fill:top=0.25,0.45,0.9:bottom=0.8,0.85,0.95 256x64 3 \
  --pattern constant:color=0.12,0.11,0.09 256x64 3 --mosaic 1x2 \
  --pattern constant:color=150,140,125 6x6 3 --swap --paste +180+40 \
  -d half --compression zip -o "$out"
