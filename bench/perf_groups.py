#!/usr/bin/env python3
"""Where a rayo run's time goes, by function group, from a perf profile (docs/performance.md,
"Where the time goes").

Usage:
  perf record -F 1999 -g -o X.data -- build/rayo render SCENE --width 2048 --height 2048 \
      --threads 2 -o /tmp/x.png
  perf script -i X.data -F comm,tid,ip,sym,dso | bench/perf_groups.py

Each sample goes to one group, decided by its call chain: start-up, the partial-render journal
and the image writer by any frame of the chain; the rest by the leaf frame, or, for samples in
the kernel or libc, by the first user-space frame under them. rayo is built without frame
pointers, so with `-g` a chain stops at rayo's frames: samples in malloc or in page faults
under rayo's code then count as "allocation, page faults" even when they come from start-up
(`--call-graph dwarf` gives the whole chains, at ~15 MB per 1000 samples).
"""
import collections
import re
import sys

# (group, pattern over the leaf frame's symbol), tried in order.
LEAF_GROUPS = [
    ("user geometry (sphere/cone intersection callbacks)",
     r"user_intersect|user_occluded|ConeFrame::nearest|SphereNearest|CallNearest|::nearest"),
    ("NFF one-sided polygons (back-face filter)", r"cull_back_faces"),
    ("hit records, Embree ray conversion",
     r"::surface|intersect_coherent|occluded_coherent|Accel::"),
    ("shading: shadow rays (light samples)",
     r"light_sample|shade_level|shadow_transmittance|unoccluded|sample_u|through_volumes"),
    ("shading: reflection/refraction",
     r"plan_transport|add_transport|::trace|combine_transport|arriving|through_medium"),
    ("shading: wavefront bookkeeping", r"PathNode|radiance_coherent|intersect_level"),
    ("shading: Phong, shading point", r"prepare|direct|phong|ambient_and_emission|::shade|pow"),
    ("camera, tile loop", r"render_tile|Camera|stratified"),
    ("allocation, page faults", r"malloc|_int_free|cfree|operator new|memset|_M_default_append"),
]
# Libraries rayo renders with; a leaf in any other library is OpenImageIO's dependencies'
# static initialisers (start-up).
RENDER_LIBS = r"rayo$|libc\.so|libm\.so|libz|embree|tbb|kernel|OpenColorIO|OpenImageIO|" \
              r"libstdc|libpng|unknown"


def classify(frames):
    syms = [s for s, _ in frames]
    dsos = [d for _, d in frames]
    chain = " ".join(syms)
    leaf_sym, leaf_dso = frames[0]
    if (any("ld-linux" in d for d in dsos) or "dl_main" in chain or "_dl_init" in chain
            or "call_init" in chain or "_GLOBAL__sub_I" in chain
            or not re.search(RENDER_LIBS, leaf_dso)):
        return "start-up (dynamic loader, static initialisers)"
    if "PartialRender" in chain or "pwrite" in chain or "fdatasync" in chain:
        return "journal (partial-render tiles to disk)"
    if (re.search(r"libz|png|OpenColorIO|OpenImageIO", leaf_dso)
            or re.search(r"DisplayEncoder|TileStream|BandStream|FileWriter|png_|deflate", chain)):
        return "image write (OCIO view, quantise, PNG/zlib)"
    if "libembree" in leaf_dso:
        return "Embree traversal, intersection, BVH build"
    if "libtbb" in leaf_dso:
        return "TBB"
    user = [(s, d) for s, d in frames if "kernel" not in d]
    user_sym = user[0][0] if user else "?"
    for group, pattern in LEAF_GROUPS:
        if re.search(pattern, user_sym):
            return group
    if "kernel" in leaf_dso:
        return "kernel, other"
    return "other"


def main():
    groups = collections.Counter()
    frames = []

    def flush():
        if frames:
            groups[classify(frames)] += 1

    for line in sys.stdin:
        if not line.strip() or not line.startswith((" ", "\t")):
            flush()
            frames = []
            continue
        match = re.match(r"\s*[0-9a-f]+ (.*) \((.*)\)\s*$", line)
        if match:
            frames.append((match.group(1), match.group(2)))
    flush()
    total = sum(groups.values())
    for group, count in groups.most_common():
        print(f"{100.0 * count / total:5.1f}%  {group}")
    print(f"{total} samples")


if __name__ == "__main__":
    main()
