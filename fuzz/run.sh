#!/usr/bin/env bash
# Runs the libFuzzer targets longer than CI does, by hand: builds the asan preset's fuzzers and
# runs each named reader (default: nff json obj gltf) for SECONDS (default 600) in turn. The
# corpus grows in build-asan/fuzz-long/<reader>/corpus across runs (seeded from fuzz/corpus/);
# a finding stops that fuzzer and leaves its input in build-asan/fuzz-long/<reader>/artifacts/.
# Keep a crashing input as a regression test (tests/data/bad/) once it is fixed.
# JSON gets a larger -max_len (262144 bytes) so that inputs can nest far past the 256-level limit
# and still carry structure around it; the line readers keep 16384.
# For the documented long run (docs/limits.md): fuzz/run.sh 3600
# Usage: fuzz/run.sh [SECONDS] [reader...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-600}"
shift || true
readers=("$@")
if ((${#readers[@]} == 0)); then readers=(nff json obj gltf); fi
RAYO_SETUP_EXTRAS="${RAYO_SETUP_EXTRAS:-} clang" "$root/scripts/setup.sh"
cd "$root"
cmake --preset asan >/dev/null
targets=()
for r in "${readers[@]}"; do targets+=("${r}_fuzz"); done
cmake --build --preset asan -j "${RAYO_JOBS:-2}" --target "${targets[@]}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
status=0
for r in "${readers[@]}"; do
  work="$root/build-asan/fuzz-long/$r"
  mkdir -p "$work/corpus" "$work/artifacts"
  dict=()
  if [[ -f "$root/fuzz/$r.dict" ]]; then dict=(-dict="$root/fuzz/$r.dict"); fi
  max_len=16384
  if [[ "$r" == json ]]; then max_len=262144; fi
  echo "fuzz/run.sh: $r for ${seconds} s (max_len ${max_len})"
  if ! "$root/build-asan/${r}_fuzz" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -max_len="$max_len" -print_final_stats=1 -artifact_prefix="$work/artifacts/" "${dict[@]}" \
      "$work/corpus" "$root/fuzz/corpus/$r"; then
    echo "fuzz/run.sh: $r found a problem; see $work/artifacts/" >&2
    status=1
  fi
done
exit $status
