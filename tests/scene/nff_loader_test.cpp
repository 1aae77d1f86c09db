// Tests of the NFF reader (apps/scene/nff_loader.h): entity mapping per the reference reader's
// conventions (docs/nff.md), geometry values, and every error with its line.
#include "apps/scene/nff_loader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <variant>
#include <vector>

#include "core/camera.h"
#include "core/error.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec3;

// Joins lines with '\n', so that element i is line i + 1 of the file.
std::string lines(std::initializer_list<const char*> items) {
    std::string text;
    for (const char* item : items) {
        text += item;
        text += '\n';
    }
    return text;
}

// A valid view block: lines 1-7.
const std::string kView =
    lines({"v", "from 0 0 5", "at 0 0 0", "up 0 1 0", "angle 45", "hither 1", "resolution 64 48"});

// The loader must throw InputError whose where is exactly `where` and whose message contains
// `fragment`; what() carries both.
void expect_error(const std::string& text, const std::string& where, const std::string& fragment) {
    try {
        load_nff_string(text, "t.nff");
        ADD_FAILURE() << "no error; expected " << where << ": ..." << fragment;
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), where) << e.what();
        EXPECT_NE(e.message().find(fragment), std::string::npos)
            << "message '" << e.message() << "' lacks '" << fragment << "'";
        EXPECT_NE(std::string(e.what()).find(where + ": "), std::string::npos) << e.what();
    }
}

class TempDir {
  public:
    TempDir() {
        m_path = std::filesystem::temp_directory_path() /
                 ("rayo_nff_test_" + std::to_string(::getpid()) + "_" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(m_path);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(m_path, ignored);
    }
    std::string write(const std::string& name, const std::string& content) const {
        const std::filesystem::path file = m_path / name;
        std::ofstream out(file, std::ios::binary);
        out << content;
        return file.string();
    }
    std::string path(const std::string& name) const { return (m_path / name).string(); }

  private:
    std::filesystem::path m_path;
};

// A scene with every entity; comments and blank lines in between.
const std::string kEveryEntity = lines({
    "# every NFF entity",                // 1
    "b 0.1 0.2 0.3",                     // 2
    "v",                                 // 3
    "from 1 2 3",                        // 4
    "at 0 0 0",                          // 5
    "up 0 0 1",                          // 6
    "angle 40",                          // 7
    "hither 0.5",                        // 8
    "resolution 320 240",                // 9
    "",                                  // 10
    "l 4 5 6",                           // 11
    "l -1 -2 -3 0.5 0.25 1",             // 12
    "f 1 0.5 0.25 0.7 0.3 20 0 1",       // 13
    "s 0 0 0 1.5",                       // 14
    "c",                                 // 15
    "0 0 0 0.5",                         // 16
    "0 0 2 0.25",                        // 17
    "c 1 1 1 0.3 1 1 3 0.3",             // 18
    "p 3",                               // 19
    "0 0 0",                             // 20
    "1 0 0",                             // 21
    "0 1 0",                             // 22
    "f 0.2 0.4 0.6 0.5 0.1 5 0.8 1.5",   // 23
    "p 4",                               // 24
    "0 0 1",                             // 25
    "1 0 1",                             // 26
    "  # a comment inside the polygon",  // 27
    "1 1 1",                             // 28
    "0 1 1",                             // 29
    "pp 3",                              // 30
    "0 0 2 0 0 2",                       // 31
    "1 0 2 0 0.5 0",                     // 32
    "0 1 2 -3 0 0",                      // 33
    "s 5 5 5 0.5",                       // 34
});

TEST(NffLoader, EveryEntityCounts) {
    const SceneDescription d = load_nff_string(kEveryEntity, "every.nff");
    EXPECT_EQ(d.source, "every.nff");
    EXPECT_EQ(d.scene.shapes.of<Sphere>().size(), 2u);
    EXPECT_EQ(d.scene.shapes.of<Cone>().size(), 2u);
    ASSERT_EQ(d.scene.meshes.size(), 3u);
    EXPECT_EQ(d.scene.triangle_count(), 1u + 2u + 1u);
    EXPECT_EQ(d.shading.materials.size(), 2u);
    EXPECT_EQ(d.shading.lights.size(), 2u);
    expect_vec3(d.shading.background, 0.1f, 0.2f, 0.3f);
    expect_vec3(d.shading.ambient_light, 1.0f, 1.0f, 1.0f);
    EXPECT_EQ(d.settings.spp, 1);
    EXPECT_EQ(d.settings.whitted().max_depth, 5);
}

TEST(NffLoader, MaterialsFollowReferenceConventions) {
    const SceneDescription d = load_nff_string(kEveryEntity, "every.nff");
    ASSERT_EQ(d.shading.materials.size(), 2u);
    const Material& opaque = d.shading.materials[0];
    expect_vec3(opaque.ka, 0.1f, 0.05f, 0.025f);  // 0.1 × colour
    expect_vec3(opaque.kd, 0.7f, 0.35f, 0.175f);  // Kd × colour
    expect_vec3(opaque.ks, 0.3f, 0.3f, 0.3f);     // white highlight
    EXPECT_FLOAT_EQ(opaque.shininess, 20.0f);
    EXPECT_EQ(opaque.specular_model, SpecularModel::Phong);
    expect_vec3(opaque.reflect, 0.3f, 0.3f, 0.3f);  // mirror reflection = Ks
    expect_vec3(opaque.transmit, 0.0f, 0.0f, 0.0f);
    EXPECT_FLOAT_EQ(opaque.ior, 1.0f);
    EXPECT_FALSE(opaque.transmissive());

    const Material& glass = d.shading.materials[1];
    expect_vec3(glass.ka, 0.02f, 0.04f, 0.06f);
    expect_vec3(glass.kd, 0.1f, 0.2f, 0.3f);
    expect_vec3(glass.ks, 0.1f, 0.1f, 0.1f);
    EXPECT_FLOAT_EQ(glass.shininess, 5.0f);
    expect_vec3(glass.reflect, 0.1f, 0.1f, 0.1f);
    expect_vec3(glass.transmit, 0.8f, 0.8f, 0.8f);
    EXPECT_FLOAT_EQ(glass.ior, 1.5f);
    EXPECT_TRUE(glass.transmissive());

    // Objects carry the material of the `f` before them.
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[0].material, 0u);
    EXPECT_EQ(d.scene.shapes.of<Cone>()[0].material, 0u);
    EXPECT_EQ(d.scene.shapes.of<Cone>()[1].material, 0u);
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[1].material, 1u);
}

