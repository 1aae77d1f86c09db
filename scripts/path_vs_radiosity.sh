#!/usr/bin/env bash
# The diffuse Cornell box (scenes/cornell_box.json) by the path integrator and by Whitted with
# seed 004's radiosity pre-pass (--gi radiosity, the scene's patch_size 60): the mean radiance of
# each wall, ceiling and floor region and of the whole image, per channel, and the relative
# difference path/radiosity − 1 (docs/path-tracing.md, "Against radiosity"). Both converge to
# the same rendering equation for Lambertian surfaces; what is left is the radiosity's patch
# discretisation and its unshot energy (1 % of the emitted energy at threshold 0.01).
# Usage: scripts/path_vs_radiosity.sh [SIZE [SPP]]   (defaults 128 px, 1024 path samples)
# Fails when any region's difference exceeds RAYO_PATH_RADIOSITY_LIMIT (default 0.03).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${RAYO_BUILD_DIR:-$root/build}"
size="${1:-128}"
spp="${2:-1024}"
limit="${RAYO_PATH_RADIOSITY_LIMIT:-0.03}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
scene="$root/scenes/cornell_box.json"
"$build/rayo" render "$scene" --integrator path --spp "$spp" --width "$size" --height "$size" \
  -o "$out/path.exr" --quiet
"$build/rayo" render "$scene" --gi radiosity --spp 16 --width "$size" --height "$size" \
  -o "$out/radiosity.exr" --quiet
# Regions as fractions of the image (x, y, width, height), inside each surface.
regions=(
  "left_wall 0.05 0.27 0.05 0.47"
  "right_wall 0.90 0.27 0.05 0.47"
  "back_wall 0.39 0.20 0.23 0.23"
  "floor 0.35 0.90 0.31 0.06"
  "ceiling 0.35 0.02 0.31 0.05"
  "image 0 0 1 1"
)
mean_of() {  # FILE GEOMETRY -> "r g b"
  oiiotool "$1" --cut "$2" --printstats 2>/dev/null | awk '/Avg:/ {print $3, $4, $5; exit}'
}
printf '%-11s %-30s %-30s %s\n' region path radiosity "path/radiosity - 1 (r g b)"
status=0
for r in "${regions[@]}"; do
  read -r name fx fy fw fh <<<"$r"
  geometry=$(awk -v s="$size" -v x="$fx" -v y="$fy" -v w="$fw" -v h="$fh" \
    'BEGIN {printf "%dx%d+%d+%d", w*s, h*s, x*s, y*s}')
  a=$(mean_of "$out/path.exr" "$geometry")
  b=$(mean_of "$out/radiosity.exr" "$geometry")
  diff=$(awk -v a="$a" -v b="$b" -v limit="$limit" 'BEGIN {
    split(a, p, " "); split(b, q, " "); bad = 0; text = "";
    for (i = 1; i <= 3; ++i) { d = p[i] / q[i] - 1; text = text sprintf("%+.4f ", d);
      if (d > limit || d < -limit) bad = 1 }
    print text (bad ? "OVER" : "") }')
  printf '%-11s %-30s %-30s %s\n' "$name" "$a" "$b" "$diff"
  [[ "$diff" == *OVER* ]] && status=1
done
exit "$status"
