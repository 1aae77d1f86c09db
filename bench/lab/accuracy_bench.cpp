#include "bench/lab/accuracy_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "apps/scene/renderer.h"
#include "apps/scene/sphere_method_choice.h"
#include "apps/scene/sphereflake.h"
#include "bench/lab/sphere_stability.h"
#include "bench/lab/study_files.h"
#include "bench/lab/study_stop.h"
#include "core/accel.h"
#include "core/error.h"
#include "shading/integrators/whitted.h"

namespace rayo {
namespace {

// The camera ray of every pixel centre, reduced to what it hits: (kind, mesh, primitive), or
// none. Pixels whose id differs from the reference's are silhouette errors.
std::vector<uint64_t> primary_ids(const SceneDescription& d, const SphereChoice& choice) {
    AccelOptions options;
    options.spheres = choice.spheres;
    options.sphere_math = choice.math;
    const Accel accel(d.scene, options);
    const Camera camera = Camera::create(d.scene.camera);
    std::vector<uint64_t> ids(static_cast<size_t>(camera.width()) * camera.height());
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            SurfaceHit hit;
            const bool found = accel.intersect(camera.generate_ray(float(x), float(y)), hit);
            ids[size_t(y) * camera.width() + x] =
                found ? (uint64_t(hit.shape) + 1) << 60 | uint64_t(hit.mesh) << 32 | hit.primitive
                      : 0;
        }
    }
    return ids;
}

SceneDescription far_cluster_scene(int size) {
    // 5×5 unit spheres 3 apart, seen from 2000 units away through a narrow lens: distance/radius
    // 2e3, where seed 000's algebraic form starts to lose hits in float (docs/stability.md).
    SceneDescription d;
    d.source = "<far cluster>";
    d.scene.camera.eye = Vec3(0.0f, 0.0f, 2000.0f);
    d.scene.camera.look_at = Vec3(0.0f);
    d.scene.camera.vfov_degrees = 0.45f;
    d.scene.camera.width = d.scene.camera.height = size;
    Material m;
    m.kd = Vec3(0.7f, 0.5f, 0.3f);
    m.ka = 0.1f * m.kd;
    m.ks = Vec3(0.4f);
    m.shininess = 40.0f;
    d.shading.materials.push_back(m);
    for (int i = -2; i <= 2; ++i) {
        for (int j = -2; j <= 2; ++j) {
            d.scene.shapes.of<Sphere>().push_back({Vec3(3.0f * i, 3.0f * j, 0.0f), 1.0f, 0});
        }
    }
    DirectionalLight light;
    light.direction = glm::normalize(Vec3(-1.0f, -1.0f, -2.0f));
    d.shading.lights.push_back(light);
    d.shading.background = Vec3(0.1f);
    return d;
}

SceneDescription close_sphere_scene(int size) {
    // One large mirror sphere filling most of the frame over a floor, with a diffuse neighbour:
    // tessellation shows on the silhouette, in the highlight and in the reflection.
    SceneDescription d;
    d.source = "<close sphere>";
    d.scene.camera.eye = Vec3(0.0f, 1.0f, 4.0f);
    d.scene.camera.look_at = Vec3(0.0f, 0.8f, 0.0f);
    d.scene.camera.vfov_degrees = 40.0f;
    d.scene.camera.width = d.scene.camera.height = size;
    Material mirror;
    mirror.kd = Vec3(0.2f);
    mirror.ka = Vec3(0.02f);
    mirror.ks = Vec3(0.6f);
    mirror.shininess = 80.0f;
    mirror.reflect = Vec3(0.6f);
    d.shading.materials.push_back(mirror);
    Material red;
    red.kd = Vec3(0.8f, 0.1f, 0.1f);
    red.ka = 0.1f * red.kd;
    d.shading.materials.push_back(red);
    Material floor;
    floor.kd = Vec3(0.6f);
    floor.ka = Vec3(0.06f);
    d.shading.materials.push_back(floor);
    d.scene.shapes.of<Sphere>().push_back({Vec3(0.0f, 1.0f, 0.0f), 1.0f, 0});
    d.scene.shapes.of<Sphere>().push_back({Vec3(1.6f, 0.4f, 0.8f), 0.4f, 1});
    TriangleMesh ground;
    ground.add_convex_polygon({Vec3(-8, 0, 8), Vec3(8, 0, 8), Vec3(8, 0, -8), Vec3(-8, 0, -8)}, {},
                              2);
    d.scene.meshes.push_back(ground);
    PointLight light;
    light.position = Vec3(3.0f, 5.0f, 4.0f);
    d.shading.lights.push_back(light);
    d.shading.background = Vec3(0.3f, 0.4f, 0.6f);
    return d;
}

}  // namespace

