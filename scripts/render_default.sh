#!/usr/bin/env bash
# README command 1: install, build, and render the built-in scene to default.png
# (extra arguments go to `rayo render`, e.g. -o default.exr --spp 16).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Only what rendering needs: the rayo executable and its image module (not the tests and
# benchmarks, which scripts/test.sh builds).
RAYO_BUILD_TARGET=rayo "$root/scripts/build.sh"
"${RAYO_BUILD_DIR:-$root/build}/rayo" render -o default.png "$@"
