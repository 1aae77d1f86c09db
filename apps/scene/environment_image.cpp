#include "apps/scene/environment_image.h"

#include <cmath>
#include <vector>

#include "apps/scene/image_file.h"
#include "core/error.h"
#include "core/path_util.h"
#include "shading/image_texture.h"

namespace rayo {

std::shared_ptr<const EnvironmentMap> read_environment_image(const std::string& path,
                                                             const std::string& where,
                                                             const FileAccess& access) {
    const std::string what = "environment image '" + path + "'";
    const OpenedImageFile file = open_image_file(path, where, "environment image", access);
    ImageReader* in = file.reader.get();
    const int width = in->width(), height = in->height();
    const uint64_t pixels = uint64_t(width) * uint64_t(height);
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (pixels > kMaxEnvironmentPixels || in->depth() > 1) {
        throw InputError(where, what + " is " + size + ": the limit is " +
                                    std::to_string(kMaxEnvironmentPixels) + " pixels");
    }
    if (height < 1 || width != 2 * height) {
        throw InputError(where, what + " is " + size +
                                    ": expected an equirectangular image, twice as wide as high");
    }
    const int channels = in->channels() >= 3 ? 3 : 1;
    std::vector<float> values(pixels * size_t(channels));
    if (!in->read_floats(channels, values.data())) {
        throw InputError(where, what + " cannot be read: " + in->error());
    }
    const std::string extension = lower_extension(path);
    const bool linear = extension == ".exr" || extension == ".hdr" || extension == ".pfm";
    std::vector<Vec3> texels(pixels);
    for (size_t i = 0; i < pixels; ++i) {
        float c[3];
        for (int k = 0; k < 3; ++k) {
            const float value = values[i * size_t(channels) + size_t(channels == 3 ? k : 0)];
            if (!std::isfinite(value) || value < 0.0f) {
                throw InputError(where, what + " has a negative or non-finite value at pixel (" +
                                            std::to_string(i % size_t(width)) + ", " +
                                            std::to_string(i / size_t(width)) + ")");
            }
            c[k] = linear ? value : srgb_to_linear(value);
        }
        texels[i] = Vec3(c[0], c[1], c[2]);
    }
    std::vector<float>().swap(values);  // freed before the map builds its distribution
    return std::make_shared<const EnvironmentMap>(width, height, std::move(texels));
}

}  // namespace rayo
