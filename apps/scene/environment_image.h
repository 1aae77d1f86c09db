#pragma once
// The image of an environment light (shading/environment_light.h), read with OpenImageIO
// (through the image module, core/image_library.h) from the bytes of a file that passed the
// scene's input-file checks (apps/scene/input_file.h). Floating-point formats (.exr, .hdr, .pfm)
// are linear radiance as they are; any other format is taken as sRGB-encoded and decoded
// (shading/image_texture.h srgb_to_linear). Grey images are grey radiance; the first three
// channels otherwise.
#include <memory>
#include <string>

#include "apps/scene/input_file.h"
#include "shading/environment_light.h"

namespace rayo {

// Most pixels an environment image may have: 2^25, an 8192 × 4096 sky. The map holds about 24
// bytes a pixel (linear RGB and its sampling distribution) and reading peaks near 28, so the
// largest image stays near 1 GB however small its file (docs/limits.md, "Memory from small
// files").
constexpr uint64_t kMaxEnvironmentPixels = uint64_t(1) << 25;

// Throws InputError(where, "environment image '<path>' ...") when the file is missing, refused
// by `access`, unreadable as an image, not twice as wide as it is high (equirectangular), larger
// than kMaxEnvironmentPixels, or holds a negative or non-finite value.
std::shared_ptr<const EnvironmentMap> read_environment_image(const std::string& path,
                                                             const std::string& where,
                                                             const FileAccess& access);

}  // namespace rayo
