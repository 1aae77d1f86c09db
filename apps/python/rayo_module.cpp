// `import rayo`: the Python module (docs/python.md). It holds no rendering logic of its own:
// scenes are read by the scene layer's readers, keywords are `rayo render`'s options parsed by
// the command line's own parser (apps/cli/render_options.h: the same names, bounds and
// messages), renders run render_scene as the CLI does, and images are written by the CLI's
// writers and OCIO views. The interpreter's lock is released while a render or a study runs;
// Ctrl-C stops the tile hand-out and the studies' loops (core/stop_request.h,
// bench/lab/study_stop.h) and raises KeyboardInterrupt.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <future>
#include <map>
#include <memory>
#include <sstream>

#include "apps/cli/int_flag.h"
#include "apps/cli/render_options.h"
#include "apps/cli/setting_flags.h"
#include "apps/cli/usage_error.h"
#include "apps/scene/image_file.h"
#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "apps/scene/shape_method_choice.h"
#include "bench/lab/accuracy_bench.h"
#include "bench/lab/convergence_study.h"
#include "bench/lab/shape_methods_study.h"
#include "bench/lab/spd_suite.h"
#include "bench/lab/study_stop.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/film.h"
#include "core/image/image_output.h"
#include "core/scene_bounds.h"
#include "core/stop_request.h"

namespace py = pybind11;