TEST(NffLoader, LightsArePointLightsWithOptionalColour) {
    const SceneDescription d = load_nff_string(kEveryEntity, "every.nff");
    ASSERT_EQ(d.shading.lights.size(), 2u);
    const auto* white = std::get_if<PointLight>(&d.shading.lights[0]);
    const auto* tinted = std::get_if<PointLight>(&d.shading.lights[1]);
    ASSERT_NE(white, nullptr);
    ASSERT_NE(tinted, nullptr);
    expect_vec3(white->position, 4.0f, 5.0f, 6.0f);
    expect_vec3(white->color, 1.0f, 1.0f, 1.0f);
    EXPECT_FLOAT_EQ(white->intensity, 1.0f / std::sqrt(2.0f));  // 1/sqrt(N), N = 2 lights
    EXPECT_EQ(white->attenuation.kind, Attenuation::Kind::None);
    expect_vec3(tinted->position, -1.0f, -2.0f, -3.0f);
    expect_vec3(tinted->color, 0.5f, 0.25f, 1.0f);
    EXPECT_FLOAT_EQ(tinted->intensity, 1.0f);  // a colour is used as given
    EXPECT_EQ(tinted->attenuation.kind, Attenuation::Kind::None);
}

// The SPD's light rule (docs/nff.md, "Conventions"): each of the N lights gets
// 1/sqrt(N) unless its `l` line gives a colour.
std::vector<float> light_intensities(const SceneDescription& d) {
    std::vector<float> out;
    for (const Light& light : d.shading.lights)
        out.push_back(std::get<PointLight>(light).intensity);
    return out;
}

TEST(NffLoader, UncolouredLightsGetOneOverSqrtOfTheLightCount) {
    for (int n : {1, 2, 3, 4, 7}) {
        std::string text = kView;
        for (int i = 0; i < n; ++i) text += "l " + std::to_string(i) + " 5 5\n";
        const std::vector<float> got = light_intensities(load_nff_string(text, "l.nff"));
        ASSERT_EQ(got.size(), static_cast<size_t>(n));
        for (float intensity : got) {
            EXPECT_FLOAT_EQ(intensity, 1.0f / std::sqrt(float(n))) << n << " lights";
        }
    }
    // No lights: nothing to scale, no error.
    EXPECT_TRUE(load_nff_string(kView, "none.nff").shading.lights.empty());
}

TEST(NffLoader, ColouredLightsAreUnscaledAndCountInN) {
    // Four lights, two with a colour: the two plain ones get 1/sqrt(4) = 0.5, the coloured ones
    // keep intensity 1 and their colour exactly.
    const SceneDescription d = load_nff_string(
        kView + lines({"l 0 0 9", "l 1 0 9 0.2 0.4 0.6", "l 2 0 9", "l 3 0 9 1 1 1"}), "c.nff");
    EXPECT_EQ(light_intensities(d), (std::vector<float>{0.5f, 1.0f, 0.5f, 1.0f}));
    expect_vec3(std::get<PointLight>(d.shading.lights[1]).color, 0.2f, 0.4f, 0.6f);
    expect_vec3(std::get<PointLight>(d.shading.lights[0]).color, 1.0f, 1.0f, 1.0f);
}

