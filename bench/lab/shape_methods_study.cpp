#include "bench/lab/shape_methods_study.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>

#include "apps/scene/shape_method_choice.h"
#include "bench/lab/study_files.h"
#include "bench/lab/study_stop.h"
#include "core/accel.h"
#include "core/error.h"

namespace rayo {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The study's frame: a unit-sized object at the origin filling about half of it.
SceneDescription frame_for(int size) {
    SceneDescription d;
    d.scene.camera.eye = Vec3(0.8f, 1.2f, 5.0f);
    d.scene.camera.look_at = Vec3(0.0f);
    d.scene.camera.vfov_degrees = 40.0f;
    d.scene.camera.width = d.scene.camera.height = size;
    Material m;
    m.kd = Vec3(0.7f, 0.5f, 0.3f);
    d.shading.materials.push_back(m);
    return d;
}

template <typename S>
std::pair<std::string, SceneDescription> scene_of(const S& shape, int size) {
    SceneDescription d = frame_for(size);
    d.source = std::string("<") + S::kName + ">";
    d.scene.shapes.of<S>().push_back(shape);
    return {S::kName, d};
}

// Camera rays in 8×8 blocks, the order the renderer streams them in (core/render.h).
std::vector<Ray> camera_rays(const Camera& camera) {
    std::vector<Ray> rays;
    for (int by = 0; by < camera.height(); by += 8) {
        for (int bx = 0; bx < camera.width(); bx += 8) {
            for (int y = by; y < std::min(by + 8, camera.height()); ++y) {
                for (int x = bx; x < std::min(bx + 8, camera.width()); ++x) {
                    rays.push_back(camera.generate_ray(float(x), float(y)));
                }
            }
        }
    }
    return rays;
}

struct Trace {
    std::vector<SurfaceHit> hits;
    std::vector<char> found;
};

// Traces every ray `repeats` times each way; the per-ray times from the best of the repeats per
// chunk of 4096 rays (so that a run interrupted by the other users of the machine's cores loses
// only its chunks).
Trace time_rays(const Accel& accel, const std::vector<Ray>& rays, int repeats, double& ns_coherent,
                double& ns_single) {
    constexpr int kChunk = 64 * Accel::kCoherentBatch;
    Trace trace;
    trace.hits.resize(rays.size());
    trace.found.resize(rays.size());
    const int n = static_cast<int>(rays.size());
    const int chunks = (n + kChunk - 1) / kChunk;
    std::vector<double> best_coherent(chunks, 1e30), best_single(chunks, 1e30);
    std::vector<SurfaceHit> hits(rays.size());
    bool found[Accel::kCoherentBatch];
    for (int r = 0; r < repeats; ++r) {
        for (int c = 0; c < chunks; ++c) {
            const int end = std::min(n, (c + 1) * kChunk);
            auto start = std::chrono::steady_clock::now();
            for (int first = c * kChunk; first < end; first += Accel::kCoherentBatch) {
                const int count = std::min(Accel::kCoherentBatch, end - first);
                accel.intersect_coherent(&rays[first], count, &hits[first], found);
            }
            best_coherent[c] = std::min(best_coherent[c], seconds_since(start));
            start = std::chrono::steady_clock::now();
            for (int i = c * kChunk; i < end; ++i) {
                trace.found[i] = accel.intersect(rays[i], trace.hits[i]);
            }
            best_single[c] = std::min(best_single[c], seconds_since(start));
        }
    }
    ns_coherent = ns_single = 0.0;
    for (int c = 0; c < chunks; ++c) {
        ns_coherent += 1e9 * best_coherent[c] / n;
        ns_single += 1e9 * best_single[c] / n;
    }
    return trace;
}

}  // namespace

std::vector<std::pair<std::string, SceneDescription>> shape_method_scenes(int size) {
    std::vector<std::pair<std::string, SceneDescription>> scenes;
    Cone cone;
    cone.base = Vec3(0.0f, -1.0f, 0.0f);
    cone.base_radius = 1.0f;
    cone.apex = Vec3(0.0f, 1.0f, 0.0f);
    cone.apex_radius = 0.25f;
    scenes.push_back(scene_of(cone, size));
    Disk disk;
    disk.normal = glm::normalize(Vec3(0.2f, 0.6f, 0.8f));
    disk.radius = 1.2f;
    scenes.push_back(scene_of(disk, size));
    Box box;
    box.min = Vec3(-0.8f, -0.6f, -0.7f);
    box.max = Vec3(0.8f, 0.6f, 0.7f);
    scenes.push_back(scene_of(box, size));
    Ellipsoid ellipsoid;
    ellipsoid.radii = Vec3(1.2f, 0.8f, 0.6f);
    scenes.push_back(scene_of(ellipsoid, size));
    Cylinder cylinder;
    cylinder.base = Vec3(-0.4f, -1.0f, 0.0f);
    cylinder.top = Vec3(0.4f, 1.0f, 0.0f);
    cylinder.radius = 0.6f;
    scenes.push_back(scene_of(cylinder, size));
    Paraboloid paraboloid;
    paraboloid.vertex = Vec3(0.0f, -1.0f, 0.0f);
    paraboloid.radius = 1.0f;
    paraboloid.height = 2.0f;
    scenes.push_back(scene_of(paraboloid, size));
    Hyperboloid hyperboloid;
    hyperboloid.radius = 0.5f;
    hyperboloid.semi_axis = 0.6f;
    hyperboloid.height = 2.0f;
    scenes.push_back(scene_of(hyperboloid, size));
    return scenes;
}

