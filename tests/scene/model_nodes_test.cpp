// What a model file brings besides its triangles (apps/scene/model_scene.h, gltf_nodes.h): glTF
// cameras (the node's transform, yfov, aspectRatio; --camera by name and index, an unknown one
// listing the file's cameras), KHR_lights_punctual lights on the side they face, emissive
// triangles as an area light (the Cornell box lit by its own light), and meshes that several
// nodes use rendered as instances, the same image as flattened.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "apps/scene/model_scene.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "tests/scene/gltf_test_writer.h"

namespace rayo {
namespace {

using nlohmann::json;

// A glTF file written by the test: meshes of quads and boxes in one data-URI buffer; nodes,
// cameras and lights added as JSON.
struct GltfWriter {
    rayo_test::GltfTestWriter g;

    // A mesh of the given corner positions and triangles, with one material.
    int mesh(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices,
             int material) {
        std::vector<float> xyz;
        for (const Vec3& v : positions) xyz.insert(xyz.end(), {v.x, v.y, v.z});
        const int position = g.positions(xyz);
        const int index = g.indices(indices, 5125);
        return g.mesh(
            {{"attributes", {{"POSITION", position}}}, {"indices", index}, {"material", material}});
    }
    // A square of side 2·half in the plane z = 0, facing +z (counter-clockwise seen from +z).
    int quad(float half, int material) {
        return mesh({{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}},
                    {0, 1, 2, 0, 2, 3}, material);
    }
    int material(const Vec3& base, const Vec3& emissive = Vec3(0.0f)) {
        return g.push("materials", {{"pbrMetallicRoughness",
                                     {{"baseColorFactor", {base.x, base.y, base.z, 1.0}},
                                      {"metallicFactor", 0.0},
                                      {"roughnessFactor", 1.0}}},
                                    {"emissiveFactor", {emissive.x, emissive.y, emissive.z}}});
    }
    int node(json n, bool root_node = true) { return g.node(std::move(n), root_node); }
    int camera(const std::string& name, double yfov, double aspect) {
        return g.push("cameras", {{"name", name},
                                  {"type", "perspective"},
                                  {"perspective",
                                   {{"yfov", yfov}, {"aspectRatio", aspect}, {"znear", 0.01}}}});
    }
    int light(json l) {
        json& lights = g.doc()["extensions"]["KHR_lights_punctual"]["lights"];
        lights.push_back(std::move(l));
        g.doc()["extensionsUsed"] = {"KHR_lights_punctual"};
        return static_cast<int>(lights.size()) - 1;
    }
    std::string write(const std::string& name) const {
        return g.write_embedded((std::filesystem::temp_directory_path() /
                                 ("rayo_nodes_" + std::to_string(::getpid()) + "_" + name))
                                    .string());
    }
};

json light_node(int light, const json& transform = json::object()) {
    json n = transform;
    n["extensions"]["KHR_lights_punctual"]["light"] = light;
    return n;
}

// glTF quaternion (x, y, z, w) of a rotation by `degrees` about the unit `axis`.
json rotation(const Vec3& axis, float degrees) {
    const float h = glm::radians(0.5f * degrees);
    return {axis.x * std::sin(h), axis.y * std::sin(h), axis.z * std::sin(h), std::cos(h)};
}

SceneDescription load(const std::string& path, ModelFraming framing = {}) {
    framing.ground = false;
    SceneDescription d = load_model_scene(path, framing);
    std::filesystem::remove(path);
    return d;
}

float luminance(const Vec3& c) {
    return c.x + c.y + c.z;
}

// The camera of a node under a rotated, translated parent: the quad of half-side 0.5 seen
// head-on from distance 2 with yfov = 2·atan(1/2) spans exactly the middle half of the rows
// and (aspect 1) of the columns: of 32 × 32 pixel centres, the middle 16 × 16 see it.
TEST(ModelNodes, CameraOfANodeFramesTheQuadAsItsTransformSays) {
    GltfWriter g;
    // The quad faces +x: turned 90° about y, at the origin.
    g.node({{"mesh", g.quad(0.5f, g.material(Vec3(0.8f)))}, {"rotation", rotation({0, 1, 0}, 90)}});
    // The camera: 2 along +x, turned to look down −x (its −z), through a parent's transform.
    const int camera = g.node({{"camera", g.camera("side", 2.0 * std::atan(0.5), 1.0)},
                               {"rotation", rotation({0, 1, 0}, 90)}},
                              false);
    g.node({{"translation", {2.0, 0.0, 0.0}}, {"children", {camera}}});
    SceneDescription d = load(g.write("camera.gltf"));
    ASSERT_EQ(d.file_cameras.size(), 1u);
    EXPECT_EQ(d.scene.camera.width, 480);  // aspectRatio 1: 480 × 480
    EXPECT_EQ(d.scene.camera.height, 480);
    d.scene.camera.width = d.scene.camera.height = 32;
    const Camera camera_model = Camera::create(d.scene.camera, "test");
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const Ray ray = camera_model.generate_ray(static_cast<float>(x), static_cast<float>(y));
            // The plane x = 0: where the ray meets it.
            const float t = -ray.origin.x / ray.direction.x;
            const Vec3 p = ray.origin + t * ray.direction;
            const bool on_quad = t > 0.0f && std::abs(p.y) < 0.5f && std::abs(p.z) < 0.5f;
            EXPECT_EQ(on_quad, x >= 8 && x < 24 && y >= 8 && y < 24) << x << "," << y;
            if (x == 16 && y == 0) {
                EXPECT_GT(p.y, 0.0f);  // row 0 is the top (+y)
            }
            if (x == 0 && y == 16) {
                EXPECT_GT(p.z, 0.0f);  // column 0 is the left (+z, seen from +x)
            }
        }
    }
    // The other aspect: the output's width follows aspectRatio, yfov stays.
    GltfWriter wide;
    wide.node({{"mesh", wide.quad(0.5f, wide.material(Vec3(0.8f)))}});
    wide.node({{"camera", wide.camera("wide", 0.5, 2.0)}, {"translation", {0.0, 0.0, 3.0}}});
    const SceneDescription w = load(wide.write("wide.gltf"));
    EXPECT_EQ(w.scene.camera.width, 960);
    EXPECT_NEAR(*w.scene.camera.vfov_degrees, glm::degrees(0.5f), 1e-4f);
    EXPECT_FALSE(w.scene.camera.hfov_degrees);
}

