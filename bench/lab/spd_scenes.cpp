#include "bench/lab/spd_scenes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <sstream>
#include <tuple>

#include "apps/scene/nff_loader.h"
#include "bench/lab/teapot_patches.h"
#include "core/error.h"

namespace rayo {
namespace {

using D3 = glm::dvec3;
constexpr double kPiD = 3.14159265358979323846;

double radians(double degrees) {
    return degrees * kPiD / 180.0;
}

// The NFF lines the SPD writes, numbers as C's %g prints them (six significant digits: the
// ostream default), so that a generated file reads like the SPD's own.
class NffWriter {
  public:
    // Background, viewpoint (45° field, 512×512) and hither, the SPD's common header.
    NffWriter(const D3& from, const D3& at, const D3& up, double hither) {
        m_out << "b 0.078 0.361 0.753\nv\nfrom " << xyz(from) << "\nat " << xyz(at) << "\nup "
              << xyz(up) << "\nangle 45\nhither " << hither << "\nresolution 512 512\n";
    }
    void light(const D3& p) { m_out << "l " << xyz(p) << "\n"; }
    // f r g b Kd Ks Shine T index_of_refraction
    void material(const D3& rgb, double kd, double ks, double shine, double t, double ior) {
        m_out << "f " << xyz(rgb) << " " << kd << " " << ks << " " << shine << " " << t << " "
              << ior << "\n";
    }
    void sphere(const D3& c, double r) { m_out << "s " << xyz(c) << " " << r << "\n"; }
    void cone(const D3& base, double base_r, const D3& apex, double apex_r) {
        m_out << "c " << xyz(base) << " " << base_r << " " << xyz(apex) << " " << apex_r << "\n";
    }
    void polygon(const std::vector<D3>& points) {
        m_out << "p " << points.size() << "\n";
        for (const D3& p : points) m_out << xyz(p) << "\n";
    }
    void patch(const std::array<D3, 3>& points, const std::array<D3, 3>& normals) {
        m_out << "pp 3\n";
        for (int i = 0; i < 3; ++i) m_out << xyz(points[i]) << " " << xyz(normals[i]) << "\n";
    }
    std::string text() const { return m_out.str(); }

