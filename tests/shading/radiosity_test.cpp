// Tests of the radiosity solver (shading/radiosity.h): seed 004's worked three-patch example
// (direct solve and the progressive table step by step), reciprocity Ai·Fij = Aj·Fji, the rows
// of a closed enclosure summing to 1, the closed-form form factor of two parallel unit squares
// from both form-factor methods, and the white furnace B = E/(1 − ρ).
#include "shading/radiosity.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/scene.h"

namespace rayo {
namespace {

// Seed 004: F12 = 0.4, F13 = 0.6, F23 = 0.2, Fii = 0, Fij = Fji, E = (1,0,0), ρ = 0.5.
std::vector<double> seed_form_factors() {
    return {0.0, 0.4, 0.6,  //
            0.4, 0.0, 0.2,  //
            0.6, 0.2, 0.0};
}

TEST(RadiosityTest, SeedExampleDirectSolve) {
    const std::vector<DVec3> e = {DVec3(1.0), DVec3(0.0), DVec3(0.0)};
    const std::vector<DVec3> rho(3, DVec3(0.5));
    int iterations = 0;
    const std::vector<DVec3> b =
        solve_radiosity_gauss_seidel(seed_form_factors(), e, rho, 1e-12, 1000, &iterations);
    EXPECT_NEAR(b[0].x, 1.16745, 5e-6);
    EXPECT_NEAR(b[1].x, 0.27123, 5e-6);
    EXPECT_NEAR(b[2].x, 0.37736, 5e-6);
    EXPECT_GT(iterations, 1);
    EXPECT_LT(iterations, 1000);
}

TEST(RadiosityTest, SeedExampleProgressiveTable) {
    const std::vector<double> f = seed_form_factors();
    ProgressiveRadiosity solver({1.0, 1.0, 1.0}, {DVec3(1.0), DVec3(0.0), DVec3(0.0)},
                                std::vector<DVec3>(3, DVec3(0.5)),
                                [&](size_t shooter, std::vector<double>& column) {
                                    for (size_t j = 0; j < 3; ++j) column[j] = f[j * 3 + shooter];
                                });
    // The seed's table: shooter (1-based), B1 B2 B3 | unshot.
    struct Step {
        int shooter;
        double b[3], unshot[3];
    };
    const Step table[] = {
        {1, {1, .2, .3}, {0, .2, .3}},
        {3, {1.09, .23, .3}, {.09, .23, 0}},
        {2, {1.136, .23, .323}, {.136, 0, .023}},
        {1, {1.136, .2572, .3638}, {0, .0272, .0638}},
        {3, {1.15514, .26358, .3638}, {.01914, .03358, 0}},
        {2, {1.16186, .26358, .36716}, {.025856, 0, .00336}},
    };
    EXPECT_DOUBLE_EQ(solver.unshot_energy(), 3.0);  // (1,1,1)·A1
    for (const Step& step : table) {
        SCOPED_TRACE(step.shooter);
        EXPECT_EQ(solver.shoot(), step.shooter - 1);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(solver.radiosity()[i].x, step.b[i], 6e-6);
            EXPECT_NEAR(solver.unshot()[i].x, step.unshot[i], 6e-6);
        }
    }
    EXPECT_EQ(solver.shots(), 6);
}

// A square of side `side` split into n×n cells of two triangles each, counter-clockwise around
// the normal u × v.
void add_square(std::vector<RadiosityPatch>& out, const Vec3& corner, const Vec3& u, const Vec3& v,
                int n, const Vec3& emission = Vec3(0.0f), const Vec3& rho = Vec3(0.0f)) {
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const Vec3 p00 = corner + u * (float(i) / n) + v * (float(j) / n);
            const Vec3 p10 = corner + u * (float(i + 1) / n) + v * (float(j) / n);
            const Vec3 p01 = corner + u * (float(i) / n) + v * (float(j + 1) / n);
            const Vec3 p11 = corner + u * (float(i + 1) / n) + v * (float(j + 1) / n);
            out.push_back(make_patch(p00, p10, p11, emission, rho));
            out.push_back(make_patch(p00, p11, p01, emission, rho));
        }
    }
}

