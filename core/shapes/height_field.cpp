#include "core/shapes/height_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/grid_walk.h"
#include "core/shadow_terminator.h"
#include "core/shapes/box.h"

namespace rayo {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The watertight ray–triangle test of Woop, Benthin & Wald (2013): the vertices are moved into
// a frame where the ray runs along +z from the origin, and the 2-D edge functions are computed
// from each vertex's own transformed coordinates (in double), so the two triangles that share an
// edge evaluate it identically with opposite signs: no ray passes between them along a grid
// line or a diagonal or through a corner (tests/core/height_field_test.cpp). Möller–Trumbore
// with a barycentric tolerance of 1e-5 let 6 of 262144 camera rays through a 2048² field and 20
// through a 4096² one, and a tolerance of 2e-3 made false hits on ridges. The edge functions
// keep a tolerance of kEdgeTolerance (in barycentric units) for another reason: a ray aimed at
// a sample point lands, after rounding, in one of the six triangles around it, which may lie in
// a cell the DDA's own rounding skipped (1 % of such rays 1000 cells away leaked without it).
constexpr double kEdgeTolerance = 1e-4;

struct RayFrame {
    int kx, ky, kz;
    float sx, sy, sz;
    Vec3 origin;
    RayFrame(const Vec3& o, const Vec3& d) : origin(o) {
        const Vec3 a = glm::abs(d);
        kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        if (d[kz] < 0.0f) std::swap(kx, ky);  // keep the winding
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1.0f / d[kz];
    }
    // A vertex in the ray's frame: (x, y) sheared, z scaled below.
    void transform(const Vec3& p, double& x, double& y, float& z) const {
        const Vec3 a = p - origin;
        x = double(a[kx] - sx * a[kz]);
        y = double(a[ky] - sy * a[kz]);
        z = a[kz];
    }
};

bool hit_triangle(const RayFrame& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2, float& t,
                  Vec3& normal) {
    double ax, ay, bx, by, cx, cy;
    float az, bz, cz;
    ray.transform(p0, ax, ay, az);
    ray.transform(p1, bx, by, bz);
    ray.transform(p2, cx, cy, cz);
    const double u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    const double tolerance = kEdgeTolerance * std::fabs(u + v + w);
    if ((u < -tolerance || v < -tolerance || w < -tolerance) &&
        (u > tolerance || v > tolerance || w > tolerance)) {
        return false;
    }
    const double det = u + v + w;
    if (det == 0.0) return false;
    const double sz = ray.sz;
    t = float((u * sz * az + v * sz * bz + w * sz * cz) / det);
    normal = glm::cross(p1 - p0, p2 - p0);
    return std::isfinite(t);
}

}  // namespace

void HeightField::finish() {
    const int cells_x = columns - 1, cells_z = rows - 1;
    m_blocks_x = (cells_x + kHeightBlock - 1) / kHeightBlock;
    m_blocks_z = (cells_z + kHeightBlock - 1) / kHeightBlock;
    m_block_min.assign(size_t(m_blocks_x) * size_t(m_blocks_z), kInfinity);
    m_block_max.assign(m_block_min.size(), -kInfinity);
    // A sample on a block border belongs to the cells of both blocks.
    for (int j = 0; j < rows; ++j) {
        const int bz0 = std::max(0, (j - 1) / kHeightBlock);
        const int bz1 = std::min(m_blocks_z - 1, j / kHeightBlock);
        for (int i = 0; i < columns; ++i) {
            const float h = height(i, j);
            const int bx0 = std::max(0, (i - 1) / kHeightBlock);
            const int bx1 = std::min(m_blocks_x - 1, i / kHeightBlock);
            for (int bz = bz0; bz <= bz1; ++bz) {
                for (int bx = bx0; bx <= bx1; ++bx) {
                    const size_t b = size_t(bz) * size_t(m_blocks_x) + size_t(bx);
                    m_block_min[b] = std::min(m_block_min[b], h);
                    m_block_max[b] = std::max(m_block_max[b], h);
                }
            }
        }
    }
    const auto [low, high] = std::minmax_element(heights.begin(), heights.end());
    m_bounds.lower = Vec3(lower.x, lower.y + *low, lower.z);
    m_bounds.upper = Vec3(lower.x + size.x, lower.y + *high, lower.z + size.z);
}