TEST(NffLoader, LightIntensityOptionReplacesTheFactor) {
    const std::string text = kView + lines({"l 0 0 9", "l 1 0 9 0.2 0.4 0.6", "l 2 0 9"});
    NffOptions unit;
    unit.light_intensity = 1.0f;  // unit lights, as before the SPD rule
    EXPECT_EQ(light_intensities(load_nff_string(text, "o.nff", nullptr, unit)),
              (std::vector<float>{1.0f, 1.0f, 1.0f}));
    NffOptions dim;
    dim.light_intensity = 0.25f;
    EXPECT_EQ(light_intensities(load_nff_string(text, "o.nff", nullptr, dim)),
              (std::vector<float>{0.25f, 1.0f, 0.25f}));
    NffOptions off;
    off.light_intensity = 0.0f;
    EXPECT_EQ(light_intensities(load_nff_string(text, "o.nff", nullptr, off)),
              (std::vector<float>{0.0f, 1.0f, 0.0f}));
    // The file path reaches the same code.
    TempDir dir;
    const std::string path = dir.write("o.nff", text);
    EXPECT_EQ(light_intensities(load_nff_file(path, nullptr, dim)),
              (std::vector<float>{0.25f, 1.0f, 0.25f}));
    const std::vector<float> by_default = light_intensities(load_nff_file(path));
    ASSERT_EQ(by_default.size(), 3u);
    EXPECT_FLOAT_EQ(by_default[0], 1.0f / std::sqrt(3.0f));
    EXPECT_FLOAT_EQ(by_default[1], 1.0f);
    EXPECT_FLOAT_EQ(by_default[2], 1.0f / std::sqrt(3.0f));
}

TEST(NffLoaderErrors, BadLightIntensityOptionNamesTheSource) {
    for (float bad : {-1.0f, std::nanf(""), INFINITY}) {
        NffOptions options;
        options.light_intensity = bad;
        try {
            load_nff_string(kView, "t.nff", nullptr, options);
            ADD_FAILURE() << "no error for light intensity " << bad;
        } catch (const InputError& e) {
            EXPECT_EQ(e.where(), "t.nff");
            EXPECT_NE(e.message().find("light intensity must be a finite number >= 0"),
                      std::string::npos)
                << e.message();
        }
    }
}

TEST(NffLoader, CameraFromViewBlock) {
    const SceneDescription d = load_nff_string(kEveryEntity, "every.nff");
    const CameraDesc& c = d.scene.camera;
    expect_vec3(c.eye, 1.0f, 2.0f, 3.0f);
    expect_vec3(c.look_at, 0.0f, 0.0f, 0.0f);
    expect_vec3(c.up, 0.0f, 0.0f, 1.0f);
    ASSERT_TRUE(c.vfov_degrees.has_value());
    EXPECT_FLOAT_EQ(*c.vfov_degrees, 40.0f);
    EXPECT_FALSE(c.hfov_degrees.has_value());
    EXPECT_TRUE(c.fov_spans_pixel_centres);
    EXPECT_FLOAT_EQ(c.distance, 1.0f);
    EXPECT_EQ(c.width, 320);
    EXPECT_EQ(c.height, 240);

    // `angle` is the angle between the rays through the centres of the first and last rows.
    const Camera camera = Camera::create(c);
    const float middle = (c.width - 1) / 2.0f;
    const Vec3 top = camera.generate_ray(middle, 0.0f).direction;
    const Vec3 bottom = camera.generate_ray(middle, static_cast<float>(c.height - 1)).direction;
    const double angle = std::acos(glm::dot(DVec3(top), DVec3(bottom))) * 180.0 / M_PI;
    EXPECT_NEAR(angle, 40.0, 1e-3);
}

TEST(NffLoader, SphereGeometry) {
    const SceneDescription d = load_nff_string(kEveryEntity, "every.nff");
    expect_vec3(d.scene.shapes.of<Sphere>()[0].center, 0.0f, 0.0f, 0.0f);
    EXPECT_FLOAT_EQ(d.scene.shapes.of<Sphere>()[0].radius, 1.5f);
    expect_vec3(d.scene.shapes.of<Sphere>()[1].center, 5.0f, 5.0f, 5.0f);
    EXPECT_FLOAT_EQ(d.scene.shapes.of<Sphere>()[1].radius, 0.5f);
}

TEST(NffLoader, ConeGeometryInBothForms) {
    const SceneDescription d = load_nff_string(kEveryEntity, "every.nff");
    const Cone& two_line = d.scene.shapes.of<Cone>()[0];  // `c` then base and apex lines
    expect_vec3(two_line.base, 0.0f, 0.0f, 0.0f);
    EXPECT_FLOAT_EQ(two_line.base_radius, 0.5f);
    expect_vec3(two_line.apex, 0.0f, 0.0f, 2.0f);
    EXPECT_FLOAT_EQ(two_line.apex_radius, 0.25f);
    const Cone& one_line =
        d.scene.shapes.of<Cone>()[1];  // all on the `c` line, as the SPD files write it
    expect_vec3(one_line.base, 1.0f, 1.0f, 1.0f);
    EXPECT_FLOAT_EQ(one_line.base_radius, 0.3f);
    expect_vec3(one_line.apex, 1.0f, 1.0f, 3.0f);
    EXPECT_FLOAT_EQ(one_line.apex_radius, 0.3f);
}

