#include "core/shapes/blob_mesh.h"

#include <algorithm>
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

double blob_mesh_chord(const Blob& blob, const TriangleMesh& mesh) {
    double chord = 0.0;
    for (const auto& t : mesh.triangles) {
        const DVec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        for (int i = 0; i <= 3; ++i) {
            for (int j = 0; i + j <= 3; ++j) {
                const DVec3 p = (double(i) * a + double(j) * b + double(3 - i - j) * c) / 3.0;
                const double slope = glm::length(blob.gradient(p));
                const double g = std::abs(blob.field(p) - blob.threshold);
                if (g > 0.0) chord = std::max(chord, slope > 0.0 ? g / slope : HUGE_VAL);
            }
        }
    }
    return chord;
}

MeshForm blob_mesh_form(const Blob& blob, float max_chord, int max_cells) {
    const Bounds3 b = blob.bounds();
    const double extent = double(max_abs_component(b.upper - b.lower));
    // The smallest sphere a lone element makes (half the smallest support radius when none is
    // strong enough alone).
    double rho = HUGE_VAL;
    for (const BlobElement& e : blob.elements) {
        if (e.strength <= 0.0f) continue;
        const double r = Blob::sphere_radius(e, blob.threshold);
        rho = std::min(rho, r > 0.0 ? r : 0.5 * double(e.radius));
    }
    const double coarsest = std::min(rho / 2.0, std::sqrt(8.0 * rho * double(max_chord) / 3.0));
    const double finest = extent / double(max_cells);
    double cell = std::max(coarsest, finest);
    MeshForm form;
    for (int attempt = 0; attempt < 4; ++attempt) {
        form.mesh = tessellate_blob(blob, cell);
        form.chord = float(blob_mesh_chord(blob, form.mesh));
        if (form.chord <= max_chord || cell <= finest) break;
        cell = std::max(finest, cell * std::sqrt(0.9 * double(max_chord) / double(form.chord)));
    }
    return form;
}

}  // namespace rayo
