#include "bench/lab/convergence_study.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "apps/scene/renderer.h"
#include "apps/scene/scene_loader.h"
#include "bench/lab/convergence_scene.h"
#include "bench/lab/study_files.h"
#include "bench/lab/study_stop.h"
#include "core/error.h"
#include "core/luminance.h"
#include "core/scene_bounds.h"

namespace rayo {
namespace {

constexpr const char* kStudy = "convergence study";

// The scene with the study's image size: the width asked for, the height in the scene's aspect.
SceneDescription load_study_scene(const ConvergenceOptions& options) {
    SceneDescription d =
        options.scene.empty() ? convergence_cornell_box() : load_scene_file(options.scene);
    CameraDesc& camera = d.scene.camera;
    const double aspect = double(camera.height) / double(std::max(1, camera.width));
    camera.width = options.width;
    camera.height = std::max(1, static_cast<int>(std::lround(options.width * aspect)));
    // Plain stratified renders of a fixed sample count: what each row's spp says.
    d.settings.progressive = ProgressiveSettings{};
    d.settings.aa = AntiAliasing::Stratified;
    return d;
}

// The scene with the path integrator (its own settings when it already uses path).
SceneDescription path_scene(const SceneDescription& scene, int spp) {
    SceneDescription d = scene;
    if (!std::holds_alternative<PathSettings>(d.settings.integrator)) {
        d.settings.integrator = PathSettings{};
    }
    d.settings.gi = GlobalIllumination::None;
    d.settings.spp = spp;
    return d;
}

SceneDescription radiosity_scene(const SceneDescription& scene, int spp, double patch_size) {
    SceneDescription d = scene;
    if (!std::holds_alternative<WhittedSettings>(d.settings.integrator)) {
        d.settings.integrator = WhittedSettings{};
    }
    d.settings.gi = GlobalIllumination::Radiosity;
    d.settings.radiosity.patch_size = static_cast<float>(patch_size);
    d.settings.spp = spp;
    return d;
}

// The patch sizes when none are given: the scene's own patch_size × 4, 2, 1 (the Cornell box:
// 240, 120, 60), or, when it sets none, its bounds' diagonal / 4, 8, 16 (about the same sizes
// for the box, whose diagonal is 961 mm).
std::vector<double> default_patch_sizes(const SceneDescription& d) {
    double finest = d.settings.radiosity.patch_size;
    if (!(finest > 0.0)) {
        const std::optional<Bounds3> bounds = scene_bounds(d.scene);
        if (!bounds) return {};
        const Vec3 size = bounds->upper - bounds->lower;
        finest =
            std::sqrt(double(size.x) * size.x + double(size.y) * size.y + double(size.z) * size.z) /
            16.0;
        if (!(finest > 0.0)) return {};
    }
    return {4.0 * finest, 2.0 * finest, finest};
}

struct FilmError {
    double rms = 0, mean = 0;
};

FilmError film_error(const Film& test, const Film& reference, double mean_luminance) {
    const std::vector<float>& a = test.rgba();
    const std::vector<float>& b = reference.rgba();
    double squares = 0.0, absolute = 0.0;
    for (size_t i = 0; i < b.size(); i += 4) {
        for (size_t c = 0; c < 3; ++c) {
            const double d = double(a[i + c]) - double(b[i + c]);
            squares += d * d;
            absolute += std::abs(d);
        }
    }
    const double values = double(b.size() / 4) * 3.0;
    return {std::sqrt(squares / values) / mean_luminance, absolute / values / mean_luminance};
}

double mean_luminance(const Film& film) {
    const std::vector<float>& p = film.rgba();
    double sum = 0.0;
    for (size_t i = 0; i < p.size(); i += 4) sum += luminance(p[i], p[i + 1], p[i + 2]);
    return sum / double(std::max<size_t>(1, p.size() / 4));
}

std::string fixed(double v, int digits) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}

std::string number(double v) {
    std::ostringstream s;
    s << std::setprecision(9) << v;
    return s.str();
}

// The row's parameter: spp for path, the patch size for radiosity.
std::string parameter(const ConvergenceRow& r) {
    return r.method == "path" ? std::to_string(r.spp) : number(r.patch_size);
}

}  // namespace

std::vector<int> convergence_spp_series(int max_spp) {
    std::vector<int> series;
    for (long long spp = 1; spp < max_spp; spp *= 4) series.push_back(static_cast<int>(spp));
    series.push_back(max_spp);
    return series;
}