TEST(NffLoader, PolygonsSortedIntoSidedMeshes) {
    const SceneDescription d = load_nff_string(kEveryEntity, "every.nff");
    ASSERT_EQ(d.scene.meshes.size(), 3u);
    const TriangleMesh& opaque = d.scene.meshes[0];
    EXPECT_TRUE(opaque.one_sided);
    ASSERT_EQ(opaque.positions.size(), 3u);
    expect_vec3(opaque.positions[0], 0.0f, 0.0f, 0.0f);
    expect_vec3(opaque.positions[1], 1.0f, 0.0f, 0.0f);
    expect_vec3(opaque.positions[2], 0.0f, 1.0f, 0.0f);
    ASSERT_EQ(opaque.triangles.size(), 1u);
    EXPECT_EQ(opaque.triangles[0], (std::array<uint32_t, 3>{0, 1, 2}));  // winding kept
    EXPECT_EQ(opaque.materials, std::vector<uint32_t>({0}));
    EXPECT_TRUE(opaque.normals.empty());

    const TriangleMesh& glass = d.scene.meshes[1];  // T > 0: two-sided
    EXPECT_FALSE(glass.one_sided);
    ASSERT_EQ(glass.positions.size(), 4u);
    expect_vec3(glass.positions[2], 1.0f, 1.0f, 1.0f);
    ASSERT_EQ(glass.triangles.size(), 2u);
    EXPECT_EQ(glass.triangles[0], (std::array<uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(glass.triangles[1], (std::array<uint32_t, 3>{0, 2, 3}));
    EXPECT_EQ(glass.materials, std::vector<uint32_t>({1, 1}));
}

TEST(NffLoader, PatchNormalsAreNormalised) {
    const SceneDescription d = load_nff_string(kEveryEntity, "every.nff");
    ASSERT_EQ(d.scene.meshes.size(), 3u);
    const TriangleMesh& patch = d.scene.meshes[2];
    EXPECT_FALSE(patch.one_sided);  // its material is transmissive
    ASSERT_EQ(patch.positions.size(), 3u);
    ASSERT_EQ(patch.normals.size(), 3u);
    expect_vec3(patch.positions[1], 1.0f, 0.0f, 2.0f);
    expect_vec3(patch.normals[0], 0.0f, 0.0f, 1.0f);
    expect_vec3(patch.normals[1], 0.0f, 1.0f, 0.0f);
    expect_vec3(patch.normals[2], -1.0f, 0.0f, 0.0f);
    EXPECT_EQ(patch.materials, std::vector<uint32_t>({1}));
}

TEST(NffLoader, ConvexPolygonBecomesFan) {
    const SceneDescription d = load_nff_string(
        kView + lines({"f 1 1 1 1 0 1 0 1", "p 5", "0 0 0", "2 0 0", "3 1 0", "1 2 0", "-1 1 0"}),
        "fan.nff");
    ASSERT_EQ(d.scene.meshes.size(), 1u);
    const TriangleMesh& mesh = d.scene.meshes[0];
    EXPECT_TRUE(mesh.one_sided);
    ASSERT_EQ(mesh.triangles.size(), 3u);
    EXPECT_EQ(mesh.triangles[0], (std::array<uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(mesh.triangles[1], (std::array<uint32_t, 3>{0, 2, 3}));
    EXPECT_EQ(mesh.triangles[2], (std::array<uint32_t, 3>{0, 3, 4}));
    expect_vec3(mesh.positions[4], -1.0f, 1.0f, 0.0f);
}

TEST(NffLoader, ConcavePolygonIsTriangulatedInsideItsOutline) {
    // An L (area 3) starting at a corner whose fan would cover the notch around (1.5, 1.5):
    // NFF polygons may be concave (only the first two edges must form a convex angle).
    const SceneDescription d = load_nff_string(
        kView + lines({"f 1 1 1 1 0 1 0 1", "p 6", "2 0 0", "2 1 0", "1 1 0", "1 2 0", "0 2 0",
                       "0 0 0", "f 1 1 1 1 0 1 0.5 1.5", "pp 6", "2 0 1 0 0 1", "2 1 1 1 0 1",
                       "1 1 1 2 0 1", "1 2 1 3 0 1", "0 2 1 4 0 1", "0 0 1 5 0 1"}),
        "l.nff");
    ASSERT_EQ(d.scene.meshes.size(), 2u);  // one-sided polygon, two-sided patch
    for (const TriangleMesh& mesh : d.scene.meshes) {
        SCOPED_TRACE(mesh.name);
        ASSERT_EQ(mesh.triangles.size(), 4u);
        float area = 0.0f;
        for (const auto& t : mesh.triangles) {
            const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
            const Vec3 n = glm::cross(b - a, c - a);
            EXPECT_GT(n.z, 0.0f);  // counter-clockwise seen from +z, like the outline
            area += 0.5f * glm::length(n);
            // The notch point (1.5, 1.5) is in no triangle.
            const auto side = [](Vec3 p, Vec3 q, float x, float y) {
                return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
            };
            EXPECT_FALSE(side(a, b, 1.5f, 1.5f) > 0 && side(b, c, 1.5f, 1.5f) > 0 &&
                         side(c, a, 1.5f, 1.5f) > 0);
        }
        EXPECT_FLOAT_EQ(area, 3.0f);
    }
    // Patch normals stay with their vertices: vertex i was given the normal (i, 0, 1).
    const TriangleMesh& patch = d.scene.meshes[1];
    ASSERT_EQ(patch.normals.size(), 6u);
    expect_vec3(patch.positions[3], 1.0f, 2.0f, 1.0f);
    for (size_t i = 0; i < 6; ++i) {
        const Vec3 n = glm::normalize(Vec3(float(i), 0.0f, 1.0f));
        expect_vec3(patch.normals[i], n.x, n.y, n.z);
    }
}

TEST(NffLoader, NumberForms) {
    const SceneDescription d = load_nff_string(
        kView + lines({"f 1 1 1 1 0 1 0 1", "s 1.11022e-16 -.5 +2 1E-1", "s 3. -0 5e0 .25"}),
        "numbers.nff");
    ASSERT_EQ(d.scene.shapes.of<Sphere>().size(), 2u);
    EXPECT_FLOAT_EQ(d.scene.shapes.of<Sphere>()[0].center.x, 1.11022e-16f);
    EXPECT_FLOAT_EQ(d.scene.shapes.of<Sphere>()[0].center.y, -0.5f);
    EXPECT_FLOAT_EQ(d.scene.shapes.of<Sphere>()[0].center.z, 2.0f);
    EXPECT_FLOAT_EQ(d.scene.shapes.of<Sphere>()[0].radius, 0.1f);
    expect_vec3(d.scene.shapes.of<Sphere>()[1].center, 3.0f, 0.0f, 5.0f);
    EXPECT_FLOAT_EQ(d.scene.shapes.of<Sphere>()[1].radius, 0.25f);
}

TEST(NffLoader, CrlfTabsAndViewLinesInAnyOrder) {
    const std::string text =
        "b\t0 0 0\r\nv\r\nresolution 10 20\r\nup 0 1 0\r\n  angle 30 \r\nat 0 0 0\r\n"
        "hither 0\r\nfrom 0 0 9\r\n\r\nf 1 1 1 1 0 1 0 1\r\ns 0 0 0 1\r\n";
    const SceneDescription d = load_nff_string(text, "crlf.nff");
    EXPECT_EQ(d.scene.camera.width, 10);
    EXPECT_EQ(d.scene.camera.height, 20);
    expect_vec3(d.scene.camera.eye, 0.0f, 0.0f, 9.0f);
    EXPECT_FLOAT_EQ(*d.scene.camera.vfov_degrees, 30.0f);
    EXPECT_EQ(d.scene.shapes.of<Sphere>().size(), 1u);
}

TEST(NffLoader, DefaultMaterialBeforeAnyF) {
    const SceneDescription d =
        load_nff_string(kView + lines({"s 0 0 0 1", "f 1 0 0 0.5 0 1 0 1", "s 0 0 2 1"}), "d.nff");
    ASSERT_EQ(d.shading.materials.size(), 2u);
    const Material& fallback = d.shading.materials[0];  // as `f 1 1 1 1 0 1 0 1`
    EXPECT_EQ(fallback.name, "nff default");
    expect_vec3(fallback.ka, 0.1f, 0.1f, 0.1f);
    expect_vec3(fallback.kd, 1.0f, 1.0f, 1.0f);
    expect_vec3(fallback.ks, 0.0f, 0.0f, 0.0f);
    expect_vec3(fallback.reflect, 0.0f, 0.0f, 0.0f);
    expect_vec3(fallback.transmit, 0.0f, 0.0f, 0.0f);
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[0].material, 0u);
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[1].material, 1u);
    expect_vec3(d.shading.materials[1].kd, 0.5f, 0.0f, 0.0f);
}

TEST(NffLoader, ConsecutiveIdenticalFShareOneMaterial) {
    const SceneDescription d = load_nff_string(
        kView + lines({"f 1 0 0 1 0 1 0 0", "s 0 0 0 1", "f 1 0 0 1 0 1 0 0", "s 0 0 3 1",
                       "f 0 1 0 1 0 1 0 0", "s 0 0 6 1", "f 1 0 0 1 0 1 0 0", "s 0 0 9 1"}),
        "dedup.nff");
    ASSERT_EQ(d.shading.materials.size(), 3u);
    EXPECT_EQ(d.shading.materials[0].name, "f line 8");
    EXPECT_EQ(d.shading.materials[2].name, "f line 14");
    ASSERT_EQ(d.scene.shapes.of<Sphere>().size(), 4u);
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[0].material, 0u);
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[1].material, 0u);
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[2].material, 1u);
    EXPECT_EQ(d.scene.shapes.of<Sphere>()[3].material, 2u);
    // ior 0 with T = 0 (common in SPD files) means "no refraction": stored as 1.
    EXPECT_FLOAT_EQ(d.shading.materials[0].ior, 1.0f);
}

