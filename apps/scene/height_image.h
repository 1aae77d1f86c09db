#pragma once
// The samples of a height-field image (docs/heightfields.md), read with OpenImageIO (through the
// image module, core/image_library.h) from the bytes of a file that passed the scene's
// input-file checks (apps/scene/input_file.h: regular file, size limit, --restrict-paths). 8- and
// 16-bit integer images are read as value/max in [0, 1] (a 16-bit PNG keeps its 16 bits), float
// images as they are. One or two channels (grey, grey + alpha): the first; three or more: the
// Rec. 709 luminance of the first three.
#include <cstdint>
#include <string>
#include <vector>

#include "apps/scene/input_file.h"

namespace rayo {

// Most samples a height field may have (16384², 1 GiB of floats); the charts of
// docs/heightfields.md go to 8192².
constexpr uint64_t kMaxHeightSamples = uint64_t(1) << 28;

struct HeightSamples {
    int columns = 0;
    int rows = 0;
    std::vector<float> values;  // rows × columns, row 0 the image's top row
};

// Throws InputError(where, "height image '<path>' ...") when the file is missing, refused by
// `access`, unreadable as an image, smaller than 2×2, larger than kMaxHeightSamples, or holds a
// non-finite value.
HeightSamples read_height_image(const std::string& path, const std::string& where,
                                const FileAccess& access);

}  // namespace rayo
