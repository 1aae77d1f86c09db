#!/usr/bin/env bash
# Whole-process wall time of rayo against POV-Ray 3.7 on the same SPD scenes (NFF for rayo, the
# SPD's own POV-Ray translation for POV-Ray), same resolution and thread count, no antialiasing.
# Usage: bench/compare_povray.sh [SIZE] [THREADS] [SCENE...]   (defaults: 512 2 balls_3)
# Needs ../shared/spd (or RAYO_SPD_DIR) and povray (RAYO_SETUP_EXTRAS=povray scripts/setup.sh).
# Prints one row per scene: the best of RUNS (default 3) runs of each program, the two
# programs' runs alternating.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
spd="${RAYO_SPD_DIR:-$root/../shared/spd}"
rayo="${RAYO_BUILD_DIR:-$root/build}/rayo"
size="${1:-512}"
threads="${2:-2}"
shift $(( $# > 2 ? 2 : $# ))
scenes=("$@")
((${#scenes[@]})) || scenes=(balls_3)
runs="${RUNS:-3}"
command -v povray >/dev/null || { echo "povray is not installed" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

run_time() {  # wall time in seconds of running "$@" once
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>&1
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { print b - a }'
}
min() { awk -v t="$1" -v b="$2" 'BEGIN { print (b == "" || t < b) ? t : b }'; }

printf "%-10s %6s %7s %10s %10s %7s\n" scene size threads rayo_s povray_s ratio
for scene in "${scenes[@]}"; do
  # The two programs alternate, run by run, so that a change in the machine's speed (a shared
  # VM drifts by 10-40 % within minutes) reaches both alike.
  r="" p=""
  for ((i = 0; i < runs; i++)); do
    r=$(min "$(run_time "$rayo" render "$spd/$scene.nff" --width "$size" --height "$size" \
                 --threads "$threads" --spp 1 --quiet -o "$out/$scene.png")" "$r")
    p=$(min "$(run_time povray "+I$spd/pov/$scene.pov" "+O$out/$scene.pov.png" "+W$size" \
                 "+H$size" -A "+WT$threads" -D -V +FN)" "$p")
  done
  printf "%-10s %6s %7s %10.3f %10.3f %7.2f\n" "$scene" "$size" "$threads" "$r" "$p" \
    "$(awk -v p="$p" -v r="$r" 'BEGIN { print p / r }')"
done