TEST(NffLoader, DegeneratePatchesAreSkippedAndCounted) {
    NffLoadInfo info;
    const SceneDescription d = load_nff_string(
        kView + lines({"f 1 1 1 1 0 1 0 0", "pp 3", "0 0 0 0 0 1", "1 0 0 0 0 1", "2 0 0 0 0 1",
                       "pp 3", "0 0 0 0 0 1", "1 0 0 0 0 1", "0 1 0 0 0 1"}),
        "pp.nff", &info);
    EXPECT_EQ(info.lines, 16u);
    EXPECT_EQ(d.skipped_triangles, 1u);
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_EQ(d.warnings[0], "pp.nff:9: degenerate patch (zero area) skipped");
    ASSERT_EQ(d.scene.meshes.size(), 1u);
    EXPECT_EQ(d.scene.meshes[0].name, "nff patches");
    EXPECT_TRUE(d.scene.meshes[0].one_sided);
    EXPECT_EQ(d.scene.meshes[0].triangle_count(), 1u);
}

TEST(NffLoader, LargeGeneratedFile) {
    TempDir dir;
    std::string text = kView + "f 0.5 0.5 0.5 0.8 0.2 10 0 1\n";
    constexpr int kSpheres = 10000, kPolygons = 2000;
    for (int i = 0; i < kSpheres; ++i) {
        text += "s " + std::to_string(i % 100) + " " + std::to_string(i / 100) + " -" +
                std::to_string(i % 7) + ".5 0.25\n";
    }
    text += "f 0.2 0.3 0.9 0.5 0.5 50 0.5 1.33\n";
    for (int i = 0; i < kPolygons; ++i) {
        const std::string z = std::to_string(i);
        text += "p 4\n0 0 " + z + "\n1 0 " + z + "\n1 1 " + z + "\n0 1 " + z + "\n";
    }
    const std::string path = dir.write("large.nff", text);
    NffLoadInfo info;
    const SceneDescription d = load_nff_file(path, &info);
    EXPECT_EQ(d.source, path);
    EXPECT_EQ(info.lines, 7u + 1u + kSpheres + 1u + 5u * kPolygons);
    ASSERT_EQ(d.scene.shapes.of<Sphere>().size(), static_cast<size_t>(kSpheres));
    expect_vec3(d.scene.shapes.of<Sphere>()[kSpheres - 1].center, 99.0f, 99.0f, -(9999 % 7) - 0.5f);
    EXPECT_FLOAT_EQ(d.scene.shapes.of<Sphere>()[kSpheres - 1].radius, 0.25f);
    ASSERT_EQ(d.scene.meshes.size(), 1u);  // all polygons in one two-sided mesh
    EXPECT_FALSE(d.scene.meshes[0].one_sided);
    EXPECT_EQ(d.scene.triangle_count(), 2u * kPolygons);
    EXPECT_EQ(d.shading.materials.size(), 2u);
}

