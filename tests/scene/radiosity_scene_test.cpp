// Tests of radiosity through the JSON reader and render_scene (docs/radiosity.md): the fields and
// their errors, the white furnace end to end (a closed box of uniform ρ emitting E seen from
// inside: E/(1 − ρ) with "gi": "radiosity", E without), an area light counted once, the patch
// cut of RadiosityField, and the same bits for any thread count and tile size.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "shading/radiosity.h"
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
    // 6 walls of 2 triangles, each cut 3×3 (its diagonal √2 over 0.5), on both sides (the
    // default material is two-sided; the backs face out and see nothing)
    EXPECT_EQ(analytic.radiosity_patches, 2u * 6u * 2u * 9u);
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

// kFurnace with every wall wound outward (its vertices reversed): the camera inside sees the
// walls' backs, as in an asset wound the other way.
std::string outward_furnace(const std::string& gi, const std::string& method, int rays,
                            const std::string& sidedness = "") {
    std::string text = kFurnace;
    auto put = [&](const std::string& key, const std::string& value) {
        text.replace(text.find(key), key.size(), value);
    };
    put("GI", gi);
    put("METHOD", method);
    put("RAYS", std::to_string(rays));
    put(R"("emission": [1, 0.5, 2])", R"("emission": [1, 0.5, 2])" + sidedness);
    const std::string vertices = R"("vertices": [)";
    for (size_t at = text.find(vertices); at != std::string::npos;
         at = text.find(vertices, at + 1)) {
        const size_t first = at + vertices.size(), end = text.find("]]", first) + 1;
        std::vector<std::string> corners;
        for (size_t c = first; c < end; c = text.find(']', c) + 3) {
            corners.push_back(text.substr(c, text.find(']', c) + 1 - c));
        }
        std::string reversed;
        for (size_t k = corners.size(); k-- > 0;) reversed += corners[k] + (k ? ", " : "");
        text.replace(first, end - first, reversed);
    }
    return text;
}

TEST(RadiosityScene, OutwardWoundFurnaceHoldsTheSameRadiosity) {
    // Every wall's back faces the inside: two-sided patches emit and receive there, so the
    // camera sees E/(1 − ρ) = 2E as in the inward-wound furnace (before two-sided patches it
    // saw ka·Ia, the walls black in the solve), with the inward furnace's tolerances.
    const std::string text = outward_furnace("radiosity", "analytic", 64);
    ASSERT_NE(text.find(R"([[0,1,0], [1,1,0], [1,0,0], [0,0,0]])"), std::string::npos) << text;
    const RenderResult analytic = render_scene(load(text), 2, false);
    EXPECT_EQ(analytic.radiosity_patches, 2u * 6u * 2u * 9u);
    EXPECT_LT(analytic.radiosity_stats.unshot_fraction, 1e-6);
    for (int y = 0; y < 12; y += 3) {
        for (int x = 0; x < 12; x += 3) {
            rayo_test::expect_vec3(analytic.film.rgb(x, y), 2.0f, 1.0f, 4.0f, 0.02f);
        }
    }
    const RenderResult rays =
        render_scene(load(outward_furnace("radiosity", "rays", 256)), 2, false);
    EXPECT_GT(rays.radiosity_stats.form_factor_rays, 0u);
    rayo_test::expect_vec3(rays.film.rgb(6, 6), 2.0f, 1.0f, 4.0f, 0.1f);
}

