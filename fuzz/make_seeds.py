#!/usr/bin/env python3
"""Writes the seed corpora of mesh_fuzz, texture_fuzz and gltf_fuzz's image cases (fuzz/corpus/):
small valid files of each format and the hostile cases of issue 30 (a binary STL counting more
triangles than it holds, a binary PLY cut short, a PLY list count of -5, an OFF face index out of
range, an OFF declaring 2^31 vertices; a truncated PNG, a PNG declaring 100000 x 100000, a JPEG
declaring 65500 x 65500; glTF images in bufferViews at byteOffset 1e8 or running past their
buffer). The JPEG, TIFF, EXR, HDR, BMP, GIF, PNM and TGA seeds are made by oiiotool
(openimageio-tools). journal_fuzz writes its own seeds (RAYO_JOURNAL_SEEDS, fuzz/journal_fuzz.cpp).
Usage: fuzz/make_seeds.py   (rewrites the files it owns; others in the folders are kept)"""
import base64
import json
import os
import struct
import subprocess
import tempfile
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")


def put(reader, name, data):
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(ROOT, reader, name), "wb") as f:
        f.write(data)


# --- meshes: PLY, STL, OFF -------------------------------------------------------------------
TETRA = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def ply_header(fmt, extra_vertex="", face_count=4):
    return ("ply\nformat %s 1.0\ncomment rayo fuzz seed\nelement vertex 4\n"
            "property float x\nproperty float y\nproperty float z\n%s"
            "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
            % (fmt, extra_vertex, face_count))


def binary_ply(endian="<"):
    fmt = "binary_little_endian" if endian == "<" else "binary_big_endian"
    body = b"".join(struct.pack(endian + "3f", *v) for v in TETRA)
    body += b"".join(struct.pack(endian + "B3i", 3, *f) for f in TETRA_FACES)
    return ply_header(fmt).encode() + body


def meshes():
    colours = "property uchar red\nproperty uchar green\nproperty uchar blue\n"
    normals = "property float nx\nproperty float ny\nproperty float nz\n"
    text = ply_header("ascii", normals + colours)
    for (x, y, z) in TETRA:
        text += "%g %g %g 0 0 1 200 100 50\n" % (x, y, z)
    text += "".join("3 %d %d %d\n" % f for f in TETRA_FACES)
    put("mesh", "tetra_ascii.ply", text)
    put("mesh", "tetra_binary_le.ply", binary_ply("<"))
    put("mesh", "tetra_binary_be.ply", binary_ply(">"))
    # Issue 30: a binary PLY cut 7 bytes short; a list count of -5 (ASCII and binary).
    put("mesh", "tetra_binary_cut_7.ply", binary_ply("<")[:-7])
    bad = ply_header("ascii")
    bad += "".join("%g %g %g\n" % v for v in TETRA) + "-5 0 1 2\n" + "3 0 1 3\n3 0 3 2\n3 1 2 3\n"
    put("mesh", "list_count_minus_5.ply", bad)
    signed = ply_header("binary_little_endian").replace("list uchar int", "list char int")
    body = b"".join(struct.pack("<3f", *v) for v in TETRA)
    body += struct.pack("<b3i", -5, 0, 1, 2) + b"".join(
        struct.pack("<b3i", 3, *f) for f in TETRA_FACES[1:])
    put("mesh", "list_count_minus_5_binary.ply", signed.encode() + body)

    def stl_binary(triangles, count=None):
        head = b"binary stl, rayo fuzz seed".ljust(80, b" ")
        data = head + struct.pack("<I", len(triangles) if count is None else count)
        for t in triangles:
            data += struct.pack("<3f", 0, 0, 0) + b"".join(
                struct.pack("<3f", *TETRA[i]) for i in t) + b"\0\0"
        return data
    put("mesh", "tetra_binary.stl", stl_binary(TETRA_FACES))
    # Issue 30: a binary STL claiming 2^32 - 1 triangles (it holds one).
    put("mesh", "count_2e32.stl", stl_binary(TETRA_FACES[:1], 0xFFFFFFFF))
    text = "solid tetra\n"
    for t in TETRA_FACES:
        text += " facet normal 0 0 0\n  outer loop\n"
        text += "".join("   vertex %g %g %g\n" % TETRA[i] for i in t)
        text += "  endloop\n endfacet\n"
    put("mesh", "tetra_ascii.stl", text + "endsolid tetra\n")

    off = "OFF\n# a tetrahedron\n4 4 6\n" + "".join("%g %g %g\n" % v for v in TETRA)
    off += "".join("3 %d %d %d\n" % f for f in TETRA_FACES)
    put("mesh", "tetra.off", off)
    put("mesh", "quad_coff.off", "COFF\n4 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
        "1 1 0 0 0 255 255\n0 1 0 9 9 9 255\n4 0 1 2 3\n")
    # Issue 30: a face index out of range; 2^31 vertices declared.
    put("mesh", "index_out_of_range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 99999\n")
    put("mesh", "vertices_2e31.off", "OFF\n2147483648 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")