// The unit cube [0,1]³, every face split into n×n cells, normals inward.
std::vector<RadiosityPatch> closed_box(int n, const Vec3& emission = Vec3(0.0f),
                                       const Vec3& rho = Vec3(0.0f)) {
    std::vector<RadiosityPatch> p;
    const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1), o(0.0f);
    add_square(p, o, x, y, n, emission, rho);  // z = 0, normal +z
    add_square(p, z, y, x, n, emission, rho);  // z = 1, normal −z
    add_square(p, o, z, x, n, emission, rho);  // y = 0, normal +y
    add_square(p, y, x, z, n, emission, rho);  // y = 1, normal −y
    add_square(p, o, y, z, n, emission, rho);  // x = 0, normal +x
    add_square(p, x, z, y, n, emission, rho);  // x = 1, normal −x
    return p;
}

// The geometry of the patches as one two-sided mesh, for the occlusion rays.
Scene scene_of(const std::vector<RadiosityPatch>& patches) {
    Scene scene;
    TriangleMesh mesh;
    for (const RadiosityPatch& p : patches) {
        const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
        for (const Vec3& v : p.vertices) mesh.positions.push_back(v);
        mesh.triangles.push_back({base, base + 1, base + 2});
        mesh.materials.push_back(0);
    }
    scene.meshes.push_back(mesh);
    return scene;
}

// F(receiver set → source set) for sets of patches: Σ over receivers (Aa/A)·Σ over sources.
template <typename FormFactor>
double set_form_factor(const std::vector<RadiosityPatch>& receivers,
                       const std::vector<RadiosityPatch>& sources, FormFactor&& ff) {
    double area = 0.0, sum = 0.0;
    for (const RadiosityPatch& r : receivers) {
        area += r.area;
        for (const RadiosityPatch& s : sources) sum += r.area * ff(r, s);
    }
    return sum / area;
}

TEST(RadiosityTest, ParallelUnitSquaresFromBothMethods) {
    // Two unit squares facing each other at distance 1: F = 0.19982 (closed form).
    std::vector<RadiosityPatch> lower, upper;
    add_square(lower, Vec3(0.0f), Vec3(1, 0, 0), Vec3(0, 1, 0), 1);     // normal +z
    add_square(upper, Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(1, 0, 0), 1);  // normal −z
    const double analytic = set_form_factor(
        lower, upper, [](const auto& r, const auto& s) { return analytic_form_factor(r, s, 32); });
    EXPECT_NEAR(analytic, 0.19982, 2e-4);

    std::vector<RadiosityPatch> both = lower;
    both.insert(both.end(), upper.begin(), upper.end());
    const Scene scene = scene_of(both);
    const Accel accel(scene);
    uint64_t traced = 0;
    uint32_t seed = 0;
    const double rays = set_form_factor(lower, upper, [&](const auto& r, const auto& s) {
        return ray_form_factor(accel, r, s, 4096, ++seed, traced);
    });
    EXPECT_NEAR(rays, 0.19982, 4e-3);
    EXPECT_EQ(traced, 4u * 4096u);  // every pair faces the other: no ray skipped
}

TEST(RadiosityTest, PointPolygonFormFactorOfAHemisphereCoveringSquareIsOne) {
    // A huge square just above the point covers its whole hemisphere.
    const DVec3 square[4] = {DVec3(-1e4, -1e4, 1), DVec3(1e4, -1e4, 1), DVec3(1e4, 1e4, 1),
                             DVec3(-1e4, 1e4, 1)};
    EXPECT_NEAR(point_polygon_form_factor(DVec3(0.0), DVec3(0, 0, 1), square, 4), 1.0, 1e-3);
    // Below the point's horizon: clipped away.
    EXPECT_EQ(point_polygon_form_factor(DVec3(0.0), DVec3(0, 0, -1), square, 4), 0.0);
}

TEST(RadiosityTest, Reciprocity) {
    // Two unrelated, partly facing triangles: Ai·Fij = Aj·Fji.
    const RadiosityPatch a =
        make_patch(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 1.5f, 0.2f), Vec3(0.0f), Vec3(0.5f));
    const RadiosityPatch b = make_patch(Vec3(0.3f, 0.2f, 1.2f), Vec3(0.1f, 1.7f, 0.9f),
                                        Vec3(1.9f, 0.4f, 1.6f), Vec3(0.0f), Vec3(0.5f));
    ASSERT_GT(glm::dot(a.normal, b.vertices[0] - a.vertices[0]), 0.0f);
    const double fab = analytic_form_factor(a, b, 48);
    const double fba = analytic_form_factor(b, a, 48);
    EXPECT_GT(fab, 0.01);
    EXPECT_NEAR(a.area * fab, b.area * fba, 1e-3 * a.area * fab);

    const Scene scene = scene_of({a, b});
    const Accel accel(scene);
    uint64_t traced = 0;
    const double rab = ray_form_factor(accel, a, b, 16384, 1, traced);
    const double rba = ray_form_factor(accel, b, a, 16384, 2, traced);
    EXPECT_NEAR(a.area * rab, b.area * rba, 0.03 * a.area * fab);
    EXPECT_NEAR(rab, fab, 0.03 * fab);  // unoccluded here: both methods agree
}

