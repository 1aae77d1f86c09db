#include "shading/radiosity_field.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace rayo {

namespace {

// Grid point (i, j), i + j ≤ k, of a triangle cut k×k: rows by i, k + 1 − i points each.
uint32_t grid_index(uint32_t k, uint32_t i, uint32_t j) {
    return i * (k + 1) - i * (i - 1) / 2 + j;
}

// Patch (i, j, upper) of a cut: row i holds lower, upper, lower, ... (2(k − i) − 1 patches).
uint32_t patch_index(uint32_t k, uint32_t i, uint32_t j, uint32_t upper) {
    return 2 * k * i - i * i + 2 * j + upper;
}

}  // namespace

RadiosityField::RadiosityField(const Scene& scene, const std::vector<Material>& materials,
                               float patch_size)
    : m_scene(scene) {
    // Vertices of patches are shared when they coincide (to a millionth of the scene's extent)
    // and face the same way (normals to an eighth).
    Vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const TriangleMesh& mesh : scene.meshes) {
        for (const Vec3& p : mesh.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    scene.shapes.for_each([&](const auto& shapes) {
        for (const auto& shape : shapes) {
            const Bounds3 b = shape.bounds();
            lo = glm::min(lo, b.lower);
            hi = glm::max(hi, b.upper);
        }
    });
    const float cell = std::max(max_abs_component(hi - lo), 1e-20f) * 1e-6f;
    std::map<std::array<int64_t, 6>, uint32_t> shared;
    auto vertex_id = [&](const Vec3& p, const Vec3& n) {
        const std::array<int64_t, 6> key = {std::llround(p.x / cell), std::llround(p.y / cell),
                                            std::llround(p.z / cell), std::llround(n.x * 8.0f),
                                            std::llround(n.y * 8.0f), std::llround(n.z * 8.0f)};
        const auto [it, inserted] = shared.emplace(key, m_vertex_count);
        if (inserted) ++m_vertex_count;
        return it->second;
    };

    // The patches of one side of a mesh triangle cut k×k: the front wound as the triangle, the
    // back reversed (its winding normal the negated one).
    auto cut_triangle = [&](const TriangleMesh& mesh, size_t t, TriangleCut& cut, int side) {
        const auto& tri = mesh.triangles[t];
        const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                   c = mesh.positions[tri[2]];
        const uint32_t k = cut.k;
        cut.sides[side].patch = static_cast<uint32_t>(m_patches.size());
        cut.sides[side].vertex = static_cast<uint32_t>(m_vertex_of.size());
        const Material& material = materials[mesh.materials[t]];
        const Vec3 cross = glm::cross(b - a, c - a);
        const float length = glm::length(cross);
        const Vec3 normal = length > 0.0f ? cross / length : Vec3(0.0f);  // 0: no patch area
        const Vec3 facing = side == 0 ? normal : -normal;
        auto point = [&](uint32_t i, uint32_t j) {
            return a + (b - a) * (static_cast<float>(i) / k) +
                   (c - a) * (static_cast<float>(j) / k);
        };
        for (uint32_t i = 0; i <= k; ++i) {
            for (uint32_t j = 0; i + j <= k; ++j) {
                m_vertex_of.push_back(vertex_id(point(i, j), facing));
            }
        }
        auto add = [&](const Vec3& p, const Vec3& q, const Vec3& r) {
            m_patches.push_back(side == 0 ? make_patch(p, q, r, material.emission, material.kd)
                                          : make_patch(p, r, q, material.emission, material.kd));
        };
        for (uint32_t i = 0; i < k; ++i) {
            for (uint32_t j = 0; i + j < k; ++j) {
                add(point(i, j), point(i + 1, j), point(i, j + 1));
                if (i + j + 1 < k) add(point(i + 1, j), point(i + 1, j + 1), point(i, j + 1));
            }
        }
    };
    // The patches of one side of an analytic shape's tessellation, likewise.
    auto cut_shape = [&](ShapeCut& cut, const Material& material, int side) {
        cut.sides[side].patch = static_cast<uint32_t>(m_patches.size());
        cut.sides[side].vertex = static_cast<uint32_t>(m_vertex_of.size());
        for (size_t v = 0; v < cut.mesh.positions.size(); ++v) {
            const Vec3 n = side == 0 ? cut.mesh.normals[v] : -cut.mesh.normals[v];
            m_vertex_of.push_back(vertex_id(cut.mesh.positions[v], n));
        }
        for (size_t n = 0; n < cut.mesh.triangles.size(); ++n) {
            const auto& tri = cut.mesh.triangles[n];
            const Vec3& p = cut.mesh.positions[tri[0]];
            const Vec3& q = cut.mesh.positions[tri[1]];
            const Vec3& r = cut.mesh.positions[tri[2]];
            RadiosityPatch patch = side == 0 ? make_patch(p, q, r, material.emission, material.kd)
                                             : make_patch(p, r, q, material.emission, material.kd);
            // A little beyond the sampled chord error (its maximum may lie between the
            // samples), and past the float rounding of the shape's intersection. The back's
            // rays start as far inside (the chord of a saddle lies on both sides of it).
            patch.lift = 1.25f * cut.mesh.bulge[n] + 1e-5f * max_abs_component(patch.vertices[0]);
            m_patches.push_back(patch);
        }
    };

    m_cuts.resize(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const TriangleMesh& mesh = scene.meshes[m];
        m_cuts[m].resize(mesh.triangles.size());
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            const auto& tri = mesh.triangles[t];
            const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                       c = mesh.positions[tri[2]];
            const float longest =
                std::max(glm::length(b - a), std::max(glm::length(c - b), glm::length(a - c)));
            uint32_t k = 1;
            if (patch_size > 0.0f) {
                k = static_cast<uint32_t>(
                    std::clamp(std::ceil(longest / patch_size), 1.0f, 256.0f));
            }
            m_cuts[m][t].k = k;
            cut_triangle(mesh, t, m_cuts[m][t], 0);
        }
    }

    // Analytic shapes: their tessellation's triangles are patches as they are; the grid points
    // are shared by position and the surface's normal there (a sphere's seam and poles are one
    // vertex each, a box's edges are not).
    TessellationOptions options;
    options.max_edge = patch_size;
    m_shape_cuts.resize(AnalyticShapes::kCount);
    scene.shapes.for_each([&](const auto& shapes) {
        using S = ShapeOf<decltype(shapes)>;
        std::vector<ShapeCut>& cuts = m_shape_cuts[Shapes::index_of<S>()];
        cuts.resize(shapes.size());
        for (size_t index = 0; index < shapes.size(); ++index) {
            ShapeCut& cut = cuts[index];
            shapes[index].pieces(cut.pieces);
            tessellate(cut.pieces, options, cut.mesh);
            cut_shape(cut, materials[shapes[index].material], 0);
        }
    });

    // The back sides of two-sided surfaces, after every front side. A one-sided mesh (NFF's
    // opaque polygons, docs/nff.md) has no back whatever its material: rays pass through it
    // from behind.
    const size_t fronts = m_patches.size();
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const TriangleMesh& mesh = scene.meshes[m];
        if (mesh.one_sided) continue;
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            if (materials[mesh.materials[t]].double_sided) cut_triangle(mesh, t, m_cuts[m][t], 1);
        }
    }
    scene.shapes.for_each([&](const auto& shapes) {
        using S = ShapeOf<decltype(shapes)>;
        std::vector<ShapeCut>& cuts = m_shape_cuts[Shapes::index_of<S>()];
        for (size_t index = 0; index < shapes.size(); ++index) {
            const Material& material = materials[shapes[index].material];
            if (material.double_sided) cut_shape(cuts[index], material, 1);
        }
    });
    m_back_patches = m_patches.size() - fronts;
}

