#include "bench/lab/spd_suite.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>

#include "apps/scene/nff_loader.h"
#include "apps/scene/renderer.h"
#include "bench/lab/spd_povray.h"
#include "bench/lab/spd_scenes.h"
#include "bench/lab/study_files.h"
#include "bench/lab/study_stop.h"
#include "core/embree_device.h"
#include "core/error.h"

namespace rayo {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::string> suite_scenes(const SuiteOptions& options) {
    return options.only.empty() ? spd_scene_names() : options.only;
}

int scene_size(const SuiteOptions& options, const std::string& name) {
    return options.spd_procedure ? spd_default_size(name) : options.size;
}

double process_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

std::vector<double> run_values(const SuiteRow& row, double SuiteRun::*member) {
    std::vector<double> v;
    for (const SuiteRun& r : row.runs) v.push_back(r.*member);
    return v;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v) {
    double sum = 0;
    for (double x : v) sum += x;
    return v.empty() ? 0 : sum / double(v.size());
}

// The sample standard deviation (n − 1), as Google Benchmark's _stddev.
double stddev(const std::vector<double>& v) {
    if (v.size() < 2) return 0;
    const double m = mean(v);
    double sum = 0;
    for (double x : v) sum += (x - m) * (x - m);
    return std::sqrt(sum / double(v.size() - 1));
}

std::string fixed(double v, int digits) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}

// "0.398" or, with repetitions, "0.398 (0.391–0.412)": the median, min and max.
std::string time_cell(const SuiteRow& row, double SuiteRun::*member, int digits) {
    const std::vector<double> v = run_values(row, member);
    if (v.size() < 2) return fixed(v.empty() ? 0.0 : v.front(), digits);
    return fixed(median(v), digits) + " (" + fixed(*std::min_element(v.begin(), v.end()), digits) +
           "-" + fixed(*std::max_element(v.begin(), v.end()), digits) + ")";
}

