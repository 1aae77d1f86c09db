#!/usr/bin/env bash
# The model gallery of docs/models.md ("Gallery"), issue 14's closing check: public model files
# rendered by rayo with one command each (no JSON), beside a reference render of the same file
# by Blender's Cycles from the same camera (when `blender` is installed: a comparison tool only,
# never a dependency of rayo), with parse, BVH, render and texture-cache figures from --stats.
#
#   scripts/model_gallery.sh [-o DIR] [--rayo PATH] [--size N] [--samples N] [--threads N]
#                            [--no-blender] [--only NAME,NAME] [--figures DIR]
#
#   -o DIR        output folder [build/model_gallery]: NAME_rayo.png, NAME_blender.png,
#                 NAME_pair.png (rayo left, Blender right), NAME.log, gallery.md (the table)
#   --rayo PATH   the rayo binary [build/rayo]
#   --size N      each render's side in pixels [512]
#   --samples N   Cycles samples per pixel [32]
#   --threads N   threads for rayo and Cycles [2]
#   --no-blender  rayo only (also when blender is not installed)
#   --only LIST   only these models (names in the table below)
#   --figures DIR also write NAME.png, the pair at 256 × 256 each (docs/figures/models/)
#   --references DIR  take NAME_blender.png from DIR (an earlier run's -o) instead of running
#                 Blender again (the camera is rayo's framing: the same while it is unchanged)
#
# The assets come from Debian's assimp-testmodels (/usr/share/assimp/models) and the project's
# scenes/meshes/cornell_box.obj. Blender 3.4 (Debian 12) reads every file but the Draco one (its
# glTF importer needs Blender's own libextern_draco.so, which Debian does not ship): the Draco
# engine's reference is its uncompressed twin, 2CylinderEngine-glTF-Binary/2CylinderEngine.glb.
# Needs rayo and oiiotool (GNU time for the peak memory, if there); the references need
# `apt-get install blender python3-numpy` (Blender's glTF importer imports numpy).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(dirname "$here")
# shellcheck source=scripts/blender_view.sh
source "$here/blender_view.sh"
out="$root/build/model_gallery"
rayo="$root/build/rayo"
size=512
samples=32
threads=2
blender=auto
only=""
figures=""
references=""
while [[ $# -gt 0 ]]; do
    case "$1" in
        -o) out=$2; shift 2 ;;
        --rayo) rayo=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        --samples) samples=$2; shift 2 ;;
        --threads) threads=$2; shift 2 ;;
        --no-blender) blender=no; shift ;;
        --only) only=$2; shift 2 ;;
        --figures) figures=$2; shift 2 ;;
        --references) references=$2; shift 2 ;;
        -h|--help) sed -n '2,27p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "model_gallery.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
[[ -x "$rayo" ]] || { echo "model_gallery.sh: no rayo binary at $rayo (build it, or --rayo)" >&2; exit 2; }
command -v oiiotool >/dev/null || { echo "model_gallery.sh: oiiotool not found" >&2; exit 2; }
if [[ $blender == auto ]]; then
    if command -v blender >/dev/null; then blender=yes; else
        echo "model_gallery.sh: blender not installed: rayo's renders only" >&2; blender=no; fi
fi
mkdir -p "$out"
[[ -n "$figures" ]] && mkdir -p "$figures"
models=/usr/share/assimp/models
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
# Runs COMMAND..., writing its peak memory to TIME_FILE through GNU time when it is there
# (Debian package `time`).
run_timed() {  # TIME_FILE COMMAND...
    local time_file=$1
    shift
    if [[ -x /usr/bin/time ]]; then /usr/bin/time -f "peak_rss_kb %M" -o "$time_file" "$@"; else "$@"; fi
}

# name | what it shows | the model file | rayo's flags beyond size and output | Blender's file
assets=(
  "box_glb|glTF binary (.glb): embedded PNG, metallic/roughness factors|$models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb||"
  "box_gltf|glTF with an external .bin and PNG|$models/glTF2/BoxTextured-glTF/BoxTextured.gltf||"
  "box_data_uri|glTF with data URIs (buffer and PNG)|$models/glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf||"
  "engine_draco|Draco-compressed glTF (KHR_draco_mesh_compression), the file's camera, 52 instances|$models/glTF2/draco/2CylinderEngine.gltf||$models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"
  "spider|OBJ + MTL with map_Kd (JPEG textures)|$models/OBJ/spider.obj||"
  "wuson|PLY scan-like mesh (per-face normals)|$models/PLY/Wuson.ply||"
  "clearcoat|glTF with metallicRoughnessTexture, normal maps, an emissive texture (the labels) and KHR_materials_clearcoat|$models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf|--auto-lights|"
  "cornell|Cornell box OBJ lit by its own emitter (MTL Ke)|$root/scenes/meshes/cornell_box.obj|--view-dir 0,0,-1 --no-ground|"
)

# The value after "LABEL" on rayo's --stats table (trimmed), or "-".
stat_value() {
    local v
    v=$(sed -n "s/^  $2 *//p" "$1" | head -1)
    echo "${v:--}"
}

# IMAGE TEXT OUTPUT: the image as RGB with TEXT in its top left corner (when the font is there).
label() {
    if [[ -f "$font" ]]; then
        oiiotool "$1" --ch R,G,B --text:x=8:y=22:size=18:color=1,1,1:font="$font" "$2" -o "$3"
    else
        oiiotool "$1" --ch R,G,B -o "$3"
    fi
}

