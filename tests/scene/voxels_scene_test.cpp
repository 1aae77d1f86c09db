// Voxel grids in JSON scenes (docs/voxels.md): a surface-mode voxelized sphere renders the exact
// sphere's coverage and has radial normals; composite mode through a known path length gives
// c·(1 − e^(−σL)) + e^(−σL)·(what lies behind), shadows through it are attenuated by its
// transmittance; bad values are refused at their JSON pointer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/accel.h"
#include "core/camera.h"
#include "core/error.h"
#include "tests/scene/json_error.h"

namespace rayo {
namespace {

std::string temp_path(const std::string& name) {
    return ::testing::TempDir() + name;
}

void write_bytes(const std::string& name, const std::string& bytes) {
    std::ofstream(temp_path(name), std::ios::binary).write(bytes.data(), long(bytes.size()));
}

// An n³ u8 grid over [−1, 1]³ whose 0.5 iso-surface is the sphere of radius r about the origin:
// value 0.5 + (r − |p|)/(4·voxel) at the voxel centres, clamped to [0, 1].
std::string sphere_bytes(int n, float r) {
    std::string bytes;
    const float voxel = 2.0f / float(n);
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                const Vec3 p = Vec3(-1.0f) + voxel * Vec3(i + 0.5f, j + 0.5f, k + 0.5f);
                const float v =
                    std::clamp(0.5f + (r - glm::length(p)) / (4.0f * voxel), 0.0f, 1.0f);
                bytes.push_back(char(std::lround(255.0f * v)));
            }
        }
    }
    return bytes;
}

SceneDescription load(const std::string& text) {
    return load_json_string(text, "s.json", ::testing::TempDir());
}

// An emissive white surface-mode sphere on black: hit pixels are 1, the others 0.
std::string sphere_scene(int width) {
    return R"({"rayo": 1, "camera": {"eye": [0.3, 0.2, 4], "look_at": [0, 0, 0], "vfov": 35,
      "width": )" +
           std::to_string(width) + R"(, "height": )" + std::to_string(width) + R"(},
      "ambient_light": 0,
      "materials": {"glow": {"ka": 0, "kd": 0, "ks": 0, "emission": 1}},
      "objects": [{"type": "voxels", "file": "sphere.raw", "dims": [48, 48, 48],
                   "size": [2, 2, 2], "material": "glow"}]})";
}

TEST(VoxelsScene, SurfaceSphereCoversTheExactSpheresPixels) {
    const int n = 48, width = 96;
    const float r = 0.7f, voxel = 2.0f / float(n);
    write_bytes("sphere.raw", sphere_bytes(n, r));
    const SceneDescription d = load(sphere_scene(width));
    ASSERT_EQ(d.scene.voxels.size(), 1u);
    EXPECT_EQ(d.scene.voxels[0].lower, Vec3(-1.0f));  // centred by default
    const RenderResult result = render_scene(d, 2, false);
    const Camera camera = Camera::create(d.scene.camera);
    int rendered = 0, exact = 0, wrong = 0, wrong_far_from_the_rim = 0;
    for (int y = 0; y < width; ++y) {
        for (int x = 0; x < width; ++x) {
            const Ray ray = camera.generate_ray(float(x) + 0.5f, float(y) + 0.5f);
            // The exact sphere: the ray's closest approach to its centre.
            const float along = -glm::dot(ray.origin, ray.direction);
            const float miss_distance = glm::length(ray.origin + along * ray.direction);
            const bool hit_exact = miss_distance < r;
            const bool hit_rendered = result.film.rgb(x, y).x > 0.5f;
            rendered += hit_rendered;
            exact += hit_exact;
            if (hit_rendered != hit_exact) {
                ++wrong;
                // Only rays that pass within half a voxel of the silhouette may differ.
                wrong_far_from_the_rim += std::abs(miss_distance - r) > 0.5f * voxel;
            }
        }
    }
    EXPECT_GT(exact, 1000);  // the projected disk, about 1/5 of the image
    EXPECT_EQ(wrong_far_from_the_rim, 0);
    EXPECT_LT(std::abs(rendered - exact), exact / 50) << rendered << " vs " << exact;
    EXPECT_LT(wrong, exact / 25);
}

// Ray (a, b) of a 16 × 16 fan toward the voxelized sphere from z = 5.
Ray probe_ray(int a, int b) {
    Ray ray;
    ray.origin = Vec3(0.1f * a - 0.75f, 0.1f * b - 0.75f, 5.0f);
    ray.direction = glm::normalize(Vec3(0.02f * a, -0.01f * b, -1.0f));
    return ray;
}

