#pragma once
// What render_scene gives every integrator it builds (shading/integrators/integrator.h): the
// traced scene, its shading data, and the pre-passes and image textures the render made.
#include "core/accel.h"
#include "shading/image_texture.h"
#include "shading/radiosity_field.h"
#include "shading/shading_scene.h"

namespace rayo {

struct IntegratorContext {
    const Accel& accel;
    const ShadingScene& scene;
    // Radiosity's first pass (docs/radiosity.md), when the render asked for it (--gi radiosity):
    // a pre-pass any integrator can use; null otherwise.
    const RadiosityField* radiosity = nullptr;
    // The materials' image textures (shading/image_texture.h); null when no material has one.
    const ImageTextures* images = nullptr;
    // The angle one pixel's samples spread over, radians (the camera's pixel angle / √spp): the
    // footprint image textures are filtered over (docs/textures.md); 0 without images.
    float pixel_spread = 0.0f;
};

}  // namespace rayo
