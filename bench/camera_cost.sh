#!/usr/bin/env bash
# What the camera features cost: Mrays/s (the render's --stats: all rays over the render time) of
# one scene rendered as it is (perspective pinhole, stratified), with a thin lens, as a fisheye,
# as a panorama, with single rays (--single-rays, the path adaptive antialiasing takes) and with
# adaptive antialiasing. The variants change what the rays hit, so compare Mrays/s, not times.
# With RAYO_BASELINE=/path/to/rayo the pinhole render is also timed with that binary (e.g. a
# build from before a change: the pinhole path must not get slower).
# Usage: bench/camera_cost.sh [SCENE.json] [WIDTH] [THREADS]   (scenes/mirror.json 512 1)
# Prints the best of RUNS (default 5) runs of each variant, the runs interleaved.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rayo="${RAYO_BUILD_DIR:-$root/build}/rayo"
scene="${1:-$root/scenes/mirror.json}"
width="${2:-512}"
threads="${3:-1}"
runs="${RUNS:-5}"
spp="${SPP:-4}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# SCENE with the camera fields changed (JSON with // comment lines).
variant() {  # NAME PYTHON-STATEMENTS-ON-camera
  python3 -c '
import json, sys
text = "\n".join(l for l in open(sys.argv[1]) if not l.lstrip().startswith("//"))
scene = json.loads(text)
camera = scene.setdefault("camera", {})
exec(sys.argv[2])
json.dump(scene, open(sys.argv[3], "w"))' "$scene" "$2" "$out/$1.json"
}
variant pinhole "pass"
variant thin_lens "camera['lens_radius'] = 0.1"
variant fisheye "camera.pop('vfov', None); camera.pop('hfov', None); camera['projection'] = 'fisheye'"
variant spherical "camera.pop('vfov', None); camera.pop('hfov', None); camera['projection'] = 'spherical'"

rows=(
  "pinhole|$rayo|$out/pinhole.json|"
  "thin lens (radius 0.1)|$rayo|$out/thin_lens.json|"
  "fisheye (180°)|$rayo|$out/fisheye.json|"
  "spherical|$rayo|$out/spherical.json|"
  "pinhole, single rays|$rayo|$out/pinhole.json|--single-rays"
  "adaptive (0.3, depth 3)|$rayo|$out/pinhole.json|--aa adaptive"
)
[[ -n ${RAYO_BASELINE:-} ]] && rows+=("pinhole, baseline binary|$RAYO_BASELINE|$out/pinhole.json|")
declare -A best rays
for ((i = 0; i < runs; i++)); do
  for row in "${rows[@]}"; do
    IFS='|' read -r name binary file extra <<<"$row"
    # shellcheck disable=SC2086
    read -r mrays camera < <("$binary" render "$file" --width "$width" --spp "$spp" --threads \
      "$threads" --quiet --stats -o "$out/x.exr" $extra |
      awk '/throughput/ { m = $2 } /rays camera/ { c = $3 } END { print m, c }')
    rays[$name]=$camera
    if [[ -z ${best[$name]:-} ]] || awk -v a="$mrays" -v b="${best[$name]}" 'BEGIN { exit !(a > b) }'; then
      best[$name]=$mrays
    fi
  done
done
printf "%-28s %12s %10s\n" "variant" "camera rays" "Mrays/s"
for row in "${rows[@]}"; do
  name="${row%%|*}"
  printf "%-28s %12s %10s\n" "$name" "${rays[$name]}" "${best[$name]}"
done
echo "(best of $runs runs; $(basename "$scene") at width $width, $spp spp, $threads thread(s))"