const std::vector<double>& shape_method_budgets() {
    static const std::vector<double> budgets = {4.0, 2.0, 1.0, 0.5, 0.25, 0.125, 0.0625};
    return budgets;
}

std::vector<ShapeMethodRow> run_shape_method_study(std::ostream& progress, int size, int repeats) {
    // One thread: per-ray costs without TBB's share of the 2 cores.
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    std::vector<ShapeMethodRow> rows;
    for (auto& [name, base] : shape_method_scenes(size)) {
        const Camera camera = Camera::create(base.scene.camera);
        const std::vector<Ray> rays = camera_rays(camera);
        // What auto picks at the default budget.
        SceneDescription automatic = base;
        automatic.settings.shape_method = ShapeMethod::Auto;
        const ShapeChoices picked = choose_shape_methods(automatic, camera);
        const bool auto_mesh =
            !picked.objects.empty() && picked.objects[0].chosen == ShapeMethod::Mesh;

        Trace reference;
        std::vector<double> budgets = {0.0};
        for (double b : shape_method_budgets()) budgets.push_back(b);
        for (double budget : budgets) {
            stop_study_if_requested("shape-method study");
            SceneDescription d = base;
            ShapeMethodRow row;
            row.shape = name;
            row.form = budget > 0.0 ? "mesh" : "analytic";
            row.budget_px = budget;
            d.settings.shape_method = budget > 0.0 ? ShapeMethod::Mesh : ShapeMethod::Analytic;
            if (budget > 0.0) d.settings.max_error_px = static_cast<float>(budget);
            auto start = std::chrono::steady_clock::now();
            const ShapeChoices choices = choose_shape_methods(d, camera);
            const Accel accel(choices.traced(d.scene));
            row.build_seconds = seconds_since(start);
            row.bytes = accel.embree_bytes();
            row.triangles = choices.traced(d.scene).triangle_count();
            row.chord_px = choices.objects.empty() ? 0.0 : choices.objects[0].chord_px;
            row.is_auto = budget == 0.0 ? !auto_mesh : (auto_mesh && budget == 0.5);
            Trace trace = time_rays(accel, rays, repeats, row.ns_coherent, row.ns_single);
            if (budget == 0.0) {
                reference = std::move(trace);
            } else {
                // Against the analytic hits: pixels hit by one form only, and where both are hit
                // the distance of the analytic hit from the plane of the facet hit,
                // |Δt|·|cos θ| (θ: the ray against the facet's normal), in pixels at the hit's
                // distance.
                size_t silhouette = 0;
                for (size_t i = 0; i < rays.size(); ++i) {
                    if (trace.found[i] != reference.found[i]) {
                        ++silhouette;
                        continue;
                    }
                    if (!trace.found[i]) continue;
                    const SurfaceHit& a = reference.hits[i];
                    const SurfaceHit& m = trace.hits[i];
                    const double separation =
                        std::abs(double(m.t) - double(a.t)) *
                        std::abs(double(glm::dot(rays[i].direction, m.geometric_normal)));
                    row.max_error_px = std::max(row.max_error_px,
                                                separation / (double(a.t) * camera.pixel_angle()));
                }
                row.silhouette_pct = 100.0 * double(silhouette) / double(rays.size());
            }
            progress << "  " << std::setw(12) << std::left << name << std::setw(9) << row.form
                     << std::right << std::fixed << std::setprecision(4) << std::setw(7)
                     << row.budget_px << " px " << std::setw(8) << row.triangles << " tris "
                     << std::setw(9) << row.bytes << " B " << std::setprecision(1) << std::setw(7)
                     << row.ns_coherent << " / " << std::setw(7) << row.ns_single
                     << " ns/ray  error " << std::setprecision(3) << row.max_error_px
                     << " px  silhouette " << row.silhouette_pct << "%"
                     << (row.is_auto ? "  <- auto" : "") << "\n";
            rows.push_back(row);
        }
    }
    return rows;
}

