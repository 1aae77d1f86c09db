#include "bench/lab/spd_suite.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <ostream>
#include <sstream>

#include "apps/scene/nff_loader.h"
#include "apps/scene/renderer.h"
#include "bench/lab/spd_povray.h"
#include "bench/lab/spd_scenes.h"
#include "bench/lab/study_files.h"
#include "bench/lab/study_stop.h"
#include "core/error.h"

namespace rayo {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::string> suite_scenes(const SuiteOptions& options) {
    return options.only.empty() ? spd_scene_names() : options.only;
}

// POV-Ray's whole run on the scene's translation, in seconds (the shell command's wall time).
double time_povray(const std::string& dir, const std::string& name, const std::string& nff,
                   const SuiteOptions& options) {
    const std::string pov = dir + "/" + name + ".pov";
    write_text_file(pov, nff_to_povray(nff, options.width));
    std::ostringstream command;
    // POV-Ray writes only below the current folder or /tmp (Debian's povray.conf): run it in DIR.
    command << "cd '" << dir << "' && povray +I" << name << ".pov +O" << name << ".pov.png +W"
            << options.width << " +H" << options.width << " -A -D -V +FN";
    if (options.threads > 0) command << " +WT" << options.threads;
    command << " >" << name << ".pov.log 2>&1";
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(command.str().c_str());
    const double seconds = seconds_since(start);
    if (status != 0) {
        throw InputError(pov, "POV-Ray failed (see " + dir + "/" + name + ".pov.log)");
    }
    return seconds;
}

}  // namespace

MachineInfo machine_info() {
    MachineInfo m;
    m.cores = default_thread_count();
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, flags;
    while (std::getline(cpuinfo, line)) {
        const size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        std::string key = line.substr(0, colon);
        key.erase(key.find_last_not_of(" \t") + 1);
        const std::string value = colon + 2 <= line.size() ? line.substr(colon + 2) : "";
        if (key == "model name" && m.cpu.empty()) m.cpu = value;
        if (key == "flags" && flags.empty()) flags = " " + value + " ";
    }
    if (m.cpu.empty()) m.cpu = "unknown";
    m.isa = "unknown";
    // Not avx512: the device stops at AVX2 (core/embree_device.h).
    for (const auto& [flag, isa] : {std::pair{"avx2", "avx2"}, std::pair{"avx", "avx"},
                                    std::pair{"sse4_2", "sse4.2"}, std::pair{"sse2", "sse2"}}) {
        if (flags.find(std::string(" ") + flag + " ") != std::string::npos) {
            m.isa = isa;
            break;
        }
    }
    return m;
}

std::vector<SuiteRow> run_spd_suite(const SuiteOptions& options, std::ostream& progress) {
    if (options.povray && std::system("command -v povray >/dev/null 2>&1") != 0) {
        throw InputError("--povray",
                         "povray is not on PATH (install POV-Ray 3.7: RAYO_SETUP_EXTRAS=povray "
                         "scripts/setup.sh)");
    }
    const std::vector<std::string> names = suite_scenes(options);
    for (const std::string& name : names) {  // every name and size checked before any render
        if (options.size > spd_max_size(name)) {
            throw InputError(
                "--size", "spd:" + name + " goes up to size " + std::to_string(spd_max_size(name)));
        }
    }
    // POV-Ray's scenes, images and logs: in DIR, or in a temporary folder removed at the end.
    std::string pov_dir = options.dir;
    std::unique_ptr<std::string, void (*)(std::string*)> temporary(nullptr, [](std::string* p) {
        std::error_code ec;
        std::filesystem::remove_all(*p, ec);
        delete p;
    });
    if (options.povray && pov_dir.empty()) {
        pov_dir = (std::filesystem::temp_directory_path() /
                   ("rayo-suite-" +
                    std::to_string(std::chrono::steady_clock::now().time_since_epoch().count())))
                      .string();
        temporary.reset(new std::string(pov_dir));
    }
    if (options.povray) create_output_dir(pov_dir);
    std::vector<SuiteRow> rows;
    for (const std::string& name : names) {
        SuiteRow row;
        row.scene = name;
        row.size = options.size;
        row.width = options.width;
        const auto start = std::chrono::steady_clock::now();
        const std::string nff = spd_nff(name, options.size);
        SceneDescription d =
            load_nff_string(nff, "spd:" + name + ":" + std::to_string(options.size));
        d.scene.camera.width = d.scene.camera.height = options.width;
        row.generate_seconds = seconds_since(start);
        const RenderResult r = render_scene(d, options.threads, false);
        stop_study_if_requested("SPD suite");
        row.threads = r.threads;
        row.primitives = r.primitives;
        row.rays = r.counters;
        row.bvh_seconds = r.bvh_seconds;
        row.render_seconds = r.render_seconds;
        row.total_seconds = row.generate_seconds + r.bvh_seconds + r.render_seconds;
        row.mrays_per_second =
            r.render_seconds > 0 ? double(r.counters.total_rays()) / r.render_seconds / 1e6 : 0;
        if (options.povray) row.povray_seconds = time_povray(pov_dir, name, nff, options);
        progress << std::fixed << std::setprecision(3) << name << " " << options.size << ": "
                 << row.primitives << " primitives, " << row.total_seconds << " s"
                 << (options.povray ? ", POV-Ray " + std::to_string(row.povray_seconds) + " s"
                                    : std::string())
                 << "\n";
        rows.push_back(row);
    }
    return rows;
}

