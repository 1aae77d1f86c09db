#pragma once
// The fuzzers' oracle: what a scene loader promises about a scene it accepted. Bad input
// must be refused with rayo::InputError; anything accepted must be finite, in range and safe to
// index, or the renderer would crash or write NaN. A violation aborts so libFuzzer keeps the input.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "apps/scene/scene_description.h"
#include "core/camera.h"
#include "core/error.h"

namespace rayo::fuzz {

[[noreturn]] inline void violated(const std::string& what) {
    std::fprintf(stderr, "scene invariant violated: %s\n", what.c_str());
    std::abort();
}

inline void expect(bool ok, const std::string& what) {
    if (!ok) violated(what);
}

// Whether every number of a registered type's fields (core/shapes/shape_fields.h) is finite.
struct FiniteFields {
    bool ok = true;
    void operator()(const char*, const Vec3& v, FieldKind) { ok = ok && finite_vec(v); }
    void operator()(const char*, const float& v, FieldKind) { ok = ok && std::isfinite(v); }
    void operator()(const char*, const Attenuation& a, FieldKind) {
        ok = ok && std::isfinite(a.d0) && std::isfinite(a.a0) && std::isfinite(a.a1) &&
             std::isfinite(a.a2) && std::isfinite(a.range);
    }
    template <typename T>
    void optional(const char* name, const T& member, FieldKind kind) {
        (*this)(name, member, kind);
    }
    static bool finite_vec(const Vec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    }
};

// Whether declared settings (core/setting.h) lie within their declarations' bounds.
struct DeclaredBounds {
    std::string broken;
    void integer(const SettingInfo& info, int v, long long min, long long max) {
        if (v < min || v > max) broken = info.name;
    }
    void real(const SettingInfo& info, float v, double min, double max) {
        // 0 under a positive range is a setting that is off until given (time_limit,
        // noise_target: the help's "default off"); a reader never gives it.
        if (v == 0.0f && min > 0.0) return;
        if (!std::isfinite(v) || v < min || v > max) broken = info.name;
    }
    void toggle(const SettingInfo&, bool) {}
    template <typename E>
    void choice(const SettingInfo&, const E&, std::initializer_list<Choice<E>>) {}
};

inline bool finite(float v) {
    return std::isfinite(v);
}
inline bool finite(const Vec3& v) {
    return finite(v.x) && finite(v.y) && finite(v.z);
}

inline void check_mesh(const TriangleMesh& mesh, size_t materials, const std::string& name) {
    for (const Vec3& p : mesh.positions) expect(finite(p), name + ": non-finite position");
    expect(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size(),
           name + ": normal count differs from position count");
    for (const Vec3& n : mesh.normals) expect(finite(n), name + ": non-finite normal");
    // Vertex colours multiply kd and ka (core/shapes/mesh.h): one per position, finite, >= 0.
    expect(mesh.colors.empty() || mesh.colors.size() == mesh.positions.size(),
           name + ": colour count differs from position count");
    for (const Vec3& c : mesh.colors) {
        expect(finite(c) && c.x >= 0.0f && c.y >= 0.0f && c.z >= 0.0f,
               name + ": non-finite or negative vertex colour");
    }
    expect(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size(),
           name + ": texture coordinate count differs from position count");
    for (const glm::vec2& uv : mesh.uvs) {
        expect(finite(uv.x) && finite(uv.y), name + ": non-finite texture coordinate");
    }
    expect(mesh.tangents.empty() || mesh.tangents.size() == mesh.positions.size(),
           name + ": tangent count differs from position count");
    expect(mesh.materials.size() == mesh.triangles.size(), name + ": material ids per triangle");
    for (const auto& t : mesh.triangles) {
        for (uint32_t i : t) expect(i < mesh.positions.size(), name + ": index past positions");
    }
    for (uint32_t m : mesh.materials) expect(m < materials, name + ": material id out of range");
}

// Checks a SceneDescription a loader returned (aborts on a violation).
inline void check_scene(const SceneDescription& d) {
    const size_t materials = d.shading.materials.size();
    for (const Sphere& s : d.scene.shapes.of<Sphere>()) {
        expect(finite(s.center) && finite(s.radius) && s.radius > 0.0f, "sphere geometry");
        expect(s.material < materials, "sphere material id out of range");
    }
    for (const Cone& c : d.scene.shapes.of<Cone>()) {
        expect(finite(c.base) && finite(c.apex) && finite(c.base_radius) && finite(c.apex_radius) &&
                   c.base_radius >= 0.0f && c.apex_radius >= 0.0f,
               "cone geometry");
        expect(c.material < materials, "cone material id out of range");
    }
    for (size_t i = 0; i < d.scene.meshes.size(); ++i) {
        check_mesh(d.scene.meshes[i], materials, "mesh " + std::to_string(i));
    }
    for (const HeightField& f : d.scene.heightfields) {
        expect(
            f.columns >= 2 && f.rows >= 2 && f.heights.size() == size_t(f.columns) * size_t(f.rows),
            "heightfield samples");
        expect(finite(f.bounds().lower) && finite(f.bounds().upper) && f.size.x > 0.0f &&
                   f.size.y > 0.0f && f.size.z > 0.0f,
               "heightfield bounds");
        expect(f.material < materials, "heightfield material id out of range");
    }
    for (const VoxelGrid& g : d.scene.voxels) {
        expect(g.dims[0] >= 2 && g.dims[1] >= 2 && g.dims[2] >= 2 &&
                   g.values.size() == size_t(g.dims[0]) * size_t(g.dims[1]) * size_t(g.dims[2]),
               "voxel grid values");
        for (float v : g.values) expect(finite(v), "voxel grid: non-finite value");
        const Vec3 voxel = g.voxel_size();
        expect(finite(g.lower) && finite(g.lower + g.size) && voxel.x > 0.0f && voxel.y > 0.0f &&
                   voxel.z > 0.0f,
               "voxel grid box");
        expect(finite(g.threshold), "voxel grid threshold");
        expect(!g.transfer.stops.empty(), "voxel grid: empty transfer");
        for (size_t i = 0; i < g.transfer.stops.size(); ++i) {
            const TransferStop& s = g.transfer.stops[i];
            expect(finite(s.value) && finite(s.color) && finite(s.density) && s.density >= 0.0f &&
                       (i == 0 || s.value >= g.transfer.stops[i - 1].value),
                   "voxel grid transfer stop");
        }
        expect(g.material < materials, "voxel grid material id out of range");
    }
    // Groups and instances (core/instance.h): the groups' objects as the scene's, every
    // instance naming a group, with a finite invertible transform and a valid material.
    for (const ShapeGroup& g : d.scene.groups) {
        expect(g.object_count() > 0, "group '" + g.name + "' is empty");
        for (const Sphere& s : g.shapes.of<Sphere>()) {
            expect(finite(s.center) && finite(s.radius) && s.radius > 0.0f, "group sphere");
            expect(s.material < materials, "group sphere material id out of range");
        }
        for (size_t i = 0; i < g.meshes.size(); ++i) {
            check_mesh(g.meshes[i], materials, "group '" + g.name + "' mesh " + std::to_string(i));
        }
    }
    for (const Instance& instance : d.scene.instances) {
        expect(instance.group < d.scene.groups.size(), "instance of a group that does not exist");
        expect(instance.material == kNoMaterialOverride || instance.material < materials,
               "instance material id out of range");
        const glm::mat4 inverse = glm::inverse(instance.transform);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) {
                expect(std::isfinite(instance.transform[c][r]) && std::isfinite(inverse[c][r]),
                       "instance transform or its inverse is not finite");
            }
        }
    }
    for (const Material& m : d.shading.materials) {
        expect(finite(m.ka) && finite(m.kd) && finite(m.ks) && finite(m.reflect) &&
                   finite(m.transmit) && finite(m.shininess) && finite(m.ior) && m.ior > 0.0f,
               "material '" + m.name + "' has a non-finite or non-positive value");
        expect(finite(m.translucency) && finite(m.absorption) && finite(m.emission) &&
                   glm::all(glm::greaterThanEqual(m.absorption, Vec3(0.0f))),
               "material '" + m.name +
                   "' has a non-finite or negative translucency/absorption/emission");
    }
    for (const Light& l : d.shading.lights) {
        std::visit(
            [&](const auto& light) {
                using L = std::decay_t<decltype(light)>;
                // Every field the light declares (shading/light.h) is finite and its
                // constraints hold (an area light's samples within kMaxAreaLightSamples, its
                // area and radiance finite): the oracle follows the registration.
                L copy = light;
                FiniteFields check;
                copy.fields(check);
                expect(check.ok && !copy.problem(), std::string(L::kName) + " light");
            },
            l);
    }
    expect(finite(d.shading.ambient_light) && finite(d.shading.background), "ambient/background");
    expect(finite(d.shading.fog.color) && std::isfinite(d.shading.fog.density) &&
               d.shading.fog.density >= 0.0f,
           "fog");
    // Every declared setting of the render and of its integrator within its declaration's
    // bounds (core/setting.h): the oracle follows the declarations, as the reader does.
    RenderSettings settings = d.settings;
    DeclaredBounds bounds;
    settings.fields(bounds);
    std::visit([&](auto& integrator) { integrator.fields(bounds); }, settings.integrator);
    expect(bounds.broken.empty() && !settings.problem(),
           "render setting out of its declared bounds: " + bounds.broken);
    // The camera may still be refused here (the CLI reports that as an InputError), but it
    // must not crash, and one it accepts must respect the resolution limits.
    try {
        const Camera camera = Camera::create(d.scene.camera, d.source + "#/camera");
        expect(camera.width() >= 1 && camera.height() >= 1 && camera.width() <= kMaxImageSide &&
                   camera.height() <= kMaxImageSide,
               "camera resolution outside the limits");
        const Ray ray = camera.generate_ray(0.0f, 0.0f);
        expect(finite(ray.origin) && finite(ray.direction), "camera ray is not finite");
    } catch (const InputError&) {
    }
}

}  // namespace rayo::fuzz
