#!/usr/bin/python3
"""The metric of scripts/cycles_compare.sh (docs/path-tracing.md, "Against Cycles"): a rayo
render and a Cycles render of the same view, both linear OpenEXR, compared

- per channel: |mean(rayo) - mean(cycles)| / mean(cycles) over the image (signed in the output:
  rayo brighter is positive);
- per pixel: the share of pixels whose luminance (Rec. 709 weights, as rayo's) differs by more
  than 10% from Cycles', relative to max(Y_cycles, floor) with floor 1% of Cycles' mean
  luminance so that near-black pixels do not divide by zero; the same after a 4 x 4 box average
  of both images, which takes most of the two renders' per-pixel noise out and leaves the
  differences with structure (edges, highlights, textures).

    cycles_compare.py RAYO.exr CYCLES.exr [--name NAME] [--json FILE] [--figure PNG]
                      [--backdrop R,G,B] [--model-mask EXR]

--backdrop leaves out of every figure the pixels where both images show only that colour
(within 1e-4 relative in each channel): camera rays that miss see the same constant backdrop in
both renderers by construction, and counting them would dilute the differences. --model-mask
gives a render of the model alone (no ground) from the same camera: its pixels that are not the
backdrop are the model's, and the figures are given again over those pixels only.

Prints one line `NAME mean_r mean_g mean_b (rayo) | (cycles) | rel_r rel_g rel_b | share share4 |
pixels compared | the model's rel_r rel_g rel_b | share share4 | pixels` (the model's figures
repeat the image's without --model-mask);
with --json also writes the figures as a JSON object; --figure writes a small PNG of three panels
(FIGURE_SIDE pixels each): rayo, Cycles (both sRGB-encoded, clipped at 1) and the relative
luminance difference of the 4 x 4 blocks (red: rayo brighter, blue: darker, full at 20%). Needs python3-numpy and
python3-openimageio (Debian).
"""

import argparse
import json
import sys

import numpy as np
import OpenImageIO as oiio

LUMINANCE = np.array([0.2126, 0.7152, 0.0722])  # Rec. 709, core/luminance.h
THRESHOLD = 0.10
FLOOR = 0.01  # of the reference's mean luminance
BLOCK = 4
FIGURE_SIDE = 160


def read_rgb(path):
    image = oiio.ImageInput.open(path)
    if image is None:
        sys.exit("cycles_compare.py: cannot open %s: %s" % (path, oiio.geterror()))
    spec = image.spec()
    if spec.nchannels < 3:
        sys.exit("cycles_compare.py: %s has %d channel(s), expected RGB" % (path, spec.nchannels))
    pixels = image.read_image(0, 0, 0, 3, "float")
    image.close()
    if pixels is None:
        sys.exit("cycles_compare.py: cannot read %s" % path)
    return np.asarray(pixels, dtype=np.float64).reshape(spec.height, spec.width, 3)