  private:
    std::string xyz(const D3& v) const {
        std::ostringstream s;
        s << v.x << " " << v.y << " " << v.z;
        return s.str();
    }
    std::ostringstream m_out;
};

// A square of half side `half` around `centre` in the plane spanned by `a` and `b`, corners
// listed as the SPD lists its floors: (+a+b), (−a+b), (−a−b), (+a−b).
std::vector<D3> square(const D3& centre, const D3& a, const D3& b, double half) {
    return {centre + half * (a + b), centre + half * (-a + b), centre - half * (a + b),
            centre + half * (a - b)};
}

// ---- balls: the sphereflake ------------------------------------------------------------------
// A sphere carries nine spheres of a third of its radius touching it: in the frame where its
// axis is +z, three around the upper cap (elevation asin √(2/3) = 54.7°, the direction
// (1, 1, 2)/√6) at azimuths 45°, 165°, 285°, each followed by two on the equator 30° either side
// of it (15°, 75°; 135°, 195°; 255°, 315°). The frame of a child is the rotation taking +z to
// its direction by the shortest arc (about −z: the half turn about y).
D3 rotate_from_z(const D3& axis, const D3& v) {
    const double c = axis.z;
    const D3 k = glm::cross(D3(0, 0, 1), axis);
    const double s = glm::length(k);
    if (s < 1e-9) return c > 0 ? v : D3(-v.x, v.y, -v.z);
    const D3 unit = k / s;  // Rodrigues' rotation formula
    return v * c + glm::cross(unit, v) * s + unit * glm::dot(unit, v) * (1.0 - c);
}

void add_flake(NffWriter& w, const D3& centre, double radius, const D3& axis, int depth) {
    w.sphere(centre, radius);
    if (depth == 0) return;
    const double up = std::asin(std::sqrt(2.0 / 3.0));
    for (int k = 0; k < 3; ++k) {
        for (const auto& [azimuth, elevation] :
             {std::pair{45.0, up}, std::pair{15.0, 0.0}, std::pair{75.0, 0.0}}) {
            const double a = radians(azimuth + 120.0 * k);
            const D3 local(std::cos(elevation) * std::cos(a), std::cos(elevation) * std::sin(a),
                           std::sin(elevation));
            const D3 direction = rotate_from_z(axis, local);
            const double child = radius / 3.0;
            add_flake(w, centre + (radius + child) * direction, child, direction, depth - 1);
        }
    }
}

std::string balls(int n) {
    NffWriter w(D3(2.1, 1.3, 1.7), D3(0, 0, 0), D3(0, 0, 1), 0.01);
    for (const D3& p : {D3(4, 3, 2), D3(1, -4, 4), D3(-3, 1, 5)}) w.light(p);
    w.material(D3(1, 0.75, 0.33), 0.8, 0, 100000, 0, 1);
    w.polygon(square(D3(0, 0, -0.5), D3(1, 0, 0), D3(0, 1, 0), 12));
    w.material(D3(1, 0.9, 0.7), 0.5, 0.5, 3.0827, 0, 1);
    add_flake(w, D3(0, 0, 0), 0.5, D3(0, 0, 1), n);
    return w.text();
}

// ---- gears -----------------------------------------------------------------------------------
// n × n × n gears of 36 teeth, layer k's tops at z = 1 − k/n, min(0.1, 1/(2n)) thick. A unit gear's
// teeth reach radius 0.995 (tips 3.8° wide) from a root circle of radius 0.9 (gaps 4° wide at the
// root); neighbours 1.9 apart mesh, the odd ones (i + j + k odd) turned half a tooth. The grid
// is scaled to span [−1, 1]²: s = 2 / (1.9n + 0.1). Each gear: its top face (counter-clockwise
// from above), the 144 side quads, its bottom face (reversed).
// The SPD's gear colours and glass (gears.c, version 3): a fraction of a sum of the gear's grid
// coordinates per channel, scaled so that the largest channel is 1; glass when
// (4i + 2j + k) mod 5 = 0 (i, j, k along x, y, z).
D3 gear_colour(int i, int j, int k, bool& glass) {
    const auto fraction = [](double v) { return v - std::floor(v); };
    D3 rgb(0.01 + fraction((3 * i + 2 * j + k + 1) * 5.0 / 7.0),
           0.01 + fraction((3 * j + 2 * k + i + 1) * 3.0 / 7.0),
           0.01 + fraction((3 * k + 2 * i + j + 1) * 2.0 / 7.0));
    const double largest = std::max({rgb[0], rgb[1], rgb[2]});
    for (int c = 0; c < 3; ++c) rgb[c] /= largest;
    glass = (4 * i + 2 * j + k) % 5 == 0;
    return rgb;
}

std::string gears(int n) {
    NffWriter w(D3(-1.1, -2.1, 2.6), D3(0, 0, 0), D3(0, 0, 1), 1);
    for (const D3& p :
         {D3(2, 4, 4), D3(-2, 4, 3), D3(2, -2.5, 2.5), D3(-1, -4, 2), D3(-1.111, -2.121, 2.626)}) {
        w.light(p);
    }
    w.material(D3(1, 0.85, 0.7), 0.3, 0.6, 3.0827, 0, 0);
    w.polygon(square(D3(0, 0, 0), D3(1, 0, 0), D3(0, 1, 0), 2));
    const double scale = 2.0 / (1.9 * n + 0.1);
    // 0.1 thick, thinner above size 5 so that the layers do not overlap (the SPD's rule).
    const double thickness = std::min(0.1, 1.0 / (2.0 * n));
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                bool glass = false;
                const D3 rgb = gear_colour(i, j, k, glass);
                if (glass) {
                    w.material(rgb, 0.2, 0, 100000, 0.8, 1.1);
                } else {
                    w.material(rgb, 1, 0, 100000, 0, 0);
                }
                const double cx = -1.0 + scale * (1.0 + 1.9 * i);
                const double cy = -1.0 + scale * (1.0 + 1.9 * j);
                const double top = 1.0 - double(k) / n;
                const double turn = (i + j + k) % 2 ? 5.0 : 0.0;
                std::vector<D3> outline;
                for (int tooth = 0; tooth < 36; ++tooth) {
                    const double a = 10.0 * tooth + turn;
                    for (const auto& [radius, angle] :
                         {std::pair{0.995, a - 1.9}, std::pair{0.995, a + 1.9},
                          std::pair{0.9, a + 3.0}, std::pair{0.9, a + 7.0}}) {
                        outline.emplace_back(cx + scale * radius * std::cos(radians(angle)),
                                             cy + scale * radius * std::sin(radians(angle)), top);
                    }
                }
                const D3 down(0, 0, -thickness);
                w.polygon(outline);
                const size_t m = outline.size();
                for (size_t v = 0; v < m; ++v) {
                    const D3& a = outline[v];
                    const D3& b = outline[(v + 1) % m];
                    w.polygon({a, a + down, b + down, b});
                }
                std::vector<D3> bottom;
                for (size_t v = 0; v < m; ++v) bottom.push_back(outline[(m + 1 - v) % m] + down);
                w.polygon(bottom);
            }
        }
    }
    return w.text();
}