GltfWriter two_cameras() {
    GltfWriter g;
    g.node({{"mesh", g.quad(0.5f, g.material(Vec3(0.8f)))}});
    g.node({{"camera", g.camera("front", 0.6, 1.0)}, {"translation", {0.0, 0.0, 3.0}}});
    g.node({{"camera", g.camera("", 0.6, 1.0)}, {"name", "high"}, {"translation", {0, 0, 4}}});
    return g;
}

TEST(ModelNodes, CameraChosenByNameOrIndexAndAnUnknownOneListsThem) {
    // Default: the first camera.
    EXPECT_EQ(load(two_cameras().write("c0.gltf")).scene.camera.eye, Vec3(0, 0, 3));
    ModelFraming framing;
    framing.camera = "high";  // the node's name (the camera has none)
    EXPECT_EQ(load(two_cameras().write("c1.gltf"), framing).scene.camera.eye, Vec3(0, 0, 4));
    framing.camera = "1";
    EXPECT_EQ(load(two_cameras().write("c2.gltf"), framing).scene.camera.eye, Vec3(0, 0, 4));
    framing.camera = "front";
    EXPECT_EQ(load(two_cameras().write("c3.gltf"), framing).scene.camera.eye, Vec3(0, 0, 3));
    framing.camera = "auto";  // the automatic framing: on the default direction
    const SceneDescription automatic = load(two_cameras().write("c4.gltf"), framing);
    EXPECT_GT(automatic.scene.camera.eye.x, 0.0f);
    for (const std::string bad : {"2", "back", ""}) {
        framing.camera = bad;
        const std::string path = two_cameras().write("c5.gltf");
        try {
            load_model_scene(path, framing);
            ADD_FAILURE() << "expected an InputError for --camera '" << bad << "'";
        } catch (const InputError& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("no camera '" + bad + "'"), std::string::npos) << m;
            EXPECT_NE(m.find("0 'front', 1 'high'"), std::string::npos) << m;
        }
        std::filesystem::remove(path);
    }
}

