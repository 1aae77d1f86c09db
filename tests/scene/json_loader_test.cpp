// Tests of the native JSON scene reader (apps/scene/json_loader.h): every field parsed to its exact
// value, the documented defaults, each error with its JSON pointer, comments, and the examples.
#include "apps/scene/json_loader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <variant>

#include "core/error.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec3;

SceneDescription load(const std::string& text, const std::string& base_dir = "") {
    return load_json_string(text, "scene.json", base_dir);
}

// Loads `text`, expecting an InputError; returns it for inspection.
InputError load_error(const std::string& text, const std::string& base_dir = "") {
    try {
        load(text, base_dir);
    } catch (const InputError& error) {
        return error;
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return InputError("", "");
}

// A scene with one object: `object` is its JSON text.
std::string with_object(const std::string& object, const std::string& extra = "") {
    return R"({"rayo": 1, )" + extra + R"("objects": [)" + object + "]}";
}

class TempDir {
  public:
    TempDir() {
        m_path =
            std::filesystem::temp_directory_path() /
            ("rayo_json_test_" + std::to_string(::getpid()) + "_" + std::to_string(s_counter++));
        std::filesystem::create_directories(m_path);
    }
    ~TempDir() { std::filesystem::remove_all(m_path); }
    std::string path() const { return m_path.string(); }
    std::string write(const std::string& name, const std::string& text) const {
        const auto file = m_path / name;
        std::ofstream(file, std::ios::binary) << text;
        return file.string();
    }

  private:
    std::filesystem::path m_path;
    static inline int s_counter = 0;
};

const char* const kOctahedronObj =
    "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
    "f 1 3 5\nf 5 3 2\nf 2 3 6\nf 6 3 1\nf 5 4 1\nf 2 4 5\nf 6 4 2\nf 1 4 6\n";

TEST(JsonLoaderCamera, ProjectionLensAndAntialiasingFields) {
    const SceneDescription thin_lens = load(R"({"rayo": 1,
      "camera": {"eye": [0, 0, 9], "lens_radius": 0.25, "focus_distance": 6.5},
      "render": {"aa": "adaptive", "aa_threshold": 0.05, "aa_depth": 5}})");
    EXPECT_EQ(thin_lens.scene.camera.projection, Projection::Perspective);
    EXPECT_EQ(thin_lens.scene.camera.lens_radius, 0.25f);
    EXPECT_EQ(thin_lens.scene.camera.focus_distance.value(), 6.5f);
    EXPECT_EQ(thin_lens.scene.camera.vfov_degrees.value(), 45.0f);
    EXPECT_EQ(thin_lens.settings.aa, AntiAliasing::Adaptive);
    EXPECT_EQ(thin_lens.settings.adaptive.threshold, 0.05f);
    EXPECT_EQ(thin_lens.settings.adaptive.depth, 5);

    const SceneDescription fisheye =
        load(R"({"rayo": 1, "camera": {"projection": "fisheye", "fov": 220}})");
    EXPECT_EQ(fisheye.scene.camera.projection, Projection::Fisheye);
    EXPECT_EQ(fisheye.scene.camera.fisheye_fov_degrees, 220.0f);
    EXPECT_FALSE(fisheye.scene.camera.vfov_degrees);  // no perspective default
    EXPECT_EQ(load(R"({"rayo": 1, "camera": {"projection": "fisheye"}})")
                  .scene.camera.fisheye_fov_degrees,
              180.0f);
    EXPECT_EQ(load(R"({"rayo": 1, "camera": {"projection": "spherical"}})").scene.camera.projection,
              Projection::Spherical);

    // Defaults: a pinhole, focused at look_at, stratified antialiasing.
    const SceneDescription plain = load(R"({"rayo": 1})");
    EXPECT_EQ(plain.scene.camera.lens_radius, 0.0f);
    EXPECT_FALSE(plain.scene.camera.focus_distance);
    EXPECT_EQ(plain.settings.aa, AntiAliasing::Stratified);
    EXPECT_EQ(plain.settings.adaptive.threshold, 0.3f);
    EXPECT_EQ(plain.settings.adaptive.depth, 3);
}

