#include "core/shapes/tessellation.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <limits>

namespace rayo {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

// The greatest speed of a piece's points along s and along t (length per unit parameter),
// from a 17 × 64 sampling: cells are uniform in (s, t), so these bound their sides (a two-sheet
// hyperboloid's profile is steepest at its vertex, a paraboloid's at its rim).
void piece_speeds(const SurfacePiece& piece, double& along_s, double& along_t) {
    constexpr int kLines = 16, kSteps = 64;
    along_s = along_t = 0.0;
    for (int line = 0; line <= kLines; ++line) {
        const double fixed = static_cast<double>(line) / kLines;
        for (int step = 0; step < kSteps; ++step) {
            const double a = static_cast<double>(step) / kSteps;
            const double b = static_cast<double>(step + 1) / kSteps;
            along_s = std::max(along_s,
                               kSteps * glm::length(piece.point(b, fixed) - piece.point(a, fixed)));
            along_t = std::max(along_t,
                               kSteps * glm::length(piece.point(fixed, b) - piece.point(fixed, a)));
        }
    }
}

uint32_t cells_for(double length, const TessellationOptions& options, uint32_t least) {
    double n = 1.0;
    if (options.max_edge > 0.0f) n = std::ceil(length / options.max_edge);
    n = std::clamp(n, static_cast<double>(std::max<uint32_t>(least, 1)),
                   static_cast<double>(std::max<uint32_t>(options.max_cells, least)));
    return static_cast<uint32_t>(n);
}

// The largest distance between a cell side's chord and the surface over its midpoint, along s
// (or t) with n cells that way, sampled on 17 lines across: the chord error of that direction.
double chord_error(const SurfacePiece& piece, uint32_t n, bool along_s) {
    constexpr int kLines = 16;
    double worst = 0.0;
    for (int line = 0; line <= kLines; ++line) {
        const double fixed = static_cast<double>(line) / kLines;
        auto at = [&](double u) { return along_s ? piece.point(u, fixed) : piece.point(fixed, u); };
        for (uint32_t k = 0; k < n; ++k) {
            const double a = static_cast<double>(k) / n, b = static_cast<double>(k + 1) / n;
            worst = std::max(worst, glm::length(at(0.5 * (a + b)) - 0.5 * (at(a) + at(b))));
        }
    }
    return worst;
}

double wrap_angle(double y, double x) {
    const double s = std::atan2(y, x) / kTwoPi;
    return s < 0.0 ? s + 1.0 : s;
}

double outside(double v, double lo, double hi) {
    return std::max(0.0, std::max(lo - v, v - hi));
}

}  // namespace

DVec3 SurfacePiece::point(double s, double t) const {
    const double angle = kTwoPi * s;
    DVec3 x(0.0);
    switch (kind) {
        case Kind::Revolution: {
            const double z = z0 + t * (z1 - z0);
            const double rho = std::sqrt(std::max(0.0, r2[0] + r2[1] * z + r2[2] * z * z));
            x = DVec3(rho * std::cos(angle), rho * std::sin(angle), z);
            break;
        }
        case Kind::Sphere: {
            const double sin_theta = std::sin(M_PI * t);
            x = DVec3(sin_theta * std::cos(angle), sin_theta * std::sin(angle),
                      -std::cos(M_PI * t));
            break;
        }
        case Kind::Cap:
            x = DVec3(t * radius * std::cos(angle), t * radius * std::sin(angle), z0);
            break;
        case Kind::Quad:
            x = DVec3(s, t, 0.0);
            break;
    }
    return origin + frame * x;
}

DVec3 SurfacePiece::normal(double s, double t) const {
    // The local normal, then to world by the inverse transpose of the frame.
    const double angle = kTwoPi * s;
    DVec3 n(0.0, 0.0, 1.0);
    switch (kind) {
        case Kind::Revolution: {
            // The gradient of ρ² − r2(z): (2x, 2y, −(r2[1] + 2·r2[2]·z)), halved.
            const DVec3 x = glm::inverse(frame) * (point(s, t) - origin);
            n = DVec3(x.x, x.y, -0.5 * (r2[1] + 2.0 * r2[2] * x.z));
            break;
        }
        case Kind::Sphere: {
            const double sin_theta = std::sin(M_PI * t);
            n = DVec3(sin_theta * std::cos(angle), sin_theta * std::sin(angle),
                      -std::cos(M_PI * t));
            break;
        }
        case Kind::Cap:
        case Kind::Quad:
            break;
    }
    DVec3 world = glm::transpose(glm::inverse(frame)) * n;
    if (flip) world = -world;
    const double length = glm::length(world);
    return length > 0.0 ? world / length : DVec3(0.0);
}

