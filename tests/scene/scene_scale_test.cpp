// Scenes far from unit scale (docs/limits.md, "Scale"; issue "Robustness, round three" items 5
// and 6): a scene scaled by s renders the same picture for any s the number rule allows, with
// every sphere method and with single rays or streams, and objects too small for their distance
// from the origin are counted for the loaders' warning (core/scene_bounds.h).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "core/scene_bounds.h"

namespace rayo {
namespace {

double mean_red(const Film& film) {
    double sum = 0.0;
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) sum += film.rgb(x, y).x;
    }
    return sum / (double(film.width()) * film.height());
}

// A sphere of radius s at the origin seen from (0, 0, 2s), lit from (s, s, 2s).
SceneDescription scaled_sphere(double s, const std::string& method) {
    std::ostringstream text;
    text.precision(17);
    text << R"({"rayo": 1, "camera": {"eye": [0, 0, )" << 2 * s
         << R"(], "look_at": [0, 0, 0], "vfov": 60, "width": 48, "height": 48},
               "render": {"sphere_method": ")"
         << method << R"("},
               "lights": [{"type": "point", "position": [)"
         << s << ", " << s << ", " << 2 * s << R"(]}],
               "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": )"
         << s << "}]}";
    return load_json_string(text.str(), "scale.json", "");
}

// The eye used to sit on the window in world space: beyond about 1e7 the window (one unit from
// the eye) rounded onto the eye, every camera ray's direction was NaN, spheres vanished (exit 0,
// a black image) and triangles aborted inside Embree ("all(valid, ray.valid())").
TEST(SceneScale, ASphereRendersTheSameAtEveryScaleWithEveryMethod) {
    for (const char* method : {"user", "bruteforce", "embree-point", "mesh:3"}) {
        SCOPED_TRACE(method);
        const double unit = mean_red(render_scene(scaled_sphere(1.0, method), 0, false).film);
        ASSERT_GT(unit, 0.2);
        const bool triangles = std::string(method).rfind("mesh", 0) == 0;
        for (double s : {1e4, 1e7, 1e12, 1e17}) {
            SCOPED_TRACE(s);
            SceneDescription d = scaled_sphere(s, method);
            if (triangles && s > 1e12) {
                // Beyond Embree's triangle range: refused before the BVH is built.
                EXPECT_THROW(render_scene(d, 0, false), InputError);
                continue;
            }
            const RenderResult r = render_scene(d, 0, false);
            EXPECT_NEAR(mean_red(r.film), unit, 1e-4 * unit);
            EXPECT_GT(r.counters.shadow, 0u);
        }
    }
}

// The issue's box of ±1e7 seen from (3e6, 2e6, 4e7), through streams and single rays.
SceneDescription scaled_box(double s, bool single_rays) {
    const double v[8][3] = {{-s, -s, -s}, {s, -s, -s}, {s, s, -s}, {-s, s, -s},
                            {-s, -s, s},  {s, -s, s},  {s, s, s},  {-s, s, s}};
    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    std::ostringstream text;
    text.precision(17);
    text << R"({"rayo": 1, "camera": {"eye": [)" << 0.3 * s << ", " << 0.2 * s << ", " << 4 * s
         << R"(], "look_at": [0, 0, 0], "vfov": 60, "width": 48, "height": 48},
               "lights": [{"type": "point", "position": [)"
         << s << ", " << 2 * s << ", " << 3 * s << R"(]}], "objects": [)";
    for (int f = 0; f < 6; ++f) {
        text << (f ? ", " : "") << R"({"type": "polygon", "vertices": [)";
        for (int k = 0; k < 4; ++k) {
            const double* p = v[faces[f][k]];
            text << (k ? ", " : "") << "[" << p[0] << ", " << p[1] << ", " << p[2] << "]";
        }
        text << "]}";
    }
    text << "]}";
    SceneDescription d = load_json_string(text.str(), "box.json", "");
    d.settings.coherent = !single_rays;
    return d;
}

TEST(SceneScale, ABoxRendersTheSameFarFromUnitScaleWithStreamsAndSingleRays) {
    for (bool single : {false, true}) {
        SCOPED_TRACE(single ? "single rays" : "streams");
        const double unit = mean_red(render_scene(scaled_box(1.0, single), 0, false).film);
        ASSERT_GT(unit, 0.05);
        for (double s : {1e7, 1e9, 1e12}) {
            SCOPED_TRACE(s);
            EXPECT_NEAR(mean_red(render_scene(scaled_box(s, single), 0, false).film), unit,
                        1e-4 * unit);
        }
    }
    // At ±3e12 Embree's triangle test overflowed and aborted the process: refused, saying why.
    try {
        render_scene(scaled_box(3e12, false), 0, false);
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), "box.json");
        EXPECT_NE(e.message().find("triangles lie up to 3e+12 from the origin and the eye "
                                   "1.2e+13: "),
                  std::string::npos)
            << e.what();
        EXPECT_NE(e.message().find("beyond the 1e+38 a float holds"), std::string::npos)
            << e.what();
    }
}

// A unit sphere at x from the origin: right to 1e-4 at 1e5 (its ray offsets, 1e-5·|P|, are
// half its diameter), wrong by a third at 2e5 (docs/limits.md, "Scale"). Counted from 2e4 on,
// where the offset passes a tenth of its size.
TEST(SceneScale, ObjectsTooSmallForTheirDistanceFromTheOriginAreCounted) {
    auto far_sphere = [](double x) {
        std::ostringstream text;
        text.precision(17);
        text << R"({"rayo": 1, "objects": [{"type": "sphere", "center": [)" << x
             << R"(, 0, 0], "radius": 1}, {"type": "sphere", "center": [0, 0, 0], "radius": 1}]})";
        return load_json_string(text.str(), "far.json", "");
    };
    EXPECT_EQ(objects_below_float_resolution(far_sphere(1e4).scene), 0u);
    EXPECT_EQ(objects_below_float_resolution(far_sphere(3e4).scene), 1u);
    EXPECT_EQ(objects_below_float_resolution(far_sphere(2e7).scene), 1u);
    // Scaled with its distance, a sphere is never too small.
    EXPECT_EQ(objects_below_float_resolution(scaled_sphere(1e17, "user").scene), 0u);
}

}  // namespace
}  // namespace rayo
