#pragma once
// Radiosity (seed 004): Bi = Ei + ρi·Σj Fij·Bj over diffuse patches, solved directly
// (Gauss–Seidel) or by progressive refinement (shoot the patch with the most unshot radiosity
// until the unshot energy falls below a threshold). Form factors come from Monte Carlo rays
// through the accel's occlusion queries (which include visibility) or, unoccluded, from the
// closed-form point-to-polygon form factor (Lambert's contour integral). docs/radiosity.md.
//
// Units: rayo's emission is a radiance, and for Lambertian patches B = π·L, so the equation is
// solved in radiance units directly (the π cancels): B below is the patch's exitant radiance.
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/accel.h"
#include "core/math.h"

namespace rayo {

// A triangular patch: counter-clockwise around `normal`, the side it emits and receives on.
struct RadiosityPatch {
    std::array<Vec3, 3> vertices{};
    Vec3 normal{0.0f};
    float area = 0.0f;
    Vec3 emission{0.0f};     // Ei (radiance)
    Vec3 reflectance{0.0f};  // ρi, the material's kd
    // How far the surface the patch stands for lies above it (a tessellated analytic shape's
    // chord, 0 for meshes): the form-factor rays start and end that far out along the normal,
    // else the analytic shape the patch cuts through would hide it.
    float lift = 0.0f;
};
RadiosityPatch make_patch(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& emission,
                          const Vec3& reflectance);

// The form factor from a differential area at `point` with unit `normal` to a planar polygon
// (n vertices): Lambert's formula F = 1/(2π)·Σk γk·n·(Rk × Rk+1)/|Rk × Rk+1|, with the polygon
// first clipped to the point's upper half-space. Unoccluded. Either winding gives the same value.
double point_polygon_form_factor(const DVec3& point, const DVec3& normal, const DVec3* polygon,
                                 int n);

// F(receiver → source), unoccluded: the point-to-polygon form factor averaged over grid² stratum
// midpoints of the receiver (seed 004's contour integral).
double analytic_form_factor(const RadiosityPatch& receiver, const RadiosityPatch& source, int grid);

// F(receiver → source) with visibility, from about `rays` stratified rays through the accel's
// occlusion queries (Embree streams): at √rays stratified points y of the receiver, the
// point-to-polygon form factor times the fraction of the source y sees, each shadow ray to a
// stratified point x of the source weighted by cosθy·cosθx/r² (Wallace et al. 1989's ray-traced
// form factors, in the bounded form: the 1/r² singularity of adjacent patches stays in the closed
// form instead of in the samples). Exact when the source is wholly visible. The points come from
// the stateless hash of (seed, point, ray) only. `traced` counts the rays.
double ray_form_factor(const Accel& accel, const RadiosityPatch& receiver,
                       const RadiosityPatch& source, int rays, uint32_t seed, uint64_t& traced);

// True when no point of one patch sees the front of the other (each lies wholly behind the
// other's plane): the form factor is 0 and costs no rays.
bool patches_face_away(const RadiosityPatch& a, const RadiosityPatch& b);

// The direct solve of Bi = Ei + ρi·Σj Fij·Bj by Gauss–Seidel sweeps until no channel changes by
// more than `tolerance`. F is row-major n×n (F[i·n + j] = Fij). `iterations` gets the sweeps.
std::vector<DVec3> solve_radiosity_gauss_seidel(const std::vector<double>& form_factors,
                                                const std::vector<DVec3>& emission,
                                                const std::vector<DVec3>& reflectance,
                                                double tolerance, int max_iterations,
                                                int* iterations = nullptr);

// Progressive refinement by shooting (Cohen et al. 1988). Shooting patch i sends its unshot
// radiosity ΔBi to every receiver j: ΔBj = ρj·Fji·ΔBi (Fji = Fij·Ai/Aj). The shooter is the
// patch with the most unshot energy ΔBi·Ai (sum of channels); ties go to the lowest index.
class ProgressiveRadiosity {
  public:
    // Fills f[j] = Fji (receiver j to shooter i) for every j; f has the patch count.
    using FormFactorColumn = std::function<void(size_t shooter, std::vector<double>& f)>;

    ProgressiveRadiosity(std::vector<double> areas, std::vector<DVec3> emission,
                         std::vector<DVec3> reflectance, FormFactorColumn column);

    // Shoots one patch; returns its index, or -1 when nothing is left to shoot.
    int shoot();
    const std::vector<DVec3>& radiosity() const { return m_radiosity; }
    const std::vector<DVec3>& unshot() const { return m_unshot; }
    // Σ ΔBi·Ai over channels and patches, and that of the emission (the initial unshot energy).
    double unshot_energy() const;
    double emitted_energy() const { return m_emitted; }
    int shots() const { return m_shots; }

  private:
    std::vector<double> m_areas;
    std::vector<DVec3> m_reflectance;
    FormFactorColumn m_column;
    std::vector<DVec3> m_radiosity, m_unshot;
    std::vector<double> m_f;
    double m_emitted = 0.0;
    int m_shots = 0;
};

enum class FormFactorMethod { Rays, Analytic };

struct RadiositySettings {
    float patch_size = 0.0f;  // longest patch edge; 0 = the scene's triangles as they are
    double threshold = 1e-3;  // stop when unshot energy / emitted energy falls below this
    int max_shots = 100000;   // and after this many shots in any case
    FormFactorMethod form_factors = FormFactorMethod::Rays;
    int rays = 16;  // per patch pair (Rays); the analytic grid is √rays rounded up
};

struct RadiosityStats {
    int shots = 0;
    double unshot_fraction = 0.0;  // unshot energy / emitted energy at the end
    uint64_t form_factor_rays = 0;
    double seconds = 0.0;
    std::vector<double> history;  // unshot fraction after each shot (for the chart)
};

// Progressive refinement over `patches`, receivers in parallel (TBB) with deterministic results
// for any thread count. `accel` holds the scene's geometry (for Rays; unused by Analytic).
// `on_shot(fraction)` is called after every shot (the progress bar), may be empty.
std::vector<DVec3> solve_radiosity(const std::vector<RadiosityPatch>& patches, const Accel* accel,
                                   const RadiositySettings& settings, RadiosityStats& stats,
                                   const std::function<void(double)>& on_shot = {});

}  // namespace rayo