TEST(VoxelsScene, SurfaceNormalsAreRadialAndHitsLieOnTheSphere) {
    const int n = 48;
    const float r = 0.7f, voxel = 2.0f / float(n);
    write_bytes("sphere.raw", sphere_bytes(n, r));
    const SceneDescription d = load(sphere_scene(64));
    const Accel accel(d.scene);
    int hits = 0;
    for (int a = 0; a < 16; ++a) {
        for (int b = 0; b < 16; ++b) {
            const Ray ray = probe_ray(a, b);
            SurfaceHit hit;
            if (!accel.intersect(ray, hit)) continue;
            ++hits;
            EXPECT_EQ(hit.shape, kVoxelShape);
            EXPECT_EQ(hit.mesh, 0u);
            EXPECT_NEAR(glm::length(hit.position), r, 0.25f * voxel);
            const Vec3 radial = glm::normalize(hit.position);
            EXPECT_GT(glm::dot(hit.geometric_normal, radial), std::cos(3.0f * kPi / 180.0f))
                << a << " " << b;
            EXPECT_NEAR(glm::length(hit.shading_normal), 1.0f, 1e-5f);
        }
    }
    EXPECT_GT(hits, 60);
}

TEST(VoxelsScene, MeshFormLiesOnTheSphereAndMatchesTheTraversal) {
    // "method": "mesh": the marching-tetrahedra mesh over the voxel centres. Its vertices
    // interpolate linearly along lattice edges where the traversal roots the trilinear
    // interpolant, so the two agree to a fraction of a voxel, and both lie on the sphere.
    const int n = 48;
    const float r = 0.7f, voxel = 2.0f / float(n);
    write_bytes("sphere.raw", sphere_bytes(n, r));
    std::string text = sphere_scene(64);
    const std::string glow = R"("material": "glow")";
    text.replace(text.find(glow), glow.size(), glow + R"(, "method": "mesh")");
    const SceneDescription meshed = load(text);
    ASSERT_TRUE(meshed.scene.voxels.empty());
    ASSERT_EQ(meshed.scene.meshes.size(), 1u);
    EXPECT_GT(meshed.scene.meshes[0].triangle_count(), 1000u);
    const SceneDescription traced = load(sphere_scene(64));
    const Accel mesh_accel(meshed.scene), dda_accel(traced.scene);
    int hits = 0;
    for (int a = 0; a < 16; ++a) {
        for (int b = 0; b < 16; ++b) {
            const Ray ray = probe_ray(a, b);
            SurfaceHit on_mesh, on_grid;
            const bool mesh_hit = mesh_accel.intersect(ray, on_mesh);
            if (!dda_accel.intersect(ray, on_grid)) continue;
            ASSERT_TRUE(mesh_hit) << a << " " << b;
            ++hits;
            EXPECT_NEAR(glm::length(on_mesh.position), r, 0.25f * voxel);
            EXPECT_NEAR(on_mesh.t, on_grid.t, 0.25f * voxel) << a << " " << b;
            EXPECT_GT(glm::dot(on_mesh.shading_normal, glm::normalize(on_mesh.position)),
                      std::cos(5.0f * kPi / 180.0f));
        }
    }
    EXPECT_GT(hits, 60);
}

// "method": "auto": the mesh while its triangles stay within the memory budget
// (auto_voxels_prefer_mesh), the DDA beyond; the choice is reported for --stats.
TEST(VoxelsScene, AutoTakesTheMeshWithinItsBudgetAndReportsIt) {
    const size_t limit = kAutoVoxelMeshBytes / kVoxelMeshBytesPerTriangle;
    EXPECT_TRUE(auto_voxels_prefer_mesh(42216));  // the example planet's mesh
    EXPECT_TRUE(auto_voxels_prefer_mesh(limit));
    EXPECT_FALSE(auto_voxels_prefer_mesh(limit + 1));
    EXPECT_FALSE(auto_voxels_prefer_mesh(size_t(1) << 24));

    write_bytes("sphere.raw", sphere_bytes(48, 0.7f));
    std::string text = sphere_scene(64);
    const std::string glow = R"("material": "glow")";
    text.replace(text.find(glow), glow.size(), glow + R"(, "method": "auto")");
    const SceneDescription chosen = load(text);
    ASSERT_TRUE(chosen.scene.voxels.empty());
    ASSERT_EQ(chosen.scene.meshes.size(), 1u);
    // The count auto weighs is the mesh's (no corner of this grid lies on the threshold).
    const SceneDescription traced = load(sphere_scene(64));
    ASSERT_EQ(traced.scene.voxels.size(), 1u);
    const size_t triangles = traced.scene.voxels[0].mesh_triangles();
    EXPECT_EQ(triangles, chosen.scene.meshes[0].triangle_count());
    EXPECT_EQ(traced.scene.voxels[0].tessellate().triangle_count(), triangles);
    ASSERT_EQ(chosen.method_choices.size(), 1u);
    EXPECT_EQ(chosen.method_choices[0],
              "voxels /objects/0 (auto): mesh, " + std::to_string(triangles) +
                  " triangles (<= " + std::to_string(limit) + ", ~" +
                  std::to_string((triangles * 100) >> 20) + " MB as a mesh)");
    EXPECT_TRUE(traced.method_choices.empty());  // dda by default, nothing chosen
}