void write_shape_method_csv(std::ostream& out, const std::vector<ShapeMethodRow>& rows) {
    out << "shape,form,budget_px,auto,triangles,embree_bytes,build_seconds,ns_per_ray_coherent,"
           "ns_per_ray_single,chord_px,max_error_px,silhouette_pct\n";
    out << std::setprecision(9);
    for (const ShapeMethodRow& r : rows) {
        out << csv_field(r.shape) << "," << r.form << "," << r.budget_px << ","
            << (r.is_auto ? 1 : 0) << "," << r.triangles << "," << r.bytes << "," << r.build_seconds
            << "," << r.ns_coherent << "," << r.ns_single << "," << r.chord_px << ","
            << r.max_error_px << "," << r.silhouette_pct << "\n";
    }
}

void run_shape_method_bench(const std::string& dir, std::ostream& progress, int size) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(dir, "cannot create the output directory: " + ec.message());
    progress << "shape methods: analytic against meshes within error budgets, " << size << "²\n";
    write_shape_method_files(dir, run_shape_method_study(progress, size), progress);
}

void write_shape_method_files(const std::string& dir, const std::vector<ShapeMethodRow>& rows,
                              std::ostream& progress) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(dir, "cannot create the output directory: " + ec.message());
    const std::string csv = dir + "/shape_methods.csv";
    const std::string dat = dir + "/shape_methods.dat";
    std::vector<std::string> shapes;
    {
        std::ofstream out(csv);
        write_shape_method_csv(out, rows);
        if (!out) throw InputError(csv, "cannot write");
        // One gnuplot block per shape and form: x the measured error (analytic: drawn across
        // the meshes' range, at its own cost), then ns/ray (coherent) and bytes.
        std::ofstream data(dat);
        for (const ShapeMethodRow& r : rows) {
            if (std::find(shapes.begin(), shapes.end(), r.shape) == shapes.end()) {
                shapes.push_back(r.shape);
            }
        }
        data << std::setprecision(6);
        for (const std::string& shape : shapes) {
            double lo = 1e30, hi = 0.0;
            for (const ShapeMethodRow& r : rows) {
                if (r.shape != shape || r.form != "mesh") continue;
                lo = std::min(lo, std::max(r.max_error_px, 1e-3));
                hi = std::max(hi, std::max(r.max_error_px, 1e-3));
            }
            data << "\"" << shape << " mesh\"\n";
            for (const ShapeMethodRow& r : rows) {
                if (r.shape != shape || r.form != "mesh") continue;
                data << std::max(r.max_error_px, 1e-3) << " " << r.ns_coherent << " " << r.bytes
                     << "\n";
            }
            data << "\n\n\"" << shape << " analytic\"\n";
            for (const ShapeMethodRow& r : rows) {
                if (r.shape != shape || r.form != "analytic") continue;
                data << lo << " " << r.ns_coherent << " " << r.bytes << "\n"
                     << hi << " " << r.ns_coherent << " " << r.bytes << "\n";
            }
            data << "\n\n";
        }
        if (!data) throw InputError(dat, "cannot write");
    }
    const std::string script = dir + "/shape_methods.gp";
    {
        std::ofstream gp(script);
        const int blocks = 2 * static_cast<int>(shapes.size());
        gp << "# Charts of rayo's shape-method study; regenerate with: rayo bench accuracy "
              "--only shapes -o "
           << dir << "\n"
           << "set key outside right\nset grid\nset logscale xy\n"
           << "set xlabel 'measured error (px; largest surface separation, 1e-3 = none)'\n";
        const struct {
            const char* name;
            const char* ylabel;
            int column;
        } charts[] = {{"time", "ns per camera ray (8x8 streams, one thread)", 2},
                      {"memory", "Embree bytes", 3}};
        for (const auto& chart : charts) {
            for (const char* format : {"png", "svg"}) {
                gp << "set terminal " << (std::string(format) == "png" ? "pngcairo" : "svg")
                   << " size 1000,640\n"
                   << "set output '" << dir << "/shape_methods_" << chart.name << "." << format
                   << "'\n"
                   << "set title 'Shape methods: " << chart.name
                   << " against error (lines: meshes at 4 .. 1/16 px budgets; flat: analytic)'\n"
                   << "set ylabel '" << chart.ylabel << "'\n"
                   << "plot for [i=0:" << blocks - 1 << "] '" << dat
                   << "' index i using 1:" << chart.column
                   << " with linespoints lc (i/2+1) title columnheader(1)\n";
            }
        }
    }
    const std::string command = "gnuplot '" + script + "' 2>&1";
    if (std::system(command.c_str()) != 0) {
        throw InputError(script, "gnuplot failed (is gnuplot-nox installed? scripts/setup.sh)");
    }
    progress << "wrote " << csv << ", " << script << " and the charts in " << dir << "\n";
}

}  // namespace rayo
