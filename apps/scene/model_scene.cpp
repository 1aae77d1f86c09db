#include "apps/scene/model_scene.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "apps/scene/area_light_emitters.h"
#include "apps/scene/mesh_loader.h"
#include "core/error.h"
#include "core/math.h"
#include "core/scene_bounds.h"
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

// The box of everything placed (core/scene_bounds.h, as `rayo info` prints it) and its sphere.
BoundingSphere bounding_sphere(const Scene& scene) {
    BoundingSphere b;
    if (const std::optional<Bounds3> box = scene_bounds(scene)) {
        b.lower = box->lower;
        b.upper = box->upper;
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

// The camera on the bounding sphere: far enough that the sphere fits the vertical field of
// view with a margin (a landscape image then fits it horizontally too).
void frame_automatically(const BoundingSphere& bounds, const Vec3& to_eye, CameraDesc& camera) {
    const float half_fov = glm::radians(0.5f * kModelVfovDegrees);
    camera.look_at = bounds.center;
    camera.eye = bounds.center + (kFrameMargin * bounds.radius / std::sin(half_fov)) * to_eye;
    camera.up = std::abs(to_eye.y) > 0.999f ? Vec3(0.0f, 0.0f, -glm::sign(to_eye.y))
                                            : Vec3(0.0f, 1.0f, 0.0f);
    camera.vfov_degrees = kModelVfovDegrees;
    camera.width = kModelWidth;
    camera.height = kModelHeight;
}

std::string camera_list(const std::vector<GltfCamera>& cameras) {
    if (cameras.empty()) return "the file has no cameras (only \"auto\" is accepted)";
    std::ostringstream list;
    list << "the file's cameras are:";
    for (size_t i = 0; i < cameras.size(); ++i) {
        list << (i ? "," : "") << " " << i << " '" << cameras[i].name << "'";
        if (!cameras[i].node_name.empty() && cameras[i].node_name != cameras[i].name) {
            list << " (node '" << cameras[i].node_name << "')";
        }
    }
    return list.str() + ", or \"auto\"";
}

// The camera `choice` names: by the camera's or node's name first, then by index.
const GltfCamera* find_camera(const std::vector<GltfCamera>& cameras, const std::string& choice,
                              const std::string& path) {
    for (const GltfCamera& c : cameras) {
        if (c.name == choice || (!c.node_name.empty() && c.node_name == choice)) return &c;
    }
    if (!choice.empty() &&
        std::all_of(choice.begin(), choice.end(), [](char ch) { return ch >= '0' && ch <= '9'; })) {
        const size_t index = choice.size() < 10 ? std::stoul(choice) : cameras.size();
        if (index < cameras.size()) return &cameras[index];
    }
    throw InputError(path, "--camera: no camera '" + choice + "'; " + camera_list(cameras));
}

// A glTF camera as rayo's. The vertical field of view is the file's yfov whatever the output's
// shape: the default resolution is 480 rows by 480·aspectRatio columns, and another aspect
// (--width/--height) widens or narrows the horizontal field (znear and zfar are not used:
// rayo's rays start at the eye and are unbounded). An orthographic camera, which rayo's camera
// model lacks, becomes a perspective camera at its place showing its height 2·ymag at the
// model's centre (a warning says so).
void use_file_camera(const GltfCamera& c, const BoundingSphere& bounds, SceneDescription& d) {
    CameraDesc& camera = d.scene.camera;
    const float depth = glm::dot(bounds.center - c.position, c.forward);
    camera.eye = c.position;
    camera.look_at = c.position + (depth > 0.0f ? depth : bounds.radius) * c.forward;
    camera.up = c.up;
    float aspect = c.aspect_ratio;
    if (c.orthographic) {
        const float vfov =
            depth > 0.0f ? 2.0f * std::atan(c.ymag / depth) : glm::radians(kModelVfovDegrees);
        camera.vfov_degrees = glm::degrees(vfov);
        aspect = c.xmag / c.ymag;
        std::ostringstream w;
        w << d.source << ": camera '" << c.name
          << "' is orthographic, which rayo's camera model does not have; rendered as a "
             "perspective camera at its place with a vertical field of view of "
          << *camera.vfov_degrees << " degrees (its height 2·ymag = " << 2.0f * c.ymag
          << " at the model's centre)";
        d.warnings.push_back(w.str());
    } else {
        camera.vfov_degrees = glm::degrees(c.yfov_radians);
    }
    camera.height = kModelHeight;
    camera.width = aspect > 0.0f ? std::clamp(static_cast<int>(std::lround(kModelHeight * aspect)),
                                              1, kMaxImageSide)
                                 : kModelWidth;
}

// KHR_lights_punctual onto rayo's lights. glTF gives luminous intensity I (candela) for point
// and spot lights and illuminance E (lux) for directional ones; one glTF unit is one unit of
// rayo's radiance (a pixel value of 1 is 1 nit; no 683 lm/W factor). rayo's point and
// directional lights give a Lambertian surface kd·intensity·cos θ (seed 000's Il, no 1/π), while
// a surface of albedo kd lit by E reflects the radiance kd·E/π: so intensity = I/π with the
// inverse-square falloff (windowed by `range`), and E/π for directional lights — the same
// convention as rayo's area lights and emissive surfaces (kd·E/π).
Light rayo_light(const GltfLight& g) {
    const float intensity = g.intensity / kPi;
    Attenuation falloff;
    falloff.kind = Attenuation::Kind::InverseSquare;
    falloff.range = g.range;
    switch (g.type) {
        case GltfLight::Type::Directional: {
            DirectionalLight light;
            light.direction = g.direction;
            light.color = g.color;
            light.intensity = intensity;
            return light;
        }
        case GltfLight::Type::Spot: {
            SpotLight light;
            light.position = g.position;
            light.direction = g.direction;
            light.color = g.color;
            light.intensity = intensity;
            light.attenuation = falloff;
            light.cos_inner = std::cos(g.inner_cone);
            light.cos_outer = std::cos(g.outer_cone);
            return light;
        }
        case GltfLight::Type::Point:
            break;
    }
    PointLight light;
    light.position = g.position;
    light.color = g.color;
    light.intensity = intensity;
    light.attenuation = falloff;
    return light;
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
    GltfNodes nodes;
    nodes.instance_shared_meshes = framing.instances;
    options.gltf_nodes = &nodes;
    ImportedMesh imported = import_mesh_file(path, d.shading.materials, options);
    d.warnings = imported.stats.warnings;
    d.skipped_triangles = imported.stats.degenerate_triangles;
    if (!imported.mesh.triangles.empty()) d.scene.meshes.push_back(std::move(imported.mesh));
    // Meshes several nodes share: one group each, one instance per node (core/instance.h).
    for (TriangleMesh& shared : nodes.shared_meshes) {
        ShapeGroup group;
        group.name = shared.name;
        group.meshes.push_back(std::move(shared));
        d.scene.groups.push_back(std::move(group));
    }
    for (const GltfNodes::Placement& p : nodes.placements) {
        Instance instance;
        instance.group = p.mesh;
        instance.transform = p.transform;
        d.scene.instances.push_back(instance);
    }
    const BoundingSphere bounds = bounding_sphere(d.scene);
    if (!(bounds.radius > 0.0f) || !std::isfinite(bounds.radius)) {
        throw InputError(path, "the model's bounding box must have a finite, non-zero size");
    }

    // The file's camera (the one --camera names, else the first) or the automatic framing.
    d.file_cameras = nodes.cameras;
    const GltfCamera* file_camera = nullptr;
    if (framing.camera && *framing.camera != "auto") {
        file_camera = find_camera(nodes.cameras, *framing.camera, path);
    } else if (!framing.camera && !framing.view_direction && !nodes.cameras.empty()) {
        file_camera = &nodes.cameras.front();
    }
    const Vec3 to_eye = glm::normalize(framing.view_direction.value_or(kDefaultViewDirection));
    if (file_camera) {
        use_file_camera(*file_camera, bounds, d);
    } else {
        frame_automatically(bounds, to_eye, d.scene.camera);
    }
    d.shading.background = kModelBackground;

    // The file's lights, its emissive triangles as an area light, and the automatic key and
    // fill lights when the file has neither and no environment lights it (or --auto-lights).
    for (const GltfLight& light : nodes.lights) {
        d.shading.lights.push_back(rayo_light(light));
        d.light_names.push_back(light.name);
    }
    if (add_mesh_emitter_light(d) > 0) d.light_names.push_back("emissive triangles");
    if ((d.shading.lights.empty() && !framing.environment_lit) || framing.auto_lights) {
        // A key light from the viewer's upper left and a dimmer fill from the right, both in
        // the camera's frame so that any view direction sees the lit side.
        const CameraDesc& camera = d.scene.camera;
        const Vec3 view = file_camera ? -file_camera->forward : to_eye;
        const Vec3 right = glm::normalize(glm::cross(camera.up, view));
        const Vec3 up = glm::cross(view, right);
        d.shading.lights.push_back(
            directional_light(-0.5f * right + 0.8f * up + 0.6f * view, 0.9f));
        d.shading.lights.push_back(
            directional_light(0.8f * right + 0.1f * up + 0.5f * view, 0.35f));
        d.light_names.push_back("key");
        d.light_names.push_back("fill");
    }

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
