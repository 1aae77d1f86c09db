#include "core/shapes/height_field_geometry.h"

#include "core/user_geometry.h"

namespace rayo {

std::unique_ptr<GeometryBinding> make_height_field_binding(const HeightField& field,
                                                           uint32_t field_index,
                                                           uint32_t shape_index) {
    return std::make_unique<ObjectBinding<HeightField>>(field, field_index, shape_index,
                                                        field.cell_count() * 2);
}

}  // namespace rayo