void print_suite_table(std::ostream& out, const std::vector<SuiteRow>& rows,
                       const MachineInfo& machine, bool markdown) {
    const bool povray = std::any_of(rows.begin(), rows.end(),
                                    [](const SuiteRow& r) { return r.povray_seconds >= 0; });
    std::vector<std::string> head = {"scene",    "size",      "primitives", "camera",
                                     "shadow",   "reflected", "refracted",  "BVH s",
                                     "render s", "total s",   "Mrays/s",    "threads"};
    if (povray) {
        head.push_back("POV-Ray s");
        head.push_back("POV-Ray/rayo");
    }
    std::vector<std::vector<std::string>> table = {head};
    auto fixed = [](double v, int digits) {
        std::ostringstream s;
        s << std::fixed << std::setprecision(digits) << v;
        return s.str();
    };
    for (const SuiteRow& r : rows) {
        std::vector<std::string> cells = {r.scene,
                                          std::to_string(r.size),
                                          std::to_string(r.primitives),
                                          std::to_string(r.rays.camera),
                                          std::to_string(r.rays.shadow + r.rays.shadow_filtered),
                                          std::to_string(r.rays.reflection),
                                          std::to_string(r.rays.refraction),
                                          fixed(r.bvh_seconds, 4),
                                          fixed(r.render_seconds, 3),
                                          fixed(r.total_seconds, 3),
                                          fixed(r.mrays_per_second, 2),
                                          std::to_string(r.threads)};
        if (povray) {
            cells.push_back(fixed(r.povray_seconds, 3));
            cells.push_back(fixed(r.povray_seconds / r.total_seconds, 2));
        }
        table.push_back(cells);
    }
    const std::string width_text = rows.empty() ? "?" : std::to_string(rows.front().width);
    out << "machine: " << machine.cpu << ", " << machine.cores << " cores, " << machine.isa
        << "; images " << width_text << "x" << width_text << ", 1 spp"
        << (markdown ? "\n\n" : "\n");
    write_aligned_table(out, table, markdown);
}

