#!/usr/bin/env bash
# Conformance against the Standard Procedural Databases in ../shared/spd (CI only: the folder
# is never on a user's machine). Two checks for every NFF file (and a third, of the generators of
# `rayo bench suite`, described at its section below):
# 1. Counts: `rayo info` must report the object counts that an independent awk count of the
#    file gives (spheres, cones, triangles = Σ(vertices − 2) over p/pp polygons, lights,
#    materials), and the scene must render to a valid PNG.
# 2. Images: rayo's render (`rayo render X.nff --width 256 --height 256 -o X.exr`) against
#    POV-Ray 3.7's render of the SPD's translation (spd/pov/X.pov, frame widened for 256 pixels
#    by spd/pov_frame.py, as spd/README.md says). Both are divided by the POV-Ray image's mean
#    (build/image_compare, bench/image_compare.cpp); a pixel is off when a channel differs by
#    more than 5 % of that mean. The share of pixels off must stay at or under the scene's
#    threshold (table below; docs/nff.md explains every scene above 1 % and how the thresholds
#    were set). POV-Ray is installed through scripts/setup.sh (RAYO_SETUP_EXTRAS=povray).
# Renders run RAYO_JOBS (default 2) scenes at a time, one thread each. With
# RAYO_CONFORMANCE_FIGURES=DIR, each scene's rayo | POV-Ray | 4×|difference| is saved in DIR as
# NAME.png (sRGB) to look at.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
spd="${RAYO_SPD_DIR:-$root/../shared/spd}"
build="${RAYO_BUILD_DIR:-$root/build}"
rayo="$build/rayo"
compare="$build/image_compare"
jobs="${RAYO_JOBS:-2}"
size=256
if [[ ! -d "$spd" ]]; then
  echo "conformance: $spd not found; nothing to check" >&2
  exit 1
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

