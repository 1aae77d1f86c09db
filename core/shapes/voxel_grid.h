#pragma once
// Voxel data traced by directional 3-D DDA (seed 004: "voxel data by directional traversal";
// Amanatides & Woo 1987, core/grid_walk.h): the scene file's `voxels` objects (docs/voxels.md).
// Values sit at voxel centres and are interpolated trilinearly between them. Two modes:
//   - surface: the iso-surface value = threshold, values above it inside. The walk goes over
//     the cells between voxel centres (the dual grid), skips cells whose eight corner values do
//     not straddle the threshold, and finds the first root of the trilinear interpolant along
//     the ray in the first cell that has one (a cubic in t, split at its turning points and
//     bisected: the trilinear root); the normal is minus the central-difference gradient
//     (outward, toward lower values). Traced as Embree user geometry (core/accel.cpp).
//   - composite: front-to-back emission–absorption along the ray (seed 004's compositing of
//     colour and opacity): per voxel segment of length Δt with interpolated value v, the
//     transfer ramp gives a colour c(v) and an extinction σ(v); α = 1 − exp(−σ·Δt),
//     C += T·α·c, T *= 1 − α. For a constant σ and c this is exactly c·(1 − e^(−σL)) with
//     transmittance e^(−σL). Not in the Embree scene: the integrator composites every ray's
//     segment over what lies behind it, C + T·behind (composite_volumes below,
//     shading/integrators/whitted.cpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/grid_walk.h"
#include "core/shapes/box.h"
#include "core/shapes/mesh.h"
#include "core/shapes/outline.h"
#include "core/shapes/shape.h"

namespace rayo {

enum class VoxelFormat { U8, U16, F32 };

// Bytes per voxel of a format.
inline size_t voxel_bytes(VoxelFormat format) {
    return format == VoxelFormat::U8 ? 1 : format == VoxelFormat::U16 ? 2 : 4;
}
// Little-endian raw voxels to values: u8 as v/255, u16 as v/65535, f32 as it is. `bytes` must
// hold exactly count·voxel_bytes(format) bytes.
std::vector<float> decode_voxels(const std::string& bytes, VoxelFormat format);

// Stop compositing once the transmittance is below this (the rest adds less than it).
constexpr float kMinTransmittance = 1e-5f;

enum class VoxelMode { Surface, Composite };

// Surface mode's `"method": "auto"` (docs/voxels.md): the mesh while its estimated memory stays
// within kAutoVoxelMeshBytes (about 671,000 triangles), the traversal beyond. The estimate is
// the memory Embree and rayo take per triangle of a mesh form, 82–120 bytes measured
// (docs/shape-methods.md). The figures behind the budget: the example planet's 42,216-triangle
// mesh traced about twice as fast as the DDA over its 64 × 32 × 64 voxels (docs/voxels.md), and
// height fields' Embree triangles traced faster than their traversal up to 512² cells (524,288
// triangles) and 2–4× slower from 1024² cells (2 M triangles) on (docs/heightfields.md).
constexpr size_t kVoxelMeshBytesPerTriangle = 100;
constexpr size_t kAutoVoxelMeshBytes = size_t(64) << 20;
inline bool auto_voxels_prefer_mesh(size_t triangles) {
    return triangles <= kAutoVoxelMeshBytes / kVoxelMeshBytesPerTriangle;
}

// One stop of a transfer ramp: at value `value`, colour `color` and extinction `density` (per
// world unit).
struct TransferStop {
    float value = 0.0f;
    Vec3 color{1.0f};
    float density = 0.0f;
};

// The composite mode's transfer function: stops sorted by value (equal values make a step),
// colour and density interpolated linearly in v between neighbouring stops, held constant
// below the first and above the last.
struct VoxelTransfer {
    std::vector<TransferStop> stops{{0.0f, Vec3(1.0f), 0.0f}, {1.0f, Vec3(1.0f), 1.0f}};

