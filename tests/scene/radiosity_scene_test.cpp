// Tests of radiosity through the JSON reader and render_scene (docs/radiosity.md): the fields and
// their errors, the white furnace end to end (a closed box of uniform ρ emitting E seen from
// inside: E/(1 − ρ) with "gi": "radiosity", E without), an area light counted once, the patch
// cut of RadiosityField, and the same bits for any thread count and tile size.
#include <gtest/gtest.h>

#include <string>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "shading/radiosity_field.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::same_bits;

SceneDescription load(const std::string& text) {
    return load_json_string(text, "scene.json", "");
}

InputError load_error(const std::string& text) {
    try {
        load(text);
    } catch (const InputError& error) {
        return error;
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return InputError("", "");
}

TEST(RadiosityScene, ReadsTheRadiosityFieldsAndGi) {
    const SceneDescription d = load(R"({"rayo": 1, "render": {"gi": "radiosity"},
      "radiosity": {"patch_size": 0.25, "threshold": 0.002, "max_shots": 77,
                    "form_factors": "analytic", "rays": 9}})");
    EXPECT_EQ(d.settings.gi, GlobalIllumination::Radiosity);
    EXPECT_FLOAT_EQ(d.settings.radiosity.patch_size, 0.25f);
    EXPECT_NEAR(d.settings.radiosity.threshold, 0.002, 1e-9);
    EXPECT_EQ(d.settings.radiosity.max_shots, 77);
    EXPECT_EQ(d.settings.radiosity.form_factors, FormFactorMethod::Analytic);
    EXPECT_EQ(d.settings.radiosity.rays, 9);
    EXPECT_EQ(load(R"({"rayo": 1})").settings.gi, GlobalIllumination::None);
}

TEST(RadiosityScene, BadFieldsNameTheirPointer) {
    struct Case {
        const char* text;
        const char* where;
        const char* message;
    };
    const Case cases[] = {
        {R"({"rayo": 1, "render": {"gi": "path"}})", "scene.json#/render/gi", "expected one of"},
        {R"({"rayo": 1, "radiosity": 3})", "scene.json#/radiosity", "expected a radiosity object"},
        {R"({"rayo": 1, "radiosity": {"form_factors": "hemicube"}})",
         "scene.json#/radiosity/form_factors", "expected one of"},
        {R"({"rayo": 1, "radiosity": {"rays": 0}})", "scene.json#/radiosity/rays",
         "expected an integer in [1, 65536]"},
        {R"({"rayo": 1, "radiosity": {"patch_size": -1}})", "scene.json#/radiosity/patch_size",
         "expected a number >= 0"},
        {R"({"rayo": 1, "radiosity": {"threshold": "low"}})", "scene.json#/radiosity/threshold",
         "expected a number >= 0"},
        {R"({"rayo": 1, "radiosity": {"max_shots": 1.5}})", "scene.json#/radiosity/max_shots",
         "expected an integer"},
        {R"({"rayo": 1, "radiosity": {"patch": 1}})", "scene.json#/radiosity/patch", "unknown key"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.text);
        const InputError error = load_error(c.text);
        EXPECT_EQ(error.where(), c.where);
        EXPECT_NE(error.message().find(c.message), std::string::npos) << error.message();
    }
}