def block_average(rgb, block):
    h, w = (rgb.shape[0] // block) * block, (rgb.shape[1] // block) * block
    return rgb[:h, :w].reshape(h // block, block, w // block, block, 3).mean(axis=(1, 3))


def share_off(test, reference, keep):
    y_test, y_ref = test @ LUMINANCE, reference @ LUMINANCE
    floor = FLOOR * y_ref[keep].mean()
    relative = np.abs(y_test - y_ref) / np.maximum(y_ref, floor)
    return float((relative[keep] > THRESHOLD).mean())


def scene_pixels(rayo, cycles, backdrop):
    """True where a pixel is not the backdrop in both images (all True without a backdrop)."""
    if backdrop is None:
        return np.ones(rayo.shape[:2], dtype=bool)
    colour = np.asarray(backdrop, dtype=np.float64)
    tolerance = 1e-4 * np.maximum(colour, 1e-3)
    is_backdrop = [np.all(np.abs(image - colour) <= tolerance, axis=-1) for image in (rayo, cycles)]
    return ~(is_backdrop[0] & is_backdrop[1])


def srgb_encode(linear):
    c = np.clip(linear, 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1.0 / 2.4) - 0.055)


def resize(rgb, side):
    """Nearest-neighbour resampling to side x side (the panels are small previews)."""
    rows = (np.arange(side) * rgb.shape[0] // side)
    cols = (np.arange(side) * rgb.shape[1] // side)
    return rgb[rows][:, cols]


def write_figure(path, rayo, cycles):
    y_rayo = block_average(rayo, BLOCK) @ LUMINANCE
    y_cycles = block_average(cycles, BLOCK) @ LUMINANCE
    signed = (y_rayo - y_cycles) / np.maximum(y_cycles, FLOOR * y_cycles.mean())
    level = np.clip(np.abs(signed) / 0.2, 0.0, 1.0)
    difference = np.stack([np.where(signed > 0, 1.0, 1.0 - level),
                           1.0 - level,
                           np.where(signed < 0, 1.0, 1.0 - level)], axis=-1)
    panels = [srgb_encode(resize(rayo, FIGURE_SIDE)), srgb_encode(resize(cycles, FIGURE_SIDE)),
              resize(difference, FIGURE_SIDE)]
    picture = (np.concatenate(panels, axis=1) * 255.0 + 0.5).astype(np.uint8)
    output = oiio.ImageOutput.create(path)
    if output is None:
        sys.exit("cycles_compare.py: cannot write %s: %s" % (path, oiio.geterror()))
    output.open(path, oiio.ImageSpec(picture.shape[1], picture.shape[0], 3, "uint8"))
    output.write_image(picture)
    output.close()


def compare(rayo, cycles, backdrop=None, only=None):
    if rayo.shape != cycles.shape:
        sys.exit("cycles_compare.py: the images differ in size: %s against %s"
                 % (rayo.shape[1::-1], cycles.shape[1::-1]))
    keep = scene_pixels(rayo, cycles, backdrop)
    if only is not None:
        keep &= only
    mean_rayo = rayo[keep].mean(axis=0)
    mean_cycles = cycles[keep].mean(axis=0)
    relative = (mean_rayo - mean_cycles) / np.maximum(mean_cycles, 1e-12)
    # a block counts when any of its pixels does
    keep_blocks = block_average(np.repeat(keep[..., None], 3, axis=-1).astype(float), BLOCK)
    keep_blocks = keep_blocks[..., 0] > 0
    return {
        "pixels_compared": int(keep.sum()),
        "max_luminance_rayo": float((rayo[keep] @ LUMINANCE).max()),
        "max_luminance_cycles": float((cycles[keep] @ LUMINANCE).max()),
        "p99_luminance_rayo": float(np.percentile(rayo[keep] @ LUMINANCE, 99)),
        "p99_luminance_cycles": float(np.percentile(cycles[keep] @ LUMINANCE, 99)),
        "mean_rayo": mean_rayo.tolist(),
        "mean_cycles": mean_cycles.tolist(),
        "relative_difference": relative.tolist(),
        "share_off_10pct": share_off(rayo, cycles, keep),
        "share_off_10pct_4x4": share_off(block_average(rayo, BLOCK),
                                         block_average(cycles, BLOCK), keep_blocks),
    }


def main():
    parser = argparse.ArgumentParser(prog="cycles_compare.py")
    parser.add_argument("rayo")
    parser.add_argument("cycles")
    parser.add_argument("--name", default="image")
    parser.add_argument("--json")
    parser.add_argument("--figure")
    parser.add_argument("--backdrop", type=lambda t: [float(x) for x in t.split(",")])
    parser.add_argument("--model-mask")
    args = parser.parse_args()
    rayo, cycles = read_rgb(args.rayo), read_rgb(args.cycles)
    result = compare(rayo, cycles, args.backdrop)
    model = result
    if args.model_mask:
        if args.backdrop is None:
            sys.exit("cycles_compare.py: --model-mask needs --backdrop")
        alone = read_rgb(args.model_mask)
        on_model = scene_pixels(alone, alone, args.backdrop)
        model = compare(rayo, cycles, args.backdrop, on_model)
        result["model"] = model
    if args.figure:
        write_figure(args.figure, rayo, cycles)
    result["name"] = args.name
    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=1)
    print("%s %s | %s | %s | %.4f %.4f | %d | %s | %.4f %.4f | %d" % (
        args.name,
        " ".join("%.5f" % v for v in result["mean_rayo"]),
        " ".join("%.5f" % v for v in result["mean_cycles"]),
        " ".join("%+.4f" % v for v in result["relative_difference"]),
        result["share_off_10pct"], result["share_off_10pct_4x4"], result["pixels_compared"],
        " ".join("%+.4f" % v for v in model["relative_difference"]),
        model["share_off_10pct"], model["share_off_10pct_4x4"], model["pixels_compared"]))


if __name__ == "__main__":
    main()
