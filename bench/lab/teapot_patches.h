#pragma once
// The Utah teapot's Bézier patches (public-domain data; origin in teapot_patches.cpp), for the
// SPD "teapot" scene (bench/lab/spd_scenes.h).

namespace rayo {

constexpr int kTeapotPointCount = 306;
constexpr int kTeapotPatchCount = 32;
extern const double kTeapotPoints[kTeapotPointCount][3];
// Each patch: 4×4 control points, 1-based numbers into kTeapotPoints, row by row.
extern const int kTeapotPatches[kTeapotPatchCount][16];

}  // namespace rayo