ConvergenceStudy run_convergence_study(const ConvergenceOptions& options, std::ostream& progress) {
    const SceneDescription scene = load_study_scene(options);
    std::vector<double> patch_sizes =
        options.patch_sizes.empty() ? default_patch_sizes(scene) : options.patch_sizes;
    ConvergenceStudy study;
    study.scene = scene.source;
    study.width = scene.scene.camera.width;
    study.height = scene.scene.camera.height;
    study.reference_spp = options.reference_spp;

    const RenderResult reference =
        render_scene(path_scene(scene, options.reference_spp), options.threads, false);
    stop_study_if_requested(kStudy);
    study.threads = reference.threads;
    study.reference_seconds = reference.render_seconds;
    study.reference_mean_luminance = mean_luminance(reference.film);
    if (!(study.reference_mean_luminance > 0.0) || !std::isfinite(study.reference_mean_luminance)) {
        throw InputError(study.scene,
                         "the path reference is black (mean luminance 0): no relative error");
    }
    progress << std::fixed << std::setprecision(3) << "reference: path, " << options.reference_spp
             << " spp, " << study.width << "x" << study.height << ", " << study.reference_seconds
             << " s\n";

    auto measure = [&](ConvergenceRow row, const RenderResult& r) {
        stop_study_if_requested(kStudy);
        row.render_seconds = r.render_seconds;
        row.solve_seconds = r.radiosity ? r.radiosity_stats.seconds : 0.0;
        row.seconds = row.render_seconds + row.solve_seconds;
        row.patches = r.radiosity_patches;
        const FilmError e = film_error(r.film, reference.film, study.reference_mean_luminance);
        row.rms_relative = e.rms;
        row.mean_relative = e.mean;
        progress << std::fixed << std::setprecision(4) << row.method << " " << parameter(row)
                 << ": " << row.seconds << " s, RMS " << row.rms_relative << "\n";
        study.rows.push_back(row);
    };
    for (const int spp : convergence_spp_series(options.max_spp)) {
        ConvergenceRow row;
        row.method = "path";
        row.spp = spp;
        measure(row, render_scene(path_scene(scene, spp), options.threads, false));
    }
    for (const double patch : patch_sizes) {
        ConvergenceRow row;
        row.method = "radiosity";
        row.spp = options.whitted_spp;
        row.patch_size = patch;
        measure(row, render_scene(radiosity_scene(scene, options.whitted_spp, patch),
                                  options.threads, false));
    }
    return study;
}

void print_convergence_table(std::ostream& out, const ConvergenceStudy& study, bool markdown) {
    const std::vector<std::string> head = {"method",  "spp",        "patch size",
                                           "patches", "render s",   "solve s",
                                           "seconds", "RMS / mean", "mean abs / mean"};
    std::vector<std::vector<std::string>> table = {head};
    for (const ConvergenceRow& r : study.rows) {
        const bool radiosity = r.method == "radiosity";
        table.push_back({r.method, std::to_string(r.spp), radiosity ? number(r.patch_size) : "-",
                         radiosity ? std::to_string(r.patches) : "-", fixed(r.render_seconds, 3),
                         radiosity ? fixed(r.solve_seconds, 3) : "-", fixed(r.seconds, 3),
                         fixed(r.rms_relative, 4), fixed(r.mean_relative, 4)});
    }
    out << study.scene << ", " << study.width << "x" << study.height << ", " << study.threads
        << " threads; reference: path, " << study.reference_spp << " spp ("
        << fixed(study.reference_seconds, 3) << " s), mean luminance "
        << number(study.reference_mean_luminance) << (markdown ? "\n\n" : "\n");
    write_aligned_table(out, table, markdown);
}