namespace rayo {
namespace {

// "--nff-light-intensity" for the keyword nff_light_intensity.
std::string flag_of_keyword(const std::string& keyword) {
    std::string flag = "--" + keyword;
    for (char& c : flag) {
        if (c == '_') c = '-';
    }
    return flag;
}

std::string keyword_of_flag(const std::string& flag) {
    std::string keyword = flag.substr(2);
    for (char& c : keyword) {
        if (c == '-') c = '_';
    }
    return keyword;
}

const char* function_of_use(OptionUse use) {
    switch (use) {
        case OptionUse::Load:
            return "rayo.load";
        case OptionUse::Render:
            return "rayo.render";
        case OptionUse::Output:
            return "rayo.write";
        case OptionUse::Command:
            return "the command line only";
    }
    return "";
}

const std::vector<RenderOptionInfo>& option_list() {
    static const std::vector<RenderOptionInfo> list = render_option_list();
    return list;
}

// The keywords of a call as `rayo render`'s argv words: a switch is given by True (False and
// None: not given); a value by its text ("0.5", "mesh:2"; a sequence as "x,y,z"). A keyword of
// another call, or of none, is a TypeError naming where it belongs.
std::vector<std::string> option_words(const py::kwargs& keywords, OptionUse use,
                                      const char* function) {
    std::vector<std::string> words;
    for (const auto& [key, value] : keywords) {
        const std::string keyword = py::str(key);
        const std::string flag = flag_of_keyword(keyword);
        const RenderOptionInfo* info = nullptr;
        for (const RenderOptionInfo& o : option_list()) {
            if (o.flag == flag) info = &o;
        }
        if (!info) {
            throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" +
                                 keyword + "' (rayo.options() lists them)");
        }
        if (info->use != use) {
            throw py::type_error(std::string(function) + "(): '" + keyword + "' is an option of " +
                                 function_of_use(info->use));
        }
        if (value.is_none()) continue;
        if (!info->takes_value) {
            if (!py::isinstance<py::bool_>(value)) {
                throw UsageError(flag + ": a switch: expected True or False, got " +
                                 std::string(py::repr(value)));
            }
            if (value.cast<bool>()) words.push_back(flag);
            continue;
        }
        std::string text;
        if (py::isinstance<py::str>(value)) {
            text = value.cast<std::string>();
        } else if (py::isinstance<py::bool_>(value)) {
            throw UsageError(flag + ": expected a value, got " + std::string(py::repr(value)));
        } else if (py::isinstance<py::sequence>(value)) {
            for (const py::handle item : value) {
                text += (text.empty() ? "" : ",") + std::string(py::str(item));
            }
        } else {
            text = py::str(value);  // ints and floats as Python writes them (repr: round trip)
        }
        words.push_back(flag);
        words.push_back(text);
    }
    return words;
}

// A loaded scene, read-only: renders take a copy with their options applied.
struct PyScene {
    std::shared_ptr<const SceneDescription> description;
    double parse_seconds = 0.0;  // reading and validating it (`rayo render --stats`: time parse)
};

// A render that a stop request cut short (the request is global: core/stop_request.h; another
// thread's Ctrl-C or failing progress callback makes one). Raised as KeyboardInterrupt: part of
// its tiles were never rendered, so it has no image to return.
struct RenderStopped : std::runtime_error {
    using std::runtime_error::runtime_error;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

py::tuple vec3_tuple(const Vec3& v) {
    return py::make_tuple(v.x, v.y, v.z);
}

py::dict camera_view(const SceneDescription& d) {
    const CameraDesc& c = d.scene.camera;
    py::dict out;
    out["width"] = c.width;
    out["height"] = c.height;
    out["projection"] = projection_name(c.projection);
    out["eye"] = vec3_tuple(c.eye);
    out["look_at"] = vec3_tuple(c.look_at);
    out["up"] = vec3_tuple(c.up);
    if (c.projection == Projection::Perspective) {
        const Camera camera = Camera::create(c, d.source + "#/camera");
        out["fov"] = py::make_tuple(camera.hfov_degrees(), camera.vfov_degrees());
    }
    out["lens_radius"] = c.lens_radius;
    return out;
}

py::dict count_view(const SceneDescription& d) {
    py::dict out;
    for (const auto& [name, count] : d.scene.shape_counts()) out[py::str(name)] = count;
    size_t vertices = 0;
    for (const TriangleMesh& m : d.scene.meshes) vertices += m.positions.size();
    out["meshes"] = d.scene.meshes.size();
    out["triangles"] = d.scene.triangle_count();
    out["vertices"] = vertices;
    out["voxel_grids"] = d.scene.voxels.size();
    out["heightfields"] = d.scene.heightfields.size();
    out["materials"] = d.shading.materials.size();
    out["lights"] = d.shading.lights.size();
    out["groups"] = d.scene.groups.size();
    out["instances"] = d.scene.instances.size();
    return out;
}

py::object bounds_view(const SceneDescription& d) {
    const std::optional<Bounds3> box = scene_bounds(d.scene);
    if (!box) return py::none();
    return py::make_tuple(vec3_tuple(box->lower), vec3_tuple(box->upper));
}

py::dict settings_view(const SceneDescription& d) {
    py::dict out;
    for (const auto& [label, value] : describe_settings(d.settings)) out[py::str(label)] = value;
    return out;
}

// Forwards the render's tiles to a film and counts the pixels done, for the progress callback.
class CountingFilm : public TileSink {
  public:
    CountingFilm(int width, int height) : m_film(width, height) {}
    void write_tile(const Tile& tile, const float* rgba) override {
        m_film.write_tile(tile, rgba);
        m_pixels.fetch_add(static_cast<uint64_t>(tile.width) * tile.height);
    }
    uint64_t pixels() const { return m_pixels.load(); }
    Film& film() { return m_film; }