// The unit cube seen from its centre, every wall emitting E = (1, 0.5, 2) with kd = ρ = 0.5.
const char* const kFurnace = R"({"rayo": 1,
  "camera": {"eye": [0.5, 0.5, 0.5], "look_at": [0.5, 0.5, 0], "vfov": 120, "width": 12,
             "height": 12},
  "render": {"tile_size": 16, "gi": "GI"}, "ambient_light": 1,
  "radiosity": {"patch_size": 0.5, "threshold": 1e-6, "form_factors": "METHOD", "rays": RAYS},
  "materials": {"default": {"kd": 0.5, "ka": 0.3, "emission": [1, 0.5, 2]}},
  "objects": [
    {"type": "polygon", "vertices": [[0,0,0], [1,0,0], [1,1,0], [0,1,0]]},
    {"type": "polygon", "vertices": [[0,0,1], [0,1,1], [1,1,1], [1,0,1]]},
    {"type": "polygon", "vertices": [[0,0,0], [0,0,1], [1,0,1], [1,0,0]]},
    {"type": "polygon", "vertices": [[0,1,0], [1,1,0], [1,1,1], [0,1,1]]},
    {"type": "polygon", "vertices": [[0,0,0], [0,1,0], [0,1,1], [0,0,1]]},
    {"type": "polygon", "vertices": [[1,0,0], [1,0,1], [1,1,1], [1,1,0]]}]})";

SceneDescription furnace(const std::string& gi, const std::string& method, int rays) {
    std::string text = kFurnace;
    auto put = [&](const std::string& key, const std::string& value) {
        text.replace(text.find(key), key.size(), value);
    };
    put("GI", gi);
    put("METHOD", method);
    put("RAYS", std::to_string(rays));
    return load(text);
}

TEST(RadiosityScene, WhiteFurnaceEndToEnd) {
    // Without GI the walls show E + ka·Ia (no lights); with radiosity E/(1 − ρ) = 2E: the
    // solution replaces the ambient term.
    const RenderResult none = render_scene(furnace("none", "analytic", 64), 1, false);
    EXPECT_FALSE(none.radiosity);
    rayo_test::expect_vec3(none.film.rgb(6, 6), 1.3f, 0.8f, 2.3f, 1e-5f);

    const RenderResult analytic = render_scene(furnace("radiosity", "analytic", 64), 2, false);
    EXPECT_TRUE(analytic.radiosity);
    // 6 walls of 2 triangles, each cut 3×3 (its diagonal √2 over 0.5)
    EXPECT_EQ(analytic.radiosity_patches, 6u * 2u * 9u);
    EXPECT_EQ(analytic.radiosity_stats.form_factor_rays, 0u);
    EXPECT_LT(analytic.radiosity_stats.unshot_fraction, 1e-6);
    for (int y = 0; y < 12; y += 3) {
        for (int x = 0; x < 12; x += 3) {
            rayo_test::expect_vec3(analytic.film.rgb(x, y), 2.0f, 1.0f, 4.0f, 0.02f);
        }
    }

    const RenderResult rays = render_scene(furnace("radiosity", "rays", 256), 2, false);
    EXPECT_GT(rays.radiosity_stats.form_factor_rays, 0u);
    rayo_test::expect_vec3(rays.film.rgb(6, 6), 2.0f, 1.0f, 4.0f, 0.1f);
}

TEST(RadiosityScene, SameBitsForAnyThreadCountAndTileSize) {
    SceneDescription d = furnace("radiosity", "rays", 16);
    const RenderResult reference = render_scene(d, 1, false);
    for (int threads : {2, 3}) {
        for (int tile : {16, 32}) {
            d.settings.tile_size = tile;
            const RenderResult r = render_scene(d, threads, false);
            EXPECT_TRUE(same_bits(reference.film, r.film)) << threads << " " << tile;
            EXPECT_EQ(r.radiosity_stats.shots, reference.radiosity_stats.shots);
            EXPECT_EQ(r.radiosity_stats.form_factor_rays,
                      reference.radiosity_stats.form_factor_rays);
        }
    }
}

