#include "core/shapes/voxel_grid.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "core/shapes/marching_tetrahedra.h"

namespace rayo {
namespace {

// P(x) = a0 + a1·x + a2·x² + a3·x³, in double.
struct Cubic {
    double a[4];
    double operator()(double x) const { return a[0] + x * (a[1] + x * (a[2] + x * a[3])); }
};

// The cubic through g0..g3 at x = 0, 1, 2, 3 (Newton's forward differences).
Cubic cubic_through(const double g[4]) {
    const double d1 = g[1] - g[0], d2 = g[2] - 2.0 * g[1] + g[0];
    const double d3 = g[3] - 3.0 * g[2] + 3.0 * g[1] - g[0];
    return {{g[0], d1 - d2 / 2.0 + d3 / 3.0, d2 / 2.0 - d3 / 2.0, d3 / 6.0}};
}

// The first root of P in [0, 3]: the interval is split at the turning points of P (the roots
// of P'), so each piece is monotone and a sign change in it brackets exactly one root, found by
// bisection. Returns −1 when there is none.
double first_root(const Cubic& p) {
    double cuts[4] = {0.0, 3.0, 3.0, 3.0};
    int n = 1;
    // P'(x) = a1 + 2·a2·x + 3·a3·x².
    const double qa = 3.0 * p.a[3], qb = 2.0 * p.a[2], qc = p.a[1];
    if (qa != 0.0) {
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc > 0.0) {
            // The stable quadratic roots (docs/stability.md).
            const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
            double r0 = q / qa, r1 = q != 0.0 ? qc / q : r0;
            if (r0 > r1) std::swap(r0, r1);
            for (double r : {r0, r1}) {
                if (r > 0.0 && r < 3.0) cuts[n++] = r;
            }
        }
    } else if (qb != 0.0) {
        const double r = -qc / qb;
        if (r > 0.0 && r < 3.0) cuts[n++] = r;
    }
    cuts[n++] = 3.0;
    for (int k = 0; k + 1 < n; ++k) {
        double a = cuts[k], b = cuts[k + 1];
        double pa = p(a);
        const double pb = p(b);
        if (pa == 0.0) return a;
        if ((pa < 0.0) == (pb < 0.0)) continue;
        for (int it = 0; it < 50; ++it) {
            const double m = 0.5 * (a + b), pm = p(m);
            if ((pm < 0.0) == (pa < 0.0)) {
                a = m;
                pa = pm;
            } else {
                b = m;
            }
        }
        return 0.5 * (a + b);
    }
    return -1.0;
}

}  // namespace

std::vector<float> decode_voxels(const std::string& bytes, VoxelFormat format) {
    const size_t count = bytes.size() / voxel_bytes(format);
    std::vector<float> out(count);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    for (size_t i = 0; i < count; ++i) {
        if (format == VoxelFormat::U8) {
            out[i] = float(data[i]) / 255.0f;
        } else if (format == VoxelFormat::U16) {
            out[i] = float(unsigned(data[2 * i]) | unsigned(data[2 * i + 1]) << 8) / 65535.0f;
        } else {
            const uint32_t bits = uint32_t(data[4 * i]) | uint32_t(data[4 * i + 1]) << 8 |
                                  uint32_t(data[4 * i + 2]) << 16 | uint32_t(data[4 * i + 3]) << 24;
            std::memcpy(&out[i], &bits, sizeof bits);
        }
    }
    return out;
}

float VoxelGrid::sample(const Vec3& p) const {
    const Vec3 voxel = voxel_size();
    int i0[3];
    float w[3];
    for (int a = 0; a < 3; ++a) {
        // Grid coordinates with the voxel centres at integers, clamped to the outer centres.
        const float g = std::clamp((p[a] - lower[a]) / voxel[a] - 0.5f, 0.0f, float(dims[a] - 1));
        i0[a] = std::min(int(g), dims[a] - 2);
        w[a] = g - float(i0[a]);
    }
    float v = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
        v += (dx ? w[0] : 1.0f - w[0]) * (dy ? w[1] : 1.0f - w[1]) * (dz ? w[2] : 1.0f - w[2]) *
             value(i0[0] + dx, i0[1] + dy, i0[2] + dz);
    }
    return v;
}

Vec3 VoxelGrid::gradient(const Vec3& p) const {
    const Vec3 h = 0.5f * voxel_size();
    Vec3 g;
    for (int a = 0; a < 3; ++a) {
        Vec3 step(0.0f);
        step[a] = h[a];
        g[a] = (sample(p + step) - sample(p - step)) / (2.0f * h[a]);
    }
    return g;
}