  private:
    Film m_film;
    std::atomic<uint64_t> m_pixels{0};
};

py::dict render_stats(const SceneDescription& d, double parse_seconds, const RenderResult& r) {
    const RayCounters& c = r.counters;
    py::dict rays;
    rays["camera"] = c.camera;
    rays["shadow"] = c.shadow;
    rays["shadow_filtered"] = c.shadow_filtered;
    rays["reflection"] = c.reflection;
    rays["refraction"] = c.refraction;
    rays["total"] = c.total_rays();
    py::dict s;
    s["width"] = d.scene.camera.width;
    s["height"] = d.scene.camera.height;
    s["spp"] = d.settings.spp;
    s["integrator"] = integrator_summary(d.settings.integrator);
    s["threads"] = r.threads;
    s["sphere_method"] = sphere_method_name(r.spheres.spheres);
    s["sphere_math"] = sphere_math_name(r.spheres.math);
    s["sphere_method_reason"] = r.spheres.reason;
    // `rayo render --stats`'s "shape method" lines: the objects' methods, then those the reader
    // chose (voxel grids, height fields).
    std::vector<std::string> shape_methods = shape_method_lines(r.shapes);
    shape_methods.insert(shape_methods.end(), d.method_choices.begin(), d.method_choices.end());
    s["shape_methods"] = shape_methods;
    s["coherent"] = r.coherent;
    s["primitives"] = r.primitives;
    s["parse_seconds"] = parse_seconds;
    s["bvh_seconds"] = r.bvh_seconds;
    s["render_seconds"] = r.render_seconds;
    s["rays"] = rays;
    s["total_internal_reflections"] = c.total_internal_reflections;
    s["paths_cut_by_depth"] = c.depth_cut;
    s["paths_cut_by_contribution"] = c.contribution_cut;
    s["mrays_per_second"] = r.render_seconds > 0 ? c.total_rays() / r.render_seconds / 1e6 : 0.0;
    if (r.radiosity) {
        s["radiosity_patches"] = r.radiosity_patches;
        s["radiosity_shots"] = r.radiosity_stats.shots;
        s["radiosity_seconds"] = r.radiosity_stats.seconds;
    }
    return s;
}

PyScene load(const std::optional<std::string>& path, const py::kwargs& keywords) {
    const std::vector<std::string> words = option_words(keywords, OptionUse::Load, "load");
    py::gil_scoped_release unlocked;
    const auto start = std::chrono::steady_clock::now();
    auto d = std::make_shared<const SceneDescription>(load_scene_with_options(path, words));
    return PyScene{d, seconds_since(start)};
}

PyScene from_json(const std::string& text, const std::string& base_dir, const std::string& name) {
    py::gil_scoped_release unlocked;
    const auto start = std::chrono::steady_clock::now();
    auto d = std::make_shared<const SceneDescription>(load_json_string(text, name, base_dir));
    return PyScene{d, seconds_since(start)};
}

// Runs `work` on a thread of its own while this one, holding the interpreter's lock only briefly,
// watches for Ctrl-C and calls `progress` with the fraction done. On Ctrl-C (KeyboardInterrupt)
// or an exception from `progress`, the work is asked to stop at its next tile or study step and
// waited for with the lock released (waiting with it held, as the future's destructor would,
// blocks every Python thread until the work ends on its own), the stop request is withdrawn for
// the next call, and the exception goes on to the caller.
template <typename Result, typename Work>
Result run_interruptible(Work work, const std::function<double()>& fraction,
                         const py::object& progress) {
    std::future<Result> running;
    {
        py::gil_scoped_release unlocked;
        running = std::async(std::launch::async, std::move(work));
    }
    double shown = -1.0;
    try {
        while (true) {
            std::future_status status;
            {
                py::gil_scoped_release unlocked;
                status = running.wait_for(std::chrono::milliseconds(50));
            }
            if (status == std::future_status::ready) break;
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            if (!progress.is_none() && fraction() != shown) {
                shown = fraction();
                progress(shown);
            }
        }
    } catch (...) {
        request_stop(SIGINT);
        {
            py::gil_scoped_release unlocked;
            running.wait();
        }
        request_stop(0);  // the next render starts afresh
        throw;            // the work's own outcome (cut short by the stop) is dropped
    }
    Result result = running.get();
    if (!progress.is_none() && shown != 1.0) progress(1.0);
    return result;
}

py::tuple render(const PyScene& scene, const py::object& progress, const py::kwargs& keywords) {
    const std::vector<std::string> words = option_words(keywords, OptionUse::Render, "render");
    auto d = std::make_shared<SceneDescription>(*scene.description);
    const int threads = apply_render_options(words, *d);
    const CameraDesc& camera = d->scene.camera;
    check_film_size(camera.width, camera.height, d->source + "#/camera");
    auto film = std::make_shared<CountingFilm>(camera.width, camera.height);
    const double pixels = static_cast<double>(camera.width) * camera.height;
    const RenderResult result = run_interruptible<RenderResult>(
        [d, film, threads, pixels] {
            RenderResult r = render_scene(*d, threads, false, film.get());
            if (film->pixels() != pixels) {
                throw RenderStopped("rayo.render: stopped by a stop request (Ctrl-C) with " +
                                    std::to_string(film->pixels()) + " of " +
                                    std::to_string(static_cast<uint64_t>(pixels)) +
                                    " pixels rendered");
            }
            return r;
        },
        [film, pixels] { return film->pixels() / pixels; }, progress);
    py::array_t<float> image({camera.height, camera.width, 4});
    const std::vector<float>& rgba = film->film().rgba();
    std::copy(rgba.begin(), rgba.end(), image.mutable_data());
    return py::make_tuple(image, render_stats(*d, scene.parse_seconds, result));
}

void write_array(const py::array_t<float, py::array::c_style | py::array::forcecast>& image,
                 const std::string& path, const py::kwargs& keywords) {
    OutputOptions options = output_options_from(option_words(keywords, OptionUse::Output, "write"));
    if (image.ndim() != 3 || (image.shape(2) != 4 && image.shape(2) != 3)) {
        throw UsageError("image: expected an array of height × width × 4 (RGBA) or × 3 (RGB)");
    }
    const int height = static_cast<int>(image.shape(0)), width = static_cast<int>(image.shape(1));
    const int channels = static_cast<int>(image.shape(2));
    check_film_size(width, height, "image");
    Film film(width, height);
    const float* source = image.data();
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x, source += channels) {
            film.set(x, y, Vec3(source[0], source[1], source[2]), channels == 4 ? source[3] : 1.0f);
        }
    }
    options.metadata["rayo:written_by"] = "rayo Python module";
    py::gil_scoped_release unlocked;
    check_output(path, options);
    write_image(film, path, options);
}