TEST(NffLoader, FileAndStringAgree) {
    TempDir dir;
    const std::string path = dir.write("every.nff", kEveryEntity);
    const SceneDescription from_file = load_nff_file(path);
    const SceneDescription from_string = load_nff_string(kEveryEntity, path);
    EXPECT_EQ(from_file.scene.shapes.of<Sphere>().size(),
              from_string.scene.shapes.of<Sphere>().size());
    EXPECT_EQ(from_file.scene.shapes.of<Cone>().size(), from_string.scene.shapes.of<Cone>().size());
    EXPECT_EQ(from_file.scene.triangle_count(), from_string.scene.triangle_count());
    EXPECT_EQ(from_file.shading.materials.size(), from_string.shading.materials.size());
}

// ---- errors: each names the exact line ------------------------------------------------------

TEST(NffLoaderErrors, UnknownEntityIsNamed) {
    expect_error(kView + lines({"s 0 0 0 1", "torus 0 0 0 1 2"}), "t.nff:9", "'torus'");
    expect_error(kView + lines({"s 0 0 0 1", "from 1 2 3"}), "t.nff:9", "outside a 'v' block");
}

TEST(NffLoaderErrors, WrongArgumentCount) {
    expect_error(kView + lines({"s 0 0 1"}), "t.nff:8", "'s' expects 4 numbers");
    expect_error(kView + lines({"s 0 0 1 1 1"}), "t.nff:8", "'s' expects 4 numbers");
    expect_error(kView + lines({"f 1 1 1 1 0 1 0"}), "t.nff:8", "'f' expects 8 numbers");
    expect_error(kView + lines({"l 1 2 3 4"}), "t.nff:8", "'l' expects 3 numbers");
    expect_error(kView + lines({"b 1 2"}), "t.nff:8", "'b' expects 3 numbers");
    expect_error(kView + lines({"c 0 0 0 1 0 0 1"}), "t.nff:8", "'c' expects");
    expect_error(kView + lines({"p"}), "t.nff:8", "'p' expects 1 integer");
    expect_error(kView + lines({"p 3", "0 0 0", "1 0 0 7", "0 1 0"}), "t.nff:10",
                 "vertex 2 of 3 (polygon at line 8) expects 3 numbers");
    expect_error(kView + lines({"pp 3", "0 0 0 0 0 1", "1 0 0", "0 1 0 0 0 1"}), "t.nff:10",
                 "expects 6 numbers");
    expect_error(lines({"v", "from 0 0 5 1"}), "t.nff:2", "'from' expects 3 numbers");
    expect_error(lines({"v 1"}), "t.nff:1", "'v' stands alone");
}