TEST(RadiosityScene, OneSidedMaterialKeepsItsWindingSideOnly) {
    // "double_sided": false: one patch per triangle, on its winding side. Wound inward, the
    // furnace holds 2E; wound outward, the camera sees the backs' ka·Ia = 0.3 as before
    // two-sided patches (neither emission nor radiosity behind a one-sided surface).
    const std::string one_sided = R"(, "double_sided": false)";
    std::string inward = kFurnace;
    inward.replace(inward.find("GI"), 2, "radiosity");
    inward.replace(inward.find("METHOD"), 6, "analytic");
    inward.replace(inward.find("RAYS"), 4, "64");
    inward.replace(inward.find(R"([1, 0.5, 2])"), 11, R"([1, 0.5, 2])" + one_sided);
    const RenderResult in = render_scene(load(inward), 2, false);
    EXPECT_EQ(in.radiosity_patches, 6u * 2u * 9u);
    rayo_test::expect_vec3(in.film.rgb(6, 6), 2.0f, 1.0f, 4.0f, 0.02f);
    const RenderResult out =
        render_scene(load(outward_furnace("radiosity", "analytic", 64, one_sided)), 2, false);
    EXPECT_EQ(out.radiosity_patches, 6u * 2u * 9u);
    for (int y = 0; y < 12; y += 3) {
        for (int x = 0; x < 12; x += 3) {
            rayo_test::expect_vec3(out.film.rgb(x, y), 0.3f, 0.3f, 0.3f, 1e-6f);
        }
    }
}

// The faces of the box [lo, hi] as polygons wound outward (or inward), the bottom face with
// `bottom` only (a block standing on a floor has none).
std::string box_polygons(const Vec3& lo, const Vec3& hi, bool inward, bool bottom,
                         const std::string& material) {
    const Vec3 a = lo, b = hi;
    const std::vector<std::vector<Vec3>> faces = {
        {{a.x, a.y, a.z}, {a.x, b.y, a.z}, {b.x, b.y, a.z}, {b.x, a.y, a.z}},  // -z
        {{a.x, a.y, b.z}, {b.x, a.y, b.z}, {b.x, b.y, b.z}, {a.x, b.y, b.z}},  // +z
        {{a.x, a.y, a.z}, {a.x, a.y, b.z}, {a.x, b.y, b.z}, {a.x, b.y, a.z}},  // -x
        {{b.x, a.y, a.z}, {b.x, b.y, a.z}, {b.x, b.y, b.z}, {b.x, a.y, b.z}},  // +x
        {{a.x, b.y, a.z}, {a.x, b.y, b.z}, {b.x, b.y, b.z}, {b.x, b.y, a.z}},  // +y
        {{a.x, a.y, a.z}, {b.x, a.y, a.z}, {b.x, a.y, b.z}, {a.x, a.y, b.z}},  // -y
    };
    std::string out;
    for (size_t f = 0; f < faces.size(); ++f) {
        if (f == 5 && !bottom) break;
        std::vector<Vec3> v = faces[f];
        if (inward) std::reverse(v.begin(), v.end());
        out += R"(, {"type": "polygon", "material": ")" + material + R"(", "vertices": [)";
        for (size_t k = 0; k < v.size(); ++k) {
            out += (k ? ", [" : "[") + std::to_string(v[k].x) + ", " + std::to_string(v[k].y) +
                   ", " + std::to_string(v[k].z) + "]";
        }
        out += "]}";
    }
    return out;
}

// A unit room wound inward, lit by a one-sided emitter under its ceiling, holding a block wound
// outward or inward (as the blocks of the common Cornell box OBJ), of a material `block`; the
// camera looks at the block's -z face.
SceneDescription room_with_block(bool block_inward, const std::string& block) {
    const std::string room = box_polygons(Vec3(0.0f), Vec3(1.0f), true, true, "white");
    const std::string blocks =
        box_polygons(Vec3(0.3f, 0.0f, 0.4f), Vec3(0.6f, 0.3f, 0.7f), block_inward, false, "block");
    return load(R"({"rayo": 1,
      "camera": {"eye": [0.45, 0.15, 0.05], "look_at": [0.45, 0.15, 0.4], "vfov": 20,
                 "width": 4, "height": 4},
      "render": {"gi": "radiosity"}, "ambient_light": 0,
      "radiosity": {"patch_size": 0.25, "threshold": 1e-2, "rays": 16},
      "materials": {"white": {"kd": 0.5, "ka": 0}, "block": )" +
                block + R"(,
                    "light": {"kd": 0, "ka": 0, "emission": 10, "double_sided": false}},
      "objects": [{"type": "polygon", "material": "light", "vertices":
                   [[0.35, 0.99, 0.35], [0.65, 0.99, 0.35], [0.65, 0.99, 0.65], [0.35, 0.99, 0.65]]})" +
                room + blocks + "]}");
}

