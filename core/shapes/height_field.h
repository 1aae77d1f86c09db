#pragma once
// A height field (seed 004: "height fields by grid traversal"): a regular grid of height samples
// over the x–z plane, y up, each grid cell split along its (i, j)–(i+1, j+1) diagonal into two
// exact triangles. Two representations (docs/heightfields.md):
//   - traversal (`dda`): Embree user geometry running a two-level 2-D DDA (Amanatides & Woo 1987)
//     over blocks of kHeightBlock² cells, then over cells, skipping every block and cell whose
//     height range the ray's height range over it misses, and testing the cell's two triangles;
//     memory: the samples and the per-block bounds (about 4 bytes per sample);
//   - mesh: tessellate() into a TriangleMesh for Embree triangles (about 210 bytes per cell).
// Both give the same triangles, the same geometric normals (up-facing winding) and, with
// `smooth`, the same vertex normals (central differences of the samples).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/shapes/mesh.h"
#include "core/shapes/outline.h"
#include "core/shapes/shape.h"

namespace rayo {

// Cells per side of a block of the coarse level of the traversal.
constexpr int kHeightBlock = 16;

// `auto` (docs/heightfields.md): Embree triangles while their estimated memory stays within
// kAutoMeshBytes (about 1131² cells), the traversal beyond. The estimate is the measured memory
// of the mesh form per cell: rayo's TriangleMesh (40 bytes) plus Embree's buffers and BVH
// (160–175), from 256² to 4096² (bench/heightfield_study.sh; the chart in docs/heightfields.md).
constexpr size_t kMeshBytesPerCell = 210;
constexpr size_t kAutoMeshBytes = size_t(256) << 20;
inline bool auto_prefers_mesh(size_t cells) {
    return cells <= kAutoMeshBytes / kMeshBytesPerCell;
}

struct HeightField {
    int columns = 0;             // samples along x (>= 2)
    int rows = 0;                // samples along z (>= 2)
    std::vector<float> heights;  // rows × columns, row j at z = lower.z + j·size.z/(rows − 1)
    Vec3 lower{0.0f};            // the corner at sample (0, 0), height 0
    Vec3 size{1.0f};             // x and z extent; y: the world height of a sample value of 1
    bool smooth = false;         // shade with interpolated vertex normals
    uint32_t material = 0;

    // Call after filling the samples: computes the height bounds of the blocks and the field.
    void finish();

    size_t cell_count() const { return size_t(columns - 1) * size_t(rows - 1); }
    float height(int i, int j) const { return heights[size_t(j) * size_t(columns) + size_t(i)]; }
    Vec3 vertex(int i, int j) const;
    // The unit normal at sample (i, j) from central differences (one-sided at the border).
    Vec3 vertex_normal(int i, int j) const;
    // Triangle `part` = 2·(cell index) + {0, 1}: its corners in mesh order (counter-clockwise
    // seen from above), as sample indices (i, j) packed as j·columns + i.
    void triangle(uint32_t part, uint32_t corners[3]) const;
    Vec3 vertex_at(uint32_t packed) const {
        return vertex(int(packed % uint32_t(columns)), int(packed / uint32_t(columns)));
    }
    Vec3 normal_at(uint32_t packed) const {
        return vertex_normal(int(packed % uint32_t(columns)), int(packed / uint32_t(columns)));
    }

    Bounds3 bounds() const { return m_bounds; }
    // The first triangle hit in (tnear, tfar): hit.part is its `part`, hit.normal its
    // (unnormalized, up-facing) geometric normal.
    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const;
    // Position, normals and size of a hit, the same as the mesh's for the same triangle.
    void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const;
    void parameterization(const Vec3& position, SurfaceHit& out) const;
    void outline(Outline& out) const;  // the bounding box's edges

    // The same triangles (and vertex normals when smooth) as Embree triangles.
    TriangleMesh tessellate() const;
    // Bytes the traversal keeps (samples and block bounds).
    size_t traversal_bytes() const;

  private:
    int m_blocks_x = 0, m_blocks_z = 0;
    std::vector<float> m_block_min, m_block_max;
    Bounds3 m_bounds;
};

}  // namespace rayo
