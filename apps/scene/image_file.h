#pragma once
// An image file a scene references (a height field's, an environment's), read through the
// scene's input-file checks (apps/scene/input_file.h: regular file, size limit,
// --restrict-paths) and opened for decoding with OpenImageIO (through the image module,
// core/image_library.h) from those bytes, not reopened by name.
#include <cstdint>
#include <memory>
#include <string>

#include "apps/scene/input_file.h"
#include "core/image_library.h"

namespace rayo {

constexpr uint64_t kMaxImageFileBytes = uint64_t(1) << 30;  // 1 GiB

struct OpenedImageFile {
    std::unique_ptr<const std::string> bytes;  // what `reader` decodes: it must outlive it
    std::unique_ptr<ImageReader> reader;
};

// Throws InputError(where, "<noun> '<path>' cannot be read: <reason>") when the file is
// missing, refused by `access`, or not an image OpenImageIO reads.
OpenedImageFile open_image_file(const std::string& path, const std::string& where,
                                const std::string& noun, const FileAccess& access);

}  // namespace rayo