TEST(RadiosityScene, ABlockWoundInwardIsLitLikeOneWoundOutward) {
    // The common Cornell box OBJ's blocks face into themselves: their backs face the room.
    // Two-sided, their back patches receive the room's light: the block's face shows within
    // the form factors' noise what the outward-wound block shows. One-sided, its backs keep
    // ka·Ia = 0: black, as every block was before two-sided patches.
    const std::string white = R"({"kd": 0.5, "ka": 0})";
    const RenderResult out = render_scene(room_with_block(false, white), 2, false);
    const RenderResult in = render_scene(room_with_block(true, white), 2, false);
    const RenderResult one_sided = render_scene(
        room_with_block(true, R"({"kd": 0.5, "ka": 0, "double_sided": false})"), 2, false);
    for (const auto& [x, y] : {std::pair{1, 1}, {2, 2}, {1, 2}, {2, 1}}) {
        SCOPED_TRACE(std::to_string(x) + "," + std::to_string(y));
        const float lit = out.film.rgb(x, y).x;
        EXPECT_GT(lit, 0.05f);
        EXPECT_NEAR(in.film.rgb(x, y).x, lit, 0.05f * lit);  // measured: within 2.7%
        EXPECT_EQ(one_sided.film.rgb(x, y).x, 0.0f);
    }
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
    // A floor under a rectangle light, seen straight down, with nothing to reflect its light
    // back (the light's surface is black): the Whitted render reflects kd·E/π of the light's
    // irradiance E (area lights are radiometric), the radiosity solution ρ·E/π, so both show
    // the same. With "gi": "radiosity" the floor shows the solution alone: the light's direct
    // term is not added on top.
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
    // count would be twice as bright, seed 000's convention π times.
    EXPECT_NEAR(radiosity, whitted, 0.04f * whitted);
}

