#include "shading/image_texture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/image_library.h"
#include "shading/material.h"

namespace rayo {
namespace {

TextureWrapMode wrap_mode(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::Clamp:
            return TextureWrapMode::Clamp;
        case TextureWrap::Mirror:
            return TextureWrapMode::Mirror;
        case TextureWrap::Repeat:
            break;
    }
    return TextureWrapMode::Periodic;
}

// The cache's name of an image: unique per image, with the extension its bytes call for, so
// that OpenImageIO picks the reader by name (PNG and JPEG by their signatures; otherwise the
// source's own extension).
std::string cache_name(const ImageSource& source, size_t index) {
    std::string extension;
    const std::string& b = source.bytes;
    if (b.size() >= 8 && std::memcmp(b.data(), "\x89PNG\r\n\x1a\n", 8) == 0) {
        extension = ".png";
    } else if (b.size() >= 3 && std::memcmp(b.data(), "\xFF\xD8\xFF", 3) == 0) {
        extension = ".jpg";
    } else {
        const size_t slash = source.name.find_last_of('/');
        const size_t dot = source.name.find_last_of('.');
        if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
            extension = source.name.substr(dot);
        }
    }
    return "rayo-image-" + std::to_string(index) + extension;
}

// The line "Peak cache memory : 12.3 MB" of OpenImageIO's statistics, in bytes (0 if absent).
int64_t peak_cache_memory(const std::string& statistics) {
    const std::string key = "Peak cache memory :";
    const size_t at = statistics.find(key);
    if (at == std::string::npos) return 0;
    std::istringstream in(statistics.substr(at + key.size()));
    double value = 0.0;
    std::string unit;
    in >> value >> unit;
    const double scale = unit == "KB"   ? 1024.0
                         : unit == "MB" ? 1024.0 * 1024.0
                         : unit == "GB" ? 1024.0 * 1024.0 * 1024.0
                                        : 1.0;
    return static_cast<int64_t>(value * scale);
}

// OpenImageIO's message with the cache's name of the image (cache_name) put back to the file's:
// '/etc/passwd' gave 'Image "rayo-image-0" does not exist'.
std::string with_file_name(std::string message, const std::string& cache,
                           const ImageSource& source) {
    for (size_t at = message.find(cache); at != std::string::npos;
         at = message.find(cache, at + source.name.size())) {
        message.replace(at, cache.size(), source.name);
    }
    return message;
}

// Why a PNG's chunks do not reach its IEND within `bytes` (empty when they do, or when the bytes
// are no PNG): said before the decoder reads past the end, where OpenImageIO's read callback
// leaks its message as libpng unwinds (LeakSanitizer: PNGInput::PngReadCallback). With
// `header_only`, only the chunks libpng reads to open the file, up to the first IDAT's header
// (what read_header reads: a file cut before it leaked there; found by fuzz/texture_fuzz.cpp).
std::string png_truncation(const std::string& bytes, bool header_only = false) {
    if (bytes.size() < 8 || std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8) != 0) return {};
    const std::string end = header_only ? "its image data (IDAT)" : "its IEND chunk";
    size_t at = 8;
    while (at + 8 <= bytes.size()) {
        const auto byte = [&](size_t i) { return static_cast<uint32_t>(uint8_t(bytes[at + i])); };
        const uint64_t length = (byte(0) << 24) | (byte(1) << 16) | (byte(2) << 8) | byte(3);
        const std::string type = bytes.substr(at + 4, 4);
        if (header_only && type == "IDAT") return {};  // libpng opens it at its header
        if (at + 12 + length > bytes.size()) {
            return "truncated PNG: chunk " + type + " at byte " + std::to_string(at) + " runs " +
                   "past the end of the file (" + std::to_string(bytes.size()) + " bytes)";
        }
        if (type == "IEND") return {};
        at += 12 + length;
    }
    return "truncated PNG: the file (" + std::to_string(bytes.size()) + " bytes) ends before " +
           end;
}