TEST(JsonLoaderFull, EveryFieldParsedToExactValues) {
    const std::string text = R"({
      "rayo": 1,
      "camera": { "eye": [1, 2, 3], "look_at": [0, 0.5, -1], "up": [0, 2, 0], "distance": 2,
                  "hfov": 50, "vfov": 30, "width": 320, "height": 200 },
      "render": { "spp": 4, "max_depth": 7, "min_contribution": 0.25, "tile_size": 32,
                  "sphere_math": "seed" },
      "background": [0.1, 0.2, 0.3],
      "ambient_light": 0.5,
      "materials": {
        "default": { "kd": 0.5 },
        "shiny": { "ka": [0.01, 0.02, 0.03], "kd": [0.4, 0.5, 0.6], "ks": [0.7, 0.8, 0.9],
                   "shininess": 100, "specular": "blinn", "reflect": 0.25,
                   "transmit": [0.5, 0.25, 0.125], "ior": 1.5 }
      },
      "lights": [
        { "type": "point", "position": [4, 5, 6], "color": [1, 0.5, 0.25], "intensity": 2,
          "attenuation": { "type": "linear", "d0": 0.5 } },
        { "type": "point", "position": [0, 9, 0],
          "attenuation": { "type": "quadratic", "a0": 0.5, "a1": 0.25, "a2": 0.125 } },
        { "type": "directional", "direction": [0, -2, 0], "color": 0.5, "intensity": 3 }
      ],
      "objects": [
        { "type": "sphere", "center": [1, 2, 3], "radius": 0.5, "material": "shiny" },
        { "type": "cone", "base": [0, 0, 0], "base_radius": 1, "apex": [0, 2, 0],
          "apex_radius": 0.25 },
        { "type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": "shiny" },
        { "type": "polygon", "vertices": [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
          "normals": [[0, 0, 2], [0, 0, 1], [0, 0, 1], [0, 0, 1]] }
      ]
    })";
    const SceneDescription d = load(text);
    EXPECT_EQ(d.source, "scene.json");
    const CameraDesc& c = d.scene.camera;
    expect_vec3(c.eye, 1, 2, 3, 0);
    expect_vec3(c.look_at, 0, 0.5f, -1, 0);
    expect_vec3(c.up, 0, 1, 0, 0);  // normalized
    EXPECT_EQ(c.distance, 2.0f);
    EXPECT_EQ(c.hfov_degrees.value(), 50.0f);
    EXPECT_EQ(c.vfov_degrees.value(), 30.0f);
    EXPECT_EQ(c.width, 320);
    EXPECT_EQ(c.height, 200);

    EXPECT_EQ(d.settings.spp, 4);
    EXPECT_EQ(d.settings.whitted().max_depth, 7);
    EXPECT_EQ(d.settings.whitted().min_contribution, 0.25f);
    EXPECT_EQ(d.settings.tile_size, 32);
    EXPECT_EQ(d.settings.sphere_math, SphereMath::Seed);

    expect_vec3(d.shading.background, 0.1f, 0.2f, 0.3f, 0);
    expect_vec3(d.shading.ambient_light, 0.5f, 0.5f, 0.5f, 0);

    ASSERT_EQ(d.shading.materials.size(), 2u);
    const Material& def = d.shading.materials[0];
    EXPECT_EQ(def.name, "default");
    expect_vec3(def.kd, 0.5f, 0.5f, 0.5f, 0);
    expect_vec3(def.ka, 0.05f, 0.05f, 0.05f, 1e-7f);  // 0.1 × kd
    const Material& m = d.shading.materials[1];
    EXPECT_EQ(m.name, "shiny");
    expect_vec3(m.ka, 0.01f, 0.02f, 0.03f, 0);
    expect_vec3(m.kd, 0.4f, 0.5f, 0.6f, 0);
    expect_vec3(m.ks, 0.7f, 0.8f, 0.9f, 0);
    EXPECT_EQ(m.shininess, 100.0f);
    EXPECT_EQ(m.specular_model, SpecularModel::Blinn);
    expect_vec3(m.reflect, 0.25f, 0.25f, 0.25f, 0);
    expect_vec3(m.transmit, 0.5f, 0.25f, 0.125f, 0);
    EXPECT_EQ(m.ior, 1.5f);

    ASSERT_EQ(d.shading.lights.size(), 3u);
    const auto& p0 = std::get<PointLight>(d.shading.lights[0]);
    expect_vec3(p0.position, 4, 5, 6, 0);
    expect_vec3(p0.color, 1, 0.5f, 0.25f, 0);
    EXPECT_EQ(p0.intensity, 2.0f);
    EXPECT_EQ(p0.attenuation.kind, Attenuation::Kind::Linear);
    EXPECT_EQ(p0.attenuation.d0, 0.5f);
    const auto& p1 = std::get<PointLight>(d.shading.lights[1]);
    EXPECT_EQ(p1.attenuation.kind, Attenuation::Kind::Quadratic);
    EXPECT_EQ(p1.attenuation.a0, 0.5f);
    EXPECT_EQ(p1.attenuation.a1, 0.25f);
    EXPECT_EQ(p1.attenuation.a2, 0.125f);
    expect_vec3(p1.color, 1, 1, 1, 0);
    EXPECT_EQ(p1.intensity, 1.0f);
    const auto& sun = std::get<DirectionalLight>(d.shading.lights[2]);
    expect_vec3(sun.direction, 0, -1, 0, 0);
    expect_vec3(sun.color, 0.5f, 0.5f, 0.5f, 0);
    EXPECT_EQ(sun.intensity, 3.0f);

    ASSERT_EQ(d.scene.shapes.of<Sphere>().size(), 1u);
    expect_vec3(d.scene.shapes.of<Sphere>()[0].center, 1, 2, 3, 0);
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[0].radius, 0.5f);
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[0].material, 1u);
    ASSERT_EQ(d.scene.shapes.of<Cone>().size(), 1u);
    expect_vec3(d.scene.shapes.of<Cone>()[0].base, 0, 0, 0, 0);
    EXPECT_EQ(d.scene.shapes.of<Cone>()[0].base_radius, 1.0f);
    expect_vec3(d.scene.shapes.of<Cone>()[0].apex, 0, 2, 0, 0);
    EXPECT_EQ(d.scene.shapes.of<Cone>()[0].apex_radius, 0.25f);
    EXPECT_EQ(d.scene.shapes.of<Cone>()[0].material, 0u);

    // The triangle and the quad (two triangles) share one mesh.
    ASSERT_EQ(d.scene.meshes.size(), 1u);
    const TriangleMesh& polygons = d.scene.meshes[0];
    ASSERT_EQ(polygons.triangle_count(), 3u);
    EXPECT_EQ(polygons.materials[0], 1u);
    EXPECT_EQ(polygons.materials[1], 0u);
    EXPECT_EQ(polygons.materials[2], 0u);
    ASSERT_EQ(polygons.normals.size(), polygons.positions.size());
    expect_vec3(polygons.normals[3], 0, 0, 1, 0);  // first quad normal, normalized from [0, 0, 2]
    expect_vec3(polygons.positions[5], 1, 1, 1, 0);
}