// An image file's pixels as float32, height × width × channels (EXR as stored: linear).
py::array_t<float> read_array(const std::string& path) {
    std::vector<float> pixels;
    int width = 0, height = 0, channels = 0;
    {
        py::gil_scoped_release unlocked;
        OpenedImageFile file = open_image_file(path, path, "image", FileAccess{});
        width = file.reader->width();
        height = file.reader->height();
        channels = file.reader->channels();
        pixels.resize(static_cast<size_t>(width) * height * channels);
        if (!file.reader->read_floats(channels, pixels.data())) {
            throw InputError(path, "image does not decode: " + file.reader->error());
        }
    }
    py::array_t<float> image({height, width, channels});
    std::copy(pixels.begin(), pixels.end(), image.mutable_data());
    return image;
}

py::list options_view() {
    py::list out;
    for (const RenderOptionInfo& o : option_list()) {
        if (o.use == OptionUse::Command) continue;
        py::dict entry;
        entry["keyword"] = keyword_of_flag(o.flag);
        entry["flag"] = o.flag;
        entry["function"] = function_of_use(o.use);
        entry["switch"] = !o.takes_value;
        entry["help"] = o.help;
        out.append(entry);
    }
    return out;
}

py::dict error_dict(const ImageError& e) {
    py::dict out;
    out["rmse"] = e.rmse;
    out["max_abs"] = e.max_abs;
    out["pixels_differing_percent"] = e.pixels_differing;
    out["silhouette_wrong_percent"] = e.silhouette_wrong;
    return out;
}

// An integer argument of a study, checked with the bounds and message of its command-line flag.
int study_int(const char* flag, int value, IntRange range) {
    return parse_int_flag(flag, std::to_string(value), range);
}

py::list accuracy_rows(const std::vector<AccuracyRow>& rows) {
    py::list out;
    for (const AccuracyRow& r : rows) {
        py::dict row;
        row["scene"] = r.scene;
        row["method"] = r.method;
        row["math"] = r.math;
        row["auto"] = r.is_auto;
        row["seconds"] = r.seconds;
        row["primitives"] = r.primitives;
        row.attr("update")(error_dict(r.error));
        out.append(row);
    }
    return out;
}

