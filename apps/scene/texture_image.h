#pragma once
// Texture images a scene names (JSON {"image": file}, MTL map_Kd, glTF images), read through the
// input-file checks (apps/scene/input_file.h) and verified to decode, kept as encoded bytes for
// the render's texture system (shading/image_texture.h).
#include <map>
#include <memory>
#include <string>

#include "apps/scene/input_file.h"
#include "shading/image_map.h"

namespace rayo {

constexpr uint64_t kMaxTextureFileBytes = uint64_t(1) << 30;  // texture images: 1 GiB

// Images already read, by resolved path: materials that share a file share one texture.
using TextureImageCache = std::map<std::string, std::shared_ptr<const ImageSource>>;

// The image file at `path`. Throws InputError(where, ...) naming the file when it is missing,
// refused by `access`, or not an image OpenImageIO reads.
std::shared_ptr<const ImageSource> load_texture_image(const std::string& path,
                                                      const std::string& where,
                                                      const FileAccess& access = {},
                                                      TextureImageCache* cache = nullptr);

// Encoded bytes from memory (a .glb buffer view, a data URI): `name` for messages. Throws
// InputError(where, ...) when they do not decode.
std::shared_ptr<const ImageSource> texture_image_from_bytes(std::string name, std::string bytes,
                                                            const std::string& where);

}  // namespace rayo
