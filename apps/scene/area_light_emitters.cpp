#include "apps/scene/area_light_emitters.h"

#include <string>
#include <variant>

namespace rayo {

void add_area_light_emitters(SceneDescription& d) {
    for (size_t i = 0; i < d.shading.lights.size(); ++i) {
        const auto* light = std::get_if<AreaLight>(&d.shading.lights[i]);
        if (!light) continue;
        Material m;
        m.name = "light " + std::to_string(i);
        m.ka = m.kd = m.ks = Vec3(0.0f);
        m.emission = light->radiance();
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

}  // namespace rayo