// The command that reproduces a run (suite.md, suite.json).
std::string suite_command(const SuiteOptions& options) {
    std::string command = "rayo bench suite";
    if (options.spd_procedure) {
        command += " --procedure spd";
    } else {
        command += " --size " + std::to_string(options.size);
    }
    command += " --width " + std::to_string(options.width);
    if (options.threads > 0) command += " --threads " + std::to_string(options.threads);
    if (options.repetitions > 1) command += " --repetitions " + std::to_string(options.repetitions);
    if (!options.only.empty()) {
        command += " --scenes ";
        for (size_t i = 0; i < options.only.size(); ++i) {
            command += (i ? "," : "") + options.only[i];
        }
    }
    if (options.povray) command += " --povray";
    if (!options.dir.empty()) command += " -o " + options.dir;
    return command;
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
        if (key == "cpu MHz" && m.mhz == 0) m.mhz = int(std::lround(std::atof(value.c_str())));
        if (key == "flags" && flags.empty()) flags = " " + value + " ";
    }
    if (m.cpu.empty()) m.cpu = "unknown";
    char host[256] = {};
    m.host_name = gethostname(host, sizeof host - 1) == 0 ? host : "unknown";
    const auto has = [&](const char* flag) {
        return flags.find(std::string(" ") + flag + " ") != std::string::npos;
    };
    m.embree_packet = embree_native_packet_width();
    m.isa = m.embree_packet >= 16  ? "avx512"
            : m.embree_packet == 8 ? (has("avx2") ? "avx2" : "avx")
            : m.embree_packet == 4 ? (has("sse4_2") ? "sse4.2" : "sse2")
                                   : "scalar";
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
        if (!options.spd_procedure && options.size > spd_max_size(name)) {
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
        row.size = scene_size(options, name);
        row.width = options.width;
        std::string nff;
        for (int repetition = 0; repetition < std::max(1, options.repetitions); ++repetition) {
            SuiteRun run;
            const auto start = std::chrono::steady_clock::now();
            nff = spd_nff(name, row.size);
            const auto parse_start = std::chrono::steady_clock::now();
            SceneDescription d =
                load_nff_string(nff, "spd:" + name + ":" + std::to_string(row.size));
            run.parse = seconds_since(parse_start);
            d.scene.camera.width = d.scene.camera.height = options.width;
            if (options.spd_procedure) apply_spd_procedure(d.settings);
            run.generate = seconds_since(start);
            const double cpu_start = process_cpu_seconds();
            const auto wall_start = std::chrono::steady_clock::now();
            const RenderResult r = render_scene(d, options.threads, false);
            run.render_wall = seconds_since(wall_start);
            run.render_cpu = process_cpu_seconds() - cpu_start;
            stop_study_if_requested("SPD suite");
            row.threads = r.threads;
            row.primitives = r.primitives;
            row.rays = r.counters;  // the same every repetition: the render is deterministic
            run.bvh = r.bvh_seconds;
            run.render = r.render_seconds;
            run.total = run.generate + r.bvh_seconds + r.render_seconds;
            row.runs.push_back(run);
        }
        row.generate_seconds = median(run_values(row, &SuiteRun::generate));
        row.parse_seconds = median(run_values(row, &SuiteRun::parse));
        row.bvh_seconds = median(run_values(row, &SuiteRun::bvh));
        row.render_seconds = median(run_values(row, &SuiteRun::render));
        row.total_seconds = median(run_values(row, &SuiteRun::total));
        row.mrays_per_second =
            row.render_seconds > 0 ? double(row.rays.total_rays()) / row.render_seconds / 1e6 : 0;
        if (options.spd_procedure) row.checks = check_spd_counts(name, row.rays, options.width);
        if (options.povray) row.povray_seconds = time_povray(pov_dir, name, nff, options);
        progress << std::fixed << std::setprecision(3) << name << " " << row.size << ": "
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
    for (const SuiteRow& r : rows) {
        std::vector<std::string> cells = {r.scene,
                                          std::to_string(r.size),
                                          std::to_string(r.primitives),
                                          std::to_string(r.rays.camera),
                                          std::to_string(r.rays.shadow + r.rays.shadow_filtered),
                                          std::to_string(r.rays.reflection),
                                          std::to_string(r.rays.refraction),
                                          time_cell(r, &SuiteRun::bvh, 4),
                                          time_cell(r, &SuiteRun::render, 3),
                                          time_cell(r, &SuiteRun::total, 3),
                                          fixed(r.mrays_per_second, 2),
                                          std::to_string(r.threads)};
        if (povray) {
            cells.push_back(fixed(r.povray_seconds, 3));
            cells.push_back(fixed(r.povray_seconds / r.total_seconds, 2));
        }
        table.push_back(cells);
    }
    const std::string width_text = rows.empty() ? "?" : std::to_string(rows.front().width);
    const bool procedure = !rows.empty() && !rows.front().checks.empty();
    const size_t repetitions = rows.empty() ? 1 : rows.front().runs.size();
    out << "machine: " << machine.cpu << ", " << machine.cores << " cores, " << machine.isa
        << "; images " << width_text << "x" << width_text
        << (procedure ? ", the SPD's testing procedure (rays through the pixel corners)"
                      : ", 1 spp")
        << (repetitions > 1
                ? "; times: median (min-max) of " + std::to_string(repetitions) + " repetitions"
                : std::string())
        << (markdown ? "\n\n" : "\n");
    write_aligned_table(out, table, markdown);
    if (procedure) {
        out << "\n";
        print_spd_procedure_table(out, rows, markdown);
    }
}

