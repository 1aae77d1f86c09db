#pragma once
// The shape-method study (`rayo bench accuracy`, docs/shape-methods.md): every shape with a mesh
// form (core/shapes/mesh_form.h), alone in front of the camera, traced analytically and as
// meshes within a range of pixel error budgets; per form: triangles, Embree bytes, build time,
// time per camera ray (coherent streams and single rays, one thread) and the error measured
// against the analytic hits. Writes CSV and gnuplot charts (time and memory against error).
#include <iosfwd>
#include <string>
#include <vector>

#include "apps/scene/scene_description.h"

namespace rayo {

struct ShapeMethodRow {
    std::string shape;
    std::string form;        // "analytic" or "mesh"
    double budget_px = 0.0;  // the mesh's --max-error-px (0 for analytic)
    bool is_auto = false;    // what auto picks at the default budget (0.5 px)
    size_t triangles = 0;
    size_t bytes = 0;             // Embree's, from its memory monitor
    double build_seconds = 0.0;   // choice and tessellation + BVH build
    double ns_coherent = 0.0;     // per camera ray, 8×8 streams (the renderer's camera path)
    double ns_single = 0.0;       // per camera ray, one at a time (the secondary rays' path)
    double chord_px = 0.0;        // the mesh's own chord error estimate, pixels
    double max_error_px = 0.0;    // measured: the largest surface separation over the pixels
    double silhouette_pct = 0.0;  // % of pixels hit by one form and missed by the other
};

// One scene per shape: (name, description), `size`×`size` pixels; the object's "method" is the
// only request (the study sets it).
std::vector<std::pair<std::string, SceneDescription>> shape_method_scenes(int size);

// The error budgets of the mesh forms, px.
const std::vector<double>& shape_method_budgets();

// `repeats`: timing runs per form (the best is kept). Throws StudyStopped (bench/lab/study_stop.h)
// when a stop is requested.
std::vector<ShapeMethodRow> run_shape_method_study(std::ostream& progress, int size,
                                                   int repeats = 7);

void write_shape_method_csv(std::ostream& out, const std::vector<ShapeMethodRow>& rows);

// Runs the study, then write_shape_method_files. Throws InputError when DIR cannot be written
// or gnuplot fails.
void run_shape_method_bench(const std::string& dir, std::ostream& progress, int size);

// Writes the study's `rows` as DIR/shape_methods.csv, DIR/shape_methods.dat and
// DIR/shape_methods.gp and runs gnuplot on it (charts shape_methods_time and
// shape_methods_memory, PNG and SVG).
void write_shape_method_files(const std::string& dir, const std::vector<ShapeMethodRow>& rows,
                              std::ostream& progress);

}  // namespace rayo
