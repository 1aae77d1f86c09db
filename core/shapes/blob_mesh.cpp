#include "core/shapes/blob_mesh.h"

#include <cmath>

#include "core/shapes/marching_tetrahedra.h"

namespace rayo {

TriangleMesh tessellate_blob(const Blob& blob, double cell) {
    // The field F − threshold on a lattice one cell beyond the blob's bounds on every side.
    SampledField field;
    const Bounds3 b = blob.bounds();
    field.lower = DVec3(b.lower) - DVec3(cell);
    field.cell = DVec3(cell);
    const DVec3 extent = DVec3(b.upper) - DVec3(b.lower) + DVec3(2.0 * cell);
    for (int axis = 0; axis < 3; ++axis)
        field.counts[axis] = int(std::ceil(extent[axis] / cell)) + 1;
    field.samples.reserve(size_t(field.counts[0]) * size_t(field.counts[1]) *
                          size_t(field.counts[2]));
    for (int k = 0; k < field.counts[2]; ++k) {
        for (int j = 0; j < field.counts[1]; ++j) {
            for (int i = 0; i < field.counts[0]; ++i) {
                field.samples.push_back(blob.field(field.lower + field.cell * DVec3(i, j, k)) -
                                        blob.threshold);
            }
        }
    }
    field.outward = [&blob](const DVec3& p) {
        const DVec3 outward = -blob.gradient(p);
        const double length = glm::length(outward);
        return Vec3(length > 0.0 ? outward / length : DVec3(0.0, 1.0, 0.0));
    };
    return marching_tetrahedra(field, blob.material, "blob");
}

}  // namespace rayo