TEST(JsonLoaderDefaults, MinimalSceneGetsDocumentedDefaults) {
    const SceneDescription d = load(R"({"rayo": 1})");
    const CameraDesc& c = d.scene.camera;
    expect_vec3(c.eye, 0, 0, 5, 0);
    expect_vec3(c.look_at, 0, 0, 0, 0);
    expect_vec3(c.up, 0, 1, 0, 0);
    EXPECT_EQ(c.distance, 1.0f);
    EXPECT_FALSE(c.hfov_degrees.has_value());
    EXPECT_EQ(c.vfov_degrees.value(), 45.0f);
    EXPECT_EQ(c.width, 640);
    EXPECT_EQ(c.height, 480);
    EXPECT_EQ(d.settings.spp, 1);
    EXPECT_EQ(d.settings.whitted().max_depth, 5);
    EXPECT_EQ(d.settings.whitted().min_contribution, 1e-3f);
    EXPECT_EQ(d.settings.tile_size, 64);
    EXPECT_EQ(d.settings.sphere_math, SphereMath::Stable);
    expect_vec3(d.shading.background, 0, 0, 0, 0);
    expect_vec3(d.shading.ambient_light, 1, 1, 1, 0);
    ASSERT_EQ(d.shading.materials.size(), 1u);
    EXPECT_EQ(d.shading.materials[0].name, "default");
    expect_vec3(d.shading.materials[0].kd, 0.8f, 0.8f, 0.8f, 0);
    EXPECT_TRUE(d.shading.lights.empty());
    EXPECT_TRUE(d.scene.shapes.of<Sphere>().empty());
    EXPECT_TRUE(d.scene.meshes.empty());
}

TEST(JsonLoaderDefaults, MaterialAndLightDefaults) {
    const SceneDescription d = load(R"({"rayo": 1,
        "materials": { "m": { "kd": [0.2, 0.4, 0.6] } },
        "lights": [ { "type": "point", "position": [0, 1, 0] },
                    { "type": "directional", "direction": [3, 0, 4] } ],
        "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1 } ]})");
    const Material& m = d.shading.materials.at(1);
    expect_vec3(m.ka, 0.02f, 0.04f, 0.06f, 1e-7f);  // 0.1 × kd
    expect_vec3(m.ks, 0, 0, 0, 0);
    EXPECT_EQ(m.shininess, 32.0f);
    EXPECT_EQ(m.specular_model, SpecularModel::Phong);
    expect_vec3(m.reflect, 0, 0, 0, 0);
    expect_vec3(m.transmit, 0, 0, 0, 0);
    EXPECT_EQ(m.ior, 1.0f);
    EXPECT_TRUE(m.double_sided);
    EXPECT_FALSE(load(R"({"rayo": 1, "materials": {"m": {"double_sided": false}}})")
                     .shading.materials.at(1)
                     .double_sided);
    const auto& point = std::get<PointLight>(d.shading.lights[0]);
    EXPECT_EQ(point.attenuation.kind, Attenuation::Kind::None);
    expect_vec3(point.color, 1, 1, 1, 0);
    const auto& sun = std::get<DirectionalLight>(d.shading.lights[1]);
    expect_vec3(sun.direction, 0.6f, 0, 0.8f, 1e-7f);
    EXPECT_EQ(d.scene.shapes.of<Sphere>().at(0).material, 0u);  // no material: "default"
}

