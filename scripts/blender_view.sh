# shellcheck shell=bash
# Sourced by scripts/model_gallery.sh and scripts/cycles_compare.sh (not run on its own): rayo's
# view and directional lights, as `rayo render --stats` prints them, turned into the arguments of
# scripts/model_gallery_blender.py, so that Cycles renders the file from rayo's camera.
#
#   mapfile -t args < <(blender_view_args LOG)   # --eye=X,Y,Z --look-at=... --up=... --vfov=V
#   mapfile -t suns < <(blender_sun_args LOG)    # one --sun=DX,DY,DZ,I per directional light
#
# "=" joins each option to its value: the values may start with "-".

# The `view` line of --stats: "eye X Y Z, look_at X Y Z, up X Y Z, fov HxV degrees".
blender_view_args() {  # LOG
    local view ex ey ez lx ly lz ux uy uz vfov
    view=$(sed -n 's/^  view  *//p' "$1" | head -1)
    if [[ -z "$view" ]]; then
        echo "blender_view.sh: no 'view' line in $1 (render with --stats)" >&2
        return 1
    fi
    read -r ex ey ez lx ly lz ux uy uz < <(echo "$view" |
        sed -E 's/eye ([^ ]+) ([^ ]+) ([^,]+), look_at ([^ ]+) ([^ ]+) ([^,]+), up ([^ ]+) ([^ ]+) ([^,]+),.*/\1 \2 \3 \4 \5 \6 \7 \8 \9/')
    vfov=$(echo "$view" | sed -E 's/.*fov [^x]+x([0-9.eE+-]+) degrees.*/\1/')
    printf '%s\n' "--eye=$ex,$ey,$ez" "--look-at=$lx,$ly,$lz" "--up=$ux,$uy,$uz" "--vfov=$vfov"
}

# rayo's directional lights (the automatic key and fill) as Cycles suns; emitters and the
# file's own lights come with the imported file.
blender_sun_args() {  # LOG
    sed -n -E 's/^  light [0-9]+ .* directional direction ([^ ]+) ([^ ]+) ([^ ]+) color [^ ]+ [^ ]+ [^ ]+ intensity ([^ ]+)$/--sun=\1,\2,\3,\4/p' "$1"
}