    void operator()(float v, Vec3& colour, float& density) const;
};

struct VoxelGrid {
    int dims[3] = {0, 0, 0};    // voxels along x, y, z (each >= 2)
    std::vector<float> values;  // x fastest, then y, then z
    Vec3 lower{0.0f};           // the grid's box: [lower, lower + size]
    Vec3 size{1.0f};
    float threshold = 0.5f;  // surface: the iso value
    uint32_t material = 0;   // surface: the material of the iso-surface
    VoxelMode mode = VoxelMode::Surface;
    VoxelTransfer transfer;  // composite: value -> colour and density

    float value(int i, int j, int k) const {
        return values[(size_t(k) * size_t(dims[1]) + size_t(j)) * size_t(dims[0]) + size_t(i)];
    }
    Vec3 voxel_size() const { return size / Vec3(float(dims[0]), float(dims[1]), float(dims[2])); }
    // The trilinear interpolant between voxel centres at p (clamped to the outer centres).
    float sample(const Vec3& p) const;
    // Its central-difference gradient (steps of half a voxel).
    Vec3 gradient(const Vec3& p) const;
    // Surface mode's tessellated form (`"method": "mesh"`): marching tetrahedra over the voxel
    // centres (core/shapes/marching_tetrahedra.h), vertices where the linear interpolation
    // along a lattice edge crosses the threshold, normals −∇ as the traversal's.
    TriangleMesh tessellate() const;
    // The triangles tessellate() would make at most (marching_tetrahedra_triangles), without
    // making them: what `auto` weighs.
    size_t mesh_triangles() const;

    Bounds3 bounds() const { return {lower, lower + size}; }
    // The first crossing of the iso-surface in (tnear, tfar); hit.normal = −gradient.
    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const;
    void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const;
    void parameterization(const Vec3& position, SurfaceHit& out) const;
    void outline(Outline& out) const { Box{lower, lower + size}.outline(out); }

    // Composites the segment (t0, t1) of the ray within the grid's box front to back (see
    // above): transfer(v, colour, extinction) gives c(v) and σ(v) (per world unit). Returns the
    // colour C; `transmittance` gets T.
    template <typename Transfer>
    Vec3 composite(const Vec3& origin, const Vec3& direction, float t0, float t1,
                   Transfer&& transfer, float& transmittance) const;
};

// The composite grids `volumes` (count of them) along the ray's segment (t0, t1), each
// composited front to back and the grids taken in the order the ray enters their boxes:
// C = C1 + T1·(C2 + T2·(...)); `transmittance` gets T1·T2·…. Overlapping boxes are taken one
// after the other by entry (an approximation there: docs/voxels.md).
Vec3 composite_volumes(const VoxelGrid* const* volumes, size_t count, const Vec3& origin,
                       const Vec3& direction, float t0, float t1, float& transmittance);

template <typename Transfer>
Vec3 VoxelGrid::composite(const Vec3& origin, const Vec3& direction, float t0, float t1,
                          Transfer&& transfer, float& transmittance) const {
    Vec3 colour(0.0f);
    transmittance = 1.0f;
    float t_enter, t_exit;
    Vec3 n_enter, n_exit;
    const Box box{lower, lower + size};
    if (!box.slabs(origin, direction, t_enter, n_enter, t_exit, n_exit)) return colour;
    t0 = std::max(t0, t_enter);
    t1 = std::min(t1, t_exit);
    if (!(t0 < t1)) return colour;
    const Vec3 voxel = voxel_size();
    float o[3], d[3];
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        o[a] = (origin[a] - lower[a]) / voxel[a];
        d[a] = direction[a] / voxel[a];
        lo[a] = 0;
        hi[a] = dims[a] - 1;
    }
    walk_grid<3>(o, d, t0, t1, lo, hi, [&](const int(&)[3], float ta, float tb) {
        const float length = tb - ta;
        if (!(length > 0.0f)) return false;
        Vec3 c;
        float sigma;
        transfer(sample(origin + (0.5f * (ta + tb)) * direction), c, sigma);
        const float alpha = 1.0f - std::exp(-sigma * length);
        colour += transmittance * alpha * c;
        transmittance *= 1.0f - alpha;
        return transmittance < kMinTransmittance;
    });
    return colour;
}

}  // namespace rayo