Vec3 HeightField::vertex(int i, int j) const {
    return Vec3(lower.x + size.x * (float(i) / float(columns - 1)), lower.y + height(i, j),
                lower.z + size.z * (float(j) / float(rows - 1)));
}

Vec3 HeightField::vertex_normal(int i, int j) const {
    // The surface y = h(x, z) has the upward normal (−∂h/∂x, 1, −∂h/∂z).
    const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, columns - 1);
    const int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, rows - 1);
    const float dx = size.x / float(columns - 1), dz = size.z / float(rows - 1);
    const float dhdx = (height(i1, j) - height(i0, j)) / (float(i1 - i0) * dx);
    const float dhdz = (height(i, j1) - height(i, j0)) / (float(j1 - j0) * dz);
    return glm::normalize(Vec3(-dhdx, 1.0f, -dhdz));
}

void HeightField::triangle(uint32_t part, uint32_t corners[3]) const {
    const uint32_t cell = part >> 1, cells_x = uint32_t(columns - 1);
    const uint32_t i = cell % cells_x, j = cell / cells_x, c = uint32_t(columns);
    const uint32_t v00 = j * c + i, v10 = v00 + 1, v01 = v00 + c, v11 = v01 + 1;
    // Counter-clockwise seen from +y, so the winding's normal points up.
    if ((part & 1u) == 0) {
        corners[0] = v00, corners[1] = v01, corners[2] = v11;
    } else {
        corners[0] = v00, corners[1] = v11, corners[2] = v10;
    }
}

bool HeightField::nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                          ShapeHit& hit) const {
    // The ray's interval in the bounding box, widened a little so that a flat field (a box of
    // zero height) and rays along its faces are still walked.
    const float pad = 1e-5f * (max_abs_component(m_bounds.upper - m_bounds.lower) + 1.0f);
    const Box box{m_bounds.lower - Vec3(pad), m_bounds.upper + Vec3(pad)};
    float t_enter, t_exit;
    Vec3 n_enter, n_exit;
    if (!box.slabs(origin, direction, t_enter, n_enter, t_exit, n_exit)) return false;
    const float t0 = std::max(t_enter, tnear), t1 = std::min(t_exit, tfar);
    if (!(t0 <= t1)) return false;

    // Grid coordinates: cell (i, j) is [i, i + 1] × [j, j + 1]; t stays the world t.
    const float cell_x = size.x / float(columns - 1), cell_z = size.z / float(rows - 1);
    const float ou = (origin.x - lower.x) / cell_x, du = direction.x / cell_x;
    const float ov = (origin.z - lower.z) / cell_z, dv = direction.z / cell_z;
    const int last_x = columns - 2, last_z = rows - 2;
    // The ray's height range over [ta, tb] misses [low, high] (with the pad).
    const auto misses = [&](float ta, float tb, float low, float high) {
        const float ya = origin.y + direction.y * ta - lower.y;
        const float yb = origin.y + direction.y * tb - lower.y;
        return std::max(ya, yb) < low - pad || std::min(ya, yb) > high + pad;
    };
    const RayFrame frame(origin, direction);
    const auto visit_cell = [&](int i, int j, float ta, float tb) {
        const float h00 = height(i, j), h10 = height(i + 1, j);
        const float h01 = height(i, j + 1), h11 = height(i + 1, j + 1);
        if (misses(ta, tb, std::min(std::min(h00, h10), std::min(h01, h11)),
                   std::max(std::max(h00, h10), std::max(h01, h11)))) {
            return false;
        }
        const uint32_t first = 2u * (uint32_t(j) * uint32_t(columns - 1) + uint32_t(i));
        bool found = false;
        for (uint32_t part = first; part < first + 2; ++part) {
            uint32_t c[3];
            triangle(part, c);
            float t;
            Vec3 normal;
            if (hit_triangle(frame, vertex_at(c[0]), vertex_at(c[1]), vertex_at(c[2]), t, normal) &&
                t > tnear && t < tfar && (!found || t < hit.t)) {
                hit = {t, normal, part};
                found = true;
            }
        }
        // The cell's triangles lie over its footprint: a hit here is nearer than any later one.
        return found;
    };
    // The blocks first, then the cells of each block the ray's height range meets.
    const float block_o[2] = {ou / kHeightBlock, ov / kHeightBlock};
    const float block_d[2] = {du / kHeightBlock, dv / kHeightBlock};
    const float cell_o[2] = {ou, ov}, cell_d[2] = {du, dv};
    const int no_block[2] = {0, 0}, last_block[2] = {m_blocks_x - 1, m_blocks_z - 1};
    return walk_grid<2>(block_o, block_d, t0, t1, no_block, last_block,
                        [&](const int(&b)[2], float ta, float tb) {
                            const size_t index = size_t(b[1]) * size_t(m_blocks_x) + size_t(b[0]);
                            if (misses(ta, tb, m_block_min[index], m_block_max[index]))
                                return false;
                            const int lo[2] = {b[0] * kHeightBlock, b[1] * kHeightBlock};
                            const int hi[2] = {std::min(lo[0] + kHeightBlock - 1, last_x),
                                               std::min(lo[1] + kHeightBlock - 1, last_z)};
                            return walk_grid<2>(cell_o, cell_d, ta, tb, lo, hi,
                                                [&](const int(&c)[2], float ca, float cb) {
                                                    return visit_cell(c[0], c[1], ca, cb);
                                                });
                        });
}

