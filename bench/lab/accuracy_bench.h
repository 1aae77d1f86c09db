#pragma once
// `rayo bench accuracy -o DIR`: the speed-against-accuracy study of the sphere methods
// (docs/sphere-methods.md). Renders a fixed set of scenes with every method, tessellation level and
// precision, measures each frame's time and its error against the double-precision brute-force
// render, writes CSV and draws the charts with gnuplot (PNG and SVG).
#include <iosfwd>
#include <string>
#include <vector>

#include "apps/scene/scene_description.h"
#include "core/film.h"

namespace rayo {

struct ImageError {
    double rmse = 0.0;            // over RGB of the linear film
    double max_abs = 0.0;         // largest channel difference
    double pixels_differing = 0;  // % of pixels with a channel off by more than 1/255
    double silhouette_wrong = 0;  // % of pixels whose camera ray hits another object (or none)
};

// Film difference; both films have the same size.
ImageError compare_films(const Film& test, const Film& reference);

// One row of the study.
struct AccuracyRow {
    std::string scene, method, math;
    bool is_auto = false;  // the representation `auto` picks for this scene
    double seconds = 0.0;  // BVH build + render, best of the runs
    size_t primitives = 0;
    ImageError error;
};

// The study's scenes (name, description) at `size`×`size` pixels, small enough that brute force
// stays affordable.
constexpr int kAccuracyImageSize = 384;
std::vector<std::pair<std::string, SceneDescription>> accuracy_scenes(
    int size = kAccuracyImageSize);

// Runs the whole study; `progress` gets one line per render. Threads: all cores. Throws
// StudyStopped (bench/lab/study_stop.h) when a stop is requested: a render it cut short would
// measure blank tiles.
std::vector<AccuracyRow> run_accuracy_study(std::ostream& progress, int size = kAccuracyImageSize);

void write_accuracy_csv(std::ostream& out, const std::vector<AccuracyRow>& rows);

// Runs the study, then write_accuracy_files. Throws InputError when DIR cannot be written or
// gnuplot fails.
void run_accuracy_bench(const std::string& dir, std::ostream& progress,
                        int size = kAccuracyImageSize);

// Runs the stability sweep, then writes the study's `rows` (made at `size`) as DIR/accuracy.csv,
// the sweep as DIR/stability.csv, DIR/charts.gp, and runs gnuplot on it. A stop requested
// during the sweep throws StudyStopped before any file is written.
void write_accuracy_files(const std::string& dir, const std::vector<AccuracyRow>& rows,
                          std::ostream& progress, int size = kAccuracyImageSize);

}  // namespace rayo