// Renders `d` at 32 × 32 (the camera's aspect) with one thread.
Film render_small(SceneDescription d) {
    d.scene.camera.width = d.scene.camera.height = 32;
    // The lights' diffuse part alone: no ambient term, no highlight (glTF's dielectric F0 0.04).
    d.shading.ambient_light = Vec3(0.0f);
    for (Material& m : d.shading.materials) m.ks = Vec3(0.0f);
    return render_scene(d, 1, false).film;
}

// A quad facing +z seen head-on; lights from the file light its front, on the side they are.
GltfWriter lit_quad() {
    GltfWriter g;
    g.node({{"mesh", g.quad(1.0f, g.material(Vec3(1.0f)))}});
    g.node({{"camera", g.camera("front", 2.0 * std::atan(0.5), 1.0)},
            {"translation", {0.0, 0.0, 2.0}}});
    return g;
}

TEST(ModelNodes, PunctualLightsLightTheSideTheyFace) {
    // A point light 1 above the quad's right half (x = 0.5): I = π candela gives the quad
    // under it the irradiance E = I/d² = π, so the radiance kd·E/π = 1 there; the far left
    // gets less (inverse square and cosine).
    GltfWriter point = lit_quad();
    point.node(light_node(point.light({{"type", "point"}, {"intensity", kPi}}),
                          {{"translation", {0.5, 0.0, 1.0}}}));
    SceneDescription pd = load(point.write("point.gltf"));
    ASSERT_EQ(pd.shading.lights.size(), 1u);  // no automatic key and fill
    EXPECT_EQ(pd.light_names, std::vector<std::string>{"light 0"});
    const Film pf = render_small(pd);
    // Pixel 24 of 32 is x = 0.5 on the quad (the image spans −1..1 across 32 pixels).
    EXPECT_NEAR(pf.rgb(24, 16).x, 1.0f, 0.02f);
    EXPECT_LT(luminance(pf.rgb(1, 16)), 0.5f * luminance(pf.rgb(30, 16)));

    // A spot light on the quad's left, aimed straight down at it with a 20° cone: the left
    // is lit, the right (outside the cone) is black.
    GltfWriter spot = lit_quad();
    spot.node(light_node(spot.light({{"type", "spot"},
                                     {"intensity", 10.0},
                                     {"spot", {{"outerConeAngle", glm::radians(20.0)}}}}),
                         {{"translation", {-0.5, 0.0, 1.0}}}));
    const Film sf = render_small(load(spot.write("spot.gltf")));
    EXPECT_GT(luminance(sf.rgb(8, 16)), 0.1f);
    EXPECT_EQ(luminance(sf.rgb(24, 16)), 0.0f);
    EXPECT_EQ(luminance(sf.rgb(8, 2)), 0.0f);

    // A directional light shining at the front (down −z, the node's own −z) lights it with
    // kd·E/π; turned 180° it shines at the back, and the front is black.
    for (const float turn : {0.0f, 180.0f}) {
        GltfWriter sun = lit_quad();
        sun.node(light_node(sun.light({{"type", "directional"}, {"intensity", kPi}}),
                            {{"rotation", rotation({0, 1, 0}, turn)}}));
        const Film f = render_small(load(sun.write("sun.gltf")));
        EXPECT_NEAR(f.rgb(16, 16).x, turn == 0.0f ? 1.0f : 0.0f, 1e-4f) << turn;
    }
}

TEST(ModelNodes, AutomaticLightsOnlyWithoutTheFilesOrWhenAsked) {
    EXPECT_EQ(load(lit_quad().write("none.gltf")).shading.lights.size(), 2u);  // key and fill
    GltfWriter point = lit_quad();
    point.node(light_node(point.light({{"type", "point"}}), {{"translation", {0, 0, 1}}}));
    ModelFraming framing;
    framing.auto_lights = true;
    const SceneDescription d = load(point.write("both.gltf"), framing);
    EXPECT_EQ(d.shading.lights.size(), 3u);
    EXPECT_EQ(d.light_names, (std::vector<std::string>{"light 0", "key", "fill"}));
}