table="$out/gallery.md"
{
    echo "| model | file | triangles | parse | BVH | render | rayo wall | peak RSS | image textures, cache used | Cycles |"
    echo "|---|---|---|---|---|---|---|---|---|---|"
} > "$table"
commands="$out/commands.txt"
: > "$commands"

for entry in "${assets[@]}"; do
    IFS='|' read -r name what file flags reference <<< "$entry"
    if [[ -n "$only" && ",$only," != *",$name,"* ]]; then continue; fi
    if [[ ! -f "$file" ]]; then
        echo "model_gallery.sh: $name: $file missing (Debian package assimp-testmodels)" >&2
        continue
    fi
    log="$out/$name.log"
    png="$out/${name}_rayo.png"
    echo "rayo render $file $flags --width $size --height $size --threads $threads --stats -o $png" |
        tr -s ' ' >> "$commands"
    start=$(date +%s%N)
    # shellcheck disable=SC2086
    run_timed "$out/$name.time" "$rayo" render "$file" $flags --width "$size" --height "$size" --threads "$threads" \
        --stats -o "$png" > "$log" 2>&1 || { echo "model_gallery.sh: $name: rayo failed, see $log" >&2; cat "$log" >&2; continue; }
    wall_ms=$((($(date +%s%N) - start) / 1000000))
    rss=$(sed -n 's/^peak_rss_kb //p' "$out/$name.time" 2>/dev/null || true)
    rss=${rss:+$((rss / 1024)) MB}
    "$rayo" info "$file" > "$out/$name.info"
    triangles=$(sed -n 's/^triangles //p' "$out/$name.info")
    instanced=$(sed -n 's/^instanced_objects //p' "$out/$name.info")
    [[ -n "$instanced" ]] && triangles="$triangles + $instanced instanced"
    # "N image(s) (... encoded, ... decoded), cache X MB used, peak Y MB, limit Z MB", shortened
    textures=$(stat_value "$log" "image textures" |
        sed -E 's/^([0-9]+) image\(s\).*cache ([0-9.]+ MB) used, peak ([0-9.]+ MB).*/\1, cache \2 (peak \3)/')
    view=$(stat_value "$log" "view")
    echo "$name ($what): $view"

    cycles="-"
    pair_inputs=("$png")
    if [[ -n "$references" && -f "$references/${name}_blender.png" ]]; then
        [[ "$references" -ef "$out" ]] || cp "$references/${name}_blender.png" "$out/"
        pair_inputs+=("$out/${name}_blender.png")
        cycles="earlier run"
    elif [[ $blender == yes ]]; then
        ref="$out/${name}_blender.png"
        mapfile -t camera < <(blender_view_args "$log")
        mapfile -t suns < <(blender_sun_args "$log")
        extra=()
        [[ " $flags " == *" --no-ground "* ]] && extra+=(--no-ground)
        # No emitter or file light: rayo's ambient term (ka = 0.1 base colour for glTF) as a
        # uniform environment of radiance 0.1; the Cornell box has no ambient (no Ka).
        if [[ ${#suns[@]} -gt 0 ]]; then extra+=(--ambient 0.1); else extra+=(--ambient 0); fi
        start=$(date +%s%N)
        if nice -n 10 blender -b --factory-startup -t "$threads" -P "$here/model_gallery_blender.py" -- \
            --model "${reference:-$file}" --out "$ref" --size "$size" --samples "$samples" \
            "${camera[@]}" "${suns[@]}" "${extra[@]}" > "$out/${name}_blender.log" 2>&1 && [[ -f "$ref" ]]; then
            cycles="$((($(date +%s%N) - start) / 1000000000)) s"
            pair_inputs+=("$ref")
        else
            echo "model_gallery.sh: $name: Blender failed, see $out/${name}_blender.log" >&2
            cycles="failed"
        fi
    fi

    # Side by side (rayo left), labelled when the DejaVu font is there.
    label "$png" "rayo" "$out/.l.png"
    pair=("$out/.l.png")
    if [[ ${#pair_inputs[@]} -gt 1 ]]; then
        label "${pair_inputs[1]}" "Cycles (Blender)" "$out/.r.png"
        pair+=("$out/.r.png")
    fi
    oiiotool "${pair[@]}" --mosaic "${#pair[@]}x1" -o "$out/${name}_pair.png"
    if [[ -n "$figures" ]]; then
        small=()
        for i in "${!pair_inputs[@]}"; do
            oiiotool "${pair_inputs[$i]}" --resize 256x256 -o "$out/.s$i.png"
            if [[ $i == 0 ]]; then label "$out/.s$i.png" "rayo" "$out/.t$i.png";
            else label "$out/.s$i.png" "Cycles" "$out/.t$i.png"; fi
            small+=("$out/.t$i.png")
        done
        oiiotool "${small[@]}" --mosaic "${#small[@]}x1" -o "$figures/$name.png"
    fi
    rm -f "$out"/.l.png "$out"/.r.png "$out"/.s*.png "$out"/.t*.png

    short=${file#"$models/"}
    short=${short#"$root/"}
    # shellcheck disable=SC2016  # the backquotes are Markdown
    printf '| %s | `%s` | %s | %s | %s | %s | %d.%02d s | %s | %s | %s |\n' \
        "$name" "$short${flags:+ $flags}" "$triangles" "$(stat_value "$log" "time parse")" \
        "$(stat_value "$log" "time BVH build")" "$(stat_value "$log" "time render")" \
        $((wall_ms / 1000)) $((wall_ms % 1000 / 10)) "${rss:--}" "$textures" "$cycles" >> "$table"
done

echo "model_gallery.sh: $out/gallery.md:"
cat "$table"