void print_spd_procedure_table(std::ostream& out, const std::vector<SuiteRow>& rows,
                               bool markdown) {
    // The SPD Readme's "Timings" (HP-835, 512 × 512): input, setup and ray tracing, seconds.
    static const std::map<std::string, std::array<int, 3>> hp835 = {
        {"balls", {14, 19, 24 * 60 + 56}},  {"gears", {56, 18, 3600 + 2 * 60 + 31}},
        {"mount", {31, 14, 18 * 60 + 49}},  {"rings", {41, 33, 53 * 60 + 41}},
        {"teapot", {62, 18, 25 * 60 + 38}}, {"tetra", {15, 6, 3 * 60 + 48}},
        {"tree", {40, 31, 11 * 60 + 36}},
    };
    const int width = rows.empty() ? kSpdProcedureWidth : rows.front().width;
    out << "Ray counts against the SPD Readme's \"Database Analysis\" (513x513 eye rays"
        << (width == kSpdProcedureWidth ? ""
                                        : "; rayo's counts at " + std::to_string(width + 1) + "x" +
                                              std::to_string(width + 1) + " scaled to it")
        << "; off: rayo / SPD - 1, at most 10%):" << (markdown ? "\n\n" : "\n");
    std::vector<std::vector<std::string>> counts = {{"scene", "size"}};
    for (const char* kind : {"eye hit", "reflect", "refract", "shadow"}) {
        counts[0].push_back(std::string(kind) + " rayo");
        counts[0].push_back("SPD");
        counts[0].push_back("off");
    }
    const auto off_text = [](const SpdCountCheck& c) {
        if (std::isinf(c.off)) return std::string("new");
        const std::string text = (c.off >= 0 ? "+" : "") + fixed(100.0 * c.off, 1) + "%";
        return c.within() ? text : text + " FAIL";
    };
    for (const SuiteRow& r : rows) {
        std::vector<std::string> cells = {r.scene, std::to_string(r.size)};
        for (const SpdCountCheck& c : r.checks) {
            cells.push_back(fixed(c.rayo, 0));
            cells.push_back(std::to_string(c.readme));
            cells.push_back(off_text(c));
        }
        counts.push_back(cells);
    }
    write_aligned_table(out, counts, markdown);
    out << (markdown ? "\n" : "\n")
        << "The SPD's time split (input: reading the NFF text; setup: the BVH; ray tracing: the "
           "render), seconds, beside the Readme's HP-835 (1987):"
        << (markdown ? "\n\n" : "\n");
    std::vector<std::vector<std::string>> times = {
        {"scene", "input s", "setup s", "ray tracing s", "Mrays/s", "HP-835 input s",
         "HP-835 setup s", "HP-835 ray tracing s", "HP-835 / rayo (ray tracing)"}};
    for (const SuiteRow& r : rows) {
        const auto hp = hp835.find(r.scene);
        std::vector<std::string> cells = {
            r.scene, time_cell(r, &SuiteRun::parse, 4), time_cell(r, &SuiteRun::bvh, 4),
            time_cell(r, &SuiteRun::render, 3), fixed(r.mrays_per_second, 2)};
        for (int i = 0; i < 3; ++i) cells.push_back(std::to_string(hp->second[size_t(i)]));
        cells.push_back(r.render_seconds > 0 ? fixed(hp->second[2] / r.render_seconds, 0) : "-");
        times.push_back(cells);
    }
    write_aligned_table(out, times, markdown);
}

std::vector<std::string> spd_count_failures(const std::vector<SuiteRow>& rows) {
    std::vector<std::string> failures;
    for (const SuiteRow& r : rows) {
        for (const SpdCountCheck& c : r.checks) {
            if (c.within()) continue;
            failures.push_back(r.scene + " " + c.kind + " rays: " + fixed(c.rayo, 0) +
                               " against the SPD Readme's " + std::to_string(c.readme) + " (" +
                               (std::isinf(c.off)
                                    ? std::string("none expected")
                                    : (c.off >= 0 ? "+" : "") + fixed(100.0 * c.off, 1) + "%") +
                               ", more than 10% off)");
        }
    }
    return failures;
}