void write_suite_files(const SuiteOptions& options, const std::vector<SuiteRow>& rows,
                       const MachineInfo& machine) {
    create_output_dir(options.dir);
    const std::string dir = options.dir;
    std::ostringstream csv, json, md, gp;
    csv << "scene,size,width,primitives,rays_camera,rays_shadow,rays_shadow_filtered,"
           "rays_reflection,rays_refraction,rays_total,generate_s,bvh_s,render_s,total_s,"
           "mrays_per_s,threads,cpu,cores,isa,povray_s,povray_ratio\n";
    csv << std::setprecision(9);
    json << std::setprecision(9) << "{\n  \"machine\": {\"cpu\": " << json_string(machine.cpu)
         << ", \"cores\": " << machine.cores << ", \"isa\": " << json_string(machine.isa)
         << "},\n  \"scenes\": [";
    for (size_t i = 0; i < rows.size(); ++i) {
        const SuiteRow& r = rows[i];
        const bool pov = r.povray_seconds >= 0;
        const double ratio = pov ? r.povray_seconds / r.total_seconds : 0;
        csv << r.scene << "," << r.size << "," << r.width << "," << r.primitives << ","
            << r.rays.camera << "," << r.rays.shadow << "," << r.rays.shadow_filtered << ","
            << r.rays.reflection << "," << r.rays.refraction << "," << r.rays.total_rays() << ","
            << r.generate_seconds << "," << r.bvh_seconds << "," << r.render_seconds << ","
            << r.total_seconds << "," << r.mrays_per_second << "," << r.threads << ","
            << csv_field(machine.cpu) << "," << machine.cores << "," << machine.isa << ",";
        if (pov) csv << r.povray_seconds << "," << ratio;
        csv << (pov ? "\n" : ",\n");
        json << (i ? "," : "") << "\n    {\"scene\": " << json_string(r.scene)
             << ", \"size\": " << r.size << ", \"width\": " << r.width
             << ", \"primitives\": " << r.primitives << ", \"rays\": {\"camera\": " << r.rays.camera
             << ", \"shadow\": " << r.rays.shadow
             << ", \"shadow_filtered\": " << r.rays.shadow_filtered
             << ", \"reflection\": " << r.rays.reflection
             << ", \"refraction\": " << r.rays.refraction << ", \"total\": " << r.rays.total_rays()
             << "}, \"generate_s\": " << r.generate_seconds << ", \"bvh_s\": " << r.bvh_seconds
             << ", \"render_s\": " << r.render_seconds << ", \"total_s\": " << r.total_seconds
             << ", \"mrays_per_s\": " << r.mrays_per_second << ", \"threads\": " << r.threads;
        if (pov) json << ", \"povray_s\": " << r.povray_seconds << ", \"povray_ratio\": " << ratio;
        json << "}";
    }
    json << "\n  ]\n}\n";
    md << "# rayo SPD suite\n\n";
    print_suite_table(md, rows, machine, true);
    md << "\nCommand: `rayo bench suite --size " << options.size << " --width " << options.width
       << (options.threads > 0 ? " --threads " + std::to_string(options.threads) : "")
       << (options.povray ? " --povray" : "") << " -o " << dir
       << "`. Times in seconds; total = scene generation + BVH build + render (rayo); POV-Ray: "
          "its whole run.\n";
    const std::string csv_path = dir + "/suite.csv";
    const bool pov = !rows.empty() && rows.front().povray_seconds >= 0;
    gp << "# Chart of rayo's SPD suite; regenerate with: gnuplot " << dir << "/suite.gp\n"
       << "set datafile separator ','\nset terminal pngcairo size 900,500\n"
       << "set output '" << dir << "/suite.png'\n"
       << "set title 'rayo SPD suite, size " << options.size << ", " << options.width << "x"
       << options.width << ": " << machine.cpu << "' noenhanced\n"
       << "set style data histograms\nset style histogram clustered gap 1\n"
       << "set style fill solid 0.8 border -1\nset boxwidth 0.9\nset grid y\n"
       << "set ylabel 'seconds'\nset y2label 'Mrays/s'\nset ytics nomirror\nset y2tics\n"
       << "set yrange [0:*]\nset y2range [0:*]\nset key outside bottom center horizontal\n"
       << "plot '" << csv_path << "' skip 1 using 12:xtic(1) title 'BVH build', "
       << "'' skip 1 using 13 title 'render', "
       << (pov ? "'' skip 1 using 20 title 'POV-Ray (whole run)', " : "")
       << "'' skip 1 using 0:15 axes x1y2 with linespoints pt 7 lw 2 title 'Mrays/s'\n";
    write_text_file(csv_path, csv.str());
    write_text_file(dir + "/suite.json", json.str());
    write_text_file(dir + "/suite.md", md.str());
    const std::string script = dir + "/suite.gp";
    write_text_file(script, gp.str());
    const std::string command = "gnuplot '" + script + "' 2>&1";
    if (std::system(command.c_str()) != 0) {
        throw InputError(script, "gnuplot failed (is gnuplot-nox installed? scripts/setup.sh)");
    }
}

void write_spd_nff_files(const SuiteOptions& options, std::ostream& progress) {
    create_output_dir(options.dir);
    for (const std::string& name : suite_scenes(options)) {
        const std::string path =
            options.dir + "/" + name + "_" + std::to_string(options.size) + ".nff";
        write_text_file(path, spd_nff(name, options.size));
        progress << "wrote " << path << "\n";
    }
}

}  // namespace rayo
