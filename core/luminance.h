#pragma once
// The luminance of linear RGB with the Rec. 709 primaries (ITU-R BT.709: Y = 0.2126 R +
// 0.7152 G + 0.0722 B): the grey value of a texel (bump heights, MTL map_d coverage), the height
// of a colour height-field image, the weight of an emitter's radiance in the power CDF.
#include "core/math.h"

namespace rayo {

inline float luminance(float r, float g, float b) {
    return 0.2126f * r + 0.7152f * g + 0.0722f * b;
}

inline float luminance(const Vec3& c) {
    return luminance(c.x, c.y, c.z);
}

}  // namespace rayo