TEST(RadiosityScene, FieldCutsTrianglesToThePatchSize) {
    Scene scene;
    TriangleMesh mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.triangles = {{0, 1, 2}};
    mesh.materials = {0};
    scene.meshes.push_back(mesh);
    std::vector<Material> materials(1);
    // The longest edge √2 over 0.5: 3 cuts per edge, 9 patches of a ninth of the area, on each
    // side of the two-sided default material: the front's 9 first, facing +z, then the back's.
    RadiosityField field(scene, materials, 0.5f);
    ASSERT_EQ(field.patches().size(), 18u);
    EXPECT_EQ(field.back_patch_count(), 9u);
    for (size_t i = 0; i < 18; ++i) {
        const RadiosityPatch& p = field.patches()[i];
        EXPECT_NEAR(p.area, 0.5f / 9.0f, 1e-6f);
        EXPECT_NEAR(p.normal.z, i < 9 ? 1.0f : -1.0f, 1e-6f);
        if (i >= 9) {  // the front patch reversed
            const RadiosityPatch& front = field.patches()[i - 9];
            EXPECT_EQ(p.vertices[0], front.vertices[0]);
            EXPECT_EQ(p.vertices[1], front.vertices[2]);
            EXPECT_EQ(p.vertices[2], front.vertices[1]);
        }
    }
    EXPECT_EQ(RadiosityField(scene, materials, 0.0f).patches().size(), 2u);
    // A one-sided mesh (NFF's polygons: rays pass through its back) has no back patches.
    scene.meshes[0].one_sided = true;
    EXPECT_EQ(RadiosityField(scene, materials, 0.5f).patches().size(), 9u);
    scene.meshes[0].one_sided = false;
    materials[0].double_sided = false;
    EXPECT_EQ(RadiosityField(scene, materials, 0.5f).patches().size(), 9u);
    EXPECT_EQ(RadiosityField(scene, materials, 0.5f).back_patch_count(), 0u);

    // Patch i gets B = i on the front, 100 + i on the back: vertex averages interpolate
    // between the patches of one side, flat shows the patch.
    std::vector<DVec3> b(18);
    for (size_t i = 0; i < 9; ++i) {
        b[i] = DVec3(static_cast<double>(i));
        b[9 + i] = DVec3(100.0 + static_cast<double>(i));
    }
    field.set_solution(b);
    SurfaceHit hit;
    hit.shape = kTriangleShape;
    hit.position = Vec3(0.0f);  // corner vertex: only patch 0 touches it
    Vec3 r;
    ASSERT_TRUE(field.reflected(hit, true, r));
    EXPECT_NEAR(r.x, 0.0f, 1e-6f);
    // Grid point (1, 0): a vertex of patches 0 and 1 (row 0's first lower and upper) and 5
    // (row 1's first lower): (0 + 1 + 5)/3.
    hit.position = Vec3(1.0f / 3.0f, 0.0f, 0.0f);
    ASSERT_TRUE(field.reflected(hit, true, r));
    EXPECT_NEAR(r.x, 2.0f, 1e-5f);
    // Halfway to grid point (2, 0), a vertex of patches 5 and 6 (row 1's first lower and upper)
    // and 8 (row 2's lower): the average of the two vertices.
    hit.position = Vec3(0.5f, 0.0f, 0.0f);
    ASSERT_TRUE(field.reflected(hit, true, r));
    EXPECT_NEAR(r.x, 0.5f * (2.0f + (5.0f + 6.0f + 8.0f) / 3.0f), 1e-5f);
    ASSERT_TRUE(field.reflected(hit, false, r));  // the back's vertices: its own patches only
    EXPECT_NEAR(r.x, 100.0f + 0.5f * (2.0f + (5.0f + 6.0f + 8.0f) / 3.0f), 1e-4f);
    field.set_flat(true);
    hit.position = Vec3(0.05f, 0.05f, 0.0f);
    ASSERT_TRUE(field.reflected(hit, true, r));
    EXPECT_EQ(r.x, 0.0f);
    ASSERT_TRUE(field.reflected(hit, false, r));
    EXPECT_EQ(r.x, 100.0f);
    hit.shape = 0;  // an analytic shape: not in the solve
    EXPECT_FALSE(field.reflected(hit, true, r));

    // A one-sided surface has no back to show.
    RadiosityField one_sided(scene, materials, 0.5f);
    one_sided.set_solution(std::vector<DVec3>(9, DVec3(1.0)));
    hit.shape = kTriangleShape;
    EXPECT_TRUE(one_sided.reflected(hit, true, r));
    EXPECT_FALSE(one_sided.reflected(hit, false, r));
}

// ---- Analytic shapes in the solve (tessellated for it; rendered analytically) -----------------

TEST(RadiosityScene, SphereInTheWhiteFurnaceGetsTheFurnaceRadiosity) {
    // A sphere of the walls' material (ρ = 0.5, emitting E) in front of the eye: it too has
    // B = E/(1 − ρ) = 2E, which the camera sees on it (the reflected B − E plus the emission).
    std::string text = kFurnace;
    auto put = [&](const std::string& key, const std::string& value) {
        text.replace(text.find(key), key.size(), value);
    };
    put("GI", "radiosity");
    put("METHOD", "rays");
    put("RAYS", "16");
    put("1e-6", "1e-3");
    put(R"("objects": [)",
        R"("objects": [{"type": "sphere", "center": [0.5, 0.5, 0.25], "radius": 0.12},)");
    const RenderResult r = render_scene(load(text), 2, false);
    ASSERT_TRUE(r.radiosity);
    EXPECT_GT(r.radiosity_patches, 400u);  // the walls' 108 and the sphere's, on both sides
    for (const auto& [x, y] : {std::pair{5, 5}, {6, 6}, {5, 6}, {6, 5}, {0, 0}, {11, 3}}) {
        SCOPED_TRACE(std::to_string(x) + "," + std::to_string(y));
        rayo_test::expect_vec3(r.film.rgb(x, y), 2.0f, 1.0f, 4.0f, 0.04f * 4.0f);
    }
}