ImageError compare_films(const Film& test, const Film& reference) {
    ImageError e;
    const std::vector<float>& a = test.rgba();
    const std::vector<float>& b = reference.rgba();
    double sum_sq = 0.0;
    size_t differing = 0;
    const size_t pixels = a.size() / 4;
    for (size_t p = 0; p < pixels; ++p) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) {
            const double d = double(a[4 * p + c]) - double(b[4 * p + c]);
            sum_sq += d * d;
            e.max_abs = std::max(e.max_abs, std::abs(d));
            differs = differs || std::abs(d) > 1.0 / 255.0;
        }
        differing += differs;
    }
    e.rmse = std::sqrt(sum_sq / double(3 * pixels));
    e.pixels_differing = 100.0 * double(differing) / double(pixels);
    return e;
}

std::vector<std::pair<std::string, SceneDescription>> accuracy_scenes(int size) {
    std::vector<std::pair<std::string, SceneDescription>> scenes;
    scenes.emplace_back("flake", make_sphereflake(3, size, size));
    scenes.emplace_back("far", far_cluster_scene(size));
    scenes.emplace_back("close", close_sphere_scene(size));
    return scenes;
}

std::vector<AccuracyRow> run_accuracy_study(std::ostream& progress, int size) {
    struct Config {
        const char* method;
        SphereMath math;
        bool smooth;
    };
    const Config configs[] = {
        {"bruteforce", SphereMath::Seed, true}, {"bruteforce", SphereMath::Stable, true},
        {"user", SphereMath::Seed, true},       {"user", SphereMath::Stable, true},
        {"user", SphereMath::Double, true},     {"embree-point", SphereMath::Stable, true},
        {"mesh:0", SphereMath::Stable, true},   {"mesh:1", SphereMath::Stable, true},
        {"mesh:2", SphereMath::Stable, true},   {"mesh:3", SphereMath::Stable, true},
        {"mesh:4", SphereMath::Stable, true},   {"mesh:5", SphereMath::Stable, true},
        {"mesh:3", SphereMath::Stable, false},
    };
    std::vector<AccuracyRow> rows;
    for (auto& [name, base] : accuracy_scenes(size)) {
        // The reference: every sphere tested, in double precision.
        SceneDescription reference = base;
        reference.settings.spheres = *parse_sphere_method("bruteforce");
        reference.settings.sphere_math = SphereMath::Double;
        const RenderResult ref = render_scene(reference, 0, false);
        stop_study_if_requested("accuracy study");
        const std::vector<uint64_t> ref_ids = primary_ids(reference, ref.spheres);
        const SphereChoice chosen = choose_sphere_method(base, Camera::create(base.scene.camera));
        progress << name << ": reference bruteforce/double in " << std::fixed
                 << std::setprecision(2) << ref.bvh_seconds + ref.render_seconds << " s; auto -> "
                 << sphere_method_name(chosen.spheres) << "/" << sphere_math_name(chosen.math)
                 << "\n";
        for (const Config& c : configs) {
            SceneDescription d = base;
            d.settings.spheres = *parse_sphere_method(c.method);
            d.settings.spheres.mesh_smooth = c.smooth;
            d.settings.sphere_math = c.math;
            AccuracyRow row;
            row.scene = name;
            row.method = sphere_method_name(d.settings.spheres) + (c.smooth ? "" : "-flat");
            const bool analytic = d.settings.spheres.method == SphereMethod::User ||
                                  d.settings.spheres.method == SphereMethod::BruteForce;
            row.math = analytic ? sphere_math_name(c.math) : "-";
            row.is_auto = chosen.spheres.method == d.settings.spheres.method &&
                          chosen.math == c.math && c.smooth;
            row.seconds = 1e30;
            RenderResult result;
            // Best of two runs; one for small test-sized images, where builds dominate anyway.
            const int runs = size >= 256 ? 2 : 1;
            for (int run = 0; run < runs; ++run) {
                result = render_scene(d, 0, false);
                stop_study_if_requested("accuracy study");
                row.seconds = std::min(row.seconds, result.bvh_seconds + result.render_seconds);
            }
            row.primitives = result.primitives;
            row.error = compare_films(result.film, ref.film);
            const std::vector<uint64_t> ids = primary_ids(d, result.spheres);
            size_t wrong = 0;
            for (size_t i = 0; i < ids.size(); ++i) wrong += ids[i] != ref_ids[i];
            row.error.silhouette_wrong = 100.0 * double(wrong) / double(ids.size());
            progress << "  " << std::setw(14) << std::left << row.method << std::setw(7) << row.math
                     << std::right << std::setprecision(4) << row.seconds << " s  rmse "
                     << std::scientific << std::setprecision(2) << row.error.rmse << std::fixed
                     << "  silhouette " << row.error.silhouette_wrong << "%"
                     << (row.is_auto ? "  <- auto" : "") << "\n";
            rows.push_back(row);
        }
    }
    return rows;
}