passed=0
failed=0
for nff in "$spd"/*.nff; do
  name="$(basename "$nff" .nff)"
  expected="$(awk '
    $1 == "s" { s++ } $1 == "c" { c++ } $1 == "l" { l++ } $1 == "f" { f++ }
    ($1 == "p" || $1 == "pp") && NF == 2 { t += $2 - 2 }
    END { printf "spheres %d\ncones %d\ntriangles %d\nlights %d\nmaterials %d\n", s, c, t, l, f }
  ' "$nff")"
  info="$("$rayo" info "$nff")"
  # Zero-area patches are skipped with a warning: count their triangles with the loaded ones.
  actual="$(awk '$1 == "skipped_triangles" { skipped = $2 } $1 == "triangles" { t = $2 }
                 $1 ~ /^(spheres|cones|lights|materials)$/ { print }
                 END { printf "triangles %d\n", t + skipped }' <<<"$info" | sort)"
  expected="$(sort <<<"$expected")"
  # rayo may merge identical materials: compare materials as "at most the f count, at least 1".
  exp_counts="$(grep -v '^materials' <<<"$expected")"
  act_counts="$(grep -v '^materials' <<<"$actual")"
  exp_materials="$(awk '$1=="materials"{print $2}' <<<"$expected")"
  act_materials="$(awk '$1=="materials"{print $2}' <<<"$actual")"
  if [[ "$exp_counts" != "$act_counts" || -z "$act_materials" || "$act_materials" -gt "$exp_materials" || "$act_materials" -lt 1 ]]; then
    echo "FAIL $name: counts differ"
    diff <(echo "$expected") <(echo "$actual") || true
    failed=$((failed + 1))
    continue
  fi
  if ! "$rayo" render "$nff" --width 128 --height 128 --quiet -o "$out/$name.png"; then
    echo "FAIL $name: render failed"
    failed=$((failed + 1))
    continue
  fi
  if ! oiiotool --info "$out/$name.png" | grep -q "128 x  128"; then
    echo "FAIL $name: output is not a 128x128 image"
    failed=$((failed + 1))
    continue
  fi
  echo "ok   $name: $(tr '\n' ' ' <<<"$act_counts")"
  passed=$((passed + 1))
done
echo "conformance counts: $passed passed, $failed failed"

# ---- the generators of `rayo bench suite` against the SPD's files ----------------------------
# bench/lab/spd_scenes.h makes the seven scenes from their published description; written out by
# `rayo bench suite --write-nff`, each NAME_SIZE must agree with the SPD's own NAME_SIZE.nff:
# 1. counts: `rayo info` of both reports the same spheres, cones, triangles (+ skipped),
#    lights and materials;
# 2. numbers: line by line, every number within 1e-4 (the SPD prints six digits), gears' colours
#    and glass and mount's heights included (the SPD's own formulas, docs/performance.md "The
#    SPD suite");
# 3. images: rayo's renders of both at 128×128 compared as above (build/image_compare, a pixel off
#    when a channel differs by more than 5 % of the mean): at most 1 % of the pixels off;
#    teapot_1 at most 4 %: at size 1
#    the handle's and spout's triangles lie flat in the plane y = 0, facing the camera, with
#    shading normals in that plane, so the side they shade comes from the 1e-16 residues of
#    the SPD's arithmetic (±7e-17 in y), which the generator does not reproduce (2.8 % measured).
[[ -x "$compare" ]] || { echo "conformance: $compare not built (scripts/build.sh)" >&2; exit 1; }
gen_passed=0
gen_failed=0
declare -A gen_max_off=([teapot_1]=4)
for nff in "$spd"/*.nff; do
  name="$(basename "$nff" .nff)"
  scene="${name%_*}"
  size="${name##*_}"
  "$rayo" bench suite --scenes "$scene" --size "$size" --write-nff -o "$out/gen" >/dev/null
  gen="$out/gen/$name.nff"
  counts() { "$rayo" info "$1" | awk '$1 ~ /^(spheres|cones|lights|materials)$/ { print }
    $1 == "triangles" || $1 == "skipped_triangles" { t += $2 } END { print "triangles", t }'; }
  if [[ "$(counts "$gen")" != "$(counts "$nff")" ]]; then
    echo "FAIL generated $name: counts differ"
    diff <(counts "$nff") <(counts "$gen") || true
    gen_failed=$((gen_failed + 1))
    continue
  fi
  numbers="$(awk -v scene="$scene" '
    NR == FNR { line[FNR] = $0; next }
    {
      if (FNR > length(line)) { print "extra line " FNR; bad = 1; exit }
      n = split(line[FNR], a, " ")
      if (n != NF) { print "line " FNR ": " NF " fields, generated " n; bad = 1; exit }
      for (i = 1; i <= NF; i++) {
        if ($i ~ /^[a-z]/) { if ($i != a[i]) { print "line " FNR ": " $i " vs " a[i]; bad = 1; exit } }
        else { d = $i - a[i]; if (d < 0) d = -d; m = ($i < 0 ? -$i : $i); if (m < 1) m = 1
               if (d > 1e-4 * m) { print "line " FNR ": " $0 " vs " line[FNR]; bad = 1; exit } }
      }
    }
    END { if (!bad && FNR != length(line)) print "generated has " length(line) " lines, SPD " FNR }
  ' "$gen" "$nff")"
  if [[ -n "$numbers" ]]; then
    echo "FAIL generated $name: numbers differ: $numbers"
    gen_failed=$((gen_failed + 1))
    continue
  fi
  for which in gen spd; do
    src="$gen"
    [[ "$which" == spd ]] && src="$nff"
    "$rayo" render "$src" --width 128 --height 128 --quiet -o "$out/$name.$which.exr"
  done
  limit="${gen_max_off[$name]:-${gen_max_off[$scene]:-1}}"
  status=0
  result="$("$compare" "$out/$name.gen.exr" "$out/$name.spd.exr" --threshold 0.05 \
    --max-off "$limit")" || status=$?
  if ((status != 0)); then
    echo "FAIL generated $name: images differ ($result; at most $limit % off)"
    gen_failed=$((gen_failed + 1))
    continue
  fi
  echo "ok   generated $name: image $result (% off, mean error, PSNR; at most $limit % off)"
  gen_passed=$((gen_passed + 1))
done
echo "conformance generators: $gen_passed passed, $gen_failed failed"
passed=$((passed + gen_passed))
failed=$((failed + gen_failed))

# ---- images: rayo against POV-Ray -------------------------------------------------------------

# Largest share of pixels (%) that may be off by more than 5 % of the POV-Ray image's mean.
# Opaque scenes: 2 % (the teapots excepted). The others: the share measured at 256×256
# (docs/nff.md, "Conformance with POV-Ray") plus 10 %, rounded up to a whole percent.
declare -A max_off=(
  [balls_1]=2 [balls_2]=2 [balls_3]=2
  [rings_1]=2 [rings_2]=2 [rings_3]=2
  [tetra_1]=2 [tetra_2]=2 [tetra_3]=2
  [tree_1]=2 [tree_2]=2 [tree_3]=2
  [teapot_1]=15 [teapot_2]=8 [teapot_3]=4  # POV-Ray: two-sided, drops straddling smooth triangles,
                                           # shadow rays from the flat triangles
  [gears_1]=97 [gears_2]=35                # transmissive: POV-Ray's filter tint, filtered shadows
  [mount_1]=21 [mount_2]=21 [mount_3]=22   # transmissive: filtered shadows, trace depth
)

RAYO_SETUP_EXTRAS="${RAYO_SETUP_EXTRAS:-} povray" "$root/scripts/setup.sh"
command -v povray >/dev/null || { echo "conformance: povray is not installed" >&2; exit 1; }
command -v python3 >/dev/null || { echo "conformance: python3 (for pov_frame.py) is missing" >&2; exit 1; }
[[ -x "$compare" ]] || { echo "conformance: $compare not built (scripts/build.sh)" >&2; exit 1; }

# Both renders of one scene, one thread each; logs beside the images.
render_pair() {
  local name="$1"
  "$rayo" render "$spd/$name.nff" --width "$size" --height "$size" --threads 1 --quiet \
    -o "$out/$name.rayo.exr" >"$out/$name.rayo.log" 2>&1 || return 0
  python3 "$spd/pov_frame.py" "$size" <"$spd/pov/$name.pov" >"$out/$name.pov" || return 0
  # POV-Ray writes only below the current folder or /tmp (Debian's povray.conf).
  (cd "$out" && povray "+I$name.pov" "+O$name.pov.exr" "+W$size" "+H$size" -A +FE -D +WT1 \
    >"$name.pov.log" 2>&1) || return 0
}

image_start=$SECONDS
running=0
for nff in "$spd"/*.nff; do
  render_pair "$(basename "$nff" .nff)" &
  running=$((running + 1))
  if ((running >= jobs)); then
    wait -n || true
    running=$((running - 1))
  fi
done
wait

image_passed=0
image_failed=0
printf "%-10s %8s %10s %10s %8s\n" scene "% off" "mean err" "PSNR dB" "max %"
for nff in "$spd"/*.nff; do
  name="$(basename "$nff" .nff)"
  limit="${max_off[$name]:-}"
  if [[ -z "$limit" ]]; then
    echo "FAIL $name: no threshold in scripts/conformance.sh (measure it, explain it in docs/nff.md)"
    image_failed=$((image_failed + 1))
    continue
  fi
  for part in rayo pov; do
    if [[ ! -s "$out/$name.$part.exr" ]]; then
      echo "FAIL $name: the $part render failed:"
      tail -n 5 "$out/$name.$part.log" 2>/dev/null || true
      image_failed=$((image_failed + 1))
      continue 2
    fi
  done
  status=0
  result="$("$compare" "$out/$name.rayo.exr" "$out/$name.pov.exr" --threshold 0.05 \
    --max-off "$limit")" || status=$?
  if ((status > 1)); then
    echo "FAIL $name: image_compare failed ($result)"
    image_failed=$((image_failed + 1))
    continue
  fi
  read -r off mean_error psnr <<<"$result"
  if [[ -n "${RAYO_CONFORMANCE_FIGURES:-}" ]]; then
    mkdir -p "$RAYO_CONFORMANCE_FIGURES"
    oiiotool "$out/$name.rayo.exr" --ch R,G,B -o "$out/$name.rgb.exr"
    oiiotool "$out/$name.rgb.exr" "$out/$name.pov.exr" --sub --abs --mulc 4 -o "$out/$name.diff.exr"
    oiiotool "$out/$name.rgb.exr" "$out/$name.pov.exr" "$out/$name.diff.exr" --mosaic:pad=4 3x1 \
      --colorconvert linear sRGB -d uint8 -o "$RAYO_CONFORMANCE_FIGURES/$name.png"
  fi
  if ((status == 1)); then
    printf "%-10s %8s %10s %10s %8s   FAIL: more than %s %% off\n" "$name" "$off" \
      "$mean_error" "$psnr" "$limit" "$limit"
    image_failed=$((image_failed + 1))
  else
    printf "%-10s %8s %10s %10s %8s   ok\n" "$name" "$off" "$mean_error" "$psnr" "$limit"
    image_passed=$((image_passed + 1))
  fi
done
echo "conformance images: $image_passed passed, $image_failed failed" \
  "($((SECONDS - image_start)) s, $jobs jobs)"
echo "conformance: $((passed + image_passed)) passed, $((failed + image_failed)) failed"
[[ $((failed + image_failed)) -eq 0 ]]