// A black-bodied square emitter of radiance 1 at height 2 (facing down) over a white sphere
// (kd 0.8, no ambient, no lights), seen from `eye` toward the point `at` of the sphere. The
// sphere is one-sided: the analytic form factors ignore visibility, so patches inside it would
// see the emitter through it (and cost the solve as many again).
SceneDescription sphere_under_emitter(const std::string& gi, const Vec3& at, const Vec3& eye) {
    auto vec = [](const Vec3& v) {
        return "[" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) +
               "]";
    };
    return load(R"({"rayo": 1,
      "camera": {"eye": )" +
                vec(eye) + R"(, "look_at": )" + vec(at) + R"(, "up": [0, 0, 1], "vfov": 1,
                 "width": 3, "height": 3},
      "render": {"gi": ")" +
                gi + R"("}, "ambient_light": 0,
      "radiosity": {"patch_size": 0.1, "form_factors": "analytic", "rays": 16},
      "materials": {"white": {"kd": 0.8, "ka": 0, "double_sided": false},
                    "light": {"kd": 0, "ka": 0, "emission": [1, 1, 1]}},
      "objects": [
        {"type": "polygon", "material": "light",
         "vertices": [[-1, 2, -1], [1, 2, -1], [1, 2, 1], [-1, 2, 1]]},
        {"type": "sphere", "material": "white", "center": [0, 0, 0], "radius": 0.5}]})");
}

TEST(RadiosityScene, DiffuseSphereNextToAnEmitterReceivesLight) {
    // At a point p of the sphere (normal n) that sees the whole emitter, the solution reflects
    // ρ·L·F(p → emitter), F the closed-form point-to-polygon factor; the vertex interpolation
    // over 0.1 patches is within 3% of it. Without radiosity the sphere is black (no lights,
    // no ambient); its underside stays black with radiosity too.
    const Vec3 n = glm::normalize(Vec3(0.0f, 1.0f, 1.0f));
    const Vec3 p = 0.5f * n;
    const DVec3 square[4] = {DVec3(-1, 2, -1), DVec3(1, 2, -1), DVec3(1, 2, 1), DVec3(-1, 2, 1)};
    const double expected = 0.8 * point_polygon_form_factor(DVec3(p), DVec3(n), square, 4);
    ASSERT_GT(expected, 0.05);
    const RenderResult lit =
        render_scene(sphere_under_emitter("radiosity", p, p + 3.0f * n), 1, false);
    EXPECT_NEAR(lit.film.rgb(1, 1).x, expected, 0.03 * expected);
    const RenderResult direct =
        render_scene(sphere_under_emitter("none", p, p + 3.0f * n), 1, false);
    EXPECT_EQ(direct.film.rgb(1, 1).x, 0.0f);
    const Vec3 below(0.0f, -0.5f, 0.0f);
    const RenderResult under =
        render_scene(sphere_under_emitter("radiosity", below, Vec3(0.0f, -3.0f, 0.0f)), 1, false);
    EXPECT_EQ(under.film.rgb(1, 1).x, 0.0f);
}

