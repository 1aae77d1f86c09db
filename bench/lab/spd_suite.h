#pragma once
// `rayo bench suite`: the seven SPD scenes (bench/lab/spd_scenes.h) rendered at one size and
// resolution, as a benchmark anyone can run with rayo alone (docs/performance.md, "The SPD
// suite"). Prints a table and writes DIR/suite.csv, suite.json, suite.md, suite.gp and the
// chart suite.png (gnuplot).
#include <iosfwd>
#include <string>
#include <vector>

#include "core/stats.h"

namespace rayo {

struct SuiteOptions {
    std::string dir;                // output folder (created)
    int size = 3;                   // SPD size of every scene
    int width = 512;                // square images, width × width
    int threads = 0;                // 0: all cores
    bool povray = false;            // also time POV-Ray 3.7 on the same scenes
    std::vector<std::string> only;  // scene names; empty: all seven
};

// The machine the suite ran on: /proc/cpuinfo's model name, the cores TBB uses, and the widest
// vector ISA in the CPU flags that rayo's Embree device uses (avx2, avx, sse4.2, sse2: the
// device stops at AVX2, core/embree_device.h).
struct MachineInfo {
    std::string cpu, isa;
    int cores = 0;
};
MachineInfo machine_info();

struct SuiteRow {
    std::string scene;
    int size = 0, width = 0, threads = 0;
    size_t primitives = 0;
    RayCounters rays;
    double generate_seconds = 0;  // the NFF text made and read
    double bvh_seconds = 0, render_seconds = 0;
    double total_seconds = 0;     // generate + BVH + render
    double mrays_per_second = 0;  // all rays / render time
    double povray_seconds = -1;   // POV-Ray's whole run (parse + render); < 0: not run
};

// Renders every scene, one progress line each. Throws InputError for a bad scene name or size,
// or when --povray is asked for and POV-Ray cannot run; StudyStopped (bench/lab/study_stop.h)
// when a stop is requested.
std::vector<SuiteRow> run_spd_suite(const SuiteOptions& options, std::ostream& progress);

// The aligned table printed at the end of a run (and, as Markdown, in suite.md).
void print_suite_table(std::ostream& out, const std::vector<SuiteRow>& rows,
                       const MachineInfo& machine, bool markdown);

// Writes the four files and the chart into options.dir. Throws InputError when a file cannot
// be written or gnuplot fails.
void write_suite_files(const SuiteOptions& options, const std::vector<SuiteRow>& rows,
                       const MachineInfo& machine);

// DIR/NAME_SIZE.nff for every scene (or options.only): the generated NFF files.
void write_spd_nff_files(const SuiteOptions& options, std::ostream& progress);

}  // namespace rayo
