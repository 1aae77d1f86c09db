#include "core/shapes/blob.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/shapes/sphere.h"

namespace rayo {
namespace {

// An element as the ray sees it: u(t) = ((t − tc)² + h2)·inverse_r2 on its support
// [tc − w, tc + w].
struct Active {
    double tc, h2, inverse_r2, strength, lo, hi;
};

// An interval [lo, hi] of real numbers.
struct Range {
    double lo, hi;
};

// Two crossings closer than this fraction of the searched span are one (a tangent touch), and
// Newton stops refining at it.
constexpr double kBlobResolution = 1e-9;
constexpr int kMaxSplits = 64;  // halvings of an interval (the resolution is reached first)

class RayField {
  public:
    RayField(const Blob& blob, const Vec3& origin, const Vec3& direction)
        : m_threshold(blob.threshold) {
        const DVec3 o(origin), d(direction);
        m_lo = std::numeric_limits<double>::infinity();
        m_hi = -m_lo;
        for (const BlobElement& e : blob.elements) {
            const DVec3 f = DVec3(e.center) - o;
            const double tc = glm::dot(f, d);
            const double h2 = std::max(glm::dot(f, f) - tc * tc, 0.0);
            const double r2 = double(e.radius) * e.radius;
            if (!(h2 < r2)) continue;  // the line misses the support sphere
            const double w = std::sqrt(r2 - h2);
            m_active[m_count++] = {tc, h2, 1.0 / r2, double(e.strength), tc - w, tc + w};
            if (e.strength > 0.0f) {  // only positive elements can reach T > 0
                m_lo = std::min(m_lo, tc - w);
                m_hi = std::max(m_hi, tc + w);
            }
        }
    }
    bool empty() const { return !(m_lo < m_hi); }
    double lo() const { return m_lo; }
    double hi() const { return m_hi; }

    // g(t) = F(o + t·d) − T and g'(t).
    double value(double t) const {
        double sum = -m_threshold;
        for (int i = 0; i < m_count; ++i) {
            const Active& a = m_active[i];
            const double x = t - a.tc, u = (x * x + a.h2) * a.inverse_r2;
            if (u < 1.0) sum += a.strength * (1.0 - u) * (1.0 - u) * (1.0 - u);
        }
        return sum;
    }
    double slope(double t) const {
        // d/dt s·(1 − u)³ = −6·s·(1 − u)²·(t − tc)/R².
        double sum = 0.0;
        for (int i = 0; i < m_count; ++i) {
            const Active& a = m_active[i];
            const double x = t - a.tc, u = (x * x + a.h2) * a.inverse_r2;
            if (u < 1.0) sum -= 6.0 * a.strength * (1.0 - u) * (1.0 - u) * x * a.inverse_r2;
        }
        return sum;
    }
    // Bounds of g and g' over [t0, t1]: per element, the exact ranges of u and of (1 − u)^k
    // (decreasing in u), and of t − tc; summed (each sum bound holds, if not tightly).
    void bounds(double t0, double t1, Range& g, Range& dg) const {
        g = {-m_threshold, -m_threshold};
        dg = {0.0, 0.0};
        for (int i = 0; i < m_count; ++i) {
            const Active& a = m_active[i];
            if (a.hi <= t0 || a.lo >= t1) continue;  // zero on the interval
            const double x0 = t0 - a.tc, x1 = t1 - a.tc;
            const double x2_min = x0 <= 0.0 && x1 >= 0.0 ? 0.0 : std::min(x0 * x0, x1 * x1);
            const double x2_max = std::max(x0 * x0, x1 * x1);
            const double v_max = std::max(1.0 - (x2_min + a.h2) * a.inverse_r2, 0.0);  // 1 − u
            const double v_min = std::max(1.0 - (x2_max + a.h2) * a.inverse_r2, 0.0);
            const double s = a.strength;
            const Range k{v_min * v_min * v_min, v_max * v_max * v_max};
            g.lo += s > 0.0 ? s * k.lo : s * k.hi;
            g.hi += s > 0.0 ? s * k.hi : s * k.lo;
            // g'_i = c·(1 − u)²·x with c = −6·s/R²; (1 − u)² in [v_min², v_max²] >= 0.
            const double q_lo = v_min * v_min, q_hi = v_max * v_max;
            const Range p{x0 < 0.0 ? q_hi * x0 : q_lo * x0, x1 > 0.0 ? q_hi * x1 : q_lo * x1};
            const double c = -6.0 * s * a.inverse_r2;
            dg.lo += c > 0.0 ? c * p.lo : c * p.hi;
            dg.hi += c > 0.0 ? c * p.hi : c * p.lo;
        }
    }
    DVec3 outward_normal(const DVec3& p, const Blob& blob) const { return -blob.gradient(p); }

  private:
    double m_threshold;
    double m_lo, m_hi;
    int m_count = 0;
    Active m_active[kMaxBlobElements];
};

// The crossings of g = 0 in [t0, t1] in increasing t, each passed to emit(t, entering), which
// returns false to stop the search (a nearest hit found). Inside is g > 0.
class RootSearch {
  public:
    template <typename Emit>
    RootSearch(const RayField& field, double t0, double t1, Emit&& emit) : m_field(field) {
        m_tolerance = kBlobResolution * (t1 - t0 + std::abs(t0) + std::abs(t1));
        const double g0 = field.value(t0), g1 = field.value(t1);
        search(t0, g0, t1, g1, 0, emit);
    }