std::string suite_json(const SuiteOptions& options, const std::vector<SuiteRow>& rows,
                       const MachineInfo& machine) {
    std::ostringstream json;
    json << std::setprecision(10);
    char date[64] = {};
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%S%z", &local);
    std::string date_text = date;  // Google Benchmark writes the offset as +hh:mm
    if (date_text.size() >= 5) date_text.insert(date_text.size() - 2, ":");
    const int threads = rows.empty() ? options.threads : rows.front().threads;
    json << "{\n  \"context\": {\n    \"date\": " << json_string(date_text)
         << ",\n    \"host_name\": " << json_string(machine.host_name)
         << ",\n    \"executable\": " << json_string(suite_command(options))
         << ",\n    \"num_cpus\": " << machine.cores << ",\n    \"mhz_per_cpu\": " << machine.mhz
         << ",\n    \"cpu_model\": " << json_string(machine.cpu)
         << ",\n    \"embree_isa\": " << json_string(machine.isa)
         << ",\n    \"embree_native_packet\": " << machine.embree_packet
         << ",\n    \"threads\": " << threads
         << ",\n    \"procedure\": " << json_string(options.spd_procedure ? "spd" : "none")
         << ",\n    \"repetitions\": " << std::max(1, options.repetitions)
#ifdef NDEBUG
         << ",\n    \"library_build_type\": \"release\""
#else
         << ",\n    \"library_build_type\": \"debug\""
#endif
         << "\n  },\n  \"benchmarks\": [";
    bool first = true;
    // One benchmark object: its times in ms, and the rays per second of each kind over `render`.
    const auto entry = [&](const SuiteRow& r, const std::string& name, const std::string& run_type,
                           int repetition, const std::string& aggregate, const SuiteRun& t,
                           bool ratio_counters) {
        const std::string run_name = "spd/" + r.scene + "/size:" + std::to_string(r.size) +
                                     "/width:" + std::to_string(r.width);
        json << (first ? "" : ",") << "\n    {\"name\": " << json_string(name)
             << ", \"run_name\": " << json_string(run_name)
             << ", \"run_type\": " << json_string(run_type)
             << ", \"repetitions\": " << r.runs.size();
        if (run_type == "iteration") json << ", \"repetition_index\": " << repetition;
        if (!aggregate.empty()) {
            json << ", \"aggregate_name\": " << json_string(aggregate)
                 << ", \"aggregate_unit\": \"time\"";
        }
        json << ", \"threads\": " << r.threads
             << ", \"iterations\": " << (run_type == "iteration" ? size_t(1) : r.runs.size())
             << ", \"real_time\": " << t.render_wall * 1e3
             << ", \"cpu_time\": " << t.render_cpu * 1e3
             << ", \"time_unit\": \"ms\", \"scene\": " << json_string(r.scene)
             << ", \"size\": " << r.size << ", \"width\": " << r.width
             << ", \"primitives\": " << r.primitives << ", \"generate_ms\": " << t.generate * 1e3
             << ", \"parse_ms\": " << t.parse * 1e3 << ", \"bvh_ms\": " << t.bvh * 1e3
             << ", \"total_ms\": " << t.total * 1e3;
        const RayCounters& c = r.rays;
        json << ", \"camera_rays\": " << c.camera << ", \"camera_hits\": " << c.camera_hits
             << ", \"shadow_rays\": " << c.shadow + c.shadow_filtered
             << ", \"reflection_rays\": " << c.reflection
             << ", \"refraction_rays\": " << c.refraction << ", \"rays\": " << c.total_rays();
        if (ratio_counters) {
            const double per = t.render > 0 ? 1.0 / t.render : 0.0;
            json << ", \"camera_rays_per_second\": " << double(c.camera) * per
                 << ", \"shadow_rays_per_second\": " << double(c.shadow + c.shadow_filtered) * per
                 << ", \"reflection_rays_per_second\": " << double(c.reflection) * per
                 << ", \"refraction_rays_per_second\": " << double(c.refraction) * per
                 << ", \"rays_per_second\": " << double(c.total_rays()) * per;
        }
        if (r.povray_seconds >= 0) json << ", \"povray_ms\": " << r.povray_seconds * 1e3;
        for (const SpdCountCheck& check : r.checks) {
            std::string key = check.kind;
            std::replace(key.begin(), key.end(), ' ', '_');
            json << ", \"spd_readme_" << key << "\": " << check.readme;
        }
        json << "}";
        first = false;
    };
    for (const SuiteRow& r : rows) {
        const std::string base = "spd/" + r.scene + "/size:" + std::to_string(r.size) +
                                 "/width:" + std::to_string(r.width);
        for (size_t i = 0; i < r.runs.size(); ++i) {
            entry(r, base, "iteration", int(i), "", r.runs[i], true);
        }
        if (r.runs.size() < 2) continue;
        // Google Benchmark's aggregates over the repetitions, and min and max.
        const auto over = [&](auto statistic) {
            SuiteRun a;
            for (double SuiteRun::*m :
                 {&SuiteRun::generate, &SuiteRun::parse, &SuiteRun::bvh, &SuiteRun::render,
                  &SuiteRun::render_cpu, &SuiteRun::render_wall, &SuiteRun::total}) {
                a.*m = statistic(run_values(r, m));
            }
            return a;
        };
        const auto minimum = [](const std::vector<double>& v) {
            return *std::min_element(v.begin(), v.end());
        };
        const auto maximum = [](const std::vector<double>& v) {
            return *std::max_element(v.begin(), v.end());
        };
        entry(r, base + "_mean", "aggregate", 0, "mean", over(mean), true);
        entry(r, base + "_median", "aggregate", 0, "median", over(median), true);
        entry(r, base + "_stddev", "aggregate", 0, "stddev", over(stddev), false);
        entry(r, base + "_min", "aggregate", 0, "min", over(minimum), true);
        entry(r, base + "_max", "aggregate", 0, "max", over(maximum), true);
    }
    json << "\n  ]\n}\n";
    return json.str();
}

