#!/usr/bin/env bash
# Time and peak memory of `rayo render` against resolution, for EXR and PNG output
# (docs/high-resolution.md): each size is rendered once with /usr/bin/time -v, the peak resident
# set and the wall time taken from it, the write phase after the last tile from rayo's summary.
# The 64×64 render of the same scene is the baseline the memory bound is stated against.
# Usage: bench/highres_memory.sh OUT_DIR [SCENE] [SIZES...]
#   (default scene bench/highres_sphere.nff, one lit sphere; sizes 1024 2048 4096 8192 16384)
# Writes OUT_DIR/highres.csv and, with gnuplot, OUT_DIR/highres_rss.svg and highres_time.svg.
# Images go to OUT_DIR/img and are deleted after each run (a 65536² half EXR is gigabytes).
# Environment: FORMATS (default "exr png"), THREADS (default: all cores), EXTRA (more flags).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rayo="${RAYO_BUILD_DIR:-$root/build}/rayo"
out="${1:?usage: bench/highres_memory.sh OUT_DIR [SCENE] [SIZES...]}"
scene="${2:-$root/bench/highres_sphere.nff}"
shift $(($# > 1 ? 2 : 1))
sizes=("${@:-1024 2048 4096 8192 16384}")
read -r -a sizes <<<"${sizes[*]}"
formats="${FORMATS:-exr png}"
threads=()
[[ -n ${THREADS:-} ]] && threads=(--threads "$THREADS")
mkdir -p "$out/img"
csv="$out/highres.csv"
echo "format,size,seconds,peak_rss_mb,write_after_last_tile_s,file_mb" >"$csv"

run() {  # FORMAT SIZE
  local img="$out/img/out.$1" log="$out/img/time.log"
  # shellcheck disable=SC2086
  /usr/bin/time -v "$rayo" render "$scene" --width "$2" --height "$2" "${threads[@]}" \
    ${EXTRA:-} -o "$img" >"$out/img/summary.txt" 2>"$log"
  local rss secs write file
  rss=$(awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' "$log")
  secs=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, t, ":"); s = 0;
    for (i = 1; i <= n; i++) s = s * 60 + t[i]; print s }' "$log")
  write=$(sed -n 's/.*, write \([0-9.]*\)s.*/\1/p' "$out/img/summary.txt")
  file=$(du -m "$img" | cut -f1)
  rm -f "$img"
  echo "$1,$2,$secs,$rss,${write:-},$file" | tee -a "$csv"
}

for format in $formats; do
  run "$format" 64
  for size in "${sizes[@]}"; do run "$format" "$size"; done
done
rm -rf "$out/img"

if command -v gnuplot >/dev/null; then
  for what in rss time; do
    column=$([[ $what == rss ]] && echo 4 || echo 3)
    label=$([[ $what == rss ]] && echo "peak resident memory (MB)" || echo "wall time (s)")
    gnuplot <<GP
set terminal svg size 720,420 font "sans,12"
set output "$out/highres_$what.svg"
set datafile separator ","
set logscale x 2
set xlabel "image side (pixels)"
set ylabel "$label"
set key top left
set grid
plot for [f in "$formats"] "< grep '^" . f . ",' $csv" using 2:$column with linespoints title f
GP
  done
fi