// The Cornell box of scenes/meshes (the published geometry, its light a `Ke` material) seen
// through its open side: the floor is lit by the light alone (no automatic lights), and is
// darker in the short block's shadow than in the open.
TEST(ModelNodes, CornellBoxIsLitByItsOwnEmitterWithShadows) {
    ModelFraming framing;
    framing.ground = false;
    framing.view_direction = Vec3(0.0f, 0.0f, -1.0f);
    SceneDescription d =
        load_model_scene(std::string(RAYO_SCENES_DIR) + "/meshes/cornell_box.obj", framing);
    ASSERT_EQ(d.shading.lights.size(), 1u);
    const auto& light = std::get<AreaLight>(d.shading.lights[0]);
    ASSERT_TRUE(light.mesh);
    EXPECT_EQ(light.mesh->size(), 2u);                 // the light's two triangles
    EXPECT_NEAR(light.area(), 130.0f * 105.0f, 1.0f);  // 130 mm × 105 mm
    // Points of the floor, shaded as the integrator does through a render: a camera straight
    // above the floor point looks down at it.
    auto floor_radiance = [&](const Vec3& p) {
        SceneDescription probe = d;
        probe.scene.camera.eye = p + Vec3(0.0f, 10.0f, 0.0f);
        probe.scene.camera.look_at = p;
        probe.scene.camera.up = Vec3(0.0f, 0.0f, 1.0f);
        probe.scene.camera.vfov_degrees = 1.0f;
        probe.scene.camera.width = probe.scene.camera.height = 1;
        probe.shading.ambient_light = Vec3(0.0f);
        return render_scene(probe, 1, false).film.rgb(0, 0);
    };
    const Vec3 open = floor_radiance(Vec3(278.0f, 0.0f, 280.0f));  // under the light
    // Just behind the short block (from the light, past its edge 82..240, z 225..272).
    const Vec3 shadowed = floor_radiance(Vec3(150.0f, 0.0f, 20.0f));
    EXPECT_GT(open.x, 0.05f);
    EXPECT_GT(open.z, 0.0f);
    EXPECT_LT(luminance(shadowed), 0.5f * luminance(open));
    // The light is seen: the camera ray straight at it sees its emission.
}

// The same two quads used by three nodes: kept once and placed three times, the same image as
// the flattened meshes (to float rounding of the instance's normals).
TEST(ModelNodes, MeshesSeveralNodesUseAreInstancesThatRenderAsFlattened) {
    auto file = [] {
        GltfWriter g = lit_quad();
        const int small = g.quad(0.2f, g.material(Vec3(0.2f, 0.6f, 0.9f)));
        g.node({{"mesh", small}, {"translation", {-0.5, 0.5, 0.3}}});
        g.node({{"mesh", small}, {"translation", {0.5, 0.5, 0.3}}, {"scale", {1.5, 1.0, 1.0}}});
        g.node({{"mesh", small},
                {"translation", {0.0, -0.5, 0.3}},
                {"rotation", rotation({0, 0, 1}, 30)}});
        g.node(light_node(g.light({{"type", "point"}, {"intensity", 3.0}}),
                          {{"translation", {0.3, 0.2, 1.0}}}));
        return g;
    };
    const SceneDescription instanced = load(file().write("inst.gltf"));
    ModelFraming framing;
    framing.instances = false;
    const SceneDescription flat = load(file().write("flat.gltf"), framing);
    ASSERT_EQ(instanced.scene.groups.size(), 1u);
    EXPECT_EQ(instanced.scene.instances.size(), 3u);
    EXPECT_EQ(instanced.scene.triangle_count(), 2u);  // the big quad; the small one in its group
    EXPECT_EQ(instanced.scene.instanced_object_count(), 6u);
    EXPECT_EQ(flat.scene.triangle_count(), 8u);
    EXPECT_TRUE(flat.scene.instances.empty());
    const Film a = render_small(instanced), b = render_small(flat);
    int lit = 0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const Vec3 d = a.rgb(x, y) - b.rgb(x, y);
            EXPECT_LE(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}), 1e-4f)
                << x << "," << y;
            if (a.rgb(x, y).z > 2.0f * a.rgb(x, y).x) ++lit;  // the blue quads
        }
    }
    EXPECT_GT(lit, 20);
}

}  // namespace
}  // namespace rayo
