#!/usr/bin/env bash
# README command 2: install, build, and run the whole test suite through ctest, then each
# in-process test binary whole.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
cd "${RAYO_BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "${RAYO_JOBS:-2}" --timeout 300
# ctest runs each test in its own process; a user's process (a library user, the lab, MPI ranks)
# renders many scenes in one. So each in-process layer's binary also runs whole, once, to catch
# state one test leaves for the next (how the AVX-512 stream hang of core/embree_device.h showed).
for layer in core image shading scene lab; do
  echo "whole-binary run: rayo_${layer}_tests"
  timeout 300 "./rayo_${layer}_tests" --gtest_brief=1
done
