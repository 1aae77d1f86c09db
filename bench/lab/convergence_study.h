#pragma once
// `rayo bench convergence`: speed against accuracy for global illumination (issue 27 item 6,
// docs/path-tracing.md "Convergence"). A scene (the built-in Cornell box unless one is given:
// rayo's JSON, NFF or a model file such as glTF) rendered by the path integrator at 1, 4, 16, ...
// samples per pixel and by Whitted with seed 004's radiosity pre-pass at three patch sizes, each
// measured against a path-traced reference of many samples: the RMS error relative to the
// reference's mean luminance against the seconds the render took (render + radiosity solve).
// Writes DIR/convergence.csv, .json, .md, .gp and the log-log chart convergence.png/.svg
// (gnuplot), on which Monte Carlo's slope −½ is a dashed line.
#include <iosfwd>
#include <string>
#include <vector>

namespace rayo {

struct ConvergenceOptions {
    std::string dir;                  // output folder (created); empty: no files
    std::string scene;                // scene file; empty: the built-in Cornell box
    int width = 128;                  // image width; the height keeps the scene's aspect
    int reference_spp = 4096;         // the path reference's samples per pixel
    int max_spp = 1024;               // path at 1, 4, 16, ... up to this (included)
    int whitted_spp = 256;            // Whitted + radiosity: samples per pixel (antialiasing)
    std::vector<double> patch_sizes;  // radiosity patch sizes; empty: convergence_patch_sizes
    int threads = 0;                  // 0: all cores
};

// One render of the study.
struct ConvergenceRow {
    std::string method;         // "path" or "radiosity"
    int spp = 0;                // samples per pixel
    double patch_size = 0;      // radiosity: the longest patch edge (scene units); path: 0
    size_t patches = 0;         // radiosity: patches in the solve
    double render_seconds = 0;  // the tile loop
    double solve_seconds = 0;   // radiosity: the solve
    double seconds = 0;         // render + solve: the cost charted
    double rms_relative = 0;  // RMS over R, G, B of (image − reference) / reference mean luminance
    double mean_relative = 0;  // mean |image − reference| over R, G, B / the same mean
};

struct ConvergenceStudy {
    std::string scene;  // the scene's source ("scenes/cornell_box.json (built in)", or the path)
    int width = 0, height = 0, threads = 0;
    int reference_spp = 0;
    double reference_seconds = 0;
    double reference_mean_luminance = 0;
    std::vector<ConvergenceRow> rows;  // path rows by spp, then radiosity rows by patch size
};

// The path series: 1, 4, 16, ... below max_spp, then max_spp.
std::vector<int> convergence_spp_series(int max_spp);

// Renders the reference, then every row, one progress line each. Throws InputError for a scene
// that cannot be read or whose reference is black, StudyStopped (bench/lab/study_stop.h) when a
// stop is requested (no file is written).
ConvergenceStudy run_convergence_study(const ConvergenceOptions& options, std::ostream& progress);

// The aligned table printed at the end of a run (and, as Markdown, in convergence.md).
void print_convergence_table(std::ostream& out, const ConvergenceStudy& study, bool markdown);

// Writes the files and draws the chart into options.dir. Throws InputError when a file cannot
// be written or gnuplot fails.
void write_convergence_files(const ConvergenceOptions& options, const ConvergenceStudy& study);

}  // namespace rayo
