#pragma once
// The analytic shapes rayo knows. Adding a shape is its file pair (core/shapes/NAME.h/.cpp, a
// Shape as core/shapes/shape.h describes) and its line in core/shapes/primitives.h (a composite
// shape, made of others: here); the accel, the scene validation, the JSON reader and `rayo info`
// all iterate this list (docs/architecture.md).
#include "core/shapes/csg.h"
#include "core/shapes/primitives.h"
#include "core/shapes/shape_set.h"

namespace rayo {

template <typename List, typename... More>
struct AppendShapes;
template <typename... S, typename... More>
struct AppendShapes<ShapeList<S...>, More...> {
    using type = ShapeList<S..., More...>;
};

// The composites come last: the primitives keep their indices (SurfaceHit::shape).
using AnalyticShapes = typename AppendShapes<PrimitiveShapes, Csg>::type;
using Shapes = ShapeSet<AnalyticShapes>;

}  // namespace rayo