TEST(JsonLoaderComments, LineAndBlockCommentsAccepted) {
    const SceneDescription d = load(R"(// a scene
    {
      "rayo": 1, /* version */
      "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 2 } ] // one sphere
    })");
    ASSERT_EQ(d.scene.shapes.of<Sphere>().size(), 1u);
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[0].radius, 2.0f);
}

struct ErrorCase {
    const char* name;
    std::string text;
    std::string where;
    std::string message_part;
};

// Printed by ctest's test list instead of the struct's raw bytes.
void PrintTo(const ErrorCase& c, std::ostream* os) {
    *os << c.name;
}

class JsonLoaderErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(JsonLoaderErrors, NamesPointerAndExpectation) {
    const ErrorCase& c = GetParam();
    const InputError error = load_error(c.text);
    EXPECT_EQ(error.where(), c.where);
    EXPECT_NE(error.message().find(c.message_part), std::string::npos)
        << "message: " << error.message();
}

const std::string kSphere = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})";

INSTANTIATE_TEST_SUITE_P(
    Pointers, JsonLoaderErrors,
    ::testing::Values(
        ErrorCase{"MissingVersion", R"({"objects": []})", "scene.json#/rayo",
                  "missing required field"},
        ErrorCase{"WrongVersion", R"({"rayo": 2})", "scene.json#/rayo", "expected 1, got 2"},
        ErrorCase{"BadSphereMethod", R"({"rayo": 1, "render": {"sphere_method": "mesh:99"}})",
                  "scene.json#/render/sphere_method", "expected one of \"auto\""},
        ErrorCase{"TopLevelNotObject", R"([1, 2])", "scene.json#", "expected a JSON object"},
        ErrorCase{"UnknownTopLevelKey", R"({"rayo": 1, "lihgts": []})", "scene.json#/lihgts",
                  "unknown key \"lihgts\""},
        ErrorCase{
            "NegativeRadius",
            with_object(kSphere + R"(, {"type": "sphere", "center": [0, 0, 0], "radius": -1})"),
            "scene.json#/objects/1/radius", "expected a number > 0, got -1"},
        ErrorCase{"ZeroRadius",
                  with_object(R"({"type": "sphere", "center": [0,0,0], "radius": 0})"),
                  "scene.json#/objects/0/radius", "expected a number > 0, got 0"},
        ErrorCase{"RadiusOverflowsFloat",
                  with_object(R"({"type": "sphere", "center": [0,0,0], "radius": 1e39})"),
                  "scene.json#/objects/0/radius", "fits a float"},
        ErrorCase{"RadiusWrongType",
                  with_object(R"({"type": "sphere", "center": [0,0,0], "radius": "big"})"),
                  "scene.json#/objects/0/radius", "expected a number > 0, got the string"},
        ErrorCase{"MissingRadius", with_object(R"({"type": "sphere", "center": [0,0,0]})"),
                  "scene.json#/objects/0/radius", "missing required field \"radius\""},
        ErrorCase{"CenterWrongLength",
                  with_object(R"({"type": "sphere", "center": [0, 0], "radius": 1})"),
                  "scene.json#/objects/0/center", "expected an array of 3 numbers"},
        ErrorCase{"CenterElementWrongType",
                  with_object(R"({"type": "sphere", "center": [0, null, 0], "radius": 1})"),
                  "scene.json#/objects/0/center/1", "expected a number, got null"},
        ErrorCase{"UnknownObjectKey",
                  with_object(R"({"type": "sphere", "center": [0,0,0], "radius": 1, "radus": 2})"),
                  "scene.json#/objects/0/radus", "unknown key \"radus\""},
        ErrorCase{"UnknownObjectType", with_object(R"({"type": "torus"})"),
                  "scene.json#/objects/0/type", "expected one of"},
        ErrorCase{"MissingObjectType", with_object(R"({"center": [0,0,0]})"),
                  "scene.json#/objects/0/type", "missing required field \"type\""},
        ErrorCase{"UnknownMaterial",
                  with_object(R"({"type": "sphere", "center": [0,0,0], "radius": 1,
                                  "material": "gold"})"),
                  "scene.json#/objects/0/material", "unknown material \"gold\""},
        ErrorCase{"ZeroLengthDirection",
                  R"({"rayo": 1, "lights": [{"type": "directional", "direction": [0, 0, 0]}]})",
                  "scene.json#/lights/0/direction", "non-zero direction"},
        ErrorCase{"MissingLightPosition", R"({"rayo": 1, "lights": [{"type": "point"}]})",
                  "scene.json#/lights/0/position", "missing required field \"position\""},
        ErrorCase{"AttenuationKeyOfOtherType",
                  R"({"rayo": 1, "lights": [{"type": "point", "position": [0, 0, 0],
                      "attenuation": {"type": "linear", "a2": 1}}]})",
                  "scene.json#/lights/0/attenuation/a2", "unknown key \"a2\""},
        ErrorCase{"AllZeroQuadratic",
                  R"({"rayo": 1, "lights": [{"type": "point", "position": [0, 0, 0],
                      "attenuation": {"type": "quadratic", "a0": 0}}]})",
                  "scene.json#/lights/0/attenuation", "at least one of a0, a1, a2"},
        ErrorCase{"NegativeColour", R"({"rayo": 1, "background": [0, -0.5, 0]})",
                  "scene.json#/background/1", "expected a number >= 0, got -0.5"},
        ErrorCase{"ColourWrongLength", R"({"rayo": 1, "ambient_light": [1, 1]})",
                  "scene.json#/ambient_light", "expected a colour"},
        ErrorCase{"MaterialBadSpecular",
                  R"({"rayo": 1, "materials": {"m": {"specular": "blink"}}})",
                  "scene.json#/materials/m/specular", "\"phong\", \"blinn\""},
        ErrorCase{"MaterialKeyWithSlash", R"({"rayo": 1, "materials": {"a/b": {"kd": "x"}}})",
                  "scene.json#/materials/a~1b/kd", "expected a colour"},
        ErrorCase{"NegativeIor", R"({"rayo": 1, "materials": {"m": {"ior": -1.5}}})",
                  "scene.json#/materials/m/ior", "expected a number > 0"},
        ErrorCase{"FovOutOfRange", R"({"rayo": 1, "camera": {"hfov": 180}})",
                  "scene.json#/camera/hfov", "(0, 180)"},
        ErrorCase{"WidthNotInteger", R"({"rayo": 1, "camera": {"width": 64.5}})",
                  "scene.json#/camera/width", "expected an integer in [1, 65536]"},
        ErrorCase{"WidthZero", R"({"rayo": 1, "camera": {"width": 0}})", "scene.json#/camera/width",
                  "got 0"},
        ErrorCase{"EyeEqualsLookAt", R"({"rayo": 1, "camera": {"eye": [1, 1, 1],
                                        "look_at": [1, 1, 1]}})",
                  "scene.json#/camera/look_at", "differ from eye"},
        ErrorCase{"UpParallelToView", R"({"rayo": 1, "camera": {"up": [0, 0, 1]}})",
                  "scene.json#/camera", "parallel"},
        ErrorCase{"NegativeLensRadius", R"({"rayo": 1, "camera": {"lens_radius": -0.1}})",
                  "scene.json#/camera/lens_radius", "expected a number >= 0, got -0.1"},
        ErrorCase{"LensOnFisheye",
                  R"({"rayo": 1, "camera": {"projection": "fisheye", "lens_radius": 0.1}})",
                  "scene.json#/camera/lens_radius", "perspective projection, not fisheye"},
        ErrorCase{"FocusDistanceZero", R"({"rayo": 1, "camera": {"focus_distance": 0}})",
                  "scene.json#/camera/focus_distance", "expected a number > 0, got 0"},
        ErrorCase{"UnknownProjection", R"({"rayo": 1, "camera": {"projection": "orthographic"}})",
                  "scene.json#/camera/projection",
                  "\"perspective\", \"fisheye\", \"spherical\", got the string \"orthographic\""},
        ErrorCase{"FisheyeFovZero", R"({"rayo": 1, "camera": {"projection": "fisheye", "fov": 0}})",
                  "scene.json#/camera/fov", "expected a number > 0, got 0"},
        ErrorCase{"FisheyeFovAbove360",
                  R"({"rayo": 1, "camera": {"projection": "fisheye", "fov": 361}})",
                  "scene.json#/camera/fov", "(0, 360] degrees, got 361"},
        ErrorCase{"FovOnPerspective", R"({"rayo": 1, "camera": {"fov": 60}})",
                  "scene.json#/camera/fov", "the perspective projection takes hfov or vfov"},
        ErrorCase{"FovOnSpherical", R"({"rayo": 1, "camera": {"projection": "spherical",
                                        "fov": 90}})",
                  "scene.json#/camera/fov", "always covers 360 x 180 degrees"},
        ErrorCase{"VfovOnFisheye",
                  R"({"rayo": 1, "camera": {"projection": "fisheye", "vfov": 60}})",
                  "scene.json#/camera/vfov", "the fisheye projection takes its angle from fov"},
        ErrorCase{
            "UnknownAa", R"({"rayo": 1, "render": {"aa": "fxaa"}})", "scene.json#/render/aa",
            "expected one of \"stratified\", \"adaptive\", \"corners\", got the string \"fxaa\""},
        ErrorCase{"NegativeAaThreshold", R"({"rayo": 1, "render": {"aa_threshold": -0.5}})",
                  "scene.json#/render/aa_threshold", "expected a number >= 0, got -0.5"},
        ErrorCase{"AaDepthTooLarge", R"({"rayo": 1, "render": {"aa_depth": 9}})",
                  "scene.json#/render/aa_depth", "expected an integer in [0, 8], got 9"},
        ErrorCase{"AaDepthNegative", R"({"rayo": 1, "render": {"aa_depth": -1}})",
                  "scene.json#/render/aa_depth", "expected an integer in [0, 8], got -1"},
        ErrorCase{"SppZero", R"({"rayo": 1, "render": {"spp": 0}})", "scene.json#/render/spp",
                  "expected an integer in [1,"},
        ErrorCase{"BadSphereMath", R"({"rayo": 1, "render": {"sphere_math": "fast"}})",
                  "scene.json#/render/sphere_math", "\"stable\", \"seed\", \"double\""},
        ErrorCase{"TriangleTwoVertices",
                  with_object(R"({"type": "triangle", "vertices": [[0,0,0], [1,0,0]]})"),
                  "scene.json#/objects/0/vertices", "expected an array of 3 vertices"},
        ErrorCase{"DegenerateTriangle",
                  with_object(R"({"type": "triangle", "vertices": [[0,0,0], [1,0,0], [2,0,0]]})"),
                  "scene.json#/objects/0/vertices", "non-zero area"},
        ErrorCase{"PolygonNormalsCount",
                  with_object(R"({"type": "polygon", "vertices": [[0,0,0], [1,0,0], [0,1,0]],
                                  "normals": [[0,0,1]]})"),
                  "scene.json#/objects/0/normals", "one per vertex"},
        ErrorCase{"ConeSameEnds", with_object(R"({"type": "cone", "base": [0,0,0], "base_radius": 1,
                                  "apex": [0,0,0], "apex_radius": 1})"),
                  "scene.json#/objects/0/apex", "differ from base"},
        ErrorCase{"MeshMissingFile", with_object(R"({"type": "mesh"})"),
                  "scene.json#/objects/0/file", "missing required field \"file\""},
        ErrorCase{"MeshFileNotFound",
                  with_object(R"({"type": "mesh", "file": "no_such_dir/none.obj"})"),
                  "scene.json#/objects/0/file", "'no_such_dir/none.obj'"},
        ErrorCase{"MeshUnknownExtension", with_object(R"({"type": "mesh", "file": "a.fbx"})"),
                  "scene.json#/objects/0/file", ".obj, .gltf, .glb, .ply, .stl or .off"},
        ErrorCase{"FresnelNotBoolean", R"({"rayo": 1, "materials": {"m": {"fresnel": 1}}})",
                  "scene.json#/materials/m/fresnel", "expected true or false"},
        ErrorCase{"DoubleSidedNotBoolean",
                  R"({"rayo": 1, "materials": {"m": {"double_sided": "yes"}}})",
                  "scene.json#/materials/m/double_sided", "expected true or false"},
        ErrorCase{"NegativeAbsorption",
                  R"({"rayo": 1, "materials": {"m": {"absorption": [0, -1, 0]}}})",
                  "scene.json#/materials/m/absorption/1", "expected a number >= 0, got -1"},
        ErrorCase{"NegativeTranslucency",
                  R"({"rayo": 1, "materials": {"m": {"translucency": -0.5}}})",
                  "scene.json#/materials/m/translucency", "expected a number >= 0"},
        ErrorCase{"EmissionWrongLength", R"({"rayo": 1, "materials": {"m": {"emission": [1, 1]}}})",
                  "scene.json#/materials/m/emission", "expected a colour"},
        ErrorCase{"NegativeFogDensity", R"({"rayo": 1, "fog": {"color": 1, "density": -0.1}})",
                  "scene.json#/fog/density", "expected a number >= 0, got -0.1"},
        ErrorCase{"FogWithoutDensity", R"({"rayo": 1, "fog": {"color": 1}})",
                  "scene.json#/fog/density", "missing required field \"density\""},
        ErrorCase{"FogUnknownKey", R"({"rayo": 1, "fog": {"density": 1, "colour": 1}})",
                  "scene.json#/fog/colour", "unknown key \"colour\""},
        ErrorCase{"BadShadowMode", R"({"rayo": 1, "render": {"shadows": "soft"}})",
                  "scene.json#/render/shadows", "\"opaque\", \"filtered\""},
        ErrorCase{"BadShadowTerminator", R"({"rayo": 1, "render": {"shadow_terminator": true}})",
                  "scene.json#/render/shadow_terminator", "\"offset\", \"none\""},
        ErrorCase{"AreaLightMissingShape",
                  R"({"rayo": 1, "lights": [{"type": "area", "center": [0, 0, 0]}]})",
                  "scene.json#/lights/0/shape", "missing required field \"shape\""},
        ErrorCase{"AreaLightZeroSamples",
                  R"({"rayo": 1, "lights": [{"type": "area", "shape": "sphere",
                      "center": [0, 0, 0], "radius": 1, "samples": 0}]})",
                  "scene.json#/lights/0/samples", "expected an integer in [1, 4096], got 0"},
        ErrorCase{"AreaLightAbsurdSamples",
                  R"({"rayo": 1, "lights": [{"type": "area", "shape": "sphere",
                      "center": [0, 0, 0], "radius": 1, "samples": 1000000}]})",
                  "scene.json#/lights/0/samples", "expected an integer in [1, 4096]"},
        ErrorCase{"AreaLightZeroRadius",
                  R"({"rayo": 1, "lights": [{"type": "area", "shape": "disk",
                      "center": [0, 0, 0], "normal": [0, -1, 0], "radius": 0}]})",
                  "scene.json#/lights/0/radius", "expected a number > 0, got 0"},
        ErrorCase{"AreaLightZeroNormal",
                  R"({"rayo": 1, "lights": [{"type": "area", "shape": "disk",
                      "center": [0, 0, 0], "normal": [0, 0, 0], "radius": 1}]})",
                  "scene.json#/lights/0/normal", "non-zero direction"},
        ErrorCase{"AreaLightDiskWithoutNormal",
                  R"({"rayo": 1, "lights": [{"type": "area", "shape": "disk",
                      "center": [0, 0, 0], "radius": 1}]})",
                  "scene.json#/lights/0/normal", "missing required field \"normal\""},
        ErrorCase{"AreaLightParallelEdges",
                  R"({"rayo": 1, "lights": [{"type": "area", "shape": "rectangle",
                      "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [-2, 0, 0]}]})",
                  "scene.json#/lights/0/edge2", "non-zero area"},
        ErrorCase{"AreaLightZeroEdge",
                  R"({"rayo": 1, "lights": [{"type": "area", "shape": "rectangle",
                      "corner": [0, 0, 0], "edge1": [0, 0, 0], "edge2": [0, 0, 1]}]})",
                  "scene.json#/lights/0/edge2", "non-zero area"},
        ErrorCase{"AreaLightKeyOfOtherShape",
                  R"({"rayo": 1, "lights": [{"type": "area", "shape": "sphere",
                      "center": [0, 0, 0], "radius": 1, "edge1": [1, 0, 0]}]})",
                  "scene.json#/lights/0/edge1", "unknown key \"edge1\""},
        ErrorCase{"AreaLightNegativeIntensity",
                  R"({"rayo": 1, "lights": [{"type": "area", "shape": "sphere",
                      "center": [0, 0, 0], "radius": 1, "intensity": -1}]})",
                  "scene.json#/lights/0/intensity", "expected a number >= 0"},
        ErrorCase{"ObjectsNotArray", R"({"rayo": 1, "objects": {}})", "scene.json#/objects",
                  "expected an array of objects"}),
    [](const ::testing::TestParamInfo<ErrorCase>& info) { return std::string(info.param.name); });

