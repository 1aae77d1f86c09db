#!/usr/bin/env bash
# Time and peak memory of one render spread over 1…N MPI ranks on this machine
# (docs/distributed.md, "Measurements"): `mpirun -np N rayo render` for N = 1..MAX_RANKS, each rank
# with THREADS threads (default: the cores divided among the ranks, at least one), and the plain
# process as the reference. Every image is compared with the plain one (`idiff -fail 0 -warn 0`):
# the distribution must not change a bit.
# Usage: bench/mpi_ranks.sh OUT_DIR [SCENE] [SIZE] [MAX_RANKS]
#   (default scene bench/highres_sphere.nff, 2048², up to 4 ranks)
# Writes OUT_DIR/mpi_ranks.csv and, with gnuplot, OUT_DIR/mpi_ranks.svg (time against ranks).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rayo="${RAYO_BUILD_DIR:-$root/build}/rayo"
out="${1:?usage: bench/mpi_ranks.sh OUT_DIR [SCENE] [SIZE] [MAX_RANKS]}"
scene="${2:-$root/bench/highres_sphere.nff}"
size="${3:-2048}"
max_ranks="${4:-4}"
cores=$(nproc)
mpirun_flags=(--oversubscribe)
[[ $(id -u) == 0 ]] && mpirun_flags+=(--allow-run-as-root)
mkdir -p "$out/img"
csv="$out/mpi_ranks.csv"
echo "ranks,threads_per_rank,wall_s,render_s,peak_rss_mb,mrays_per_s,identical" >"$csv"

# "1m02s" or "3.4s" → seconds.
seconds() { awk '{ if (match($0, /m/)) { split($0, p, "m"); sub(/s$/, "", p[2]); print p[1] * 60 + p[2] }
                   else { sub(/s$/, ""); print } }' <<<"$1"; }

run() {  # RANKS (0: the plain process) THREADS
  local img="$out/img/ranks_$1.exr" log="$out/img/time.log" summary="$out/img/summary.txt"
  local command=("$rayo" render "$scene" --width "$size" --height "$size" --threads "$2"
                 --no-journal -o "$img")
  if [[ $1 == 0 ]]; then
    /usr/bin/time -v "${command[@]}" >"$summary" 2>"$log"
  else
    /usr/bin/time -v mpirun "${mpirun_flags[@]}" -np "$1" "${command[@]}" >"$summary" 2>"$log"
  fi
  local wall rss render mrays identical=reference
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, t, ":"); s = 0;
    for (i = 1; i <= n; i++) s = s * 60 + t[i]; print s }' "$log")
  rss=$(awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' "$log")
  render=$(seconds "$(sed -n 's/.*| parse .*, render \([0-9ms.]*\),.*/\1/p' "$summary")")
  mrays=$(sed -n 's/.* \([0-9.]*\) Mrays\/s.*/\1/p' "$summary" | tail -1)
  if [[ $1 != 0 ]]; then
    identical=$(idiff -fail 0 -warn 0 "$out/img/ranks_0.exr" "$img" >/dev/null && echo yes || echo NO)
    rm -f "$img"
  fi
  echo "$1,$2,$wall,$render,$rss,$mrays,$identical" | tee -a "$csv"
}

run 0 "$cores"
for ((ranks = 1; ranks <= max_ranks; ++ranks)); do
  run "$ranks" "${THREADS:-$(((cores / ranks) > 0 ? cores / ranks : 1))}"
done
rm -rf "$out/img"

if command -v gnuplot >/dev/null; then
  gnuplot <<GP
set terminal svg size 720,420 font "sans,12"
set output "$out/mpi_ranks.svg"
set datafile separator ","
set xlabel "MPI ranks on one ${cores}-core host (0: plain rayo)"
set ylabel "seconds"
set key top left
set grid
set xtics 1
plot "$csv" every ::1 using 1:3 with linespoints title "whole command", \
     "$csv" every ::1 using 1:4 with linespoints title "render (rayo's summary)"
GP
fi
