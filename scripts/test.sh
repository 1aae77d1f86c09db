#!/usr/bin/env bash
# README command 2: install, build, and run the whole test suite through ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
cd "${RAYO_BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "${RAYO_JOBS:-2}" --timeout 300