// ---- mount: a fractal mountain with four glass spheres --------------------------------------
// Heights on a (2^n + 1)² grid over [−1, 1]², the corners at 0, by midpoint displacement
// (Carpenter's method as the SPD's mount.c extends it to square grids): at each level every
// cell's edge midpoints take the mean of the edge's ends and its centre the mean of its four
// corners, plus a Gaussian displacement of rise = (half the cell's side) · √(r² − 1), r =
// 2 / 2^(1/(D − 1)) for the fractal dimension D = 2.2 (√2 · rise at the centre). The Gaussian
// numbers are the SPD's, so the mountain is the SPD's: a polar Box–Muller pair from the linear
// congruential sequence x' = (28411 + 8121·x) mod 134456 (Numerical Recipes' GASDEV with its
// short generator; the SPD's lib_gauss_rand) seeded with 21 + the SPD's original grid hash
// ((x << (23 − n)) + (y << (15 − n)) + (x << (7 − n))) & 0xffff, which the SPD asks timing tests
// to keep. (Above size 7 its shifts go negative, undefined in C: here they shift right.)
// Triangles are written cell by cell in the SPD's order: the quadrants of each cell
// counter-clockwise from the lower left, two triangles per cell split along its rising diagonal.
double spd_gauss(long seed) {
    constexpr long kModulus = 134456, kMultiplier = 8121, kIncrement = 28411;
    long second = seed;
    double v1 = 0, r = 0;
    do {
        const long first = (kIncrement + second * kMultiplier) % kModulus;
        second = (kIncrement + first * kMultiplier) % kModulus;
        v1 = first * 2.0 / kModulus - 1.0;
        const double v2 = second * 2.0 / kModulus - 1.0;
        r = v1 * v1 + v2 * v2;
    } while (r >= 1.0);
    return v1 * std::sqrt(-2.0 * std::log(r) / r);
}

long spd_mount_hash(long x, long y, int n) {
    const auto shift = [](unsigned long v, int by) { return by >= 0 ? v << by : v >> -by; };
    return long((shift(x, 23 - n) + shift(y, 15 - n) + shift(x, 7 - n)) & 0xffff);
}