# --- images -------------------------------------------------------------------------------------
def png(width, height, rows, colour_type=2, bit_depth=8):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(
            ">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows, 9)) +
            chunk(b"IEND", b""))


def rgb_rows(width, height, seed=1):
    rows = b""
    value = seed
    for _ in range(height):
        rows += b"\0"
        for _ in range(width * 3):
            value = (value * 1103515245 + 12345) & 0x7FFFFFFF
            rows += bytes([value >> 23])
    return rows


def oiiotool(ext, *args):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "seed" + ext)
        subprocess.run(["oiiotool", "--pattern", "checker:width=2:height=2", "8x8", "3",
                        *args, "-o", out], check=True)
        with open(out, "rb") as f:
            return f.read()


def textures():
    put("texture", "tiny.png", png(4, 4, rgb_rows(4, 4)))
    put("texture", "tiny_rgba.png", png(2, 2, b"\0" + b"\xff\0\0\x80\0\xff\0\xff" * 1 +
                                        b"\0" + b"\0\0\xff\x40\xff\xff\xff\x00", colour_type=6))
    noisy = png(16, 16, rgb_rows(16, 16, 7))
    put("texture", "truncated_half.png", noisy[:len(noisy) // 2])
    # Issue 30: a valid header declaring 100000 x 100000 RGB, one row of data, IEND.
    put("texture", "bomb_100000.png", png(100000, 100000, b"\0" + b"\0" * 300000))
    jpg = oiiotool(".jpg", "-d", "uint8")
    put("texture", "tiny.jpg", jpg)
    # Issue 30: the JPEG's frame header (SOF0) says 65500 x 65500.
    sof = jpg.find(b"\xff\xc0")
    bomb = bytearray(jpg)
    struct.pack_into(">HH", bomb, sof + 5, 65500, 65500)
    put("texture", "bomb_65500.jpg", bytes(bomb))
    put("texture", "tiny.tif", oiiotool(".tif", "-d", "uint8"))
    put("texture", "tiled_16.tif", oiiotool(".tif", "-d", "uint16", "--tile", "16", "16"))
    put("texture", "tiny_half.exr", oiiotool(".exr", "-d", "half"))
    put("texture", "tiny.hdr", oiiotool(".hdr"))
    put("texture", "tiny.bmp", oiiotool(".bmp", "-d", "uint8"))
    put("texture", "tiny.gif", oiiotool(".gif", "-d", "uint8"))
    put("texture", "tiny.ppm", oiiotool(".ppm", "-d", "uint8"))
    put("texture", "tiny.tga", oiiotool(".tga", "-d", "uint8"))


# --- glTF images in bufferViews -----------------------------------------------------------------
def gltf_textured(buffer, views, image):
    tri = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 2},
                                       "indices": 1, "material": 0}]}],
           "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
           "textures": [{"source": 0}], "images": [image], "buffers": [buffer],
           "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                           {"buffer": 0, "byteOffset": 36, "byteLength": 6},
                           {"buffer": 0, "byteOffset": 44, "byteLength": 24}] + views,
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                          "min": [0, 0, 0], "max": [1, 1, 0]},
                         {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
                         {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}]}
    return json.dumps(tri, separators=(",", ":"))


def tri_bytes():
    return (struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<4H", 0, 1, 2, 0) +
            struct.pack("<6f", 0, 1, 1, 1, 0, 0))


def glb(json_text, binary):
    j = json_text.encode()
    j += b" " * (-len(j) % 4)
    binary += b"\0" * (-len(binary) % 4)
    return (b"glTF" + struct.pack("<II", 2, 12 + 8 + len(j) + 8 + len(binary)) +
            struct.pack("<I", len(j)) + b"JSON" + j + struct.pack("<I", len(binary)) + b"BIN\0" +
            binary)


def gltf_images():
    image = png(4, 4, rgb_rows(4, 4))
    data = tri_bytes() + image
    image_ref = {"bufferView": 3, "mimeType": "image/png"}

    def with_view(offset, length):
        return gltf_textured({"byteLength": len(data)},
                             [{"buffer": 0, "byteOffset": offset, "byteLength": length}], image_ref)
    put("gltf", "image_bufferview.glb", glb(with_view(68, len(image)), data))
    # Issue 30: an image bufferView at byteOffset 1e8; one whose byteLength runs past the buffer.
    put("gltf", "image_offset_1e8.glb", glb(with_view(100000000, len(image)), data))
    put("gltf", "image_past_buffer.glb", glb(with_view(68, len(image) + 1000), data))
    uri = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    put("gltf", "image_bufferview_data_uri.gltf", gltf_textured(
        {"byteLength": len(data), "uri": uri},
        [{"buffer": 0, "byteOffset": 68, "byteLength": len(image)}], image_ref))
    put("gltf", "image_data_uri.gltf", gltf_textured(
        {"byteLength": 68, "uri": "data:application/octet-stream;base64," +
         base64.b64encode(tri_bytes()).decode()}, [],
        {"uri": "data:image/png;base64," + base64.b64encode(image).decode()}))


if __name__ == "__main__":
    meshes()
    textures()
    gltf_images()