py::list shape_method_rows(const std::vector<ShapeMethodRow>& rows) {
    py::list out;
    for (const ShapeMethodRow& r : rows) {
        py::dict row;
        row["shape"] = r.shape;
        row["form"] = r.form;
        row["budget_px"] = r.budget_px;
        row["auto"] = r.is_auto;
        row["triangles"] = r.triangles;
        row["embree_bytes"] = r.bytes;
        row["build_seconds"] = r.build_seconds;
        row["ns_per_ray_coherent"] = r.ns_coherent;
        row["ns_per_ray_single"] = r.ns_single;
        row["chord_px"] = r.chord_px;
        row["max_error_px"] = r.max_error_px;
        row["silhouette_pct"] = r.silhouette_pct;
        out.append(row);
    }
    return out;
}

// `rayo bench accuracy`: the sphere-method study and the shape-method study (or the one `only`
// names, as --only does), each run to the end before any file is written: a Ctrl-C during them
// leaves no file (bench/lab/study_stop.h).
py::dict bench_accuracy(const std::optional<std::string>& output, int size,
                        const std::optional<std::string>& only, const py::object& progress) {
    study_int("--size", size, kAccuracySizeRange);
    if (only && *only != "spheres" && *only != "shapes") {
        throw py::value_error("only: expected 'spheres', 'shapes' or None, got '" + *only + "'");
    }
    const bool spheres = only.value_or("spheres") == "spheres";
    const bool shapes = only.value_or("shapes") == "shapes";
    struct Tables {
        std::vector<AccuracyRow> spheres;
        std::vector<ShapeMethodRow> shapes;
    };
    std::ostringstream log;
    const Tables tables = run_interruptible<Tables>(
        [output, size, spheres, shapes, &log] {
            Tables t;
            if (spheres) t.spheres = run_accuracy_study(log, size);
            if (shapes) t.shapes = run_shape_method_study(log, size);
            if (output && spheres) write_accuracy_files(*output, t.spheres, log, size);
            if (output && shapes) write_shape_method_files(*output, t.shapes, log);
            return t;
        },
        [] { return 0.0; }, progress);
    py::dict out;
    if (spheres) out["spheres"] = accuracy_rows(tables.spheres);
    if (shapes) out["shapes"] = shape_method_rows(tables.shapes);
    return out;
}

py::list bench_suite(const std::optional<std::string>& output, int size, int width,
                     const std::optional<int>& threads, const std::vector<std::string>& scenes,
                     const py::object& progress) {
    SuiteOptions options;
    if (output) options.dir = *output;
    options.size = study_int("--size", size, kSuiteSizeRange);
    options.width = study_int("--width", width, kSuiteWidthRange);
    if (threads) options.threads = study_int("--threads", *threads, kSuiteThreadsRange);
    options.only = scenes;
    std::ostringstream log;
    const std::vector<SuiteRow> rows = run_interruptible<std::vector<SuiteRow>>(
        [options, &log] {
            std::vector<SuiteRow> result = run_spd_suite(options, log);
            if (!options.dir.empty()) write_suite_files(options, result, machine_info());
            return result;
        },
        [] { return 0.0; }, progress);
    py::list out;
    for (const SuiteRow& r : rows) {
        py::dict row;
        row["scene"] = r.scene;
        row["size"] = r.size;
        row["width"] = r.width;
        row["threads"] = r.threads;
        row["primitives"] = r.primitives;
        row["rays"] = r.rays.total_rays();
        row["generate_seconds"] = r.generate_seconds;
        row["bvh_seconds"] = r.bvh_seconds;
        row["render_seconds"] = r.render_seconds;
        row["total_seconds"] = r.total_seconds;
        row["mrays_per_second"] = r.mrays_per_second;
        out.append(row);
    }
    return out;
}