void RadiosityField::set_solution(const std::vector<DVec3>& radiosity) {
    m_patch_radiance.assign(m_patches.size(), Vec3(0.0f));
    for (size_t p = 0; p < m_patches.size(); ++p) {
        m_patch_radiance[p] = Vec3(radiosity[p] - DVec3(m_patches[p].emission));
    }
    std::vector<DVec3> sum(m_vertex_count, DVec3(0.0));
    std::vector<uint32_t> count(m_vertex_count, 0);
    for (size_t m = 0; m < m_cuts.size(); ++m) {
        for (const TriangleCut& cut : m_cuts[m]) {
            const uint32_t k = cut.k;
            for (const Side& side : cut.sides) {
                if (side.patch == kNoSide) continue;
                auto add = [&](uint32_t i, uint32_t j, uint32_t patch) {
                    const uint32_t v = m_vertex_of[side.vertex + grid_index(k, i, j)];
                    sum[v] += DVec3(m_patch_radiance[patch]);
                    ++count[v];
                };
                for (uint32_t i = 0; i < k; ++i) {
                    for (uint32_t j = 0; i + j < k; ++j) {
                        const uint32_t lower = side.patch + patch_index(k, i, j, 0);
                        add(i, j, lower);
                        add(i + 1, j, lower);
                        add(i, j + 1, lower);
                        if (i + j + 1 < k) {
                            const uint32_t upper = side.patch + patch_index(k, i, j, 1);
                            add(i + 1, j, upper);
                            add(i + 1, j + 1, upper);
                            add(i, j + 1, upper);
                        }
                    }
                }
            }
        }
    }
    for (const std::vector<ShapeCut>& cuts : m_shape_cuts) {
        for (const ShapeCut& cut : cuts) {
            for (const Side& side : cut.sides) {
                if (side.patch == kNoSide) continue;
                for (size_t n = 0; n < cut.mesh.triangles.size(); ++n) {
                    for (const uint32_t corner : cut.mesh.triangles[n]) {
                        const uint32_t v = m_vertex_of[side.vertex + corner];
                        sum[v] += DVec3(m_patch_radiance[side.patch + n]);
                        ++count[v];
                    }
                }
            }
        }
    }
    m_vertex_radiance.assign(m_vertex_count, Vec3(0.0f));
    for (uint32_t v = 0; v < m_vertex_count; ++v) {
        if (count[v] > 0) m_vertex_radiance[v] = Vec3(sum[v] / static_cast<double>(count[v]));
    }
}