TEST(RadiosityScene, AreaLightIsCountedOnce) {
    // A floor under a rectangle light, seen straight down. Whitted's local model has no 1/π
    // (seed 000: kd·Il·cosθ, so kd·E for an area light's irradiance E); the radiosity solution
    // reflects ρ·E/π. With "gi": "radiosity" the floor shows the solution alone: the light's
    // direct term is not added on top.
    const std::string text = R"({"rayo": 1,
      "camera": {"eye": [0, 0.5, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "vfov": 2,
                 "width": 4, "height": 4},
      "render": {"gi": "GI"}, "ambient_light": 0,
      "radiosity": {"patch_size": 0.2, "form_factors": "analytic", "rays": 64},
      "materials": {"default": {"kd": 0.5, "ka": 0}},
      "lights": [{"type": "area", "shape": "rectangle", "corner": [-0.5, 1, -0.5],
                  "edge1": [1, 0, 0], "edge2": [0, 0, 1], "samples": 256, "intensity": 1}],
      "objects": [{"type": "polygon", "vertices": [[-1,0,-1], [-1,0,1], [1,0,1], [1,0,-1]]}]})";
    auto with = [&](const char* gi) {
        std::string t = text;
        t.replace(t.find("GI"), 2, gi);
        return render_scene(load(t), 1, false).film.rgb(2, 2).x;
    };
    const float whitted = with("none");
    const float radiosity = with("radiosity");
    EXPECT_GT(whitted, 0.1f);
    // The patches average the peak under the light a little down (0.2 patches): 4%; a double
    // count would be 1 + π times more.
    EXPECT_NEAR(radiosity, whitted / kPi, 0.04f * whitted / kPi);
}

TEST(RadiosityScene, FieldCutsTrianglesToThePatchSize) {
    Scene scene;
    TriangleMesh mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.triangles = {{0, 1, 2}};
    mesh.materials = {0};
    scene.meshes.push_back(mesh);
    std::vector<Material> materials(1);
    // The longest edge √2 over 0.5: 3 cuts per edge, 9 patches of a ninth of the area.
    RadiosityField field(scene, materials, 0.5f);
    ASSERT_EQ(field.patches().size(), 9u);
    for (const RadiosityPatch& p : field.patches()) {
        EXPECT_NEAR(p.area, 0.5f / 9.0f, 1e-6f);
        EXPECT_NEAR(p.normal.z, 1.0f, 1e-6f);
    }
    EXPECT_EQ(RadiosityField(scene, materials, 0.0f).patches().size(), 1u);

    // Patch i gets B = i: vertex averages interpolate between patches, flat shows the patch.
    std::vector<DVec3> b(9);
    for (size_t i = 0; i < 9; ++i) b[i] = DVec3(static_cast<double>(i));
    field.set_solution(b);
    SurfaceHit hit;
    hit.shape = kTriangleShape;
    hit.position = Vec3(0.0f);  // corner vertex: only patch 0 touches it
    Vec3 r;
    ASSERT_TRUE(field.reflected(hit, r));
    EXPECT_NEAR(r.x, 0.0f, 1e-6f);
    // Grid point (1, 0): a vertex of patches 0 and 1 (row 0's first lower and upper) and 5
    // (row 1's first lower): (0 + 1 + 5)/3.
    hit.position = Vec3(1.0f / 3.0f, 0.0f, 0.0f);
    ASSERT_TRUE(field.reflected(hit, r));
    EXPECT_NEAR(r.x, 2.0f, 1e-5f);
    // Halfway to grid point (2, 0), a vertex of patches 5 and 6 (row 1's first lower and upper)
    // and 8 (row 2's lower): the average of the two vertices.
    hit.position = Vec3(0.5f, 0.0f, 0.0f);
    ASSERT_TRUE(field.reflected(hit, r));
    EXPECT_NEAR(r.x, 0.5f * (2.0f + (5.0f + 6.0f + 8.0f) / 3.0f), 1e-5f);
    field.set_flat(true);
    hit.position = Vec3(0.05f, 0.05f, 0.0f);
    ASSERT_TRUE(field.reflected(hit, r));
    EXPECT_EQ(r.x, 0.0f);
    hit.shape = 0;  // an analytic shape: not in the solve
    EXPECT_FALSE(field.reflected(hit, r));
}

}  // namespace
}  // namespace rayo
