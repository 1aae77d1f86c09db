#include "apps/scene/default_scene.h"

#include <cmath>

namespace rayo {
namespace {

uint32_t add_material(ShadingScene& shading, Material m) {
    shading.materials.push_back(std::move(m));
    return static_cast<uint32_t>(shading.materials.size() - 1);
}

// A regular octahedron of circumradius r around `center`: 6 vertices, 8 flat faces.
TriangleMesh make_octahedron(const Vec3& center, float r, uint32_t material) {
    TriangleMesh mesh;
    mesh.name = "octahedron";
    const Vec3 px(r, 0, 0), py(0, r, 0), pz(0, 0, r);
    const Vec3 corners[6] = {center + px, center - px, center + py,
                             center - py, center + pz, center - pz};
    // Faces counter-clockwise seen from outside (right-handed).
    const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                             {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (const auto& f : faces) {
        mesh.add_convex_polygon({corners[f[0]], corners[f[1]], corners[f[2]]}, {}, material);
    }
    return mesh;
}

}  // namespace

SceneDescription make_default_scene() {
    SceneDescription d;
    d.source = "<default>";
    CameraDesc& camera = d.scene.camera;
    camera.eye = Vec3(0.0f, 1.6f, 6.5f);
    camera.look_at = Vec3(0.0f, 0.7f, 0.0f);
    camera.up = Vec3(0.0f, 1.0f, 0.0f);
    camera.vfov_degrees = 38.0f;
    camera.width = 800;
    camera.height = 600;

    ShadingScene& shading = d.shading;
    shading.background = Vec3(0.55f, 0.70f, 0.90f);
    shading.ambient_light = Vec3(1.0f);

    Material floor;
    floor.name = "floor";
    floor.kd = Vec3(0.75f, 0.72f, 0.65f);
    floor.ka = 0.1f * floor.kd;
    const uint32_t floor_id = add_material(shading, floor);

    Material red;
    red.name = "red plastic";
    red.kd = Vec3(0.8f, 0.12f, 0.1f);
    red.ka = 0.1f * red.kd;
    red.ks = Vec3(0.6f);
    red.shininess = 60.0f;
    const uint32_t red_id = add_material(shading, red);

    Material mirror;
    mirror.name = "mirror";
    mirror.kd = Vec3(0.05f);
    mirror.ka = Vec3(0.0f);
    mirror.ks = Vec3(0.8f);
    mirror.shininess = 200.0f;
    mirror.reflect = Vec3(0.85f);
    const uint32_t mirror_id = add_material(shading, mirror);

    Material glass;
    glass.name = "glass";
    glass.kd = Vec3(0.0f);
    glass.ka = Vec3(0.0f);
    glass.ks = Vec3(0.9f);
    glass.shininess = 300.0f;
    glass.reflect = Vec3(0.08f);
    glass.transmit = Vec3(0.9f);
    glass.ior = 1.5f;
    const uint32_t glass_id = add_material(shading, glass);

    Material blue;
    blue.name = "blue blinn";
    blue.kd = Vec3(0.15f, 0.3f, 0.85f);
    blue.ka = 0.1f * blue.kd;
    blue.ks = Vec3(0.4f);
    blue.shininess = 80.0f;
    blue.specular_model = SpecularModel::Blinn;
    const uint32_t blue_id = add_material(shading, blue);

    d.scene.shapes.of<Sphere>().push_back({Vec3(-1.7f, 0.8f, -0.6f), 0.8f, red_id});
    d.scene.shapes.of<Sphere>().push_back({Vec3(0.2f, 1.0f, -1.6f), 1.0f, mirror_id});
    d.scene.shapes.of<Sphere>().push_back({Vec3(0.9f, 0.6f, 1.1f), 0.6f, glass_id});
    d.scene.shapes.of<Sphere>().push_back({Vec3(-0.5f, 0.3f, 1.4f), 0.3f, red_id});

    TriangleMesh ground;
    ground.name = "floor";
    const float e = 12.0f;
    ground.add_convex_polygon({Vec3(-e, 0, e), Vec3(e, 0, e), Vec3(e, 0, -e), Vec3(-e, 0, -e)}, {},
                              floor_id);
    d.scene.meshes.push_back(std::move(ground));
    d.scene.meshes.push_back(make_octahedron(Vec3(2.1f, 0.75f, -0.5f), 0.75f, blue_id));

    PointLight key;
    key.position = Vec3(-4.0f, 7.0f, 5.0f);
    key.intensity = 0.9f;
    shading.lights.push_back(key);
    DirectionalLight fill;
    fill.direction = glm::normalize(Vec3(1.0f, -1.5f, -0.5f));
    fill.intensity = 0.35f;
    fill.color = Vec3(1.0f, 0.95f, 0.85f);
    shading.lights.push_back(fill);
    return d;
}

}  // namespace rayo
