#!/usr/bin/env bash
# What writing the image costs a whole `rayo render` process: wall and CPU time (user + sys,
# `/usr/bin/time`) of one SPD scene rendered at each size to PNG and EXR, for each writer
# configuration, the configurations' runs interleaved so that a drift of the machine reaches all
# alike; medians (and the best wall time) of RUNS runs (docs/performance.md "Writing PNG and EXR
# without OpenImageIO").
# Usage: bench/image_writer_cost.sh [SCENE] [CONFIG...]
#   SCENE   an NFF file (default ../shared/spd/balls_3.nff)
#   CONFIG  "label=BINARY [render flags...]" (default "rayo=build/rayo"), e.g.
#           "direct=build/rayo --image-writer direct" "oiio=build/rayo --image-writer oiio"
# Env: RUNS (5), SIZES ("512 2048"), THREADS (2), FORMATS ("png exr").
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scene="${1:-$root/../shared/spd/balls_3.nff}"
shift $(($# > 0 ? 1 : 0))
configs=("$@")
((${#configs[@]})) || configs=("rayo=$root/build/rayo")
runs="${RUNS:-5}"
threads="${THREADS:-2}"
read -r -a sizes <<<"${SIZES:-512 2048}"
read -r -a formats <<<"${FORMATS:-png exr}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

printf "%-12s %5s %4s %8s %8s %8s\n" config size fmt wall_med wall_min cpu_med
for size in "${sizes[@]}"; do
  for fmt in "${formats[@]}"; do
    for ((i = 0; i < runs; i++)); do
      for c in "${configs[@]}"; do
        label="${c%%=*}"
        read -r -a command <<<"${c#*=}"
        /usr/bin/time -f "%e %U %S" -o "$out/time" "${command[0]}" render "$scene" \
          --width "$size" --height "$size" --threads "$threads" --spp 1 --quiet \
          "${command[@]:1}" -o "$out/image.$fmt" >/dev/null
        awk '{ print $1 }' "$out/time" >>"$out/$label.$size.$fmt.wall"
        awk '{ print $2 + $3 }' "$out/time" >>"$out/$label.$size.$fmt.cpu"
      done
    done
    for c in "${configs[@]}"; do
      label="${c%%=*}"
      base="$out/$label.$size.$fmt"
      printf "%-12s %5s %4s %8s %8s %8s\n" "$label" "$size" "$fmt" "$(median <"$base.wall")" \
        "$(sort -g "$base.wall" | head -1)" "$(median <"$base.cpu")"
    done
  done
done
