#!/usr/bin/env bash
# Antialiasing study (docs/antialiasing.md): image error against camera rays for stratified
# supersampling (spp 1..64) and adaptive corner subdivision (thresholds at depths 2..4), each
# measured against a 256-spp stratified render of the same scene.
# Error: image_compare's numbers (bench/image_compare.cpp), RGB divided by the reference's mean:
# RMS = 10^(−PSNR/20) and the mean absolute error. Camera rays: the render's --stats.
# Writes docs/figures/aa_error.csv and the chart docs/figures/aa_error.{png,svg} (gnuplot).
# Needs a build (build/rayo, build/image_compare) and ../shared/spd (or RAYO_SPD_DIR).
# Usage: bench/aa_study.sh [SIZE]   (default 256; the scenes are balls_3.nff and mirror.json)
#        CHART_ONLY=1 bench/aa_study.sh   redraws the chart from the CSV without rendering.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
spd="${RAYO_SPD_DIR:-$root/../shared/spd}"
build="${RAYO_BUILD_DIR:-$root/build}"
rayo="$build/rayo"
compare="$build/image_compare"
size="${1:-256}"
figures="$root/docs/figures"
csv="$figures/aa_error.csv"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

scenes=("balls_3:$spd/balls_3.nff" "mirror:$root/scenes/mirror.json")

# render NAME SCENE OUT.exr [rayo options...]: prints "camera_rays render_seconds"
render() {
  local scene="$1" exr="$2"
  shift 2
  "$rayo" render "$scene" --width "$size" --height "$size" --quiet --stats -o "$exr" "$@" |
    awk '/rays camera/ { rays = $3 } /time render/ { t = $3; sub(/s$/, "", t) } END { print rays, t }'
}

if [[ -z ${CHART_ONLY:-} ]]; then
  echo "scene,method,parameter,depth,camera_rays,rays_per_pixel,rms_relative,mean_relative,render_s" >"$csv"
  for entry in "${scenes[@]}"; do
    name="${entry%%:*}" scene="${entry#*:}"
    render "$scene" "$out/ref.exr" --spp 256 >/dev/null
    row() {  # METHOD PARAMETER DEPTH EXR "RAYS SECONDS"
      local method="$1" parameter="$2" depth="$3" exr="$4" rays seconds psnr mean
      read -r rays seconds <<<"$5"
      read -r _ mean psnr < <("$compare" "$exr" "$out/ref.exr")
      awk -v n="$name" -v m="$method" -v p="$parameter" -v d="$depth" -v r="$rays" -v s="$seconds" \
        -v px="$((size * size))" -v psnr="$psnr" -v mean="$mean" \
        'BEGIN { printf "%s,%s,%s,%s,%d,%.3f,%.6g,%.6g,%s\n", n, m, p, d, r, r / px,
                 (psnr == "inf" ? 0 : 10 ^ (-psnr / 20)), mean, s }' >>"$csv"
    }
    for spp in 1 2 4 8 16 32 64; do
      row stratified "$spp" - "$out/s.exr" "$(render "$scene" "$out/s.exr" --spp "$spp")"
    done
    for depth in 2 3 4; do
      for threshold in 1 0.3 0.1 0.03 0.01; do
        row adaptive "$threshold" "$depth" "$out/a.exr" \
          "$(render "$scene" "$out/a.exr" --aa adaptive --aa-threshold "$threshold" --aa-depth "$depth")"
      done
    done
  done
fi
column -s, -t "$csv"

for format in png svg; do
  if [[ $format == png ]]; then terminal="pngcairo size 1000,450"; else terminal="svg size 1000,450"; fi
  gnuplot <<EOF
set datafile separator ','
set terminal $terminal
set output '$figures/aa_error.$format'
set multiplot layout 1,2 title 'Antialiasing: error against a 256-spp reference (${size}x${size})'
set logscale xy
set grid
set key top right
set xlabel 'camera rays per pixel'
set ylabel 'RMS error / mean of the reference'
do for [s in "balls_3 mirror"] {
  set title s noenhanced
  plot '$csv' skip 1 using (strcol(1) eq s && strcol(2) eq 'stratified' ? \$6 : NaN):7 with linespoints pt 7 title 'stratified (spp 1-64)', \
       '' skip 1 using (strcol(1) eq s && strcol(2) eq 'adaptive' && \$4 == 2 ? \$6 : NaN):7 with linespoints pt 5 title 'adaptive, depth 2', \
       '' skip 1 using (strcol(1) eq s && strcol(2) eq 'adaptive' && \$4 == 3 ? \$6 : NaN):7 with linespoints pt 9 title 'adaptive, depth 3', \
       '' skip 1 using (strcol(1) eq s && strcol(2) eq 'adaptive' && \$4 == 4 ? \$6 : NaN):7 with linespoints pt 11 title 'adaptive, depth 4'
}
unset multiplot
EOF
done
echo "wrote $csv and $figures/aa_error.{png,svg}"
