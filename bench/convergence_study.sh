#!/usr/bin/env bash
# Speed against accuracy for global illumination (docs/path-tracing.md, "Convergence"): the
# Cornell box (scenes/cornell_box.json) by the path integrator at 1 to 1024 samples per pixel,
# and by Whitted with seed 004's radiosity pre-pass at patch sizes 240, 120 and 60 (256 spp for
# the antialiasing: at 16 the light's bright edge alone makes an RMS of 0.39), each measured
# against a path-traced reference of RAYO_REFERENCE_SPP (default 4096) samples per pixel.
# Error: image_compare's numbers (bench/image_compare.cpp), RGB divided by the reference's mean:
# RMS = 10^(−PSNR/20) and the mean absolute error. Seconds: the render's --stats (time render +
# time radiosity solve), two threads. The reference's own noise adds to the measured error of
# the path renders: at 1024 spp against 4096, √(1 + 1/4) = 1.12 times the true RMS.
# Writes docs/figures/convergence.csv and the chart docs/figures/convergence.{png,svg}
# (gnuplot, log-log: error against seconds; Monte Carlo's slope −½ is the dashed line).
# Usage: bench/convergence_study.sh [SIZE]   (default 128)
#        CHART_ONLY=1 bench/convergence_study.sh   redraws the chart from the CSV.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${RAYO_BUILD_DIR:-$root/build}"
rayo="$build/rayo"
compare="$build/image_compare"
size="${1:-128}"
reference_spp="${RAYO_REFERENCE_SPP:-4096}"
figures="$root/docs/figures"
csv="$figures/convergence.csv"
scene="$root/scenes/cornell_box.json"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# render SCENE OUT.exr [rayo options...]: prints the seconds (render + radiosity solve)
render() {
  local scene="$1" exr="$2"
  shift 2
  "$rayo" render "$scene" --width "$size" --height "$size" --quiet --stats -o "$exr" "$@" |
    awk '/time render|time radiosity solve/ { t = $NF; sub(/s$/, "", t); s += t } END { print s }'
}

if [[ -z ${CHART_ONLY:-} ]]; then
  mkdir -p "$figures"
  render "$scene" "$out/ref.exr" --integrator path --spp "$reference_spp" >/dev/null
  echo "method,parameter,seconds,rms_relative,mean_relative" >"$csv"
  row() {  # METHOD PARAMETER EXR SECONDS
    local psnr mean
    read -r _ mean psnr < <("$compare" "$3" "$out/ref.exr")
    awk -v m="$1" -v p="$2" -v s="$4" -v psnr="$psnr" -v mean="$mean" \
      'BEGIN { printf "%s,%s,%s,%.6g,%.6g\n", m, p, s, (psnr == "inf" ? 0 : 10 ^ (-psnr / 20)), mean }' >>"$csv"
  }
  for spp in 1 2 4 8 16 32 64 128 256 512 1024; do
    row path "$spp" "$out/p.exr" "$(render "$scene" "$out/p.exr" --integrator path --spp "$spp")"
  done
  for patch in 240 120 60; do
    # The scene references no file, so its copy may live anywhere.
    sed "s/\"patch_size\": 60/\"patch_size\": $patch/" "$scene" >"$out/patch_$patch.json"
    seconds=$(render "$out/patch_$patch.json" "$out/r.exr" --gi radiosity --spp 256)
    row radiosity "$patch" "$out/r.exr" "$seconds"
  done
fi
column -s, -t "$csv"

for format in png svg; do
  if [[ $format == png ]]; then terminal="pngcairo size 700,500"; else terminal="svg size 700,500"; fi
  gnuplot <<EOF
set datafile separator ','
set terminal $terminal
set output '$figures/convergence.$format'
set title 'Cornell box ${size}x${size}: RMS error against a ${reference_spp}-spp path reference'
set logscale xy
set grid
set key bottom left
set xlabel 'seconds (render + radiosity solve, 2 threads)'
set ylabel 'RMS error / mean of the reference'
stats '$csv' skip 1 using (strcol(1) eq 'path' && \$2 == 64 ? \$3 : NaN):4 nooutput
first_t = STATS_min_x; first_e = STATS_min_y
plot '$csv' skip 1 using (strcol(1) eq 'path' ? \$3 : NaN):4 with linespoints pt 7 title 'path (1-1024 spp)', \
     '' skip 1 using (strcol(1) eq 'radiosity' ? \$3 : NaN):4:2 with linespoints pt 5 title 'whitted + radiosity (patch 240, 120, 60)', \
     '' skip 1 using (strcol(1) eq 'radiosity' ? \$3 : NaN):4:2 with labels offset 0,1 notitle, \
     first_e * sqrt(first_t / x) dashtype 2 lc rgb 'gray' title 'slope -1/2'
EOF
done
echo "wrote $csv and $figures/convergence.{png,svg}"