// Why an OpenEXR file's header attributes do not fit within `bytes` (empty when they do, or when
// the bytes are no OpenEXR file): OpenEXR 3.1 allocates an attribute's declared size before it
// reads it, so a 545-byte file declaring a 1.7 GB string took 2 GB to read its header (found by
// fuzz/texture_fuzz.cpp). Walks every header (a multi-part file has several, the last one
// empty): name, type, a 4-byte size, the value.
std::string exr_truncation(const std::string& bytes) {
    if (bytes.size() < 8 || std::memcmp(bytes.data(), "\x76\x2f\x31\x01", 4) != 0) return {};
    const bool multipart = (uint8_t(bytes[5]) & 0x10) != 0;  // version flags, bit 12
    size_t at = 8;
    const auto text = [&](std::string& out) {
        const size_t end = bytes.find('\0', at);
        if (end == std::string::npos) return false;
        out = bytes.substr(at, end - at);
        at = end + 1;
        return true;
    };
    const std::string ends =
        "truncated OpenEXR header: the file (" + std::to_string(bytes.size()) + " bytes) ends ";
    for (bool header_start = true;;) {
        std::string name, type;
        if (!text(name)) return ends + "in an attribute's name";
        if (name.empty()) {
            if (!multipart || header_start) return {};  // the (last) header's end
            header_start = true;
            continue;
        }
        header_start = false;
        if (!text(type) || at + 4 > bytes.size()) return ends + "in attribute '" + name + "'";
        uint32_t size = 0;
        std::memcpy(&size, bytes.data() + at, 4);  // little-endian (OpenEXR's byte order)
        at += 4;
        if (size > bytes.size() - at) {
            return "truncated OpenEXR header: attribute '" + name + "' declares " +
                   std::to_string(size) + " bytes, past the end of the file (" +
                   std::to_string(bytes.size()) + " bytes)";
        }
        at += size;
    }
}

// Why a GIF's logical screen is too large to open (empty when it is not, or when the bytes are
// no GIF): OpenImageIO's GIF reader allocates the whole screen as RGBA when it opens the file, so a
// 115-byte GIF declaring 19976 x 21573 took 1.8 GB before its first block was found wrong (found
// by fuzz/texture_fuzz.cpp). The screen's size is the two 16-bit little-endian words after the
// signature (GIF89a specification, "Logical Screen Descriptor").
std::string gif_screen_too_large(const std::string& bytes) {
    // giflib checks the first three bytes only ("GIF83a" opened too: the fuzzer's next find).
    if (bytes.size() < 10 || bytes.compare(0, 3, "GIF") != 0) return {};
    const auto word = [&](size_t at) {
        return uint32_t(uint8_t(bytes[at])) | (uint32_t(uint8_t(bytes[at + 1])) << 8);
    };
    const uint32_t width = word(6), height = word(8);
    if (uint64_t(width) * height <= kMaxTexturePixels) return {};
    return "image is " + std::to_string(width) + "x" + std::to_string(height) +
           " (a GIF's screen); the limit is " + std::to_string(kMaxTexturePixels) + " pixels";
}

}  // namespace