std::string mount(int n) {
    NffWriter w(D3(-1.6, 1.6, 1.7), D3(0, 0, 0), D3(0, 0, 1), 0.01);
    w.light(D3(-100, -100, 100));
    // Four glass spheres of radius 0.17 stacked as a tetrahedron over (−0.8, 0.8): three
    // touching at z = 0.930598 (the SPD's height), the fourth on them.
    w.material(D3(1, 1, 1), 0.1, 0.1, 101.148, 0.9, 1.5);
    const double r = 0.17, base = 0.930598;
    w.sphere(D3(-0.8, 0.8, base + 2 * r * std::sqrt(2.0 / 3.0)), r);
    for (double azimuth : {-45.0, 75.0, 195.0}) {
        const double d = 2 * r / std::sqrt(3.0);
        w.sphere(
            D3(-0.8 + d * std::cos(radians(azimuth)), 0.8 + d * std::sin(radians(azimuth)), base),
            r);
    }
    w.material(D3(0.5, 0.45, 0.35), 1, 0, 100000, 0, 0);
    const int cells = 1 << n;
    std::vector<double> z(size_t(cells + 1) * (cells + 1), 0.0);
    auto at = [&](int x, int y) -> double& { return z[size_t(y) * (cells + 1) + x]; };
    const double ratio = 2.0 / std::exp(std::log(2.0) / (2.2 - 1.0));
    const double roughness = std::sqrt(ratio * ratio - 1.0);
    double rise = 0;  // this level's
    auto displaced = [&](int x, int y, double mean, double factor = 1.0) {
        return mean + factor * rise * spd_gauss(21 + spd_mount_hash(x, y, n));
    };
    for (int level = 1; level <= n; ++level) {
        const int half = cells >> level, step = 2 * half;
        rise = half * 2.0 / cells * roughness;
        for (int y = 0; y < cells; y += step) {
            for (int x = 0; x < cells; x += step) {
                const double a = at(x, y), b = at(x + step, y), c = at(x + step, y + step),
                             d = at(x, y + step);
                at(x + half, y + half) =
                    displaced(x + half, y + half, (a + b + c + d) / 4.0, 1.4142136);
                // Each edge midpoint once: the lower and left edges here, the others at the grid's
                // upper and right borders.
                at(x + half, y) = displaced(x + half, y, (a + b) / 2.0);
                at(x, y + half) = displaced(x, y + half, (d + a) / 2.0);
                if (x + step == cells) {
                    at(cells, y + half) = displaced(cells, y + half, (b + c) / 2.0);
                }
                if (y + step == cells) {
                    at(x + half, cells) = displaced(x + half, cells, (c + d) / 2.0);
                }
            }
        }
    }
    auto point = [&](int x, int y) {
        return D3(-1.0 + 2.0 * x / cells, -1.0 + 2.0 * y / cells, at(x, y));
    };
    std::function<void(int, int, int)> cell = [&](int x, int y, int side) {
        if (side == 1) {
            w.polygon({point(x, y), point(x + 1, y), point(x + 1, y + 1)});
            w.polygon({point(x + 1, y + 1), point(x, y + 1), point(x, y)});
            return;
        }
        const int h = side / 2;
        cell(x, y, h);
        cell(x + h, y, h);
        cell(x + h, y + h, h);
        cell(x, y + h, h);
    };
    cell(0, 0, cells);
    return w.text();
}

// ---- rings -----------------------------------------------------------------------------------
// Clusters of six pentagonal rings (radius 0.930995, rods of radius 0.07412: five cylinders
// between five spheres), each ring's axis one of the six axes of an icosahedron: +z and five at
// 63.43° from it (cos = 1/√5), azimuths −54° + 72°k; a ring's first corner lies in the
// horizontal plane, at its axis' azimuth + 90°. The clusters form a pyramid seen from its apex:
// layer k (0..n−1) holds (k+1)² clusters 2 apart in x and z at y = (k+1)/sin 22.5° (2.61313
// apart). A white wall at y = (n+1)/sin 22.5° fills the 45° view with 1 % to spare. Ring colours
// cycle red, green, blue, cyan, magenta, yellow, one material each.
std::string rings(int n) {
    const double spacing = 1.0 / std::sin(radians(22.5)), ring_radius = 0.930995, rod = 0.07412;
    const D3 eye(-1, -spacing, 0.5);
    NffWriter w(eye, D3(-1, 1 - spacing, 0.5), D3(0, 0, 1), 1);
    for (const D3& p : {D3(3, -spacing, 3), D3(-4, -spacing, 1), D3(2, -spacing, -4)}) w.light(p);
    w.material(D3(1, 1, 1), 1, 0, 100000, 0, 0);
    const double wall_y = spacing * (n + 1);
    w.polygon(square(D3(eye.x, wall_y, eye.z), D3(1, 0, 0), D3(0, 0, 1),
                     1.01 * std::tan(radians(22.5)) * (wall_y - eye.y)));
    const D3 colours[6] = {D3(1, 0, 0), D3(0, 1, 0), D3(0, 0, 1),
                           D3(0, 1, 1), D3(1, 0, 1), D3(1, 1, 0)};
    for (int layer = 0; layer < n; ++layer) {
        for (int j = 0; j <= layer; ++j) {
            for (int i = 0; i <= layer; ++i) {
                const D3 centre(-layer + 2.0 * i, spacing * (layer + 1), -layer + 2.0 * j);
                for (int ring = 0; ring < 6; ++ring) {
                    w.material(colours[ring], 0.5, 0.2, 3.0827, 0, 0);
                    D3 axis(0, 0, 1), u(1, 0, 0);
                    if (ring > 0) {
                        const double azimuth = radians(-54.0 + 72.0 * (ring - 1));
                        const double sin_t = 2.0 / std::sqrt(5.0), cos_t = 1.0 / std::sqrt(5.0);
                        axis = D3(sin_t * std::cos(azimuth), sin_t * std::sin(azimuth), cos_t);
                        u = D3(-std::sin(azimuth), std::cos(azimuth), 0);
                    }
                    const D3 v = glm::cross(axis, u);
                    auto corner = [&](int c) {
                        const double a = radians(72.0 * ((c + 5) % 5));
                        return centre + ring_radius * (std::cos(a) * u + std::sin(a) * v);
                    };
                    for (int c = 0; c < 5; ++c) {
                        w.cone(corner(c), rod, corner(c - 1), rod);
                        w.sphere(corner(c), rod);
                    }
                }
            }
        }
    }
    return w.text();
}