void write_convergence_files(const ConvergenceOptions& options, const ConvergenceStudy& study) {
    create_output_dir(options.dir);
    const std::string dir = options.dir;
    std::ostringstream csv, json, md, gp;
    // The first five columns are those of the study's earlier script (bench/convergence_study.sh).
    csv << "method,parameter,seconds,rms_relative,mean_relative,spp,patch_size,patches,render_s,"
           "solve_s,width,height,threads,reference_spp,scene\n";
    json << "{\n  \"scene\": " << json_string(study.scene) << ", \"width\": " << study.width
         << ", \"height\": " << study.height << ", \"threads\": " << study.threads
         << ",\n  \"reference\": {\"integrator\": \"path\", \"spp\": " << study.reference_spp
         << ", \"seconds\": " << number(study.reference_seconds)
         << ", \"mean_luminance\": " << number(study.reference_mean_luminance)
         << "},\n  \"rows\": [";
    for (size_t i = 0; i < study.rows.size(); ++i) {
        const ConvergenceRow& r = study.rows[i];
        csv << r.method << "," << parameter(r) << "," << number(r.seconds) << ","
            << number(r.rms_relative) << "," << number(r.mean_relative) << "," << r.spp << ","
            << number(r.patch_size) << "," << r.patches << "," << number(r.render_seconds) << ","
            << number(r.solve_seconds) << "," << study.width << "," << study.height << ","
            << study.threads << "," << study.reference_spp << "," << csv_field(study.scene) << "\n";
        json << (i ? "," : "") << "\n    {\"method\": " << json_string(r.method)
             << ", \"spp\": " << r.spp << ", \"patch_size\": " << number(r.patch_size)
             << ", \"patches\": " << r.patches << ", \"render_s\": " << number(r.render_seconds)
             << ", \"solve_s\": " << number(r.solve_seconds)
             << ", \"seconds\": " << number(r.seconds)
             << ", \"rms_relative\": " << number(r.rms_relative)
             << ", \"mean_relative\": " << number(r.mean_relative) << "}";
    }
    json << "\n  ]\n}\n";

    std::ostringstream command;
    command << "rayo bench convergence"
            << (options.scene.empty() ? std::string() : " " + options.scene) << " --width "
            << options.width << " --reference-spp " << options.reference_spp << " --max-spp "
            << options.max_spp << " --whitted-spp " << options.whitted_spp;
    if (!options.patch_sizes.empty()) {
        command << " --patch-sizes ";
        for (size_t i = 0; i < options.patch_sizes.size(); ++i) {
            command << (i ? "," : "") << number(options.patch_sizes[i]);
        }
    }
    if (options.threads > 0) command << " --threads " << options.threads;
    command << " -o " << dir;
    md << "# rayo convergence study\n\n";
    print_convergence_table(md, study, true);
    md << "\nCommand: `" << command.str()
       << "`. Seconds: render + radiosity solve. Errors over R, G, B, divided by the "
          "reference's mean luminance; the reference's own noise adds to the path rows' error "
          "(at n spp against N, by a factor √(1 + n/N)).\n";

    // Monte Carlo's slope −½ through the middle path row: e = e₀·√(t₀/t).
    std::vector<const ConvergenceRow*> path;
    for (const ConvergenceRow& r : study.rows) {
        if (r.method == "path" && r.seconds > 0) path.push_back(&r);
    }
    const std::string csv_path = dir + "/convergence.csv";
    const std::string scene_name = std::filesystem::path(study.scene).filename().string();
    gp << "# The convergence chart; regenerate with: gnuplot " << dir << "/convergence.gp\n"
       << "set datafile separator ','\n"
       << "set title '" << scene_name << " " << study.width << "x" << study.height
       << ": RMS error against a " << study.reference_spp << "-spp path reference' noenhanced\n"
       << "set logscale xy\nset grid\nset key bottom left\n"
       << "set xlabel 'seconds (render + radiosity solve, " << study.threads << " threads)'\n"
       << "set ylabel 'RMS error / mean luminance of the reference'\n"
       << "set terminal pngcairo size 700,500\nset output '" << dir << "/convergence.png'\n"
       << "plot '" << csv_path
       << "' skip 1 using (strcol(1) eq 'path' ? $3 : NaN):4 with linespoints pt 7 title 'path (1-"
       << options.max_spp << " spp)', \\\n"
       << "     '' skip 1 using (strcol(1) eq 'radiosity' ? $3 : NaN):4 with linespoints pt 5 "
          "title 'whitted + radiosity (patch size)', \\\n"
       << "     '' skip 1 using (strcol(1) eq 'radiosity' ? $3 : NaN):4:2 with labels offset 0,1 "
          "notitle";
    if (!path.empty()) {
        const ConvergenceRow& anchor = *path[path.size() / 2];
        gp << ", \\\n     " << number(anchor.rms_relative) << " * sqrt(" << number(anchor.seconds)
           << " / x) dashtype 2 lc rgb 'gray' title 'slope -1/2'";
    }
    gp << "\nset terminal svg size 700,500\nset output '" << dir
       << "/convergence.svg'\nreplot\nunset output\n";

    write_text_file(csv_path, csv.str());
    write_text_file(dir + "/convergence.json", json.str());
    write_text_file(dir + "/convergence.md", md.str());
    const std::string script = dir + "/convergence.gp";
    write_text_file(script, gp.str());
    const std::string gnuplot = "gnuplot '" + script + "' 2>&1";
    if (std::system(gnuplot.c_str()) != 0) {
        throw InputError(script, "gnuplot failed (is gnuplot-nox installed? scripts/setup.sh)");
    }
}

}  // namespace rayo
