#!/usr/bin/env bash
# The experiments behind docs/nff.md "Conformance with POV-Ray": each renders an SPD scene with one
# convention changed on one side (rayo or POV-Ray) and prints image_compare's numbers
# (% pixels off, mean relative error, PSNR) against POV-Ray, as scripts/conformance.sh measures.
# Needs ../shared/spd (or RAYO_SPD_DIR), a build (build/rayo, build/image_compare), povray and
# python3. rayo renders with `--shadow-terminator none`, POV-Ray's convention (docs/nff.md), so
# that each experiment isolates one other convention. Usage: bench/spd_experiments.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
spd="${RAYO_SPD_DIR:-$root/../shared/spd}"
build="${RAYO_BUILD_DIR:-$root/build}"
rayo="$build/rayo"
compare="$build/image_compare"
size=256
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
cd "$out"  # POV-Ray writes only below the current folder or /tmp

rayo_render() {  # NFF OUT.exr [rayo options...]
  local nff="$1" exr="$2"
  shift 2
  "$rayo" render "$nff" --width "$size" --height "$size" --quiet --shadow-terminator none \
    -o "$exr" "$@"
}
pov_render() {  # POV OUT.exr (the translation as shipped, frame widened by pov_frame.py)
  python3 "$spd/pov_frame.py" "$size" <"$1" >frame.pov
  povray +Iframe.pov "+O$2" "+W$size" "+H$size" -A +FE -D >/dev/null 2>&1
}
row() { printf "%-48s %s\n" "$1" "$("$compare" "$2" "$3")"; }

# POV-Ray's smooth_triangle -> triangle (flat), for the "both flat" teapots.
flat_pov() {
  python3 -c '
import re, sys
n = r"[-+0-9.eE]+"
v = r"<\s*(%s)\s*,\s*(%s)\s*,\s*(%s)\s*>" % (n, n, n)
p = re.compile(r"smooth_triangle\s*\{\s*" + r"\s*,\s*".join([v + r"\s*" + v] * 3) + r"\s*\}")
sys.stdout.write(p.sub(lambda m: "triangle { <%s, %s, %s>, <%s, %s, %s>, <%s, %s, %s> }"
                 % tuple(m.group(i) for i in (1, 2, 3, 7, 8, 9, 13, 14, 15)), sys.stdin.read()))'
}
# NFF: pp -> p without the normals, zero-area patches left out (a zero-area p is an error).
flat_nff() {
  python3 -c '
import sys
lines = sys.stdin.read().split("\n"); out = []; i = 0
while i < len(lines):
    t = lines[i].split()
    if t and t[0] == "pp":
        k = int(t[1]); vs = [list(map(float, lines[i + 1 + j].split()[:3])) for j in range(k)]
        a = [0.0, 0.0, 0.0]
        for j in range(1, k - 1):
            e = [vs[j][c] - vs[0][c] for c in range(3)]; f = [vs[j + 1][c] - vs[0][c] for c in range(3)]
            a = [a[0] + e[1] * f[2] - e[2] * f[1], a[1] + e[2] * f[0] - e[0] * f[2], a[2] + e[0] * f[1] - e[1] * f[0]]
        if any(a):
            out.append("p %d" % k); out += ["%r %r %r" % tuple(x) for x in vs]
        i += 1 + k; continue
    out.append(lines[i]); i += 1
sys.stdout.write("\n".join(out))'
}
two_sided() { awk '$1 == "f" && $8 == 0 { $8 = "1e-6"; $9 = "1" } { print }'; }  # T > 0
no_lights_nff() { grep -v '^l '; }
no_lights_pov() { python3 -c '
import re, sys
sys.stdout.write(re.sub(r"light_source \{[^}]*\}\s*// light", "", sys.stdin.read()))'; }

echo "scene / experiment                               % off, mean relative error, PSNR dB"
for s in balls_3 teapot_3; do
  pov_render "$spd/pov/$s.pov" "$s.pov.exr"
  rayo_render "$spd/$s.nff" "$s.unit.exr" --nff-light-intensity 1
  row "$s unit lights (--nff-light-intensity 1)" "$s.unit.exr" "$s.pov.exr"
done

for s in teapot_1 teapot_2 teapot_3; do
  pov_render "$spd/pov/$s.pov" "$s.pov.exr"
  rayo_render "$spd/$s.nff" "$s.exr"
  row "$s as shipped" "$s.exr" "$s.pov.exr"
  two_sided <"$spd/$s.nff" >"$s.2s.nff"
  rayo_render "$s.2s.nff" "$s.2s.exr"
  row "$s rayo two-sided" "$s.2s.exr" "$s.pov.exr"
  flat_nff <"$s.2s.nff" >"$s.flat.nff"
  flat_pov <"$spd/pov/$s.pov" >"$s.flat.pov"
  pov_render "$s.flat.pov" "$s.flat.pov.exr"
  rayo_render "$s.flat.nff" "$s.flat.exr"
  row "$s both flat, rayo two-sided" "$s.flat.exr" "$s.flat.pov.exr"
done

for s in gears_1 gears_2 mount_1 mount_2 mount_3; do
  pov_render "$spd/pov/$s.pov" "$s.pov.exr"
  rayo_render "$spd/$s.nff" "$s.exr"
  row "$s as shipped" "$s.exr" "$s.pov.exr"
  no_lights_nff <"$spd/$s.nff" >"$s.nol.nff"
  no_lights_pov <"$spd/pov/$s.pov" >"$s.nol.pov"
  sed 's/ filter / transmit /' "$s.nol.pov" >"$s.noltr.pov"
  pov_render "$s.nol.pov" "$s.nol.pov.exr"
  pov_render "$s.noltr.pov" "$s.noltr.pov.exr"
  rayo_render "$s.nol.nff" "$s.nol.exr"
  rayo_render "$s.nol.nff" "$s.nol4.exr" --max-depth 4
  rayo_render "$spd/$s.nff" "$s.d4.exr" --max-depth 4
  row "$s no lights, filter" "$s.nol.exr" "$s.nol.pov.exr"
  row "$s no lights, transmit" "$s.nol.exr" "$s.noltr.pov.exr"
  row "$s no lights, transmit, rayo --max-depth 4" "$s.nol4.exr" "$s.noltr.pov.exr"
  row "$s rayo --max-depth 4" "$s.d4.exr" "$s.pov.exr"
done