void HeightField::surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const {
    uint32_t c[3];
    triangle(hit.part, c);
    const Vec3 p0 = vertex_at(c[0]), p1 = vertex_at(c[1]), p2 = vertex_at(c[2]);
    out.position = ray.at(hit.t);
    out.geometric_normal = unit_vector(glm::cross(p1 - p0, p2 - p0));
    out.shading_normal = out.geometric_normal;
    if (smooth) {
        // Barycentrics of the hit in the triangle's footprint (the triangle projects onto the
        // x–z plane one to one), then the vertex normals interpolated as on the mesh.
        const float ax = p1.x - p0.x, az = p1.z - p0.z, bx = p2.x - p0.x, bz = p2.z - p0.z;
        const float px = out.position.x - p0.x, pz = out.position.z - p0.z;
        const float det = ax * bz - az * bx;
        const float u = (px * bz - pz * bx) / det, v = (ax * pz - az * px) / det;
        const Vec3 n = (1.0f - u - v) * normal_at(c[0]) + u * normal_at(c[1]) + v * normal_at(c[2]);
        const float length = glm::length(n);
        if (length > 0.0f && std::isfinite(length)) {
            const Vec3 unit = n / length;
            const float side = glm::dot(unit, out.geometric_normal) >= 0.0f ? 1.0f : -1.0f;
            out.shading_normal = side * unit;
            const Vec3 corners[3] = {p0, p1, p2};
            const Vec3 normals[3] = {side * normal_at(c[0]), side * normal_at(c[1]),
                                     side * normal_at(c[2])};
            const float weights[3] = {1.0f - u - v, u, v};
            out.terminator_offset = terminator_offset(out.position, corners, normals, weights);
        }
    }
    out.object_size = glm::max(glm::length(p1 - p0), glm::length(p2 - p0));
}

void HeightField::parameterization(const Vec3& position, SurfaceHit& out) const {
    out.uv = glm::vec2((position.x - lower.x) / size.x, (position.z - lower.z) / size.z);
    out.dpdu = Vec3(size.x, 0.0f, 0.0f);
}

void HeightField::outline(Outline& out) const {
    Box{m_bounds.lower, m_bounds.upper}.outline(out);
}

TriangleMesh HeightField::tessellate() const {
    TriangleMesh mesh;
    mesh.name = "heightfield";
    mesh.positions.reserve(heights.size());
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) mesh.positions.push_back(vertex(i, j));
    }
    if (smooth) {
        mesh.normals.reserve(heights.size());
        for (int j = 0; j < rows; ++j) {
            for (int i = 0; i < columns; ++i) mesh.normals.push_back(vertex_normal(i, j));
        }
    }
    const size_t parts = 2 * cell_count();
    mesh.triangles.resize(parts);
    for (size_t part = 0; part < parts; ++part) {
        uint32_t c[3];
        triangle(uint32_t(part), c);
        mesh.triangles[part] = {c[0], c[1], c[2]};
    }
    mesh.materials.assign(parts, material);
    return mesh;
}

size_t HeightField::traversal_bytes() const {
    return sizeof(float) * (heights.size() + m_block_min.size() + m_block_max.size());
}

}  // namespace rayo