void write_accuracy_csv(std::ostream& out, const std::vector<AccuracyRow>& rows) {
    out << "scene,method,math,auto,seconds,primitives,rmse,max_abs,pixels_differing_pct,"
           "silhouette_wrong_pct\n";
    out << std::setprecision(9);
    for (const AccuracyRow& r : rows) {
        out << csv_field(r.scene) << "," << csv_field(r.method) << "," << csv_field(r.math) << ","
            << (r.is_auto ? 1 : 0) << "," << r.seconds << "," << r.primitives << "," << r.error.rmse
            << "," << r.error.max_abs << "," << r.error.pixels_differing << ","
            << r.error.silhouette_wrong << "\n";
    }
}

void run_accuracy_bench(const std::string& dir, std::ostream& progress, int size) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(dir, "cannot create the output directory: " + ec.message());
    write_accuracy_files(dir, run_accuracy_study(progress, size), progress, size);
}

void write_accuracy_files(const std::string& dir, const std::vector<AccuracyRow>& rows,
                          std::ostream& progress, int size) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(dir, "cannot create the output directory: " + ec.message());
    // The stability sweep (docs/stability.md): wrong hit/miss rate against distance/radius per
    // method, as CSV and as one gnuplot data block per method for the chart. It runs before any
    // file is written, so that a stop during it (Ctrl-C from Python) leaves no file.
    progress << "stability sweep (distance/radius 1 .. 1e7)\n";
    const std::vector<StabilityRow> sweep = run_distance_sweep(StabilityConfig{});
    stop_study_if_requested("stability sweep");
    const std::string csv = dir + "/accuracy.csv";
    {
        std::ofstream out(csv);
        write_accuracy_csv(out, rows);
        if (!out) throw InputError(csv, "cannot write");
    }
    const std::string stability_csv = dir + "/stability.csv";
    const std::string stability_dat = dir + "/stability_chart.dat";
    int series = 0;
    {
        std::ofstream out(stability_csv);
        write_csv(out, sweep);
        std::ofstream dat(stability_dat);
        std::vector<std::string> labels;
        for (const StabilityRow& r : sweep) {
            const std::string label = r.method + "/" + r.math;
            if (std::find(labels.begin(), labels.end(), label) == labels.end()) {
                labels.push_back(label);
            }
        }
        for (const std::string& label : labels) {
            dat << "\"" << label << "\" \"wrong %\"\n";
            for (const StabilityRow& r : sweep) {
                if (r.method + "/" + r.math != label) continue;
                dat << r.config.distance_ratio << " " << std::max(100.0 * r.wrong_rate, 1e-2)
                    << "\n";
            }
            dat << "\n\n";
        }
        series = static_cast<int>(labels.size());
        if (!out || !dat) throw InputError(stability_csv, "cannot write");
    }
    const std::string script = dir + "/charts.gp";
    {
        std::ofstream gp(script);
        gp << "# Charts of rayo's sphere-method study; regenerate with: rayo bench accuracy -o "
           << dir << "\n"
           << "set datafile separator ','\n"
           << "set key off\nset grid\nset logscale xy\n"
           << "set xlabel 'time per frame (s, BVH build + render, all cores)'\n"
           << "set ylabel 'RMSE against bruteforce/double'\n";
        for (const auto& [name, scene] : accuracy_scenes(size)) {
            (void)scene;
            for (const char* format : {"png", "svg"}) {
                gp << "set terminal " << (std::string(format) == "png" ? "pngcairo" : "svg")
                   << " size 900,600\n"
                   << "set output '" << dir << "/accuracy_" << name << "." << format << "'\n"
                   << "set title 'Sphere methods, scene \"" << name
                   << "\": time against error (circled: auto; 0 drawn at 1e-7)'\n"
                   << "plot '" << csv << "' skip 1 using (strcol(1) eq '" << name
                   << "' ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7):(strcol(2).(strcol(3) eq '-' ? '' : "
                      "'/'.strcol(3))) with labels point pt 7 ps 1 offset char 1,0.6 font ',8', "
                      "\\\n"
                   << "     '' skip 1 using (strcol(1) eq '" << name
                   << "' && $4 == 1 ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7) with points pt 6 ps 3 "
                      "lw 2\n";
            }
        }
        for (const char* format : {"png", "svg"}) {
            gp << "set terminal " << (std::string(format) == "png" ? "pngcairo" : "svg")
               << " size 900,600\n"
               << "set output '" << dir << "/stability." << format << "'\n"
               << "set datafile separator whitespace\n"
               << "set key outside right\n"
               << "set title 'Wrong hit/miss rate against distance/radius (disk rays; 0 drawn at "
                  "0.01%)'\n"
               << "set xlabel 'distance / radius'\nset ylabel 'wrong hit/miss (%)'\n"
               << "plot for [i=0:" << series - 1 << "] '" << stability_dat
               << "' index i using 1:2 with linespoints title columnheader(1)\n"
               << "set datafile separator ','\nset key off\n";
        }
    }
    const std::string command = "gnuplot '" + script + "' 2>&1";
    if (std::system(command.c_str()) != 0) {
        throw InputError(script, "gnuplot failed (is gnuplot-nox installed? scripts/setup.sh)");
    }
    progress << "wrote " << csv << ", " << script << " and the charts in " << dir << "\n";
}

}  // namespace rayo