TEST(NffLoaderErrors, NonNumericNanAndInf) {
    expect_error(kView + lines({"s 0 zero 0 1"}), "t.nff:8", "expected a number, got 'zero'");
    expect_error(kView + lines({"s 0 1.5x 0 1"}), "t.nff:8", "got '1.5x'");
    expect_error(kView + lines({"s 0 0 0 nan"}), "t.nff:8", "expected a finite number");
    expect_error(kView + lines({"s inf 0 0 1"}), "t.nff:8", "expected a finite number");
    expect_error(kView + lines({"s 0 0 0 1e39"}), "t.nff:8", "expected a finite number");
    expect_error(kView + lines({"s 0 0 0 1e999"}), "t.nff:8", "out of range");
    expect_error(kView + lines({"s 0x10 0 0 1"}), "t.nff:8", "got '0x10'");
    expect_error(kView + lines({"s +-1 0 0 1"}), "t.nff:8", "got '+-1'");
    expect_error(kView + lines({"f 1 1 1 1 0 1 0 1", "p 3", "0 0 0", "1 NaN 0", "0 1 0"}),
                 "t.nff:11", "vertex: expected a finite number");
    expect_error(lines({"v", "from 0 0 5", "at 0 0 0", "up 0 1 0", "angle -inf"}), "t.nff:5",
                 "angle: expected a finite number");
}

TEST(NffLoaderErrors, BadSphereRadius) {
    expect_error(kView + lines({"s 0 0 0 0"}), "t.nff:8", "sphere radius must be > 0");
    expect_error(kView + lines({"s 1 1 1 1", "s 0 0 0 -2"}), "t.nff:9",
                 "sphere radius must be > 0");
}

TEST(NffLoaderErrors, BadCone) {
    expect_error(kView + lines({"c 0 0 0 -1 0 0 1 1"}), "t.nff:8", "cone base radius must be >= 0");
    expect_error(kView + lines({"c", "0 0 0 1", "0 0 1 -0.5"}), "t.nff:10",
                 "cone apex radius must be >= 0");
    expect_error(kView + lines({"c 1 2 3 1 1 2 3 0.5"}), "t.nff:8", "zero length");
    expect_error(kView + lines({"c 0 0 0 0 0 0 1 0"}), "t.nff:8", "both radii zero");
    expect_error(kView + lines({"c", "0 0 0 1"}), "t.nff:8", "truncated file");
    expect_error(kView + lines({"c", "0 0 0", "0 0 1 1"}), "t.nff:9", "cone base line expects 4");
}

TEST(NffLoaderErrors, BadPolygon) {
    expect_error(kView + lines({"p 2", "0 0 0", "1 0 0"}), "t.nff:8", "at least 3 vertices");
    expect_error(kView + lines({"pp -1"}), "t.nff:8", "at least 3 vertices");
    expect_error(kView + lines({"p 3.0", "0 0 0", "1 0 0", "0 1 0"}), "t.nff:8",
                 "expected an integer, got '3.0'");
    expect_error(kView + lines({"s 0 0 0 1", "p 3", "0 0 0", "1 1 1", "2 2 2"}), "t.nff:9",
                 "degenerate polygon");
    expect_error(kView + lines({"p 4", "0 0 0", "0 0 0", "0 0 0", "0 0 0"}), "t.nff:8",
                 "degenerate polygon");
    expect_error(kView + lines({"pp 3", "0 0 0 0 0 1", "1 0 0 0 0 0", "0 1 0 0 0 1"}), "t.nff:10",
                 "vertex normal has zero length");
}