TEST(JsonLoaderSyntax, SyntaxErrorGivesLineAndColumn) {
    const InputError error = load_error("{\n  \"rayo\": 1,\n  \"objects\": [tru]\n}");
    EXPECT_EQ(error.where(), "scene.json:3:18");  // where reading "tru]" stopped
    EXPECT_NE(error.message().find("invalid literal"), std::string::npos) << error.message();
}

TEST(JsonLoaderSyntax, TrailingCommaGivesLineAndColumn) {
    const InputError error = load_error("{\n  \"rayo\": 1,\n}");
    EXPECT_EQ(error.where(), "scene.json:3:1");
}

TEST(JsonLoaderSyntax, InfiniteNumberRejectedWithPosition) {
    // 1e999 overflows a double: nlohmann reports it without a position; we add one.
    const InputError error = load_error("{\"rayo\": 1,\n \"background\": 1e999}");
    EXPECT_EQ(error.where(), "scene.json:2:16");
    EXPECT_NE(error.message().find("1e999"), std::string::npos) << error.message();
}

TEST(JsonLoaderSyntax, EmptyTextRejected) {
    const InputError error = load_error("");
    EXPECT_EQ(error.where(), "scene.json:1:1");
}

TEST(JsonLoaderFile, MissingSceneFileNamesPath) {
    try {
        load_json_file("/nonexistent/rayo/scene.json");
        FAIL() << "no InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.where(), "/nonexistent/rayo/scene.json");
    }
}