// A composite box [−1, 1] × [−1, 1] × [−L/2, L/2] of constant value 1 (u8 255) and one transfer
// stop (colour c, density σ), seen along the z axis by the centre pixel of a 3 × 3 image.
std::string slab_scene(const std::string& behind, const std::string& render = "{}") {
    return R"({"rayo": 1, "camera": {"eye": [0, 0, 6], "look_at": [0, 0, 0], "vfov": 10,
      "width": 3, "height": 3},
      "render": )" +
           render + R"(, "background": [0.1, 0.3, 0.9], "ambient_light": 0,
      "materials": {"wall": {"ka": 0, "kd": [0.6, 0.5, 0.4], "ks": 0}},
      "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1}],
      "objects": [{"type": "voxels", "file": "slab.raw", "dims": [4, 4, 2], "size": [2, 2, 1.5],
                   "origin": [-1, -1, -0.75], "mode": "composite",
                   "transfer": [{"value": 0, "color": [0.9, 0.6, 0.2], "density": 0.8}]})" +
           behind + "]}";
}

TEST(VoxelsScene, CompositeOverTheBackgroundAndASurfaceIsTheClosedForm) {
    write_bytes("slab.raw", std::string(4 * 4 * 2, '\xff'));
    const Vec3 c(0.9f, 0.6f, 0.2f), background(0.1f, 0.3f, 0.9f), kd(0.6f, 0.5f, 0.4f);
    const float length = 1.5f, t = std::exp(-0.8f * length);
    // Over the background.
    {
        const RenderResult result = render_scene(load(slab_scene("")), 1, false);
        const Vec3 expected = c * (1.0f - t) + t * background;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(result.film.rgb(1, 1)[k], expected[k], 1e-5f);
    }
    // Over a wall behind it lit by a light behind the camera (its shadow ray leaves the volume
    // toward the eye: the wall's light crosses the slab, then the camera ray crosses it again).
    for (const char* settings : {"{}", R"({"shadows": "filtered"})"}) {
        const std::string wall =
            R"(, {"type": "disk", "center": [0, 0, -3], "normal": [0, 0, 1], "radius": 5,
                  "material": "wall"})";
        SceneDescription d = load(slab_scene(wall, settings));
        for (bool coherent : {true, false}) {
            d.settings.coherent = coherent;
            const RenderResult result = render_scene(d, 1, false);
            const Vec3 expected = c * (1.0f - t) + t * (t * kd);
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(result.film.rgb(1, 1)[k], expected[k], 1e-5f) << settings << coherent;
            }
        }
    }
}

