#!/usr/bin/env bash
# Installs what is missing, configures (Release, Ninja) and builds rayo into build/.
# Usage: scripts/build.sh [extra cmake -D options...]
# RAYO_BUILD_TARGET=T builds only target T and what it needs (render_default.sh: rayo).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
build="${RAYO_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build" -j "${RAYO_JOBS:-2}" ${RAYO_BUILD_TARGET:+--target "$RAYO_BUILD_TARGET"}