TEST(JsonLoaderMesh, ObjMeshTransformedWithOverrideAndSmoothing) {
    TempDir dir;
    dir.write("octa.obj", kOctahedronObj);
    const std::string scene_path = dir.write("scene.json", R"({"rayo": 1,
        "materials": { "blue": { "kd": [0, 0, 1] } },
        "objects": [
          { "type": "mesh", "file": "octa.obj", "material": "blue", "smooth": true,
            "transform": { "scale": 2, "rotate": [0, 0, 90], "translate": [10, 0, 0] } },
          { "type": "mesh", "file": "octa.obj" } ]})");
    const SceneDescription d = load_json_file(scene_path);
    ASSERT_EQ(d.scene.meshes.size(), 2u);
    const TriangleMesh& a = d.scene.meshes[0];
    ASSERT_EQ(a.triangle_count(), 8u);
    // Vertex (1,0,0): scaled to (2,0,0), rotated 90° about z to (0,2,0), moved to (10,2,0).
    expect_vec3(a.positions[0], 10, 2, 0, 1e-5f);
    for (uint32_t id : a.materials) EXPECT_EQ(id, 1u);  // the override
    ASSERT_EQ(a.normals.size(), a.positions.size());    // smooth: computed
    expect_vec3(a.normals[0], 0, 1, 0, 1e-5f);
    // No material in the file, no override: the scene's "default" (index 0).
    const TriangleMesh& b = d.scene.meshes[1];
    for (uint32_t id : b.materials) EXPECT_EQ(id, 0u);
    EXPECT_TRUE(b.normals.empty());
    EXPECT_EQ(d.shading.materials.size(), 2u);  // nothing appended
}

