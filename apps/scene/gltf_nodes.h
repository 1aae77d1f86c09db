#pragma once
// What a glTF file's nodes place besides flattened triangles (docs/models.md): the cameras and
// the KHR_lights_punctual lights of the default scene, in world space, and — when asked — the
// meshes that several nodes reference, kept once in their own space with one placement per node
// (rendered as instances, core/instance.h). load_gltf (apps/scene/mesh_loader.h) fills it.
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <string>
#include <vector>

#include "core/shapes/mesh.h"

namespace tinygltf {
class Model;
class Node;
}  // namespace tinygltf

namespace rayo {

// A camera node: the glTF camera looks down the node's −Z with +Y up (glTF 2.0, 3.10.1).
struct GltfCamera {
    std::string name;  // the camera's name, else the node's, else "camera N"
    std::string node_name;
    bool orthographic = false;
    Vec3 position{0.0f}, forward{0.0f, 0.0f, -1.0f}, up{0.0f, 1.0f, 0.0f};  // world, unit
    float yfov_radians = 0.0f;                                              // perspective
    float aspect_ratio = 0.0f;       // perspective: 0 when the file gives none
    float xmag = 0.0f, ymag = 0.0f;  // orthographic half-extents
};

// A KHR_lights_punctual light node: it shines down the node's −Z (spot, directional).
struct GltfLight {
    enum class Type { Point, Spot, Directional };
    std::string name;  // the light's name, else "light N"
    Type type = Type::Point;
    Vec3 color{1.0f};
    float intensity = 1.0f;  // candela (point, spot) or lux (directional)
    float range = 0.0f;      // 0: infinite
    float inner_cone = 0.0f, outer_cone = 0.78539816f;  // spot, radians
    Vec3 position{0.0f}, direction{0.0f, 0.0f, -1.0f};  // world; direction unit
};

struct GltfNodes {
    // Input: keep meshes that more than one node references as `shared_meshes`.
    bool instance_shared_meshes = false;

    std::vector<GltfCamera> cameras;  // in the order the scene's nodes are visited
    std::vector<GltfLight> lights;
    // Output with instance_shared_meshes: each reused glTF mesh once, in its own space (the
    // flattened mesh then holds only the meshes placed once), and its placements.
    std::vector<TriangleMesh> shared_meshes;
    struct Placement {
        uint32_t mesh = 0;  // index in shared_meshes
        glm::mat4 transform{1.0f};
    };
    std::vector<Placement> placements;
};

// The camera or light a node carries, if any, appended to `nodes` (errors name `path`).
void collect_gltf_node_items(const tinygltf::Model& model, const tinygltf::Node& node,
                             int node_index, const glm::dmat4& world, const std::string& path,
                             GltfNodes& nodes);

}  // namespace rayo
