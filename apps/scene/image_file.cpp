#include "apps/scene/image_file.h"

#include "core/error.h"

namespace rayo {

OpenedImageFile open_image_file(const std::string& path, const std::string& where,
                                const std::string& noun, const FileAccess& access) {
    OpenedImageFile file;
    file.bytes = std::make_unique<const std::string>(
        read_input_file(path, where, noun, kMaxImageFileBytes, access));
    std::string reason;
    file.reader = image_library().open_reader(path, *file.bytes, reason);
    if (!file.reader) {
        if (reason.empty()) reason = "not an image format OpenImageIO reads";
        throw InputError(where, noun + " '" + path + "' cannot be read: " + reason);
    }
    return file;
}

}  // namespace rayo
