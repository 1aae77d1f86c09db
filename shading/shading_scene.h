#pragma once
// What the shaders need besides geometry: materials (indexed by the primitives' material ids),
// lights, procedural textures (indexed by the materials), the ambient light Ia, the background
// and the fog.
#include <cstdint>
#include <variant>
#include <vector>

#include "shading/light.h"
#include "shading/material.h"
#include "shading/media.h"
#include "shading/texture.h"

namespace rayo {

struct ShadingScene {
    std::vector<Material> materials;
    std::vector<Light> lights;
    std::vector<Texture> textures;  // MaterialTextures index this table
    Vec3 ambient_light{1.0f};       // Ia, seed 000 eq. [20]
    Vec3 background{0.0f};
    Fog fog;  // none by default (density 0)
    // The light among `lights` that rays leaving the scene reach (an EnvironmentLight, at most
    // one), or -1.
    int32_t environment = -1;

    // What a ray that leaves the scene along `direction` sees: the environment, else the
    // background colour.
    Vec3 escaped(const Vec3& direction) const {
        if (environment < 0) return background;
        return light_emitted(lights[size_t(environment)], direction, EmitterPoint{});
    }
};

}  // namespace rayo
