// libFuzzer target for image textures as the scene readers take them and the render checks them
// (apps/scene/texture_image.cpp, shading/image_texture.cpp; the pixels through OpenImageIO in the
// image module librayo_oiio.so, which the fuzzer loads from beside itself as rayo does). The input
// is the image's bytes, used four ways:
//   - a JSON scene's sphere material `"kd": {"image": "tex.EXT"}` (load_texture_image: the file
//     read, its header read from memory, the pixel-count limit; a refusal is an InputError);
//   - an OBJ triangle whose MTL says `map_Kd tex.EXT` (the same file: a refusal is a warning and
//     the material keeps its factor);
//   - a .glb whose image is a bufferView of its binary chunk (copy_buffer_view_images' range
//     check, then the same checks on the bytes), and a .gltf whose image is a data URI (tinygltf's
//     base64 decoding).
// EXT is picked from the content's signature (PNG, JPEG, TIFF, EXR, GIF, BMP, Radiance HDR, PNM,
// PFM, DDS, PSD, WebP, SGI, FITS; anything else .tga, the one common format without one).
// The readers must agree: the JSON scene accepts the image exactly when the OBJ material keeps it,
// and, for PNG and JPEG (the formats glTF allows, named by their signature whatever the source
// name), exactly when both glTF materials keep it. An accepted JSON scene then goes through what
// the render does before it registers an image (check_texture_fits, as the ImageTextures
// constructor calls it: the decoded size against the texture cache, the PNG chunk walk, every
// pixel decoded), with the cache limited to 8 MB so that an input costs little; an image it accepts
// must then register (for one input in 8: see check_register_and_look_up) and give finite texels
// in [0, 1] for integer formats. Refusals must be rayo::InputError.
// The bufferView range checks themselves (byteOffset or byteLength past the buffer) are fuzzed by
// gltf_fuzz, whose seeds include images in bufferViews (fuzz/corpus/gltf/).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "apps/scene/json_loader.h"
#include "apps/scene/mesh_loader.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/scene_invariants.h"
#include "shading/image_texture.h"
#include "shading/material.h"

namespace {

constexpr float kCacheMB = 8.0f;

bool starts_with(const uint8_t* data, size_t size, const char* magic, size_t n) {
    return size >= n && std::memcmp(data, magic, n) == 0;
}

// The extension a user's file of these bytes would have.
std::string extension_of(const uint8_t* d, size_t n) {
    if (starts_with(d, n, "\x89PNG\r\n\x1a\n", 8)) return ".png";
    if (starts_with(d, n, "\xFF\xD8\xFF", 3)) return ".jpg";
    if (starts_with(d, n, "II*\0", 4) || starts_with(d, n, "MM\0*", 4) ||
        starts_with(d, n, "II+\0", 4) || starts_with(d, n, "MM\0+", 4)) {
        return ".tif";
    }
    if (starts_with(d, n, "\x76\x2f\x31\x01", 4)) return ".exr";
    if (starts_with(d, n, "GIF8", 4)) return ".gif";
    if (starts_with(d, n, "BM", 2)) return ".bmp";
    if (starts_with(d, n, "#?", 2)) return ".hdr";
    if (n >= 2 && d[0] == 'P' && d[1] >= '1' && d[1] <= '6') return ".pnm";
    if (starts_with(d, n, "PF", 2) || starts_with(d, n, "Pf", 2)) return ".pfm";
    if (starts_with(d, n, "DDS ", 4)) return ".dds";
    if (starts_with(d, n, "8BPS", 4)) return ".psd";
    if (starts_with(d, n, "RIFF", 4)) return ".webp";
    if (starts_with(d, n, "\x01\xda", 2)) return ".sgi";
    if (starts_with(d, n, "SIMPLE", 6)) return ".fits";
    return ".tga";
}

// Formats whose texels are integers (the lookups must give [0, 1]).
bool integer_format(const std::string& ext) {
    return ext == ".png" || ext == ".jpg" || ext == ".gif" || ext == ".bmp" || ext == ".pnm";
}

std::string base64(const uint8_t* data, size_t size) {
    static const char* const kDigits =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((size + 2) / 3 * 4);
    for (size_t i = 0; i < size; i += 3) {
        const uint32_t a = data[i], b = i + 1 < size ? data[i + 1] : 0,
                       c = i + 2 < size ? data[i + 2] : 0;
        const uint32_t v = (a << 16) | (b << 8) | c;
        out += kDigits[(v >> 18) & 63];
        out += kDigits[(v >> 12) & 63];
        out += i + 1 < size ? kDigits[(v >> 6) & 63] : '=';
        out += i + 2 < size ? kDigits[v & 63] : '=';
    }
    return out;
}

void append_u32(std::string& s, uint32_t v) {
    s.append(reinterpret_cast<const char*>(&v), 4);  // little-endian (x86, as .glb is)
}

// A triangle with texture coordinates (positions, u16 indices, uvs: 68 bytes) followed by the
// image: the binary chunk of the .glb.
std::string triangle_bytes() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint16_t indices[4] = {0, 1, 2, 0};
    const float uvs[6] = {0, 1, 1, 1, 0, 0};
    std::string bytes(68, '\0');
    std::memcpy(&bytes[0], positions, sizeof positions);
    std::memcpy(&bytes[36], indices, sizeof indices);
    std::memcpy(&bytes[44], uvs, sizeof uvs);
    return bytes;
}