TEST(JsonLoaderMesh, DegenerateMeshTrianglesReportedAsWarnings) {
    TempDir dir;
    dir.write("some_flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n");
    const SceneDescription d =
        load(with_object(R"({"type": "mesh", "file": "some_flat.obj"})"), dir.path());
    ASSERT_EQ(d.scene.meshes.size(), 1u);
    EXPECT_EQ(d.scene.meshes[0].triangle_count(), 1u);
    EXPECT_EQ(d.skipped_triangles, 1u);
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_EQ(d.warnings[0].rfind("scene.json#/objects/0/file: dropped 1 degenerate", 0), 0u)
        << d.warnings[0];
}

TEST(JsonLoaderMesh, ZeroScaleRejected) {
    TempDir dir;
    dir.write("octa.obj", kOctahedronObj);
    const InputError error = load_error(
        with_object(R"({"type": "mesh", "file": "octa.obj", "transform": {"scale": [1, 0, 1]}})"),
        dir.path());
    EXPECT_EQ(error.where(), "scene.json#/objects/0/transform/scale");
}

TEST(JsonLoaderMesh, MeshWithoutTrianglesRejectedAtFilePointer) {
    TempDir dir;
    dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");  // one degenerate face
    const InputError error =
        load_error(with_object(R"({"type": "mesh", "file": "flat.obj"})"), dir.path());
    EXPECT_EQ(error.where(), "scene.json#/objects/0/file");
    EXPECT_NE(error.message().find("flat.obj"), std::string::npos) << error.message();
}