// `rayo bench convergence`: the rows of its table, each a dict; with output, its files. The
// arguments take the flags' bounds and messages (apps/cli/int_flag.h).
py::list bench_convergence(const std::optional<std::string>& output,
                           const std::optional<std::string>& scene, int width, int reference_spp,
                           int max_spp, int whitted_spp,
                           const std::optional<std::vector<double>>& patch_sizes,
                           const std::optional<int>& threads, const py::object& progress) {
    ConvergenceOptions options;
    if (output) options.dir = *output;
    if (scene) options.scene = *scene;
    options.width = study_int("--width", width, kConvergenceWidthRange);
    options.reference_spp = study_int("--reference-spp", reference_spp, kConvergenceSppRange);
    options.max_spp = study_int("--max-spp", max_spp, kConvergenceSppRange);
    options.whitted_spp = study_int("--whitted-spp", whitted_spp, kConvergenceSppRange);
    check_convergence_spp(options.max_spp, options.reference_spp);
    if (patch_sizes) {
        for (const double size : *patch_sizes) {
            if (!std::isfinite(size) || size <= 0.0) {
                throw UsageError("--patch-sizes: expected numbers > 0 (scene units), got " +
                                 std::to_string(size));
            }
        }
        if (patch_sizes->empty()) throw UsageError("--patch-sizes: expected at least one size");
        options.patch_sizes = *patch_sizes;
    }
    if (threads) options.threads = study_int("--threads", *threads, kSuiteThreadsRange);
    std::ostringstream log;
    const ConvergenceStudy study = run_interruptible<ConvergenceStudy>(
        [options, &log] {
            ConvergenceStudy result = run_convergence_study(options, log);
            if (!options.dir.empty()) write_convergence_files(options, result);
            return result;
        },
        [] { return 0.0; }, progress);
    py::list out;
    for (const ConvergenceRow& r : study.rows) {
        py::dict row;
        row["scene"] = study.scene;
        row["method"] = r.method;
        row["spp"] = r.spp;
        row["patch_size"] = r.patch_size;
        row["patches"] = r.patches;
        row["render_seconds"] = r.render_seconds;
        row["solve_seconds"] = r.solve_seconds;
        row["seconds"] = r.seconds;
        row["rms_relative"] = r.rms_relative;
        row["mean_relative"] = r.mean_relative;
        row["width"] = study.width;
        row["height"] = study.height;
        row["threads"] = study.threads;
        row["reference_spp"] = study.reference_spp;
        out.append(row);
    }
    return out;
}

}  // namespace
}  // namespace rayo