TEST(NffLoaderErrors, TruncatedFile) {
    expect_error(kView + lines({"p 5", "0 0 0", "1 0 0", "1 1 0"}), "t.nff:8",
                 "polygon declares 5 vertices, the file ends after 3");
    expect_error(kView + lines({"pp 4000"}), "t.nff:8", "truncated file");
    // A count beyond kMaxPolygonVertices is refused before any vertex is read.
    expect_error(kView + lines({"pp 1000000000"}), "t.nff:8",
                 "polygon of 1000000000 vertices; the limit is 4096");
    expect_error(lines({"# header", "v", "from 0 0 5", "at 0 0 0"}), "t.nff:2",
                 "missing up angle hither resolution");
    expect_error(
        lines({"v", "from 0 0 5", "at 0 0 0", "up 0 1 0", "angle 45", "hither 1", "s 0 0 0 1"}),
        "t.nff:1", "missing resolution");
    expect_error(lines({"v", "from 0 0 5", "from 0 0 6"}), "t.nff:3", "repeated 'from'");
}

TEST(NffLoaderErrors, BinaryGarbage) {
    std::string with_nul = kView + "s 0 0 0 1\n";
    with_nul += std::string("s 0 0\0 1\n", 9);
    expect_error(with_nul, "t.nff:9", "NUL byte");
    expect_error(kView + lines({"# fine", "s 0 0 0 1\x01"}), "t.nff:9", "control byte 0x01");
    expect_error(kView + lines({"s 0 0 0 \xff\xfe"}), "t.nff:8", "non-ASCII byte 0xFF");
    // UTF-8 in comments is text.
    EXPECT_NO_THROW(load_nff_string(kView + lines({"# caf\xc3\xa9", "s 0 0 0 1"}), "t.nff"));
}

TEST(NffLoaderErrors, MissingFile) {
    TempDir dir;
    const std::string path = dir.path("does_not_exist.nff");
    try {
        load_nff_file(path);
        ADD_FAILURE() << "no error for a missing file";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), path);
        EXPECT_NE(e.message().find("cannot open"), std::string::npos) << e.message();
    }
}

TEST(NffLoaderErrors, NoViewpoint) {
    expect_error(lines({"b 0 0 0", "f 1 1 1 1 0 1 0 1", "s 0 0 0 1"}), "t.nff:3", "no viewpoint");
    expect_error("", "t.nff:1", "no viewpoint");
    expect_error(kView + kView, "t.nff:8", "second 'v' block (the first is at line 1)");
}

TEST(NffLoaderErrors, BadResolution) {
    expect_error(lines({"v", "from 0 0 5", "at 0 0 0", "up 0 1 0", "angle 45", "hither 1",
                        "resolution 0 48"}),
                 "t.nff:7", "resolution must be positive");
    expect_error(lines({"v", "from 0 0 5", "at 0 0 0", "up 0 1 0", "angle 45", "hither 1",
                        "resolution 64 -2"}),
                 "t.nff:7", "resolution must be positive");
    expect_error(lines({"v", "from 0 0 5", "at 0 0 0", "up 0 1 0", "angle 45", "hither 1",
                        "resolution 64.5 48"}),
                 "t.nff:7", "expected an integer, got '64.5'");
    expect_error(
        lines({"v", "from 0 0 5", "at 0 0 0", "up 0 1 0", "angle 45", "hither 1", "resolution 64"}),
        "t.nff:7", "'resolution' expects 2 integers");
}

TEST(NffLoaderErrors, DegenerateCameraReportsViewLine) {
    // Camera::create's checks, reported at the `v` line.
    expect_error(lines({"# c", "v", "from 1 1 1", "at 1 1 1", "up 0 1 0", "angle 45", "hither 1",
                        "resolution 8 8"}),
                 "t.nff:2", "eye and look_at must differ");
    expect_error(lines({"v", "from 0 5 0", "at 0 0 0", "up 0 1 0", "angle 45", "hither 1",
                        "resolution 8 8"}),
                 "t.nff:1", "parallel");
    expect_error(lines({"v", "from 0 0 5", "at 0 0 0", "up 0 1 0", "angle 180", "hither 1",
                        "resolution 8 8"}),
                 "t.nff:1", "vfov must be in (0, 180)");
}

TEST(NffLoaderErrors, BadMaterialAndLightValues) {
    expect_error(kView + lines({"f 1 1 1 -1 0 1 0 1"}), "t.nff:8", "f Kd must be >= 0");
    expect_error(kView + lines({"f 1 1 1 1 0 1 0.5 0"}), "t.nff:8", "index of refraction");
    expect_error(kView + lines({"l 0 0 0 1 -1 1"}), "t.nff:8", "light colour must be >= 0");
}

}  // namespace
}  // namespace rayo
