// The scene-magnitude rule (core/scene_limits.h): its bounds, and every loader refusing a number
// beyond it with the same wording at the number's place.
#include "core/scene_limits.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "apps/scene/json_loader.h"
#include "apps/scene/mesh_loader.h"
#include "apps/scene/nff_loader.h"
#include "core/error.h"

namespace rayo {
namespace {

TEST(SceneLimits, WithinSceneMagnitudeBounds) {
    EXPECT_TRUE(within_scene_magnitude(0.0));
    EXPECT_TRUE(within_scene_magnitude(1e18));
    EXPECT_TRUE(within_scene_magnitude(-1e18));
    EXPECT_FALSE(within_scene_magnitude(std::nextafter(1e18, 2e18)));
    EXPECT_FALSE(within_scene_magnitude(-1e30));
    EXPECT_FALSE(within_scene_magnitude(std::numeric_limits<double>::infinity()));
    EXPECT_FALSE(within_scene_magnitude(std::numeric_limits<double>::quiet_NaN()));
    // The point of the limit: its square is still a finite float, 1e20's is not.
    EXPECT_TRUE(std::isfinite(static_cast<float>(kMaxSceneMagnitude) *
                              static_cast<float>(kMaxSceneMagnitude)));
    EXPECT_FALSE(std::isfinite(1e20f * 1e20f));
}

// The loader's InputError (where, message) for `f`.
template <typename F>
InputError refusal(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError";
    return InputError("", "");
}

TEST(SceneLimits, EveryLoaderRefusesWithTheSameRule) {
    const std::string rule = kSceneMagnitudeRule;
    const InputError json = refusal([] {
        load_json_string(R"({"rayo": 1, "objects": [
                               {"type": "sphere", "center": [0, 0, 0], "radius": 1e30}]})",
                         "t.json", "");
    });
    EXPECT_EQ(json.where(), "t.json#/objects/0/radius");
    EXPECT_EQ(json.message(), "expected " + rule + ", got 1e+30") << json.what();

    const InputError nff = refusal([] {
        load_nff_string(
            "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\n"
            "resolution 8 8\ns 0 0 0 1e30\n",
            "t.nff");
    });
    EXPECT_EQ(nff.where(), "t.nff:8");
    EXPECT_NE(nff.message().find(": expected " + rule + ", got "), std::string::npos) << nff.what();

    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("rayo_scene_limits_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string obj = (dir / "big.obj").string();
    std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1e30 0\nf 1 2 3\n";
    std::vector<Material> materials;
    const InputError mesh = refusal([&] { load_obj(obj, materials, "here"); });
    EXPECT_EQ(mesh.where(), obj + ":3");
    EXPECT_EQ(mesh.message(), "'v': expected " + rule + ", got '1e30'") << mesh.what();

    // A mesh the JSON transform pushes beyond the limit (1e3 × 1e17 = 1e20).
    std::ofstream(dir / "m.obj") << "v 1000 0 0\nv 0 1000 0\nv 0 0 1000\nf 1 2 3\n";
    const InputError moved = refusal([&] {
        load_json_string(R"({"rayo": 1, "objects": [{"type": "mesh", "file": "m.obj",
                                                      "transform": {"scale": 1e17}}]})",
                         "t.json", dir.string());
    });
    EXPECT_EQ(moved.where(), "t.json#/objects/0/transform");
    EXPECT_NE(moved.message().find("every coordinate must be " + rule), std::string::npos)
        << moved.what();
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rayo
