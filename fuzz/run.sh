#!/usr/bin/env bash
# Runs the libFuzzer targets longer than CI does, by hand: builds the asan preset's fuzzers and
# runs each named reader (default: all of them, nff json obj gltf mesh texture journal) for
# SECONDS (default 600) in turn. The corpus grows in build-asan/fuzz-long/<reader>/corpus across runs (seeded from fuzz/corpus/);
# a finding stops that fuzzer and leaves its input in build-asan/fuzz-long/<reader>/artifacts/.
# Keep a crashing input as a regression test (tests/data/bad/) once it is fixed.
# JSON gets a larger -max_len (262144 bytes) so that inputs can nest far past the 256-level limit
# and still carry structure around it; the line readers keep 16384.
# For the documented long run (docs/limits.md): fuzz/run.sh 3600 (RAYO_FUZZ_PARALLEL=1 runs the
# readers at once, RAYO_FUZZ_NICE=19 lowers their priority). RAYO_FUZZ_ARGS adds libFuzzer flags,
# e.g. "-fork=1 -ignore_crashes=1 -ignore_ooms=1" to go on after a finding and collect them all.
# Usage: fuzz/run.sh [SECONDS] [reader...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-600}"
shift || true
readers=("$@")
if ((${#readers[@]} == 0)); then readers=(nff json obj gltf mesh texture journal); fi
RAYO_SETUP_EXTRAS="${RAYO_SETUP_EXTRAS:-} clang" "$root/scripts/setup.sh"
cd "$root"
cmake --preset asan >/dev/null
targets=()
for r in "${readers[@]}"; do targets+=("${r}_fuzz"); done
cmake --build --preset asan -j "${RAYO_JOBS:-2}" --target "${targets[@]}"
# As the asan test preset (CMakePresets.json) runs them: OpenImageIO's TextureSystem (texture_fuzz
# makes one per input) is freed with a mismatched sized delete and leaks an aligned block inside
# OIIO, which scripts/lsan.supp suppresses.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:new_delete_type_mismatch=0}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$root/scripts/lsan.supp:print_suppressions=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# One reader: its fuzzer for SECONDS; the log goes to build-asan/fuzz-long/<reader>/log.
fuzz_one() {
  local r="$1" work="$root/build-asan/fuzz-long/$1" max_len=16384 dict=()
  mkdir -p "$work/corpus" "$work/artifacts"
  if [[ -f "$root/fuzz/$r.dict" ]]; then dict=(-dict="$root/fuzz/$r.dict"); fi
  if [[ "$r" == json ]]; then max_len=262144; fi
  echo "fuzz/run.sh: $r for ${seconds} s (max_len ${max_len}), log in $work/log"
  if ! nice -n "${RAYO_FUZZ_NICE:-0}" "$root/build-asan/${r}_fuzz" -max_total_time="$seconds" \
      -timeout="${RAYO_FUZZ_TIMEOUT:-10}" -rss_limit_mb=2048 -max_len="$max_len" -print_final_stats=1 \
      -artifact_prefix="$work/artifacts/" "${dict[@]}" ${RAYO_FUZZ_ARGS:-} "$work/corpus" \
      "$root/fuzz/corpus/$r" \
      >"$work/log" 2>&1; then
    echo "fuzz/run.sh: $r found a problem; see $work/artifacts/ and $work/log" >&2
    return 1
  fi
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|cov: .*corp" "$work/log" | tail -3
}

# RAYO_FUZZ_PARALLEL=1 runs the readers at the same time (each gets a share of the cores).
# libFuzzer's -timeout is wall-clock time: on a machine busy with other work, raise it
# (RAYO_FUZZ_TIMEOUT=120), or starved inputs that take 20 ms are reported as 10-second hangs.
status=0
if [[ "${RAYO_FUZZ_PARALLEL:-0}" == 1 ]]; then
  pids=()
  for r in "${readers[@]}"; do fuzz_one "$r" & pids+=($!); done
  for p in "${pids[@]}"; do wait "$p" || status=1; done
else
  for r in "${readers[@]}"; do fuzz_one "$r" || status=1; done
fi
exit $status
