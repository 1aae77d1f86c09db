#pragma once
// The analytic shapes rayo knows. Adding a shape is its file pair (core/shapes/NAME.h/.cpp, a
// Shape as core/shapes/shape.h describes) and its line here; the accel, the scene validation,
// the JSON reader and `rayo info` all iterate this list (docs/architecture.md).
#include "core/shapes/box.h"
#include "core/shapes/cone.h"
#include "core/shapes/disk.h"
#include "core/shapes/quadric.h"
#include "core/shapes/quadric_forms.h"
#include "core/shapes/shape_set.h"
#include "core/shapes/sphere.h"

namespace rayo {

using AnalyticShapes =
    ShapeList<Sphere, Cone, Disk, Box, Quadric, Ellipsoid, Cylinder, Paraboloid, Hyperboloid>;
using Shapes = ShapeSet<AnalyticShapes>;

}  // namespace rayo