TEST(VoxelsScene, InfoCountsAndBadValuesAreRefusedAtTheirPointer) {
    write_bytes("v222.raw", std::string(8, '\x80'));
    write_bytes("f32.raw", [] {
        std::string bytes(8 * 4, '\0');
        const float nan = std::nanf("");
        std::memcpy(&bytes[12], &nan, 4);
        return bytes;
    }());
    const auto scene = [](const std::string& fields) {
        return R"({"rayo": 1, "materials": {"m": {}},
                   "objects": [{"type": "voxels", "size": [1, 1, 1], )" +
               fields + "}]}";
    };
    const auto error = [&](const std::string& fields) {
        return json_error_of(scene(fields), "s.json", ::testing::TempDir());
    };
    // Accepted: two grids over the same bytes.
    const SceneDescription d = load(R"({"rayo": 1, "objects": [
          {"type": "voxels", "file": "v222.raw", "dims": [2, 2, 2], "size": [1, 1, 1]},
          {"type": "voxels", "file": "v222.raw", "dims": [2, 2, 2], "size": [1, 1, 1],
           "mode": "composite"}]})");
    ASSERT_EQ(d.scene.voxels.size(), 2u);
    EXPECT_NEAR(d.scene.voxels[0].values[0], 128.0f / 255.0f, 1e-6f);
    EXPECT_EQ(d.scene.voxels[0].mode, VoxelMode::Surface);
    EXPECT_EQ(d.scene.voxels[1].mode, VoxelMode::Composite);
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 2, 3])"),
              "s.json#/objects/0/dims: expected dims that match the size of the voxel file '" +
                  ::testing::TempDir() +
                  "v222.raw': 2 × 2 × 3 u8 voxels are 12 bytes, the file has 8");
    EXPECT_EQ(error(R"("file": "f32.raw", "dims": [2, 2, 2])"),
              "s.json#/objects/0/dims: expected dims that match the size of the voxel file '" +
                  ::testing::TempDir() +
                  "f32.raw': 2 × 2 × 2 u8 voxels are 8 bytes, the file has 32");
    EXPECT_NE(error(R"("file": "v222.raw", "dims": [2, 2, 2], "format": "u16")")
                  .find("#/objects/0/dims: expected dims that match the size of the voxel file"),
              std::string::npos);
    EXPECT_NE(error(R"("file": "none.raw", "dims": [2, 2, 2])").find("s.json#/objects/0/file"),
              std::string::npos);
    EXPECT_NE(error(R"("file": "none.raw", "dims": [2, 2, 2])").find("none.raw"),
              std::string::npos);
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 1, 4])"),
              "s.json#/objects/0/dims/1: expected an integer in [2, 65536], got 1");
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 2])"),
              "s.json#/objects/0/dims: expected [nx, ny, nz], each in [2, 65536], got an array "
              "of 2");
    EXPECT_EQ(json_error_of(R"({"rayo": 1, "objects": [{"type": "voxels", "file": "v222.raw",
                                "dims": [2, 2, 2], "size": [1, -1, 1]}]})",
                            "s.json", ::testing::TempDir()),
              "s.json#/objects/0/size/1: expected a number > 0, got -1");
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 2, 2], "format": "u32")"),
              "s.json#/objects/0/format: expected one of \"u8\", \"u16\", \"f32\", got the "
              "string \"u32\"");
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 2, 2], "mode": "volume")"),
              "s.json#/objects/0/mode: expected one of \"surface\", \"composite\", got the "
              "string \"volume\"");
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 2, 2], "mode": "composite",
                       "transfer": [{"value": 0.5, "color": 1, "density": 1},
                                    {"value": 0.2, "color": 1, "density": 1}])"),
              "s.json#/objects/0/transfer/1/value: expected stops sorted by value: 0.2 comes "
              "after 0.5");
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 2, 2], "mode": "composite",
                       "transfer": [{"value": 0.5, "color": 1, "density": -1}])"),
              "s.json#/objects/0/transfer/0/density: expected a number >= 0, got -1");
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 2, 2], "mode": "composite",
                       "material": "m")"),
              "s.json#/objects/0/material: material applies to \"mode\": \"surface\" only");
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 2, 2],
                       "transfer": [{"value": 0, "color": 1, "density": 1}])"),
              "s.json#/objects/0/transfer: transfer applies to \"mode\": \"composite\" only");
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 2, 2], "method": "bvh")"),
              "s.json#/objects/0/method: expected one of \"dda\", \"mesh\", \"auto\", got the "
              "string "
              "\"bvh\"");
    EXPECT_EQ(error(R"("file": "v222.raw", "dims": [2, 2, 2], "mode": "composite",
                       "method": "mesh")"),
              "s.json#/objects/0/method: method applies to \"mode\": \"surface\" only");
    EXPECT_NE(error(R"("file": "f32.raw", "dims": [2, 2, 2], "format": "f32")")
                  .find("s.json#/objects/0/file: voxel (1, 1, 0) of "),
              std::string::npos);
    EXPECT_NE(error(R"("file": "v222.raw", "dims": [2, 2, 2], "threshold": "x")")
                  .find("s.json#/objects/0/threshold: expected a number"),
              std::string::npos);
    EXPECT_EQ(json_error_of(R"({"rayo": 1, "groups": {"g": [{"type": "voxels"}]}})", "s.json",
                            ::testing::TempDir()),
              "s.json#/groups/g/0/type: a group may not contain voxel grids (they are placed "
              "directly only)");
}

}  // namespace
}  // namespace rayo
