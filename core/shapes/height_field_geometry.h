#pragma once
// A HeightField as Embree user geometry (the `dda` method, docs/heightfields.md): one primitive
// whose intersection runs the field's grid traversal through the generic callbacks of
// core/user_geometry.h; the hit's triangle travels as the primitive id (ShapeHit::part).
#include <memory>

#include "core/geometry_binding.h"
#include "core/shapes/height_field.h"

namespace rayo {

// `field_index` goes to SurfaceHit::mesh; `shape_index` to SurfaceHit::shape.
std::unique_ptr<GeometryBinding> make_height_field_binding(const HeightField& field,
                                                           uint32_t field_index,
                                                           uint32_t shape_index);

}  // namespace rayo