void tessellate(const SurfacePieces& pieces, const TessellationOptions& options,
                TessellatedMesh& out) {
    out = TessellatedMesh{};
    for (const SurfacePiece& piece : pieces) {
        double along_s = 0.0, along_t = 0.0;
        piece_speeds(piece, along_s, along_t);
        const bool curved = piece.kind != SurfacePiece::Kind::Quad;
        PieceGrid grid;
        grid.nu = cells_for(along_s, options, curved ? options.min_around : 1);
        grid.nv = cells_for(along_t, options,
                            piece.kind == SurfacePiece::Kind::Sphere ? options.min_along : 1);
        if (options.max_chord > 0.0f) {
            // The chord error of a side falls as 1/n²: each direction gets half the budget
            // (a triangle's deviation adds both), a few passes for the sampling.
            const double budget = 0.5 * options.max_chord;
            for (int pass = 0; pass < 4; ++pass) {
                bool refined = false;
                for (const bool along_s : {true, false}) {
                    uint32_t& n = along_s ? grid.nu : grid.nv;
                    const double error = chord_error(piece, n, along_s);
                    if (error <= budget || n >= options.max_cells) continue;
                    const double wanted = std::ceil(n * std::sqrt(error / budget));
                    n = static_cast<uint32_t>(std::min<double>(wanted, options.max_cells));
                    refined = true;
                }
                if (!refined) break;
            }
        }
        grid.first_vertex = static_cast<uint32_t>(out.positions.size());
        grid.first_triangle = static_cast<uint32_t>(out.slot.size());
        for (uint32_t j = 0; j <= grid.nv; ++j) {
            for (uint32_t i = 0; i <= grid.nu; ++i) {
                const double s = static_cast<double>(i) / grid.nu;
                const double t = static_cast<double>(j) / grid.nv;
                out.positions.push_back(Vec3(piece.point(s, t)));
                out.normals.push_back(Vec3(piece.normal(s, t)));
            }
        }
        auto vertex = [&](uint32_t i, uint32_t j) {
            return grid.first_vertex + i + j * (grid.nu + 1);
        };
        for (uint32_t j = 0; j < grid.nv; ++j) {
            for (uint32_t i = 0; i < grid.nu; ++i) {
                const uint32_t v00 = vertex(i, j), v10 = vertex(i + 1, j),
                               v11 = vertex(i + 1, j + 1), v01 = vertex(i, j + 1);
                // Lower (s ≥ t in the cell) and upper halves, each wound to face outward.
                const std::array<std::array<uint32_t, 3>, 2> halves = {
                    std::array<uint32_t, 3>{v00, v10, v11}, std::array<uint32_t, 3>{v00, v11, v01}};
                const std::array<std::array<double, 2>, 2> centres = {
                    std::array<double, 2>{(i + 2.0 / 3.0) / grid.nu, (j + 1.0 / 3.0) / grid.nv},
                    std::array<double, 2>{(i + 1.0 / 3.0) / grid.nu, (j + 2.0 / 3.0) / grid.nv}};
                for (int h = 0; h < 2; ++h) {
                    std::array<uint32_t, 3> tri = halves[h];
                    const DVec3 a(out.positions[tri[0]]), b(out.positions[tri[1]]),
                        c(out.positions[tri[2]]);
                    const DVec3 cross = glm::cross(b - a, c - a);
                    const double longest =
                        std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
                    if (!(glm::length(cross) > 1e-6 * longest * longest)) {
                        out.slot.push_back(TessellatedMesh::kNoTriangle);  // collapsed
                        continue;
                    }
                    const double facing =
                        glm::dot(cross, piece.normal(centres[h][0], centres[h][1])) < 0.0 ? -1.0
                                                                                          : 1.0;
                    if (facing < 0.0) std::swap(tri[1], tri[2]);
                    // The surface over the midpoints of the triangle's sides (in (s, t)) and
                    // over its centroid, above its plane.
                    const DVec3 n = facing * cross / glm::length(cross);
                    const std::array<std::array<double, 2>, 3> corners = {
                        std::array<double, 2>{double(i), double(j)},
                        h == 0 ? std::array<double, 2>{i + 1.0, double(j)}
                               : std::array<double, 2>{i + 1.0, j + 1.0},
                        h == 0 ? std::array<double, 2>{i + 1.0, j + 1.0}
                               : std::array<double, 2>{double(i), j + 1.0}};
                    double bulge = 0.0;
                    auto rise = [&](double ci, double cj) {
                        const DVec3 p = piece.point(ci / grid.nu, cj / grid.nv);
                        bulge = std::max(bulge, glm::dot(p - a, n));
                    };
                    for (int c = 0; c < 3; ++c) {
                        const auto& p = corners[c];
                        const auto& q = corners[(c + 1) % 3];
                        rise(0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]));
                    }
                    rise((corners[0][0] + corners[1][0] + corners[2][0]) / 3.0,
                         (corners[0][1] + corners[1][1] + corners[2][1]) / 3.0);
                    out.slot.push_back(static_cast<uint32_t>(out.triangles.size()));
                    out.triangles.push_back(tri);
                    out.bulge.push_back(static_cast<float>(bulge));
                }
            }
        }
        out.grids.push_back(grid);
    }
}

