#!/usr/bin/env bash
# The bit-identity check of refactors: renders every example scene (scenes/*.json) and every SPD
# file (../shared/spd/*.nff, when present) at 128 px wide into DIR as float EXR, or, with
# --compare BEFORE AFTER, says which pairs differ in any pixel (idiff with a zero threshold).
# Usage: scripts/reference_renders.sh DIR [rayo flags...]
#        scripts/reference_renders.sh --compare BEFORE_DIR AFTER_DIR
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ "${1:-}" == "--compare" ]]; then
    before=$2 after=$3 differ=0 same=0
    for f in "$before"/*.exr; do
        name=$(basename "$f")
        if [[ ! -f "$after/$name" ]]; then echo "missing: $name"; differ=$((differ + 1)); continue; fi
        if idiff -q -fail 0 -failpercent 0 -warn 0 "$f" "$after/$name" >/dev/null 2>&1; then
            same=$((same + 1))
        else
            echo "differs: $name"; differ=$((differ + 1))
        fi
    done
    echo "$same identical, $differ different"
    exit $((differ > 0))
fi
out=${1:?usage: reference_renders.sh DIR [rayo flags...]}
shift
mkdir -p "$out"
rayo="${RAYO:-$root/build/rayo}"
scenes=("$root"/scenes/*.json)
if compgen -G "$root/../shared/spd/*.nff" >/dev/null; then scenes+=("$root"/../shared/spd/*.nff); fi
for scene in "${scenes[@]}"; do
    name=$(basename "${scene%.*}")
    (cd "$(dirname "$scene")" && "$rayo" render "$scene" --width 128 --quiet -o "$out/$name.exr" "$@")
done
echo "${#scenes[@]} renders in $out"
