#pragma once
// `rayo bench suite`: the seven SPD scenes (bench/lab/spd_scenes.h) rendered at one size and
// resolution, as a benchmark anyone can run with rayo alone (docs/performance.md, "The SPD
// suite"). Prints a table and writes DIR/suite.csv, suite.json (Google Benchmark's JSON form),
// suite.md, suite.gp and the chart suite.png (gnuplot). With `procedure` it follows the SPD's
// testing procedure (bench/lab/spd_procedure.h) and sets each count beside the SPD's Readme.
#include <iosfwd>
#include <string>
#include <vector>

#include "bench/lab/spd_procedure.h"
#include "core/stats.h"

namespace rayo {

struct SuiteOptions {
    std::string dir;                // output folder (created)
    int size = 3;                   // SPD size of every scene (not with spd_procedure)
    int width = 512;                // square images, width × width
    int threads = 0;                // 0: all cores
    bool povray = false;            // also time POV-Ray 3.7 on the same scenes
    std::vector<std::string> only;  // scene names; empty: all seven
    // The SPD's testing procedure (--procedure spd): every database at its default size, the
    // procedure's render settings (apply_spd_procedure), the counts checked against the Readme.
    bool spd_procedure = false;
    int repetitions = 1;  // renders of each scene; the table shows the median, min and max
};

// The machine the suite ran on: /proc/cpuinfo's model name, the cores TBB uses, and the ISA of
// rayo's Embree device: its native packet width (core/embree_device.h: 16 avx512, 8 avx2 or
// avx, 4 sse4.2 or sse2; the device stops at AVX2), the CPU's flags telling the two apart.
struct MachineInfo {
    std::string cpu, isa;
    int cores = 0;
    int embree_packet = 0;  // embree_native_packet_width()
    int mhz = 0;            // /proc/cpuinfo's "cpu MHz" of the first CPU (0: unknown)
    std::string host_name;  // gethostname
};
MachineInfo machine_info();

// One repetition's times, in seconds.
struct SuiteRun {
    double generate = 0;     // the NFF text made and read (parse included)
    double parse = 0;        // the NFF text read (the SPD's "input")
    double bvh = 0;          // the BVH build (the SPD's "setup")
    double render = 0;       // the render (the SPD's "ray tracing")
    double render_cpu = 0;   // the process's CPU time, all threads, over the BVH build + render
    double render_wall = 0;  // the wall time of the same (suite.json's real_time)
    double total = 0;        // generate + BVH + render
};

struct SuiteRow {
    std::string scene;
    int size = 0, width = 0, threads = 0;
    size_t primitives = 0;
    RayCounters rays;
    // The medians over the repetitions (each repetition in `runs`).
    double generate_seconds = 0;  // the NFF text made and read
    double parse_seconds = 0;     // of which reading it
    double bvh_seconds = 0, render_seconds = 0;
    double total_seconds = 0;     // generate + BVH + render
    double mrays_per_second = 0;  // all rays / render time
    double povray_seconds = -1;   // POV-Ray's whole run (parse + render); < 0: not run
    std::vector<SuiteRun> runs;
    // With the SPD procedure: the four counts against the Readme's.
    std::vector<SpdCountCheck> checks;
};

// Renders every scene, one progress line each. Throws InputError for a bad scene name or size,
// or when --povray is asked for and POV-Ray cannot run; StudyStopped (bench/lab/study_stop.h)
// when a stop is requested.
std::vector<SuiteRow> run_spd_suite(const SuiteOptions& options, std::ostream& progress);

// The aligned table printed at the end of a run (and, as Markdown, in suite.md); with the SPD
// procedure, its counts and time split as well (print_spd_procedure_table).
void print_suite_table(std::ostream& out, const std::vector<SuiteRow>& rows,
                       const MachineInfo& machine, bool markdown);

// The SPD procedure's tables: each count beside the Readme's (scaled to 513² eye rays), and the
// SPD's time split (input, setup, ray tracing) beside the Readme's HP-835 times.
void print_spd_procedure_table(std::ostream& out, const std::vector<SuiteRow>& rows, bool markdown);

// The counts more than 10% off the Readme's, one line each ("gears reflect rays: ..."); empty
// when all agree (or without the procedure).
std::vector<std::string> spd_count_failures(const std::vector<SuiteRow>& rows);

// suite.json: Google Benchmark's JSON form ("context", "benchmarks": one entry per scene and
// repetition, real_time and cpu_time those of the BVH build and the render, rays per second of
// the render by kind as counters; with repetitions, the aggregates _mean, _median, _stddev, _min
// and _max).
std::string suite_json(const SuiteOptions& options, const std::vector<SuiteRow>& rows,
                       const MachineInfo& machine);

// Writes the four files and the chart into options.dir. Throws InputError when a file cannot
// be written or gnuplot fails.
void write_suite_files(const SuiteOptions& options, const std::vector<SuiteRow>& rows,
                       const MachineInfo& machine);

// DIR/NAME_SIZE.nff for every scene (or options.only): the generated NFF files.
void write_spd_nff_files(const SuiteOptions& options, std::ostream& progress);

}  // namespace rayo