// ---- teapot ----------------------------------------------------------------------------------
// The 32 bicubic Bézier patches of the Utah teapot (bench/lab/teapot_patches.h), each cut into
// n × n parameter squares of two triangles (split along the rising diagonal; those with two
// corners in one point, where the lid and the bottom close, left out), with the surface normal
// ∂P/∂s × ∂P/∂t at each corner (s along a control row, t across rows; at a closing point taken
// just inside the patch). A checkered floor of n × n squares over [−4, 4]², z = 0: white where
// i + j is odd, grey elsewhere (so size 1's one square is grey).
struct PatchPoint {
    D3 position, normal;
};

PatchPoint evaluate_patch(const int (&patch)[16], double s, double t) {
    auto bernstein = [](double x, double(&b)[4], double(&db)[4]) {
        const double y = 1.0 - x;
        b[0] = y * y * y;
        b[1] = 3 * x * y * y;
        b[2] = 3 * x * x * y;
        b[3] = x * x * x;
        db[0] = -3 * y * y;
        db[1] = 3 * y * y - 6 * x * y;
        db[2] = 6 * x * y - 3 * x * x;
        db[3] = 3 * x * x;
    };
    auto eval = [&](double ss, double tt, D3& p, D3& ds, D3& dt) {
        double bs[4], dbs[4], bt[4], dbt[4];
        bernstein(ss, bs, dbs);
        bernstein(tt, bt, dbt);
        p = ds = dt = D3(0.0);
        for (int row = 0; row < 4; ++row) {
            for (int col = 0; col < 4; ++col) {
                const double* c = kTeapotPoints[patch[4 * row + col] - 1];
                const D3 control(c[0], c[1], c[2]);
                p += bt[row] * bs[col] * control;
                ds += bt[row] * dbs[col] * control;
                dt += dbt[row] * bs[col] * control;
            }
        }
    };
    PatchPoint out;
    D3 ds, dt;
    eval(s, t, out.position, ds, dt);
    D3 normal = glm::cross(ds, dt);
    if (glm::length(normal) < 1e-9) {  // a closing point: the normal just inside the patch
        constexpr double kInside = 1e-6;
        D3 unused;
        eval(s + (s < 0.5 ? kInside : -kInside), t + (t < 0.5 ? kInside : -kInside), unused, ds,
             dt);
        normal = glm::cross(ds, dt);
    }
    out.normal = glm::normalize(normal);
    return out;
}

