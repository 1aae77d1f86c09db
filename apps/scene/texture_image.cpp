#include "apps/scene/texture_image.h"

#include "core/error.h"
#include "shading/image_texture.h"

namespace rayo {

std::shared_ptr<const ImageSource> texture_image_from_bytes(std::string name, std::string bytes,
                                                            const std::string& where) {
    auto source = std::make_shared<ImageSource>();
    source->name = std::move(name);
    source->bytes = std::move(bytes);
    std::string error;
    if (!image_source_readable(*source, error)) {
        throw InputError(where, "texture image '" + source->name + "' cannot be read: " + error);
    }
    return source;
}

std::shared_ptr<const ImageSource> load_texture_image(const std::string& path,
                                                      const std::string& where,
                                                      const FileAccess& access,
                                                      TextureImageCache* cache) {
    if (cache) {
        const auto found = cache->find(path);
        if (found != cache->end()) return found->second;
    }
    auto source = texture_image_from_bytes(
        path, read_input_file(path, where, "texture image", kMaxTextureFileBytes, access), where);
    if (cache) cache->emplace(path, source);
    return source;
}

}  // namespace rayo
