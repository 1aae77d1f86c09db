#include "apps/scene/area_light_emitters.h"

#include <memory>
#include <string>
#include <variant>

namespace rayo {

void add_area_light_emitters(SceneDescription& d) {
    for (size_t i = 0; i < d.shading.lights.size(); ++i) {
        const auto* light = std::get_if<AreaLight>(&d.shading.lights[i]);
        if (!light || light->shape == AreaLight::Shape::Mesh) continue;
        Material m;
        m.name = "light " + std::to_string(i);
        m.ka = m.kd = m.ks = Vec3(0.0f);
        m.emission = light->radiance();
        m.emitter_light = static_cast<int32_t>(i);
        m.double_sided = false;  // an area light emits on its front only (shading/area_light.h)
        const auto id = static_cast<uint32_t>(d.shading.materials.size());
        d.shading.materials.push_back(m);
        switch (light->shape) {
            case AreaLight::Shape::Disk:
                d.scene.shapes.of<Disk>().push_back(
                    {light->center, light->normal, light->radius, id});
                break;
            case AreaLight::Shape::Sphere:
                d.scene.shapes.of<Sphere>().push_back({light->center, light->radius, id});
                break;
            case AreaLight::Shape::Mesh:  // its triangles are in the scene already
                break;
            case AreaLight::Shape::Rectangle: {
                // Counter-clockwise seen from the emitting side: the winding normal is
                // edge1 × edge2.
                TriangleMesh mesh;
                mesh.name = m.name;
                const Vec3 c = light->corner, e1 = light->edge1, e2 = light->edge2;
                mesh.add_convex_polygon({c, c + e1, c + e1 + e2, c + e2}, {}, id);
                d.scene.meshes.push_back(std::move(mesh));
                break;
            }
        }
    }
}

size_t add_mesh_emitter_light(SceneDescription& d, int samples) {
    std::vector<Material>& materials = d.shading.materials;
    std::vector<bool> emitting(materials.size(), false);
    auto emitter = std::make_shared<MeshEmitter>();
    auto add_mesh = [&](const TriangleMesh& mesh, const glm::mat4* transform,
                        uint32_t material_override) {
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            const uint32_t id =
                material_override != kNoMaterialOverride ? material_override : mesh.materials[t];
            if (id >= materials.size() || !materials[id].emissive()) continue;
            Vec3 p[3];
            for (int k = 0; k < 3; ++k) {
                p[k] = mesh.positions[mesh.triangles[t][k]];
                if (transform) p[k] = Vec3(*transform * glm::vec4(p[k], 1.0f));
            }
            const Material& m = materials[id];
            emitting[id] = true;
            if (m.images.emission.used() && !mesh.uvs.empty()) {
                // The emission image multiplies the factor at the sampled point.
                const auto& v = mesh.triangles[t];
                emitter->add(p[0], p[1], p[2], m.emission, id, mesh.uvs[v[0]], mesh.uvs[v[1]],
                             mesh.uvs[v[2]], m.double_sided);
            } else {
                emitter->add(p[0], p[1], p[2], m.emission, m.double_sided);
            }
        }
    };
    for (const TriangleMesh& mesh : d.scene.meshes) add_mesh(mesh, nullptr, kNoMaterialOverride);
    for (const Instance& instance : d.scene.instances) {
        for (const TriangleMesh& mesh : d.scene.groups[instance.group].meshes) {
            add_mesh(mesh, &instance.transform, instance.material);
        }
    }
    if (emitter->empty()) return 0;
    emitter->finish();
    AreaLight light;
    light.shape = AreaLight::Shape::Mesh;
    light.samples = samples;
    light.mesh = emitter;
    for (size_t id = 0; id < materials.size(); ++id) {
        if (emitting[id])
            materials[id].emitter_light = static_cast<int32_t>(d.shading.lights.size());
    }
    d.shading.lights.push_back(light);
    return emitter->size();
}

}  // namespace rayo