TEST(JsonLoaderExamples, AllScenesLoad) {
    const std::filesystem::path dir(RAYO_SCENES_DIR);
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        SceneDescription d;
        ASSERT_NO_THROW(d = load_json_file(entry.path().string()));
        EXPECT_FALSE(d.shading.lights.empty());
        EXPECT_GT(d.scene.shapes.size() + d.scene.triangle_count(), 0u);
        // Small enough to render in a moment: 320 × 240, or as many pixels in the shape the
        // camera needs (a square fisheye, a 2:1 panorama).
        EXPECT_LE(d.scene.camera.width * d.scene.camera.height, 320 * 240);
        EXPECT_LE(d.scene.camera.width, 320);
        ++count;
    }
    EXPECT_GE(count, 7);
}

TEST(JsonLoaderExamples, MeshExamplesCarryTheirMaterials) {
    const SceneDescription obj = load_json_file(std::string(RAYO_SCENES_DIR) + "/mesh_obj.json");
    bool gold = false;
    for (const Material& m : obj.shading.materials) {
        if (m.name == "gold_mirror") {
            gold = true;
            expect_vec3(m.reflect, 0.6f, 0.5f, 0.2f, 0);  // illum 3: reflect = Ks
        }
    }
    EXPECT_TRUE(gold);
    const SceneDescription gltf = load_json_file(std::string(RAYO_SCENES_DIR) + "/mesh_gltf.json");
    ASSERT_EQ(gltf.scene.meshes.size(), 2u);  // the pyramid, then the floor polygon
    EXPECT_EQ(gltf.scene.meshes[0].triangle_count(), 6u);
    EXPECT_EQ(gltf.scene.meshes[1].name, "polygons");
}

}  // namespace
}  // namespace rayo
