#include "apps/scene/gltf_nodes.h"

#include <tiny_gltf.h>

#include <cmath>

#include "core/error.h"

namespace rayo {
namespace {

Vec3 world_point(const glm::dmat4& world, const glm::dvec3& p) {
    return Vec3(world * glm::dvec4(p, 1.0));
}

// A direction of the node's space in the world, unit (zero when the transform collapses it).
Vec3 world_direction(const glm::dmat4& world, const glm::dvec3& d) {
    const glm::dvec3 w = glm::dvec3(world * glm::dvec4(d, 0.0));
    const double length = glm::length(w);
    return length > 0.0 && std::isfinite(length) ? Vec3(w / length) : Vec3(0.0f);
}

std::string named(const std::string& name, const std::string& fallback) {
    return name.empty() ? fallback : name;
}

bool positive_finite(double v) {
    return std::isfinite(v) && v > 0.0;
}

void add_camera(const tinygltf::Model& model, const tinygltf::Node& node, int node_index,
                const glm::dmat4& world, const std::string& path, GltfNodes& nodes) {
    const std::string what =
        "node " + std::to_string(node_index) + ": camera " + std::to_string(node.camera);
    if (static_cast<size_t>(node.camera) >= model.cameras.size()) {
        throw InputError(path, what + " does not exist");
    }
    const tinygltf::Camera& c = model.cameras[static_cast<size_t>(node.camera)];
    GltfCamera camera;
    camera.name = named(c.name, named(node.name, "camera " + std::to_string(nodes.cameras.size())));
    camera.node_name = node.name;
    camera.position = world_point(world, glm::dvec3(0.0));
    camera.forward = world_direction(world, glm::dvec3(0.0, 0.0, -1.0));
    camera.up = world_direction(world, glm::dvec3(0.0, 1.0, 0.0));
    if (camera.forward == Vec3(0.0f) || camera.up == Vec3(0.0f)) {
        throw InputError(path, what + ": the node's transform collapses the view direction");
    }
    if (c.type == "orthographic") {
        camera.orthographic = true;
        if (!positive_finite(std::abs(c.orthographic.xmag)) ||
            !positive_finite(std::abs(c.orthographic.ymag))) {
            throw InputError(path, what + ": xmag and ymag must be finite and non-zero");
        }
        camera.xmag = static_cast<float>(std::abs(c.orthographic.xmag));
        camera.ymag = static_cast<float>(std::abs(c.orthographic.ymag));
    } else if (c.type == "perspective") {
        const double yfov = c.perspective.yfov;
        if (!positive_finite(yfov) || yfov >= M_PI) {
            throw InputError(
                path, what + ": yfov must be in (0, π) radians, got " + std::to_string(yfov));
        }
        camera.yfov_radians = static_cast<float>(yfov);
        const double aspect = c.perspective.aspectRatio;
        if (aspect != 0.0 && !positive_finite(aspect)) {
            throw InputError(path, what + ": aspectRatio must be > 0");
        }
        camera.aspect_ratio = static_cast<float>(aspect);
    } else {
        throw InputError(path, what + ": unknown camera type '" + c.type + "'");
    }
    nodes.cameras.push_back(camera);
}

void add_light(const tinygltf::Model& model, int light_index, int node_index,
               const glm::dmat4& world, const std::string& path, GltfNodes& nodes) {
    const std::string what = "node " + std::to_string(node_index) + ": KHR_lights_punctual light " +
                             std::to_string(light_index);
    if (light_index < 0 || static_cast<size_t>(light_index) >= model.lights.size()) {
        throw InputError(path, what + " does not exist");
    }
    const tinygltf::Light& l = model.lights[static_cast<size_t>(light_index)];
    GltfLight light;
    light.name = named(l.name, "light " + std::to_string(light_index));
    if (l.type == "point") {
        light.type = GltfLight::Type::Point;
    } else if (l.type == "spot") {
        light.type = GltfLight::Type::Spot;
    } else if (l.type == "directional") {
        light.type = GltfLight::Type::Directional;
    } else {
        throw InputError(path, what + ": unknown light type '" + l.type + "'");
    }
    if (!l.color.empty()) {
        if (l.color.size() != 3) throw InputError(path, what + ": color must have 3 components");
        for (int i = 0; i < 3; ++i) {
            const double c = l.color[static_cast<size_t>(i)];
            if (!std::isfinite(c) || c < 0.0) {
                throw InputError(path, what + ": color must be finite and >= 0");
            }
            light.color[i] = static_cast<float>(c);
        }
    }
    if (!std::isfinite(l.intensity) || l.intensity < 0.0) {
        throw InputError(path, what + ": intensity must be finite and >= 0");
    }
    light.intensity = static_cast<float>(l.intensity);
    if (!std::isfinite(l.range) || l.range < 0.0) {
        throw InputError(path, what + ": range must be finite and > 0");
    }
    light.range = static_cast<float>(l.range);
    if (light.type == GltfLight::Type::Spot) {
        const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
        // KHR_lights_punctual: 0 <= innerConeAngle < outerConeAngle <= π/2.
        if (!(inner >= 0.0) || !(outer > inner) || !(outer <= 0.5 * M_PI + 1e-9)) {
            throw InputError(path, what +
                                       ": spot cone angles must satisfy 0 <= innerConeAngle < "
                                       "outerConeAngle <= π/2");
        }
        light.inner_cone = static_cast<float>(inner);
        light.outer_cone = static_cast<float>(outer);
    }
    light.position = world_point(world, glm::dvec3(0.0));
    light.direction = world_direction(world, glm::dvec3(0.0, 0.0, -1.0));
    if (light.type != GltfLight::Type::Point && light.direction == Vec3(0.0f)) {
        throw InputError(path, what + ": the node's transform collapses the light's direction");
    }
    nodes.lights.push_back(light);
}

}  // namespace

void collect_gltf_node_items(const tinygltf::Model& model, const tinygltf::Node& node,
                             int node_index, const glm::dmat4& world, const std::string& path,
                             GltfNodes& nodes) {
    if (node.camera >= 0) add_camera(model, node, node_index, world, path, nodes);
    const auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext != node.extensions.end() && ext->second.Has("light")) {
        const tinygltf::Value& index = ext->second.Get("light");
        if (!index.IsInt()) {
            throw InputError(path, "node " + std::to_string(node_index) +
                                       ": KHR_lights_punctual light must be an index");
        }
        add_light(model, index.Get<int>(), node_index, world, path, nodes);
    }
}

}  // namespace rayo