std::string teapot(int n) {
    NffWriter w(D3(4.86, 7.2, 5.4), D3(0, 0, 0), D3(0, 0, 1), 1);
    w.light(D3(-3.1, 9.8, 12.1));
    w.light(D3(11.3, 5.1, 8.8));
    const double cell = 8.0 / n;
    for (int white = 1; white >= 0; --white) {
        w.material(white ? D3(1, 1, 1) : D3(0.5, 0.5, 0.5), 0.5, 0.5, 4.81884, 0, 0);
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                if ((i + j) % 2 != white) continue;
                const double x0 = -4 + cell * i, y0 = -4 + cell * j;
                w.polygon({D3(x0, y0, 0), D3(x0 + cell, y0, 0), D3(x0 + cell, y0 + cell, 0),
                           D3(x0, y0 + cell, 0)});
            }
        }
    }
    w.material(D3(1, 0.5, 0.1), 0.75, 0.25, 3.0827, 0, 0);
    for (const auto& patch : kTeapotPatches) {
        std::vector<PatchPoint> grid;
        for (int row = 0; row <= n; ++row) {
            for (int col = 0; col <= n; ++col) {
                grid.push_back(evaluate_patch(patch, double(col) / n, double(row) / n));
            }
        }
        auto emit = [&](const PatchPoint& a, const PatchPoint& b, const PatchPoint& c) {
            // Two corners in one point (up to rounding): where a patch closes. Collinear
            // triangles with distinct corners stay, as in the SPD (the NFF loader skips them).
            constexpr double kSame = 1e-9;
            if (glm::length(a.position - b.position) < kSame ||
                glm::length(b.position - c.position) < kSame ||
                glm::length(c.position - a.position) < kSame) {
                return;
            }
            w.patch({a.position, b.position, c.position}, {a.normal, b.normal, c.normal});
        };
        for (int row = 0; row < n; ++row) {
            for (int col = 0; col < n; ++col) {
                const PatchPoint& p00 = grid[size_t(row) * (n + 1) + col];
                const PatchPoint& p10 = grid[size_t(row) * (n + 1) + col + 1];
                const PatchPoint& p11 = grid[size_t(row + 1) * (n + 1) + col + 1];
                const PatchPoint& p01 = grid[size_t(row + 1) * (n + 1) + col];
                emit(p00, p10, p11);
                emit(p11, p01, p00);
            }
        }
    }
    return w.text();
}

// ---- tetra: the Sierpinski tetrahedron --------------------------------------------------------
// A regular tetrahedron of corners (−1,−1,1), (−1,1,−1), (1,−1,−1), (1,1,1) replaced n − 1 times
// by the four half-size tetrahedra at its corners (in that order); each final one written as its
// four faces (v0 v1 v2), (v3 v2 v1), (v2 v3 v0), (v1 v0 v3).
void add_tetra(NffWriter& w, const D3& centre, double half, int depth) {
    const D3 corners[4] = {D3(-1, -1, 1), D3(-1, 1, -1), D3(1, -1, -1), D3(1, 1, 1)};
    if (depth > 0) {
        for (const D3& c : corners) add_tetra(w, centre + 0.5 * half * c, 0.5 * half, depth - 1);
        return;
    }
    D3 v[4];
    for (int i = 0; i < 4; ++i) v[i] = centre + half * corners[i];
    w.polygon({v[0], v[1], v[2]});
    w.polygon({v[3], v[2], v[1]});
    w.polygon({v[2], v[3], v[0]});
    w.polygon({v[1], v[0], v[3]});
}

std::string tetra(int n) {
    NffWriter w(D3(1.02285, -3.17715, -2.17451), D3(-0.004103, -0.004103, 0.216539),
                D3(-0.816497, -0.816497, 0.816497), 1);
    w.light(D3(2, -18, -5));
    w.material(D3(1, 0.2, 0.2), 1, 0, 100000, 0, 0);
    add_tetra(w, D3(0, 0, 0), 1, n - 1);
    return w.text();
}

// ---- tree ------------------------------------------------------------------------------------
// A trunk (a cone from radius 0.15 at the origin to 0.1005 at (0, 0, 1)) and n levels of
// branching: every branch carries two, one 0.65 as long bent 40° from it, one 0.7 as long bent
// 25° at 140° around it; radii shrink by 0.67 per level. A branch's frame is its parent's, bent
// with it and then turned 90° about the new axis. Each branch is a cone from its parent's top to
// its own and a sphere at its top (the cone's top radius), written depth first.
struct Branch {
    D3 top, axis, across;  // across: the direction of azimuth 0 around the axis
    double length, radius;
};

