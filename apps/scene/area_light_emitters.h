#pragma once
// Area lights made visible: each area light's surface becomes an object of the scene with an
// emissive material (radiance L = color·intensity on its emitting side, black elsewhere), so that
// camera and reflection rays see the light (seed 004: "emissive objects to see lights").
#include "apps/scene/scene_description.h"

namespace rayo {

// Appends, for every AreaLight of d.shading.lights, a material named after the light ("light N")
// and its surface: a disk, a sphere, or a rectangle as a two-triangle mesh. The light's own
// shadow rays stop short of its surface (WhittedIntegrator::light_sample).
void add_area_light_emitters(SceneDescription& d);

// The other way round: triangles of the scene whose material emits (MTL Ke, glTF
// emissiveFactor), placed directly or through instances, become one AreaLight of shape Mesh
// (shading/area_light.h: sampled by power, `samples` points per shading point), so that they
// light the scene with shadows besides being seen. Returns the emissive triangle count (0: no
// light added).
size_t add_mesh_emitter_light(SceneDescription& d, int samples = 16);

}  // namespace rayo
