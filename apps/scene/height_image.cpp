#include "apps/scene/height_image.h"

#include <cmath>

#include "apps/scene/image_file.h"
#include "core/error.h"
#include "core/luminance.h"

namespace rayo {

HeightSamples read_height_image(const std::string& path, const std::string& where,
                                const FileAccess& access) {
    const std::string what = "height image '" + path + "'";
    const OpenedImageFile file = open_image_file(path, where, "height image", access);
    ImageReader* in = file.reader.get();
    const int width = in->width(), height = in->height();
    const uint64_t samples = uint64_t(width) * uint64_t(height);
    const int channels = in->channels() >= 3 ? 3 : 1;
    const uint64_t most = kMaxHeightSamples / uint64_t(channels);
    if (width < 2 || height < 2 || in->depth() > 1 || samples > most) {
        throw InputError(
            where, what + " is " + std::to_string(width) + "x" + std::to_string(height) +
                       ": expected at least 2x2 and at most " + std::to_string(most) + " samples" +
                       (channels == 3 ? " (a colour image; a grey one may have " +
                                            std::to_string(kMaxHeightSamples) + ")"
                                      : ""));
    }
    std::vector<float> pixels(samples * size_t(channels));
    // Integer formats convert to value/max in [0, 1] at their full depth; float stays float.
    if (!in->read_floats(channels, pixels.data())) {
        throw InputError(where, what + " cannot be read: " + in->error());
    }
    HeightSamples out;
    out.columns = width;
    out.rows = height;
    if (channels == 1) {
        out.values = std::move(pixels);
    } else {
        out.values.resize(samples);
        for (size_t i = 0; i < samples; ++i) {
            out.values[i] = luminance(pixels[3 * i], pixels[3 * i + 1], pixels[3 * i + 2]);
        }
    }
    for (size_t i = 0; i < out.values.size(); ++i) {
        if (!std::isfinite(out.values[i])) {
            throw InputError(where, what + " has a non-finite value at pixel (" +
                                        std::to_string(i % size_t(out.columns)) + ", " +
                                        std::to_string(i / size_t(out.columns)) + ")");
        }
    }
    return out;
}

}  // namespace rayo