float srgb_to_linear(float encoded) {
    // IEC 61966-2-1: the linear toe below 0.04045, the 2.4 power above.
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

bool image_source_readable(const ImageSource& source, std::string& error) {
    error = png_truncation(source.bytes, /*header_only=*/true);
    if (error.empty()) error = exr_truncation(source.bytes);
    if (error.empty()) error = gif_screen_too_large(source.bytes);
    if (!error.empty()) return false;
    ImageHeader header;
    const std::string name = cache_name(source, 0);
    if (!image_library().read_header(name, source.bytes, header, error)) {
        // Without a known signature or extension OpenImageIO looks for a file of the cache's
        // name and says it "does not exist".
        const bool named_format = name.find('.') != std::string::npos;
        error = error.empty() || !named_format
                    ? "not an image OpenImageIO can read (no reader recognizes its bytes)"
                    : with_file_name(error, name, source);
        return false;
    }
    // An image without pixels (a TGA header may say 0 x 0) passed every size check, and
    // OpenImageIO's bicubic lookup divided by its size (SIGFPE; found by fuzz/texture_fuzz.cpp).
    if (header.width < 1 || header.height < 1 || header.depth < 1) {
        error = "image is " + std::to_string(header.width) + "x" + std::to_string(header.height) +
                (header.depth != 1 ? "x" + std::to_string(header.depth) : std::string()) +
                ": it has no pixels";
        return false;
    }
    const uint64_t pixels = uint64_t(std::max(header.width, 0)) *
                            uint64_t(std::max(header.height, 0)) * uint64_t(header.depth);
    if (pixels > kMaxTexturePixels) {
        error = "image is " + std::to_string(header.width) + "x" + std::to_string(header.height) +
                (header.depth > 1 ? "x" + std::to_string(header.depth) : std::string()) +
                "; the limit is " + std::to_string(kMaxTexturePixels) + " pixels";
        return false;
    }
    return true;
}

namespace {

// check_texture_fits up to the decoding: the header reads, an image without tiles fits the
// limit decoded, a PNG's chunks reach its end. Returns the header.
ImageHeader check_texture_header(const ImageSource& source, float max_memory_mb) {
    const std::string name = cache_name(source, 0);
    std::string error;
    ImageHeader header;
    if (!image_library().read_header(name, source.bytes, header, error)) {
        throw InputError(source.name,
                         "texture image cannot be read: " + with_file_name(error, name, source));
    }
    // A file without tiles is decoded whole by its reader (libpng's through OpenImageIO keeps
    // the full image), outside the cache's limit: it must fit in that limit itself.
    const double decoded = double(header.width) * header.height * header.depth * header.channels *
                           header.bytes_per_channel;
    const double limit = double(max_memory_mb) * 1024.0 * 1024.0;
    if (!header.tiled && decoded > limit) {
        std::ostringstream text;
        text.precision(4);
        text << "texture image is " << header.width << "x" << header.height << ", "
             << header.channels << " channel(s): " << decoded / (1024.0 * 1024.0)
             << " MB decoded, without tiles, above the texture cache's " << max_memory_mb
             << " MB (--texture-cache, render.texture_cache_mb; docs/limits.md, \"Texture "
                "images\"): raise the limit, or convert the image to a tiled, MIP-mapped file "
                "(maketx), which is read tile by tile";
        throw InputError(source.name, text.str());
    }
    const std::string truncated = png_truncation(source.bytes);
    if (!truncated.empty()) {
        throw InputError(source.name, "texture image does not decode: " + truncated);
    }
    return header;
}

// The image's pixels decoded into a MIP map (8-bit images as bytes, the others as floats);
// throws InputError as check_texture_fits does when a pixel does not decode.
std::unique_ptr<MipPyramid> decode_pyramid(const ImageSource& source, const ImageHeader& header) {
    const std::string name = cache_name(source, 0);
    const size_t values =
        size_t(header.width) * size_t(header.height) * size_t(std::max(header.channels, 1));
    std::string error;
    const auto failed = [&] {
        return InputError(source.name,
                          "texture image does not decode: " + with_file_name(error, name, source));
    };
    if (header.bytes_per_channel == 1 && !header.floating) {
        std::vector<uint8_t> pixels(values);
        if (!image_library().read_texture_pixels(name, source.bytes, PixelType::UInt8,
                                                 pixels.data(), error)) {
            throw failed();
        }
        return std::make_unique<MipPyramid>(header.width, header.height, header.channels,
                                            pixels.data());
    }
    std::vector<float> pixels(values);
    if (!image_library().read_texture_pixels(name, source.bytes, PixelType::Float, pixels.data(),
                                             error)) {
        throw failed();
    }
    return std::make_unique<MipPyramid>(header.width, header.height, header.channels,
                                        pixels.data());
}

// The smallest cache OpenImageIO is given (what the MIP maps left may be less).
constexpr float kMinCacheMB = 1.0f;

}  // namespace

void check_texture_fits(const ImageSource& source, float max_memory_mb) {
    check_texture_header(source, max_memory_mb);
    const std::string name = cache_name(source, 0);
    std::string error;
    if (!image_library().decodes(name, source.bytes, error)) {
        throw InputError(source.name,
                         "texture image does not decode: " + with_file_name(error, name, source));
    }
}

struct ImageTextures::Impl {
    // One image: rayo's MIP map of it, or its handle in OpenImageIO's cache (which reads its
    // bytes from memory).
    struct Entry {
        std::shared_ptr<const ImageSource> source;
        std::unique_ptr<MipPyramid> pyramid;
        TextureCache::Handle handle = nullptr;
        bool good = false;
        bool floating = false;
        bool alpha = false;  // has an alpha channel
    };
    // One material's use of an image.
    struct Use {
        const MipPyramid* pyramid = nullptr;
        TextureCache::Handle handle = nullptr;
        TextureWrap wrap_s = TextureWrap::Repeat, wrap_t = TextureWrap::Repeat;
        TextureWrapMode swrap = TextureWrapMode::Periodic, twrap = TextureWrapMode::Periodic;
        bool srgb = false;
        bool alpha = false;
        glm::mat3 transform{1.0f};
        // The footprint's scale through the transform: the longer of its axes' images (a MIP
        // map's lookup is isotropic; the longer axis keeps either from aliasing).
        float footprint_scale = 1.0f;
        bool used() const { return pyramid != nullptr || handle != nullptr; }
    };

    float limit_mb = 0.0f;
    TextureFilter filter = TextureFilter::Bilinear;
    int64_t pyramid_bytes = 0;
    std::vector<Entry> entries;
    std::map<const ImageSource*, size_t> index_of;
    std::vector<std::array<Use, kSlotCount>> uses;  // per material, per Slot
    std::unique_ptr<TextureCache> system;           // last: destroyed before the bytes it reads

    // What is left of the limit for OpenImageIO's cache once the MIP maps are made.
    float cache_mb() const {
        const double left = double(limit_mb) - double(pyramid_bytes) / (1024.0 * 1024.0);
        return std::max(kMinCacheMB, static_cast<float>(left));
    }

    size_t add(const std::shared_ptr<const ImageSource>& source) {
        const auto found = index_of.find(source.get());
        if (found != index_of.end()) return found->second;
        const ImageHeader header = check_texture_header(*source, limit_mb);
        Entry entry;
        entry.source = source;
        const size_t bytes = MipPyramid::bytes_for(
            header.width, header.height, !(header.bytes_per_channel == 1 && !header.floating));
        const double left = double(limit_mb) * 1024.0 * 1024.0 - double(pyramid_bytes);
        // A MIP map while they fit (and before any image went to the cache, whose limit is what
        // was left when it was made); volumes (depth > 1) stay with OpenImageIO.
        if (!system && header.depth == 1 && double(bytes) <= left) {
            entry.pyramid = decode_pyramid(*source, header);
            pyramid_bytes += static_cast<int64_t>(entry.pyramid->bytes());
            entry.good = true;
            entry.floating = header.floating;
            entry.alpha = header.alpha;
        } else {
            std::string error;
            const std::string name = cache_name(*source, 0);
            if (!image_library().decodes(name, source->bytes, error)) {
                throw InputError(source->name, "texture image does not decode: " +
                                                   with_file_name(error, name, *source));
            }
            // PNG and JPEG are scanline images: cut into 64² tiles so that the memory limit
            // bounds what is held, with their MIP levels built in the cache.
            if (!system) system = image_library().create_texture_cache(cache_mb(), /*autotile=*/64);
            entry.handle = system->add(cache_name(*source, entries.size()), source->bytes);
            entry.good = system->good(entry.handle);
            entry.floating = system->floating_point(entry.handle);
            entry.alpha = system->has_alpha(entry.handle);
        }
        index_of.emplace(source.get(), entries.size());
        entries.push_back(std::move(entry));
        return entries.size() - 1;
    }

    Use use_of(const ImageMap& map) {
        Use use;
        if (!map.used()) return use;
        const Entry& entry = entries[add(map.image)];
        if (!entry.good) return use;  // unreadable: the loaders warned
        use.pyramid = entry.pyramid.get();
        use.handle = entry.handle;
        use.wrap_s = map.wrap_s;
        use.wrap_t = map.wrap_t;
        use.swrap = wrap_mode(map.wrap_s);
        use.twrap = wrap_mode(map.wrap_t);
        use.srgb = map.encoding == TextureEncoding::Srgb ||
                   (map.encoding == TextureEncoding::Auto && !entry.floating);
        use.alpha = entry.alpha;
        use.transform = map.transform;
        use.footprint_scale = std::max(glm::length(glm::vec2(map.transform[0])),
                                       glm::length(glm::vec2(map.transform[1])));
        return use;
    }
};

ImageTextures::ImageTextures(const std::vector<Material>& materials, float max_memory_mb,
                             TextureFilter filter)
    : m_impl(std::make_unique<Impl>()) {
    Impl& impl = *m_impl;
    impl.limit_mb = max_memory_mb;
    impl.filter = filter;
    impl.uses.resize(materials.size());
    for (size_t m = 0; m < materials.size(); ++m) {
        const MaterialImages& images = materials[m].images;
        impl.uses[m][static_cast<size_t>(Slot::Base)] = impl.use_of(images.base);
        impl.uses[m][static_cast<size_t>(Slot::Specular)] = impl.use_of(images.specular);
        impl.uses[m][static_cast<size_t>(Slot::Emission)] = impl.use_of(images.emission);
        impl.uses[m][static_cast<size_t>(Slot::MetallicRoughness)] =
            impl.use_of(images.pbr.metallic_roughness);
        impl.uses[m][static_cast<size_t>(Slot::Occlusion)] = impl.use_of(images.pbr.occlusion);
        impl.uses[m][static_cast<size_t>(Slot::Normal)] = impl.use_of(images.normal);
        impl.uses[m][static_cast<size_t>(Slot::Bump)] = impl.use_of(images.bump);
        impl.uses[m][static_cast<size_t>(Slot::Cutout)] = impl.use_of(images.cutout.image);
    }
}

ImageTextures::~ImageTextures() = default;

bool ImageTextures::has(uint32_t material, Slot slot) const {
    return material < m_impl->uses.size() &&
           m_impl->uses[material][static_cast<size_t>(slot)].used();
}

bool ImageTextures::has_alpha(uint32_t material, Slot slot) const {
    return has(material, slot) && m_impl->uses[material][static_cast<size_t>(slot)].alpha;
}

glm::vec4 ImageTextures::lookup(uint32_t material, Slot slot, const glm::vec2& uv,
                                float width) const {
    const Impl::Use& use = m_impl->uses[material][static_cast<size_t>(slot)];
    if (!use.used()) return glm::vec4(1.0f);
    const glm::vec3 st = use.transform * glm::vec3(uv, 1.0f);
    float texel[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    if (use.pyramid) {
        const glm::vec4 t = use.pyramid->lookup(st.x, st.y, width * use.footprint_scale, use.wrap_s,
                                                use.wrap_t, m_impl->filter);
        texel[0] = t.x;
        texel[1] = t.y;
        texel[2] = t.z;
        texel[3] = t.w;
    } else {
        // The footprint's axes through the transform (its linear part scales and rotates them).
        const glm::vec2 dx = glm::vec2(use.transform * glm::vec3(width, 0.0f, 0.0f));
        const glm::vec2 dy = glm::vec2(use.transform * glm::vec3(0.0f, width, 0.0f));
        // fill 1: the alpha of images without one.
        m_impl->system->lookup(use.handle, use.swrap, use.twrap, /*fill=*/1.0f,
                               m_impl->filter == TextureFilter::Bicubic, st.x, st.y, dx.x, dx.y,
                               dy.x, dy.y, texel);
    }
    if (use.srgb) {
        for (int c = 0; c < 3; ++c) texel[c] = srgb_to_linear(texel[c]);
    }
    return glm::vec4(texel[0], texel[1], texel[2], texel[3]);
}

size_t ImageTextures::texture_count() const {
    return m_impl->entries.size();
}

ImageTextureStats ImageTextures::stats() const {
    ImageTextureStats out;
    out.textures = m_impl->entries.size();
    out.limit_mb = m_impl->limit_mb;
    for (const auto& entry : m_impl->entries) {
        out.encoded_bytes += static_cast<int64_t>(entry.source->bytes.size());
        if (entry.pyramid) ++out.mip_mapped;
    }
    // The MIP maps are held from the start to the end of the render.
    out.memory_used = out.image_bytes = out.memory_peak = m_impl->pyramid_bytes;
    if (m_impl->system) {
        const int64_t cache_used = m_impl->system->memory_used();
        out.memory_used += cache_used;
        out.image_bytes += m_impl->system->image_bytes();
        // OpenImageIO prints its peak rounded (and counts pixel memory only): never below what
        // the cache holds now.
        out.memory_peak += std::max(peak_cache_memory(m_impl->system->statistics()), cache_used);
    }
    return out;
}

}  // namespace rayo
