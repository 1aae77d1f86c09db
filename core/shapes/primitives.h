#pragma once
// The analytic shapes that are not made of other shapes: the children CSG may take
// (core/shapes/csg.h). Adding such a shape is its file pair and its entry here; the registry
// (core/shapes/registry.h) adds the composite shapes after them.
#include <variant>

#include "core/shapes/blob.h"
#include "core/shapes/box.h"
#include "core/shapes/cone.h"
#include "core/shapes/disk.h"
#include "core/shapes/quadric.h"
#include "core/shapes/quadric_forms.h"
#include "core/shapes/shape_set.h"
#include "core/shapes/sphere.h"

namespace rayo {

using PrimitiveShapes =
    ShapeList<Sphere, Cone, Disk, Box, Quadric, Ellipsoid, Cylinder, Paraboloid, Hyperboloid, Blob>;

// One shape of a list, any type: std::variant<S...>, and the variant of their intersectors
// (core/shapes/shape.h; several types may share one, as the quadrics share ClippedQuadric, so
// it is built by index).
template <typename List>
struct ShapeVariants;
template <typename... S>
struct ShapeVariants<ShapeList<S...>> {
    using Shape = std::variant<S...>;
    using Intersector = std::variant<typename ShapeTraits<S>::Intersector...>;
    template <typename T>
    static Intersector intersector_of(const T& shape) {
        constexpr size_t index = index_in_pack<T, S...>();
        if constexpr (ShapeTraits<T>::kSelfIntersecting) {
            return Intersector(std::in_place_index<index>, shape);
        } else {
            return Intersector(std::in_place_index<index>, shape.intersector());
        }
    }
};

// Whether a shape bounds a solid: its closed() (core/shapes/shape.h); a shape without one is
// open.
template <typename S, typename = void>
struct HasClosed : std::false_type {};
template <typename S>
struct HasClosed<S, std::void_t<decltype(std::declval<const S&>().closed())>> : std::true_type {};
template <typename S>
bool is_closed(const S& shape) {
    if constexpr (HasClosed<S>::value) {
        return shape.closed();
    } else {
        return false;
    }
}

}  // namespace rayo
