#!/usr/bin/env bash
# Sanitizer and fuzzing checks, run by .ci/run after the normal test suite:
#   asan  clang AddressSanitizer + UndefinedBehaviorSanitizer (CMakePresets.json "asan"): the whole
#         test suite, plus each libFuzzer target (fuzz/) for RAYO_FUZZ_SECONDS (default 20) over a
#         copy of its seed corpus; crashing inputs land in build-asan/fuzz/<reader>/artifacts/.
#   tsan  clang ThreadSanitizer ("tsan"): the render and CLI tests (Render*, Cli*), with
#         third_party/sanitizers/tsan.supp for the uninstrumented TBB and Embree.
# Usage: scripts/sanitize.sh [asan] [tsan]   (both by default; build dirs build-asan, build-tsan)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RAYO_SETUP_EXTRAS="${RAYO_SETUP_EXTRAS:-} clang" "$root/scripts/setup.sh"
cd "$root"
jobs="${RAYO_JOBS:-2}"
steps=("$@")
if ((${#steps[@]} == 0)); then steps=(asan tsan); fi

for step in "${steps[@]}"; do
  start=$SECONDS
  case "$step" in
    asan) cmake --preset asan -DRAYO_FUZZ_SECONDS="${RAYO_FUZZ_SECONDS:-20}" >/dev/null ;;
    tsan) cmake --preset tsan >/dev/null ;;
    *) echo "sanitize: unknown step '$step' (expected asan or tsan)" >&2; exit 2 ;;
  esac
  cmake --build --preset "$step" -j "$jobs"
  built=$SECONDS
  ctest --preset "$step" -j "$jobs" --timeout 300
  echo "sanitize: $step: build $((built - start)) s, tests $((SECONDS - built)) s"
done