void add_branches(NffWriter& w, const Branch& b, int depth) {
    if (depth == 0) return;
    for (const auto& [bend, azimuth, shrink] :
         {std::tuple{40.0, 0.0, 0.65}, std::tuple{25.0, 140.0, 0.7}}) {
        const D3 side = glm::cross(b.axis, b.across);
        const D3 radial = std::cos(radians(azimuth)) * b.across + std::sin(radians(azimuth)) * side;
        const D3 axis = std::cos(radians(bend)) * b.axis + std::sin(radians(bend)) * radial;
        const D3 bent = -std::sin(radians(bend)) * b.axis + std::cos(radians(bend)) * radial;
        Branch child;
        child.length = b.length * shrink;
        child.radius = b.radius * 0.67;
        child.top = b.top + child.length * axis;
        child.axis = axis;
        child.across = glm::cross(axis, bent);  // `bent` turned 90° about the new axis
        w.cone(b.top, b.radius, child.top, child.radius);
        w.sphere(child.top, child.radius);
        add_branches(w, child, depth - 1);
    }
}

std::string tree(int n) {
    NffWriter w(D3(4.5, 0.4, 2), D3(0, 0, 1.5), D3(0, 0, 1), 1);
    for (const D3& p : {D3(-5, 5, 50), D3(30, -30, 30), D3(-40, -30, 20), D3(10, 30, 40),
                        D3(-30, 40, 10), D3(50, 25, 20), D3(-10, -60, 30)}) {
        w.light(p);
    }
    w.material(D3(0.2, 0.7, 0.2), 1, 0, 100000, 0, 0);
    w.polygon(square(D3(0, 0, 0), D3(1, 0, 0), D3(0, 1, 0), 50));
    w.material(D3(0.55, 0.4, 0.2), 1, 0, 100000, 0, 0);
    const Branch trunk{D3(0, 0, 1), D3(0, 0, 1), D3(1, 0, 0), 1.0, 0.15 * 0.67};
    w.cone(D3(0, 0, 0), 0.15, trunk.top, trunk.radius);
    w.sphere(trunk.top, trunk.radius);
    add_branches(w, trunk, n);
    return w.text();
}

struct Generator {
    std::string (*make)(int);
    int max_size;
    int default_size;  // the SPD generator's size_factor
};

// Largest sizes: about a million primitives or fewer.
const std::map<std::string, Generator>& generators() {
    static const std::map<std::string, Generator> table = {
        {"balls", {balls, 6, 4}},  {"gears", {gears, 12, 4}},    {"mount", {mount, 9, 6}},
        {"rings", {rings, 20, 7}}, {"teapot", {teapot, 64, 12}}, {"tetra", {tetra, 9, 6}},
        {"tree", {tree, 18, 11}},
    };
    return table;
}

const Generator& generator(const std::string& name) {
    const auto it = generators().find(name);
    if (it == generators().end()) {
        throw InputError("spd:" + name,
                         "unknown SPD scene (expected balls, gears, mount, rings, teapot, tetra "
                         "or tree)");
    }
    return it->second;
}

}  // namespace

const std::vector<std::string>& spd_scene_names() {
    static const std::vector<std::string> names = {"balls",  "gears", "mount", "rings",
                                                   "teapot", "tetra", "tree"};
    return names;
}

int spd_max_size(const std::string& name) {
    return generator(name).max_size;
}

int spd_default_size(const std::string& name) {
    return generator(name).default_size;
}

std::string spd_nff(const std::string& name, int size) {
    const Generator& g = generator(name);
    if (size < 1 || size > g.max_size) {
        throw InputError("spd:" + name, "size " + std::to_string(size) + " is out of range: " +
                                            "expected 1.." + std::to_string(g.max_size));
    }
    return g.make(size);
}

SceneDescription spd_scene(const std::string& name, int size) {
    return load_nff_string(spd_nff(name, size), "spd:" + name + ":" + std::to_string(size));
}

}  // namespace rayo