bool VoxelGrid::nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                        ShapeHit& hit) const {
    // The dual grid: cells between voxel centres, the centres at integer grid coordinates.
    const Vec3 voxel = voxel_size();
    const Box centres{lower + 0.5f * voxel, lower + size - 0.5f * voxel};
    float t_enter, t_exit;
    Vec3 n_enter, n_exit;
    if (!centres.slabs(origin, direction, t_enter, n_enter, t_exit, n_exit)) return false;
    const float t0 = std::max(t_enter, tnear), t1 = std::min(t_exit, tfar);
    if (!(t0 <= t1)) return false;
    float o[3], d[3];
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        o[a] = (origin[a] - lower[a]) / voxel[a] - 0.5f;
        d[a] = direction[a] / voxel[a];
        lo[a] = 0;
        hi[a] = dims[a] - 2;
    }
    return walk_grid<3>(o, d, t0, t1, lo, hi, [&](const int(&c)[3], float ta, float tb) {
        float corner[8], low = corner[0] = value(c[0], c[1], c[2]), high = low;
        for (int k = 1; k < 8; ++k) {
            corner[k] = value(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + (k >> 2));
            low = std::min(low, corner[k]);
            high = std::max(high, corner[k]);
        }
        if (low > threshold || high < threshold || !(tb > ta)) return false;
        // The trilinear interpolant minus the threshold at four points of [ta, tb]: the cubic.
        double g[4];
        for (int s = 0; s < 4; ++s) {
            const double t = ta + (tb - ta) * s / 3.0;
            double l[3];
            for (int a = 0; a < 3; ++a) {
                l[a] = std::clamp(o[a] + d[a] * t - c[a], 0.0, 1.0);
            }
            double v = 0.0;
            for (int k = 0; k < 8; ++k) {
                v += ((k & 1) ? l[0] : 1.0 - l[0]) * (((k >> 1) & 1) ? l[1] : 1.0 - l[1]) *
                     ((k >> 2) ? l[2] : 1.0 - l[2]) * corner[k];
            }
            g[s] = v - threshold;
        }
        const double x = first_root(cubic_through(g));
        if (x < 0.0) return false;
        const float t = float(ta + (tb - ta) * x / 3.0);
        if (!(t > tnear && t < tfar)) return false;
        const Vec3 normal = -gradient(origin + t * direction);
        hit = {t, normal != Vec3(0.0f) ? normal : -direction, 0};
        return true;
    });
}

void VoxelGrid::surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const {
    out.position = ray.at(hit.t);
    const float length = glm::length(hit.normal);
    out.geometric_normal = length > 0.0f ? hit.normal / length : -ray.direction;
    out.shading_normal = out.geometric_normal;
    out.object_size = max_abs_component(voxel_size());
}

void VoxelTransfer::operator()(float v, Vec3& colour, float& density) const {
    // The first stop above v; v at or past the last stop takes the last.
    const auto above = std::upper_bound(stops.begin(), stops.end(), v,
                                        [](float x, const TransferStop& s) { return x < s.value; });
    if (above == stops.begin() || above == stops.end()) {
        const TransferStop& s = above == stops.begin() ? stops.front() : stops.back();
        colour = s.color;
        density = s.density;
        return;
    }
    const TransferStop& a = *(above - 1);
    const TransferStop& b = *above;
    const float w = (v - a.value) / (b.value - a.value);  // b.value > v >= a.value
    colour = a.color + w * (b.color - a.color);
    density = a.density + w * (b.density - a.density);
}

Vec3 composite_volumes(const VoxelGrid* const* volumes, size_t count, const Vec3& origin,
                       const Vec3& direction, float t0, float t1, float& transmittance) {
    Vec3 colour(0.0f);
    transmittance = 1.0f;
    // The grids in order of entry, by repeated selection (scenes hold a few grids: no heap).
    float previous = -std::numeric_limits<float>::infinity();
    size_t previous_index = 0;
    for (size_t taken = 0; taken < count; ++taken) {
        size_t next = count;
        float next_entry = std::numeric_limits<float>::infinity();
        for (size_t i = 0; i < count; ++i) {
            float t_enter, t_exit;
            Vec3 n_enter, n_exit;
            const VoxelGrid& g = *volumes[i];
            if (!Box{g.lower, g.lower + g.size}.slabs(origin, direction, t_enter, n_enter, t_exit,
                                                      n_exit) ||
                !(t_exit > t0) || !(t_enter < t1)) {
                continue;
            }
            // After the previous grid in (entry, index) order, and the first such.
            const bool after = t_enter > previous || (t_enter == previous && i > previous_index);
            if (after && (t_enter < next_entry || next == count)) {
                next = i;
                next_entry = t_enter;
            }
        }
        if (next == count) break;
        previous = next_entry;
        previous_index = next;
        float t;
        const Vec3 c =
            volumes[next]->composite(origin, direction, t0, t1, volumes[next]->transfer, t);
        colour += transmittance * c;
        transmittance *= t;
        if (transmittance < kMinTransmittance) break;
    }
    return colour;
}

void VoxelGrid::parameterization(const Vec3& position, SurfaceHit& out) const {
    const Vec3 local = (position - lower) / size;
    out.uv = glm::vec2(local.x, local.y);
    out.dpdu = Vec3(size.x, 0.0f, 0.0f);
}

size_t VoxelGrid::mesh_triangles() const {
    return marching_tetrahedra_triangles(dims, [this](int i, int j, int k) {
        return double(value(i, j, k)) - double(threshold);  // as tessellate()'s samples
    });
}

TriangleMesh VoxelGrid::tessellate() const {
    SampledField field;
    const Vec3 voxel = voxel_size();
    field.lower = DVec3(lower + 0.5f * voxel);  // values sit at voxel centres
    field.cell = DVec3(voxel);
    for (int a = 0; a < 3; ++a) field.counts[a] = dims[a];
    field.samples.reserve(values.size());
    for (const float v : values) field.samples.push_back(double(v) - double(threshold));
    field.outward = [this](const DVec3& p) {
        const Vec3 outward = -gradient(Vec3(p));
        const float length = glm::length(outward);
        return length > 0.0f ? outward / length : Vec3(0.0f, 1.0f, 0.0f);
    };
    return marching_tetrahedra(field, material, "voxels");
}

}  // namespace rayo
