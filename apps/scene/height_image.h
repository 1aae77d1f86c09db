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

// Most floats a height image may decode to: 2^27 samples of a grey image (11585², 512 MiB), a
// third of that for a colour image, which is read as three floats a sample before its
// luminance is taken. About 6.5 bytes a grey sample and 18 a colour one at the peak, so the worst
// small file stays near 1 GB (docs/limits.md, "Memory from small files"); the charts of
// docs/heightfields.md go to 8192².
constexpr uint64_t kMaxHeightSamples = uint64_t(1) << 27;

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