PYBIND11_MODULE(rayo, m) {
    using namespace rayo;
    m.doc() = "rayo: a ray tracer (Embree, TBB, OpenImageIO, OpenColorIO). docs/python.md";
    m.attr("__version__") = RAYO_VERSION;
    // Bad input names its place (file:line or file#/JSON/pointer) and what was expected.
    py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
    // A bad option value: the same message as the command line's for its flag.
    py::register_exception<UsageError>(m, "UsageError", PyExc_ValueError);
    // A render or study cut short by a stop request (Ctrl-C, here or in another thread).
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const RenderStopped& e) {
            PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
        } catch (const StudyStopped& e) {
            PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
        }
    });

    py::class_<PyScene>(m, "Scene", "A loaded scene (read-only); rayo.render takes a copy.")
        .def_static(
            "from_json", &from_json, py::arg("text"), py::arg("base_dir") = ".",
            py::arg("name") = "<json>",
            "A scene from rayo's JSON text; relative paths resolve against base_dir; errors "
            "name `name#/pointer`.")
        .def_static(
            "from_dict",
            [](const py::dict& scene, const std::string& base_dir, const std::string& name) {
                const std::string text = py::str(py::module_::import("json").attr("dumps")(scene));
                return from_json(text, base_dir, name);
            },
            py::arg("scene"), py::arg("base_dir") = ".", py::arg("name") = "<dict>",
            "A scene from a dict of rayo's JSON format, validated as a file is.")
        .def_property_readonly("source", [](const PyScene& s) { return s.description->source; })
        .def_property_readonly("parse_seconds", [](const PyScene& s) { return s.parse_seconds; })
        .def_property_readonly("camera",
                               [](const PyScene& s) { return camera_view(*s.description); })
        .def_property_readonly("counts",
                               [](const PyScene& s) { return count_view(*s.description); })
        .def_property_readonly("lights",
                               [](const PyScene& s) {
                                   std::vector<std::string> out;
                                   for (const Light& l : s.description->shading.lights)
                                       out.push_back(describe_light(l));
                                   return out;
                               })
        .def_property_readonly("bounds",
                               [](const PyScene& s) { return bounds_view(*s.description); })
        .def_property_readonly("settings",
                               [](const PyScene& s) { return settings_view(*s.description); })
        .def_property_readonly("warnings", [](const PyScene& s) { return s.description->warnings; })
        .def("__repr__", [](const PyScene& s) {
            const CameraDesc& c = s.description->scene.camera;
            return "<rayo.Scene '" + s.description->source + "' " + std::to_string(c.width) + "x" +
                   std::to_string(c.height) + ">";
        });

    m.def("load", &load, py::arg("path") = py::none(),
          "Reads a scene file (.json, .nff, .obj, .gltf, .glb, .ply, .stl, .off) as `rayo "
          "render` does; no path: the built-in scene. Keywords: the reading options of "
          "rayo.options().");
    m.def("render", &render, py::arg("scene"), py::kw_only(), py::arg("progress") = py::none(),
          "Renders a scene: returns (image, stats), image a float32 array height × width × 4 "
          "(linear, premultiplied RGBA, as the EXR). Keywords: the render options of "
          "rayo.options() (width, "
          "spp, integrator, threads, sphere_method, ...), with the command line's bounds. "
          "progress: called with the fraction done.");
    m.def("write", &write_array, py::arg("image"), py::arg("path"),
          "Writes an image array through rayo's writers: .exr linear, .png/.tif/.jpg through the "
          "OCIO view. Keywords: display, view, range, half, exr_compression, image_writer.");
    m.def("read", &read_array, py::arg("path"),
          "An image file's pixels: a float32 array height × width × channels (EXR linear as "
          "stored; 8-bit formats as value/255).");
    m.def("options", &options_view,
          "Every keyword of rayo.load, rayo.render and rayo.write, with its flag and help.");
    m.def("bench_accuracy", &bench_accuracy, py::arg("output") = py::none(), py::kw_only(),
          py::arg("size") = kAccuracyImageSize, py::arg("only") = py::none(),
          py::arg("progress") = py::none(),
          "The studies of `rayo bench accuracy`: {'spheres': one dict per scene, sphere method "
          "and precision, with its time and its error against the double-precision reference; "
          "'shapes': one dict per shape and form (analytic, mesh per error budget) with its "
          "cost and measured error}; only='spheres' or 'shapes' runs one. With output, also "
          "their CSV files and charts. size: as --size, in [16, 4096].");
    m.def("bench_suite", &bench_suite, py::arg("output") = py::none(), py::kw_only(),
          py::arg("size") = 3, py::arg("width") = 512, py::arg("threads") = py::none(),
          py::arg("scenes") = std::vector<std::string>(), py::arg("progress") = py::none(),
          "The SPD suite (`rayo bench suite`): one dict per scene; with output, also its files. "
          "size, width, threads: as the flags, with their bounds; threads None: all cores.");
    m.def("bench_convergence", &bench_convergence, py::arg("output") = py::none(), py::kw_only(),
          py::arg("scene") = py::none(), py::arg("width") = 128, py::arg("reference_spp") = 4096,
          py::arg("max_spp") = 1024, py::arg("whitted_spp") = 256,
          py::arg("patch_sizes") = py::none(), py::arg("threads") = py::none(),
          py::arg("progress") = py::none(),
          "The convergence study (`rayo bench convergence`): path at 1, 4, 16, ... spp up to "
          "max_spp and Whitted + radiosity at patch_sizes, against a path reference of "
          "reference_spp; one dict per render (method, spp, patch_size, patches, seconds, "
          "rms_relative, mean_relative, ...). scene None: the built-in Cornell box. With output, "
          "also its files and chart. Arguments: as the flags, with their bounds; threads None: "
          "all cores.");
}