TEST(RadiosityScene, DiskAndSphereAreaLightsShootLikeTheirDirectLight) {
    // A floor under a disk or a sphere area light, seen straight down: the solve (the light's
    // tessellation shooting) gives the floor what the Whitted pass gives it from the light's
    // samples, kd·E/π, less the power between the tessellation's chords (1% at 26 cells
    // around) and the vertex averaging's.
    for (const char* light : {R"("shape": "disk", "center": [0, 1, 0], "normal": [0, -1, 0],
                                 "radius": 0.4)",
                              R"("shape": "sphere", "center": [0, 1.2, 0], "radius": 0.4)"}) {
        SCOPED_TRACE(light);
        const std::string text = std::string(R"({"rayo": 1,
          "camera": {"eye": [0, 0.5, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "vfov": 2,
                     "width": 4, "height": 4},
          "render": {"gi": "GI"}, "ambient_light": 0,
          "radiosity": {"patch_size": 0.1, "form_factors": "analytic", "rays": 16},
          "materials": {"default": {"kd": 0.5, "ka": 0}},
          "lights": [{"type": "area", )") +
                                 light + R"(, "samples": 1024, "intensity": 2}],
          "objects": [{"type": "polygon", "vertices": [[-0.3,0,-0.3], [-0.3,0,0.3], [0.3,0,0.3], [0.3,0,-0.3]]}]})";
        auto with = [&](const char* gi) {
            std::string t = text;
            t.replace(t.find("GI"), 2, gi);
            return render_scene(load(t), 1, false).film.rgb(2, 2).x;
        };
        const float whitted = with("none");
        EXPECT_GT(whitted, 0.05f);
        EXPECT_NEAR(with("radiosity"), whitted, 0.025f * whitted);
    }
}

TEST(RadiosityScene, FieldShowsTheSpheresPatchesAndInterpolatesItsVertices) {
    Scene scene;
    scene.shapes.of<Sphere>().push_back({Vec3(1.0f, 2.0f, 0.0f), 0.5f, 0});
    std::vector<Material> materials(1);
    RadiosityField field(scene, materials, 0.25f);
    const std::vector<RadiosityPatch>& patches = field.patches();
    // 2π·0.5/0.25 → 13 around (at least 16), π·0.5/0.25 → 7 along (at least 8), less the
    // collapsed halves of the cells at the poles; outside, then inside (two-sided).
    const size_t outside = 2u * 16u * 8u - 2u * 16u;
    ASSERT_EQ(patches.size(), 2u * outside);
    ASSERT_EQ(field.back_patch_count(), outside);
    SurfaceHit hit;
    hit.shape = Shapes::index_of<Sphere>();
    hit.primitive = 0;
    // Every patch's B: red its centroid's height above the sphere's centre, green its index.
    // The smooth view interpolates the height (within the patches' size: the vertex averages
    // lie below the surface near the poles), the flat one shows the index of the patch that
    // holds the hit.
    std::vector<DVec3> b(patches.size());
    for (size_t i = 0; i < patches.size(); ++i) {
        const Vec3 c =
            (patches[i].vertices[0] + patches[i].vertices[1] + patches[i].vertices[2]) / 3.0f;
        b[i] = DVec3(c.y - 2.0f, static_cast<double>(i), 0.0);
    }
    field.set_solution(b);
    Vec3 r;
    for (float theta : {0.3f, 1.0f, 1.6f, 2.5f}) {
        for (float phi : {0.2f, 2.0f, 4.0f}) {
            const Vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                         std::sin(theta) * std::sin(phi));
            hit.position = Vec3(1.0f, 2.0f, 0.0f) + 0.5f * n;
            field.set_flat(false);
            ASSERT_TRUE(field.reflected(hit, true, r));
            EXPECT_NEAR(r.x, 0.5f * n.y, 0.06f);  // the patches' height differences: 0.19
            field.set_flat(true);
            ASSERT_TRUE(field.reflected(hit, true, r));
            // The patch whose index came back holds the hit's radial projection (to 0.02 rad:
            // the grid's rows are small circles, the patches' edges chords).
            const auto holder = static_cast<size_t>(r.y);
            ASSERT_LT(holder, patches.size());
            const RadiosityPatch& patch = patches[holder];
            const Vec3 o(1.0f, 2.0f, 0.0f);
            for (int e = 0; e < 3; ++e) {
                const Vec3 a = patch.vertices[e] - o, c = patch.vertices[(e + 1) % 3] - o;
                EXPECT_GE(glm::dot(glm::normalize(glm::cross(a, c)), n), -0.02f)
                    << "theta " << theta << " phi " << phi;
            }
        }
    }
}

}  // namespace
}  // namespace rayo