// The glTF JSON of that triangle with one textured material; `image` is the images entry.
std::string gltf_json(const std::string& buffer, const std::string& image_view,
                      const std::string& image) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "indices": 1,
                              "material": 0}]}],
  "materials": [{"name": "textured",
                 "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0}],
  "images": [)" +
           image +
           R"(],
  "buffers": [)" +
           buffer +
           R"(],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6},
                  {"buffer": 0, "byteOffset": 44, "byteLength": 24})" +
           image_view + R"(],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
    {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}]})";
}

std::string padded(std::string s, char pad) {
    s.resize((s.size() + 3) / 4 * 4, pad);
    return s;
}

// The .glb: the image in bufferView 3, right after the triangle.
std::string glb_with_image(const uint8_t* data, size_t size, const char* mime) {
    const std::string bin = padded(triangle_bytes() + std::string(data, data + size), '\0');
    const std::string json =
        padded(gltf_json(R"({"byteLength": )" + std::to_string(68 + size) + "}",
                         R"(,
                  {"buffer": 0, "byteOffset": 68, "byteLength": )" +
                             std::to_string(size) + "}",
                         R"({"bufferView": 3, "mimeType": ")" + std::string(mime) + R"("})"),
               ' ');
    std::string glb = "glTF";
    append_u32(glb, 2);
    append_u32(glb, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    append_u32(glb, uint32_t(json.size()));
    glb += "JSON" + json;
    append_u32(glb, uint32_t(bin.size()));
    glb += std::string("BIN\0", 4) + bin;
    return glb;
}

// The .gltf: the triangle as a data-URI buffer, the image as a data URI.
std::string gltf_with_data_uri(const uint8_t* data, size_t size, const char* mime) {
    const std::string tri = triangle_bytes();
    return gltf_json(
        R"({"byteLength": 68, "uri": "data:application/octet-stream;base64,)" +
            base64(reinterpret_cast<const uint8_t*>(tri.data()), tri.size()) + "\"}",
        "", R"({"uri": "data:)" + std::string(mime) + ";base64," + base64(data, size) + "\"}");
}

// Whether a material of `materials` keeps a base-colour image.
bool keeps_image(const std::vector<rayo::Material>& materials) {
    for (const rayo::Material& m : materials) {
        if (m.images.base.used()) return true;
    }
    return false;
}

// A mesh loader run on `path`: whether its material kept the image. Loading must succeed (the
// image is the only thing that varies; its problems are warnings).
template <typename Load>
bool model_keeps_image(Load load, const std::string& path, const char* what) {
    std::vector<rayo::Material> materials(1);
    try {
        rayo::MeshImportStats stats;
        const rayo::TriangleMesh mesh = load(path, materials, "fuzz.json#/objects/0/file", &stats);
        rayo::fuzz::check_mesh(mesh, materials.size(), what);
    } catch (const rayo::InputError& e) {
        rayo::fuzz::violated(std::string(what) + " refused for its texture: " + e.what());
    }
    return keeps_image(materials);
}