bool RadiosityField::shape_reflected(const SurfaceHit& hit, bool front, Vec3& radiance) const {
    if (hit.shape >= m_shape_cuts.size() || hit.primitive >= m_shape_cuts[hit.shape].size()) {
        return false;
    }
    const ShapeCut& cut = m_shape_cuts[hit.shape][hit.primitive];
    const Side& side = cut.sides[front ? 0 : 1];
    if (side.patch == kNoSide) return false;
    PiecePoint where;
    if (cut.mesh.triangles.empty() || !locate(cut.pieces, hit.position, where)) return false;
    const CellPoint cell = cell_point(cut.mesh, where);
    if (cell.triangle == TessellatedMesh::kNoTriangle) return false;
    if (m_flat) {
        radiance = m_patch_radiance[side.patch + cell.triangle];
        return true;
    }
    radiance = Vec3(0.0f);
    for (int c = 0; c < 3; ++c) {
        radiance +=
            cell.weights[c] * m_vertex_radiance[m_vertex_of[side.vertex + cell.vertices[c]]];
    }
    return true;
}

bool RadiosityField::reflected(const SurfaceHit& hit, bool front, Vec3& radiance) const {
    // Instanced objects (hit.instance) are not patches: radiosity solves the scene's own
    // shapes and meshes only.
    if (m_patch_radiance.empty() || hit.instance != kNoInstance) return false;
    if (hit.shape != kTriangleShape) return shape_reflected(hit, front, radiance);
    if (hit.mesh >= m_cuts.size()) return false;
    const TriangleCut& cut = m_cuts[hit.mesh][hit.primitive];
    const Side& side = cut.sides[front ? 0 : 1];
    if (side.patch == kNoSide) return false;
    const TriangleMesh& mesh = m_scene.meshes[hit.mesh];
    const auto& tri = mesh.triangles[hit.primitive];
    const Vec3 a = mesh.positions[tri[0]];
    const Vec3 e1 = mesh.positions[tri[1]] - a, e2 = mesh.positions[tri[2]] - a;
    const Vec3 w = hit.position - a;
    const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const float d1w = glm::dot(e1, w), d2w = glm::dot(e2, w);
    const float den = d11 * d22 - d12 * d12;
    if (!(den > 0.0f)) return false;
    const float k = static_cast<float>(cut.k);
    // The hit in grid units, clamped into the triangle.
    const float s = std::clamp((d22 * d1w - d12 * d2w) / den, 0.0f, 1.0f) * k;
    const float t = std::clamp((d11 * d2w - d12 * d1w) / den, 0.0f, 1.0f) * k;
    uint32_t i = static_cast<uint32_t>(std::min(s, k - 1.0f));
    uint32_t j = static_cast<uint32_t>(std::min(t, k - 1.0f));
    if (i + j > cut.k - 1) j = cut.k - 1 - i;
    const float fs = std::clamp(s - static_cast<float>(i), 0.0f, 1.0f);
    const float ft = std::clamp(t - static_cast<float>(j), 0.0f, 1.0f);
    const bool upper = fs + ft > 1.0f && i + j + 1 < cut.k;
    if (m_flat) {
        radiance = m_patch_radiance[side.patch + patch_index(cut.k, i, j, upper ? 1 : 0)];
        return true;
    }
    auto at = [&](uint32_t ii, uint32_t jj) {
        return m_vertex_radiance[m_vertex_of[side.vertex + grid_index(cut.k, ii, jj)]];
    };
    if (upper) {
        radiance = at(i + 1, j + 1) * (fs + ft - 1.0f) + at(i + 1, j) * (1.0f - ft) +
                   at(i, j + 1) * (1.0f - fs);
    } else {
        const float w0 = std::max(0.0f, 1.0f - fs - ft);
        radiance = at(i, j) * w0 + at(i + 1, j) * fs + at(i, j + 1) * ft;
        radiance /= w0 + fs + ft;  // renormalized where the clamp left the triangle
    }
    return true;
}

}  // namespace rayo