  private:
    template <typename Emit>
    bool search(double t0, double g0, double t1, double g1, int depth, Emit& emit) {
        Range g, dg;
        m_field.bounds(t0, t1, g, dg);
        if (g.lo > 0.0 || g.hi <= 0.0) return true;  // wholly inside or outside: no crossing
        const bool change = (g0 > 0.0) != (g1 > 0.0);
        const bool monotone = dg.lo > 0.0 || dg.hi < 0.0;
        if (monotone || t1 - t0 < m_tolerance || depth >= kMaxSplits) {
            // One crossing at most (or an unresolvably close pair, which merges).
            if (!change) return true;
            return emit(refine(t0, g0, t1), g1 > 0.0);
        }
        const double tm = 0.5 * (t0 + t1), gm = m_field.value(tm);
        return search(t0, g0, tm, gm, depth + 1, emit) && search(tm, gm, t1, g1, depth + 1, emit);
    }

    // The root of g in a bracket [a, b] (g(a) and g(b) on opposite sides of 0): Newton from
    // the middle, bisection when a step leaves the bracket.
    double refine(double a, double ga, double b) const {
        const bool a_inside = ga > 0.0;
        double t = 0.5 * (a + b);
        for (int i = 0; i < 100 && b - a > m_tolerance; ++i) {
            const double gt = m_field.value(t);
            if (gt == 0.0) return t;
            if ((gt > 0.0) == a_inside) {
                a = t;
            } else {
                b = t;
            }
            const double slope = m_field.slope(t);
            const double next = slope != 0.0 ? t - gt / slope : a - 1.0;
            t = next > a && next < b ? next : 0.5 * (a + b);
        }
        return t;
    }

    const RayField& m_field;
    double m_tolerance;
};

}  // namespace

std::optional<FieldProblem> Blob::problem() const {
    if (elements.empty()) return FieldProblem{"elements", "expected at least one element"};
    if (elements.size() > static_cast<size_t>(kMaxBlobElements)) {
        return FieldProblem{"elements", "expected at most " + std::to_string(kMaxBlobElements) +
                                            " elements (core/shapes/blob.h), got " +
                                            std::to_string(elements.size())};
    }
    double positive = 0.0;
    for (const BlobElement& e : elements) positive += std::max(e.strength, 0.0f);
    if (!(positive > threshold)) {
        return FieldProblem{"threshold",
                            "expected a threshold below the sum of the positive strengths "
                            "(else the blob is empty)"};
    }
    return std::nullopt;
}

Bounds3 Blob::bounds() const {
    Bounds3 b{Vec3(std::numeric_limits<float>::max()), Vec3(-std::numeric_limits<float>::max())};
    for (const BlobElement& e : elements) {
        if (!(e.strength > 0.0f)) continue;
        b.lower = glm::min(b.lower, e.center - Vec3(e.radius));
        b.upper = glm::max(b.upper, e.center + Vec3(e.radius));
    }
    return b;
}

int Blob::crossings(const Vec3& origin, const Vec3& direction, ShapeCrossing* out,
                    int capacity) const {
    const RayField field(*this, origin, direction);
    if (field.empty()) return 0;
    int n = 0;
    RootSearch(field, field.lo(), field.hi(), [&](double t, bool entering) {
        const DVec3 p = DVec3(origin) + t * DVec3(direction);
        out[n++] = {static_cast<float>(t), entering, Vec3(field.outward_normal(p, *this))};
        return n < capacity;
    });
    return n;
}

bool Blob::nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                   ShapeHit& hit) const {
    const RayField field(*this, origin, direction);
    if (field.empty()) return false;
    const double t0 = std::max(field.lo(), double(tnear)), t1 = std::min(field.hi(), double(tfar));
    if (!(t0 < t1)) return false;
    bool found = false;
    RootSearch(field, t0, t1, [&](double t, bool) {
        const float rounded = static_cast<float>(t);
        if (!(rounded > tnear && rounded < tfar)) return true;  // rounded onto the window's end
        hit.t = rounded;
        hit.normal = Vec3(field.outward_normal(DVec3(origin) + t * DVec3(direction), *this));
        found = true;
        return false;
    });
    return found;
}

double Blob::field(const DVec3& p) const {
    double sum = 0.0;
    for (const BlobElement& e : elements) {
        const DVec3 f = p - DVec3(e.center);
        const double u = glm::dot(f, f) / (double(e.radius) * e.radius);
        if (u < 1.0) sum += e.strength * (1.0 - u) * (1.0 - u) * (1.0 - u);
    }
    return sum;
}

DVec3 Blob::gradient(const DVec3& p) const {
    // ∇ s·(1 − u)³ = −6·s·(1 − u)²·(p − c)/R².
    DVec3 sum(0.0);
    for (const BlobElement& e : elements) {
        const DVec3 f = p - DVec3(e.center);
        const double inverse_r2 = 1.0 / (double(e.radius) * e.radius);
        const double u = glm::dot(f, f) * inverse_r2;
        if (u < 1.0) sum -= 6.0 * e.strength * (1.0 - u) * (1.0 - u) * inverse_r2 * f;
    }
    return sum;
}

double Blob::sphere_radius(const BlobElement& e, double threshold) {
    // s·(1 − ρ²/R²)³ = T.
    if (!(e.strength > threshold)) return 0.0;
    return e.radius * std::sqrt(1.0 - std::cbrt(threshold / e.strength));
}

void Blob::surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const {
    surface_at_ray_point(ray, hit, bounds(), out);
}

void Blob::parameterization(const Vec3& position, SurfaceHit& out) const {
    bounds_parameterization(bounds(), position, out);
}

void Blob::outline(Outline& out) const {
    for (const BlobElement& e : elements) {
        const double r = sphere_radius(e, threshold);
        if (r > 0.0) Sphere{e.center, static_cast<float>(r), 0}.outline(out);
    }
}

}  // namespace rayo