TEST(RadiosityTest, EnclosureRowsSumToOne) {
    const std::vector<RadiosityPatch> box = closed_box(2);
    const Scene scene = scene_of(box);
    const Accel accel(scene);
    uint64_t traced = 0;
    for (size_t i = 0; i < box.size(); i += 7) {
        SCOPED_TRACE(i);
        double analytic = 0.0, rays = 0.0;
        for (size_t j = 0; j < box.size(); ++j) {
            if (j == i || patches_face_away(box[i], box[j])) continue;
            analytic += analytic_form_factor(box[i], box[j], 24);
            rays += ray_form_factor(accel, box[i], box[j], 1024, uint32_t(i * 1000 + j), traced);
        }
        EXPECT_NEAR(analytic, 1.0, 2e-3);
        EXPECT_NEAR(rays, 1.0, 0.03);
    }
}

TEST(RadiosityTest, OccluderBlocksRayFormFactor) {
    // A plate between the two squares: the rays see it, the (unoccluded) closed form does not.
    std::vector<RadiosityPatch> lower, upper, plate;
    add_square(lower, Vec3(0.0f), Vec3(1, 0, 0), Vec3(0, 1, 0), 1);
    add_square(upper, Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(1, 0, 0), 1);
    add_square(plate, Vec3(-5, -5, 0.5f), Vec3(10, 0, 0), Vec3(0, 10, 0), 1);
    std::vector<RadiosityPatch> all = lower;
    all.insert(all.end(), upper.begin(), upper.end());
    all.insert(all.end(), plate.begin(), plate.end());
    const Scene scene = scene_of(all);
    const Accel accel(scene);
    uint64_t traced = 0;
    EXPECT_EQ(ray_form_factor(accel, lower[0], upper[0], 256, 7, traced), 0.0);
    EXPECT_GT(analytic_form_factor(lower[0], upper[0], 8), 0.01);
}

TEST(RadiosityTest, WhiteFurnaceAnalytic) {
    // A closed box of uniform ρ emitting E everywhere: B = E/(1 − ρ) on every patch.
    const std::vector<RadiosityPatch> box = closed_box(2, Vec3(1.0f, 0.5f, 2.0f), Vec3(0.5f));
    RadiositySettings settings;
    settings.form_factors = FormFactorMethod::Analytic;
    settings.rays = 256;  // a 16×16 grid
    settings.threshold = 1e-7;
    RadiosityStats stats;
    const std::vector<DVec3> b = solve_radiosity(box, nullptr, settings, stats);
    EXPECT_LT(stats.unshot_fraction, 1e-7);
    EXPECT_EQ(stats.form_factor_rays, 0u);
    EXPECT_EQ(static_cast<size_t>(stats.shots), stats.history.size());
    for (const DVec3& bi : b) {
        EXPECT_NEAR(bi.x, 2.0, 5e-3);
        EXPECT_NEAR(bi.y, 1.0, 3e-3);
        EXPECT_NEAR(bi.z, 4.0, 1e-2);
    }
}

TEST(RadiosityTest, WhiteFurnaceRays) {
    const std::vector<RadiosityPatch> box = closed_box(2, Vec3(1.0f), Vec3(0.5f));
    const Scene scene = scene_of(box);
    const Accel accel(scene);
    RadiositySettings settings;
    settings.rays = 1024;
    settings.threshold = 1e-4;
    RadiosityStats stats;
    const std::vector<DVec3> b = solve_radiosity(box, &accel, settings, stats);
    EXPECT_GT(stats.form_factor_rays, 0u);
    for (const DVec3& bi : b) EXPECT_NEAR(bi.x, 2.0, 0.06);
}

TEST(RadiosityTest, MaxShotsStopsTheSolve) {
    const std::vector<RadiosityPatch> box = closed_box(1, Vec3(1.0f), Vec3(0.5f));
    RadiositySettings settings;
    settings.form_factors = FormFactorMethod::Analytic;
    settings.threshold = 0.0;
    settings.max_shots = 5;
    RadiosityStats stats;
    solve_radiosity(box, nullptr, settings, stats);
    EXPECT_EQ(stats.shots, 5);
    EXPECT_GT(stats.unshot_fraction, 0.0);
}

}  // namespace
}  // namespace rayo