void write_suite_files(const SuiteOptions& options, const std::vector<SuiteRow>& rows,
                       const MachineInfo& machine) {
    create_output_dir(options.dir);
    const std::string dir = options.dir;
    std::ostringstream csv, md, gp;
    // New columns go at the end: suite.gp reads columns by number.
    csv << "scene,size,width,primitives,rays_camera,rays_shadow,rays_shadow_filtered,"
           "rays_reflection,rays_refraction,rays_total,generate_s,bvh_s,render_s,total_s,"
           "mrays_per_s,threads,cpu,cores,isa,povray_s,povray_ratio,parse_s,rays_camera_hits\n";
    csv << std::setprecision(9);
    for (const SuiteRow& r : rows) {
        const bool pov = r.povray_seconds >= 0;
        csv << r.scene << "," << r.size << "," << r.width << "," << r.primitives << ","
            << r.rays.camera << "," << r.rays.shadow << "," << r.rays.shadow_filtered << ","
            << r.rays.reflection << "," << r.rays.refraction << "," << r.rays.total_rays() << ","
            << r.generate_seconds << "," << r.bvh_seconds << "," << r.render_seconds << ","
            << r.total_seconds << "," << r.mrays_per_second << "," << r.threads << ","
            << csv_field(machine.cpu) << "," << machine.cores << "," << machine.isa << ",";
        if (pov)
            csv << r.povray_seconds << "," << r.povray_seconds / r.total_seconds;
        else
            csv << ",";
        csv << "," << r.parse_seconds << "," << r.rays.camera_hits << "\n";
    }
    md << "# rayo SPD suite\n\n";
    print_suite_table(md, rows, machine, true);
    md << "\nCommand: `" << suite_command(options)
       << "`. Times in seconds; total = scene generation + BVH build + render (rayo); POV-Ray: "
          "its whole run.\n";
    const std::string csv_path = dir + "/suite.csv";
    const bool pov = !rows.empty() && rows.front().povray_seconds >= 0;
    gp << "# Chart of rayo's SPD suite; regenerate with: gnuplot " << dir << "/suite.gp\n"
       << "set datafile separator ','\nset terminal pngcairo size 900,500\n"
       << "set output '" << dir << "/suite.png'\n"
       << "set title 'rayo SPD suite, "
       << (options.spd_procedure ? std::string("default SPD sizes")
                                 : "size " + std::to_string(options.size))
       << ", " << options.width << "x" << options.width << ": " << machine.cpu << "' noenhanced\n"
       << "set style data histograms\nset style histogram clustered gap 1\n"
       << "set style fill solid 0.8 border -1\nset boxwidth 0.9\nset grid y\n"
       << "set ylabel 'seconds'\nset y2label 'Mrays/s'\nset ytics nomirror\nset y2tics\n"
       << "set yrange [0:*]\nset y2range [0:*]\nset key outside bottom center horizontal\n"
       << "plot '" << csv_path << "' skip 1 using 12:xtic(1) title 'BVH build', "
       << "'' skip 1 using 13 title 'render', "
       << (pov ? "'' skip 1 using 20 title 'POV-Ray (whole run)', " : "")
       << "'' skip 1 using 0:15 axes x1y2 with linespoints pt 7 lw 2 title 'Mrays/s'\n";
    write_text_file(csv_path, csv.str());
    write_text_file(dir + "/suite.json", suite_json(options, rows, machine));
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
        const int size = scene_size(options, name);
        const std::string path = options.dir + "/" + name + "_" + std::to_string(size) + ".nff";
        write_text_file(path, spd_nff(name, size));
        progress << "wrote " << path << "\n";
    }
}

}  // namespace rayo
