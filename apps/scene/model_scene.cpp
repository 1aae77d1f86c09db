#include "apps/scene/model_scene.h"

#include <cmath>
#include <string>

#include "apps/scene/mesh_loader.h"
#include "core/error.h"
#include "shading/directional_light.h"

namespace rayo {
namespace {

constexpr float kModelVfovDegrees = 40.0f;
constexpr int kModelWidth = 640, kModelHeight = 480;  // the JSON scene's default resolution
constexpr float kFrameMargin = 1.1f;                  // the bounding sphere fills 1/1.1 of the view
constexpr float kGroundHalfSize = 50.0f;  // ground square: ±50 bounding radii, near the horizon
const Vec3 kDefaultViewDirection = glm::normalize(Vec3(0.6f, 0.45f, 1.0f));
const Vec3 kModelBackground(0.18f, 0.2f, 0.24f);

struct BoundingSphere {
    Vec3 lower{0.0f}, upper{0.0f}, center{0.0f};
    float radius = 0.0f;
};

BoundingSphere bounding_sphere(const TriangleMesh& mesh) {
    BoundingSphere b;
    b.lower = b.upper = mesh.positions.front();
    for (const Vec3& p : mesh.positions) {
        b.lower = glm::min(b.lower, p);
        b.upper = glm::max(b.upper, p);
    }
    b.center = 0.5f * (b.lower + b.upper);
    b.radius = 0.5f * glm::length(b.upper - b.lower);
    return b;
}

Light directional_light(const Vec3& from, float intensity) {
    DirectionalLight light;
    light.direction = -glm::normalize(from);
    light.intensity = intensity;
    return Light(light);
}

}  // namespace

bool is_model_file(const std::string& path) {
    return is_mesh_file(path);
}

SceneDescription load_model_scene(const std::string& path, const ModelFraming& framing,
                                  const FileAccess& access) {
    SceneDescription d;
    d.source = path;
    Material fallback;
    fallback.name = "default";
    d.shading.materials.push_back(fallback);
    MeshImportOptions options;
    options.where = path;
    options.access = access;
    ImportedMesh imported = import_mesh_file(path, d.shading.materials, options);
    TriangleMesh& mesh = imported.mesh;
    d.warnings = imported.stats.warnings;
    d.skipped_triangles = imported.stats.degenerate_triangles;
    const BoundingSphere bounds = bounding_sphere(mesh);
    if (!(bounds.radius > 0.0f) || !std::isfinite(bounds.radius)) {
        throw InputError(path, "the model's bounding box must have a finite, non-zero size");
    }

    // The camera on the bounding sphere: far enough that the sphere fits the vertical field of
    // view with a margin (a landscape image then fits it horizontally too).
    const Vec3 to_eye = glm::normalize(framing.view_direction.value_or(kDefaultViewDirection));
    const float half_fov = glm::radians(0.5f * kModelVfovDegrees);
    CameraDesc& camera = d.scene.camera;
    camera.look_at = bounds.center;
    camera.eye = bounds.center + (kFrameMargin * bounds.radius / std::sin(half_fov)) * to_eye;
    camera.up = std::abs(to_eye.y) > 0.999f ? Vec3(0.0f, 0.0f, -glm::sign(to_eye.y))
                                            : Vec3(0.0f, 1.0f, 0.0f);
    camera.vfov_degrees = kModelVfovDegrees;
    camera.width = kModelWidth;
    camera.height = kModelHeight;

    // A key light from the viewer's upper left and a dimmer fill from the right, both in the
    // camera's frame so that any view direction sees the lit side.
    const Vec3 right = glm::normalize(glm::cross(camera.up, to_eye));
    const Vec3 up = glm::cross(to_eye, right);
    d.shading.lights.push_back(directional_light(-0.5f * right + 0.8f * up + 0.6f * to_eye, 0.9f));
    d.shading.lights.push_back(directional_light(0.8f * right + 0.1f * up + 0.5f * to_eye, 0.35f));
    d.shading.background = kModelBackground;

    d.scene.meshes.push_back(std::move(mesh));
    if (framing.ground) {
        // A grey square under the model's lowest point (up = +y), wide enough to catch the
        // key light's shadow.
        Material ground;
        ground.name = "ground";
        ground.kd = Vec3(0.4f);
        d.shading.materials.push_back(ground);
        const float y = bounds.lower.y, h = kGroundHalfSize * bounds.radius;
        const float x0 = bounds.center.x - h, x1 = bounds.center.x + h;
        const float z0 = bounds.center.z - h, z1 = bounds.center.z + h;
        TriangleMesh floor;
        floor.add_convex_polygon(
            {Vec3(x0, y, z1), Vec3(x1, y, z1), Vec3(x1, y, z0), Vec3(x0, y, z0)}, {},
            static_cast<uint32_t>(d.shading.materials.size() - 1));
        d.scene.meshes.push_back(std::move(floor));
    }
    return d;
}

}  // namespace rayo