double grid_chord_error(const SurfacePiece& piece, const PieceGrid& grid) {
    return chord_error(piece, grid.nu, true) + chord_error(piece, grid.nv, false);
}

bool locate(const SurfacePieces& pieces, const Vec3& position, PiecePoint& out) {
    double best = std::numeric_limits<double>::infinity();
    for (uint32_t index = 0; index < pieces.size(); ++index) {
        const SurfacePiece& piece = pieces[index];
        const DVec3 x = glm::inverse(piece.frame) * (DVec3(position) - piece.origin);
        const double rho = std::sqrt(x.x * x.x + x.y * x.y);
        double s = wrap_angle(x.y, x.x), t = 0.0, residual = 0.0;
        switch (piece.kind) {
            case SurfacePiece::Kind::Revolution: {
                const double z =
                    std::clamp(x.z, std::min(piece.z0, piece.z1), std::max(piece.z0, piece.z1));
                t = (z - piece.z0) / (piece.z1 - piece.z0);
                const double r2 = piece.r2[0] + piece.r2[1] * z + piece.r2[2] * z * z;
                residual = std::abs(rho - std::sqrt(std::max(0.0, r2))) + std::abs(x.z - z);
                break;
            }
            case SurfacePiece::Kind::Sphere: {
                const double length = glm::length(x);
                t = length > 0.0 ? std::acos(std::clamp(-x.z / length, -1.0, 1.0)) / M_PI : 0.0;
                residual = std::abs(length - 1.0) * glm::length(piece.frame[0]);
                break;
            }
            case SurfacePiece::Kind::Cap:
                t = rho / piece.radius;
                residual = std::abs(x.z - piece.z0) + std::max(0.0, rho - piece.radius);
                break;
            case SurfacePiece::Kind::Quad:
                s = x.x;
                t = x.y;
                residual = std::abs(x.z) * glm::length(piece.frame[2]) +
                           outside(s, 0.0, 1.0) * glm::length(piece.frame[0]) +
                           outside(t, 0.0, 1.0) * glm::length(piece.frame[1]);
                break;
        }
        if (residual < best) {
            best = residual;
            out.piece = index;
            out.s = std::clamp(s, 0.0, 1.0);
            out.t = std::clamp(t, 0.0, 1.0);
        }
    }
    return best < std::numeric_limits<double>::infinity();
}

CellPoint cell_point(const TessellatedMesh& mesh, const PiecePoint& p) {
    const PieceGrid& grid = mesh.grids[p.piece];
    const double su = p.s * grid.nu, tv = p.t * grid.nv;
    const uint32_t i = std::min(static_cast<uint32_t>(su), grid.nu - 1);
    const uint32_t j = std::min(static_cast<uint32_t>(tv), grid.nv - 1);
    const float fs = static_cast<float>(std::clamp(su - i, 0.0, 1.0));
    const float ft = static_cast<float>(std::clamp(tv - j, 0.0, 1.0));
    auto vertex = [&](uint32_t ii, uint32_t jj) {
        return grid.first_vertex + ii + jj * (grid.nu + 1);
    };
    const uint32_t cell = grid.first_triangle + 2 * (i + j * grid.nu);
    CellPoint out;
    const bool upper = ft > fs;
    if (upper) {
        out.vertices = {vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
        out.weights = {1.0f - ft, fs, ft - fs};
    } else {
        out.vertices = {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)};
        out.weights = {1.0f - fs, fs - ft, ft};
    }
    out.triangle = mesh.slot[cell + (upper ? 1 : 0)];
    if (out.triangle == TessellatedMesh::kNoTriangle)
        out.triangle = mesh.slot[cell + (upper ? 0 : 1)];
    return out;
}

}  // namespace rayo