// What the render does with the scene's images before it traces (apps/scene/renderer.cpp): each
// image checked (check_texture_fits: the decoded size against the cache, the PNG chunk walk, every
// pixel decoded), then the texture system with every image registered, and lookups. Creating a
// TextureSystem leaks 25 KB inside OpenImageIO under ASan (scripts/lsan.supp): the registration
// is made for one accepted input in 8 (by a hash of its bytes), so that an hour's run stays far
// below -rss_limit_mb; the checks run for all.
void check_register_and_look_up(const rayo::SceneDescription& d, const std::string& bytes,
                                bool integer_texels) {
    const std::vector<rayo::Material>& materials = d.shading.materials;
    try {
        for (const rayo::Material& m : materials) {
            if (m.images.base.used()) rayo::check_texture_fits(*m.images.base.image, kCacheMB);
        }
    } catch (const rayo::InputError&) {
        return;
    }
    if (std::hash<std::string>()(bytes) % 8 != 0) return;
    std::unique_ptr<rayo::ImageTextures> textures;
    try {
        textures = std::make_unique<rayo::ImageTextures>(materials, kCacheMB);
    } catch (const rayo::InputError& e) {
        rayo::fuzz::violated(std::string("texture passed its checks, then refused: ") + e.what());
    }
    using Slot = rayo::ImageTextures::Slot;
    for (uint32_t m = 0; m < materials.size(); ++m) {
        if (!materials[m].images.base.used()) continue;
        rayo::fuzz::expect(textures->has(m, Slot::Base),
                           "texture accepted by the checks but not registered");
        const float uvs[][3] = {
            {0.5f, 0.5f, 0.0f}, {0.0f, 0.0f, 0.01f}, {0.9f, 0.3f, 1.0f}, {-2.5f, 7.25f, 0.1f}};
        for (const auto& uv : uvs) {
            const glm::vec4 texel = textures->lookup(m, Slot::Base, glm::vec2(uv[0], uv[1]), uv[2]);
            if (!integer_texels) continue;
            for (int c = 0; c < 4; ++c) {
                rayo::fuzz::expect(
                    std::isfinite(texel[c]) && texel[c] >= -1e-4f && texel[c] <= 1.0f + 1e-4f,
                    "8-bit texture gave a texel outside [0, 1]");
            }
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string ext = extension_of(data, size);
    const std::string image = "tex" + ext;
    rayo::fuzz::write_input(image, data, size);
    const std::filesystem::path& dir = rayo::fuzz::scratch_dir();

    // JSON: the scene is refused exactly when the image is.
    const std::string scene = R"({"rayo": 1, "render": {"texture_cache_mb": 8},
      "materials": {"m": {"kd": {"image": ")" +
                              image +
                              R"("}}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
    bool json_ok = false;
    rayo::SceneDescription description;
    try {
        // Only the image varies: the rest of the scene is json_fuzz's to check.
        description = rayo::load_json_string(scene, "fuzz.json", dir.string());
        rayo::fuzz::expect(keeps_image(description.shading.materials),
                           "JSON scene accepted without its image");
        json_ok = true;
    } catch (const rayo::InputError&) {
    }

    // OBJ with an MTL map_Kd of the same file.
    rayo::fuzz::write_file(dir / "tex_obj.mtl", "newmtl m\nKd 1 1 1\nmap_Kd " + image + "\n");
    rayo::fuzz::write_file(dir / "tex_obj.obj",
                           "mtllib tex_obj.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
                           "vt 0 1\nusemtl m\nf 1/1 2/2 3/3\n");
    const bool obj_ok = model_keeps_image([](auto&&... a) { return rayo::load_obj(a...); },
                                          (dir / "tex_obj.obj").string(), "OBJ with map_Kd");
    rayo::fuzz::expect(obj_ok == json_ok, "JSON and OBJ disagree on a texture image");

    // glTF: the image in a .glb bufferView and as a data URI.
    const bool jpeg = ext == ".jpg";
    const char* mime = jpeg ? "image/jpeg" : "image/png";
    rayo::fuzz::write_file(dir / "tex.glb", glb_with_image(data, size, mime));
    rayo::fuzz::write_file(dir / "tex.gltf", gltf_with_data_uri(data, size, mime));
    const auto gltf = [](auto&&... a) { return rayo::load_gltf(a...); };
    const bool glb_ok = size > 0 && model_keeps_image(gltf, (dir / "tex.glb").string(), ".glb");
    const bool uri_ok =
        size > 0 && model_keeps_image(gltf, (dir / "tex.gltf").string(), ".gltf data URI");
    if (jpeg || ext == ".png") {
        rayo::fuzz::expect(glb_ok == json_ok, "JSON and .glb bufferView disagree on a texture");
        rayo::fuzz::expect(uri_ok == json_ok, "JSON and glTF data URI disagree on a texture");
    }

    if (json_ok) {
        check_register_and_look_up(description,
                                   std::string(reinterpret_cast<const char*>(data), size),
                                   integer_format(ext));
    }
    return 0;
}
