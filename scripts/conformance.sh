#!/usr/bin/env bash
# Conformance against the Standard Procedural Databases in ../shared/spd (CI only: the folder
# is never on a user's machine). For every NFF file: `rayo info` must report the object counts
# that an independent awk count of the file gives (spheres, cones, triangles = Σ(vertices − 2)
# over p/pp polygons, lights, materials), and the scene must render to a valid PNG.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
spd="${RAYO_SPD_DIR:-$root/../shared/spd}"
rayo="${RAYO_BUILD_DIR:-$root/build}/rayo"
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
echo "conformance: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
