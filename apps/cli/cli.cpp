#include "apps/cli/cli.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "apps/cli/flag_table.h"
#include "apps/cli/int_flag.h"
#include "apps/cli/render_options.h"
#include "apps/cli/setting_flags.h"
#include "apps/cli/usage_error.h"
#include "apps/mpi/mpi_tile_distribution.h"
#include "apps/mpi/mpi_world.h"
#include "apps/scene/default_scene.h"
#include "apps/scene/environment_image.h"
#include "apps/scene/input_file.h"
#include "apps/scene/preview.h"
#include "apps/scene/renderer.h"
#include "apps/scene/scene_loader.h"
#include "bench/lab/accuracy_bench.h"
#include "bench/lab/convergence_study.h"
#include "bench/lab/shape_methods_study.h"
#include "bench/lab/spd_scenes.h"
#include "bench/lab/spd_suite.h"
#include "core/error.h"
#include "core/image/image_output.h"
#include "core/image/image_writers.h"
#include "core/image/interrupt_cleanup.h"
#include "core/image/partial_render.h"
#include "core/image/pass_journal.h"
#include "core/image/tile_stream.h"
#include "core/image_library.h"
#include "core/path_util.h"
#include "core/progress.h"
#include "core/scene_bounds.h"
#include "core/stop_request.h"
#include "shading/texture.h"

namespace rayo {
namespace {

constexpr int kExitInput = 1;
constexpr int kExitUsage = 2;
// A render keeps its tiles for --resume from this many seconds on (docs/high-resolution.md,
// "Interrupt and resume"): a shorter render writes no OUTPUT.rayo-partial.
constexpr double kJournalAfterSeconds = 2.0;

// `rayo --help`: the commands and every input rayo reads (kInputs); each command's own usage
// and flags are its help (`rayo render --help`, command_help).
const char* const kOverview =
    R"(rayo — a Whitted ray tracer (Embree + TBB + OpenImageIO + OpenColorIO)

usage:
  rayo render [SCENE] [options]   render SCENE (a scene, or a model file: its own camera and
                                  lights when it has them, else framed automatically); the
                                  built-in scene without one
  rayo info SCENE                 load SCENE and print what it contains
  rayo bench accuracy -o DIR [options]
                                  the sphere- and shape-method studies: CSV and charts
                                  (gnuplot) in DIR
  rayo bench suite [options]      the seven SPD scenes as a benchmark: a table, and with -o DIR
                                  suite.csv/.json/.md and a chart (docs/performance.md)
  rayo bench convergence [SCENE] -o DIR [options]
                                  speed against accuracy of path tracing and radiosity: error
                                  against seconds, CSV and a chart (docs/path-tracing.md)
  rayo texture NAME [options]     write a procedural texture flat (the plane z = 0)
  rayo preview [SCENE] [options]  draw every object's outline from SCENE's camera, in well
                                  under a second: framing before a long render
  rayo COMMAND --help             that command's usage and options
  rayo --help | --version

)";

// The inputs, by extension (case-insensitive): in rayo --help and in the help of the commands
// that read a scene.
const char* const kInputs =
    R"(inputs (SCENE, by its extension, case-insensitive; docs/scene-format.md):
  .json                    rayo's scene format
  .nff                     Neutral File Format (the SPD scenes)
  model files, also the files a JSON "mesh" object may name; rendered with their own
  camera and lights when the file has them (glTF cameras, --camera chooses; KHR_lights_punctual;
  emissive surfaces), else framed automatically (camera, key and fill light); a ground square
  under the model (--no-ground):
  .obj                     Wavefront OBJ, with its .mtl material libraries
  .gltf, .glb              glTF 2.0, also Draco-compressed (KHR_draco_mesh_compression)
  .ply                     Stanford PLY, ASCII or binary, with vertex colours and normals
  .stl                     STL, ASCII or binary
  .off                     Object File Format

)";

const char* const kOcioNote =
    "The OCIO config is $OCIO when set, else rayo's own (sRGB display: sRGB, ACES 1.0 "
    "SDR-video, Raw).\n";

// `rayo render --help`: written from the render's options (kRenderOptions, below) and the
// declared settings.
std::string render_help();

const char* const kInfoHelp = R"(usage: rayo info SCENE
  load SCENE and print what it contains: resolution, field of view and view (eye, look_at,
  up: a model's automatic framing), objects by kind, meshes, triangles, vertices, materials,
  lights, bounds (of everything placed, instances included: the box the framing of model files
  uses) and the load's warnings (a model file without the ground square of its framing); no
  options

)";

// `rayo bench --help` and `rayo texture --help`: written from their flag tables
// (kAccuracyFlags, kSuiteFlags, kConvergenceFlags, kTextureFlags, below).
std::string bench_help();
std::string texture_help();

const char* const kPreviewHelp = R"(usage: rayo preview [SCENE] [options]
  draw every object's outline from SCENE's camera, in well under a second: framing before a
  long render

preview options (docs/preview.md):
  -o, --output FILE        output image, as for render [SCENE's name with -preview.png]
  --width W, --height H    resolution, as for render
  --over-render            draw over a darkened 1 spp render instead of black
  --threads N              worker threads for --over-render [all cores]
  --nff-light-intensity X, --display D, --view V, --quiet   as for render

)";

// rayo --help.
std::string usage() {
    return std::string(kOverview) + kInputs + kOcioNote;
}

// `rayo COMMAND --help`: the command's usage and flags (the inputs too for commands that read a
// scene).
std::string command_help(const std::string& command) {
    if (command == "render") return render_help() + "\n" + kInputs + kOcioNote;
    if (command == "info") return std::string(kInfoHelp) + kInputs;
    if (command == "bench") return bench_help();
    if (command == "preview") return std::string(kPreviewHelp) + kInputs + kOcioNote;
    if (command == "texture") return texture_help() + kOcioNote;
    return usage();  // an unknown command: the overview
}

// What --view-dir takes, for its help and its refusal.
std::string direction_expectation() {
    return "a direction X,Y,Z of finite numbers, not all zero";
}

// "X,Y,Z": a direction of three finite numbers, not all zero.
Vec3 parse_direction(const FlagValue& value) {
    Vec3 v(0.0f);
    std::istringstream in(value.text);
    char comma1 = 0, comma2 = 0;
    in >> v.x >> comma1 >> v.y >> comma2 >> v.z;
    if (!in || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() || !std::isfinite(v.x) ||
        !std::isfinite(v.y) || !std::isfinite(v.z) || v == Vec3(0.0f)) {
        refuse_flag(value, "expected " + direction_expectation() + ", got '" + value.text + "'");
    }
    return v;
}

// Walks a command's arguments: `next()` moves to the next one, `cursor.value()` takes the argument
// that follows the current flag (a UsageError when there is none).
class ArgCursor {
  public:
    explicit ArgCursor(const std::vector<std::string>& args) : m_args(args) {}
    bool next() { return ++m_index < m_args.size(); }
    const std::string& current() const { return m_args[m_index]; }
    const std::string& value() {
        if (m_index + 1 >= m_args.size()) throw UsageError(current() + ": missing value");
        return m_args[++m_index];
    }

  private:
    const std::vector<std::string>& m_args;
    size_t m_index = static_cast<size_t>(-1);
};

struct RenderArgs {
    std::optional<std::string> scene_path;
    std::optional<std::string> output;
    std::optional<int> width, height, threads;
    // The declared settings' flags (apps/cli/setting_flags.h), in order, and --integrator.
    std::vector<SettingFlag> settings;
    std::optional<std::string> integrator;
    std::optional<SphereRepresentation> sphere_method;
    std::optional<float> max_error_px;
    std::optional<ShapeMethod> shape_method;
    bool gi_view_patches = false;
    std::optional<std::string> gi_log;
    std::optional<std::string> environment;  // --environment FILE
    SceneLoadOptions load_options;
    bool flat_spheres = false;
    bool single_rays = false;
    OutputOptions output_options;
    StreamMode stream = StreamMode::Auto;
    bool resume = false;
    bool journal = true;
    std::optional<double> journal_after_s;  // --journal-after (default kJournalAfterSeconds)
    bool quiet = false;
    bool stats = false;
};

// One option of `rayo render` besides the declared settings (apps/cli/setting_flags.h): its
// spelling, the name of its value, its help, its default, its rule (bounds or choices) and what
// it does. `rayo render --help` (flags_help), parse_render_args and the refusals of bad values
// (read_flag_value) all read this one list, in its order (apps/cli/flag_table.h). An entry
// without `apply` places a declared setting's help (from its declaration); one without `help`
// shares the previous entry's line ("--width W, --height H").
struct RenderOption {
    const char* flag;
    OptionUse use = OptionUse::Render;  // a declared setting's: Render
    const char* value_name = nullptr;
    const char* help = nullptr;
    const char* default_value = nullptr;
    FlagRule rule = switch_rule();
    void (*apply)(RenderArgs&, const FlagValue&) = nullptr;
    const char* alias = nullptr;  // "-o"
};

// The most worker threads a command takes (render, preview, bench suite).
constexpr int kMaxThreads = 4096;

// --width/--height (and texture's --size) take the bounds of "camera": {"width", "height"}
// from their declaration (CameraDesc::resolution_fields), so flag and field refuse alike.
FlagRule resolution_rule(const char* name) {
    RuleFinder finder{name};
    CameraDesc().resolution_fields(finder);
    return *finder.rule;
}

const std::initializer_list<Choice<bool>> kGiViewChoices = {{"smooth", false}, {"patches", true}};
const std::initializer_list<Choice<RangeMode>> kRangeChoices = {
    {"clamp", RangeMode::Clamp}, {"normalize", RangeMode::Normalize}};
const std::initializer_list<Choice<ImageWriterChoice>> kImageWriterChoices = {
    {"direct", ImageWriterChoice::Direct}, {"oiio", ImageWriterChoice::OpenImageIO}};

// A value of a Words rule, once read_flag_value has passed it.
template <typename E>
E chosen(std::initializer_list<Choice<E>> choices, const FlagValue& v) {
    E value{};
    refuse_flag(v, read_choice(SettingValue::from_text(v.text), choices, value));
    return value;
}

const RenderOption kRenderOptions[] = {
    {"--output", OptionUse::Command, "FILE",
     "output image: .exr (linear float), .png, .tif, .jpg (display view)",
     "default: SCENE's name with .png, or default.png", text_rule(),
     [](RenderArgs& r, const FlagValue& v) { r.output = v.text; }, "-o"},
    {"--width", OptionUse::Render, "W", "resolution (one alone keeps the scene's aspect ratio)",
     nullptr, resolution_rule("width"),
     [](RenderArgs& r, const FlagValue& v) { r.width = v.integer; }},
    {"--height", OptionUse::Render, "H", nullptr, nullptr, resolution_rule("height"),
     [](RenderArgs& r, const FlagValue& v) { r.height = v.integer; }},
    {"--spp"},
    {"--threads", OptionUse::Render, "N", "worker threads", "all cores",
     integer_rule(1, kMaxThreads),
     [](RenderArgs& r, const FlagValue& v) { r.threads = v.integer; }},
    {"--nff-light-intensity", OptionUse::Load, "X", "intensity of each NFF light without a colour",
     "1/sqrt(number of lights), the SPD's rule; 1 gives unit lights", real_rule(0.0, 1e30),
     [](RenderArgs& r, const FlagValue& v) { r.load_options.nff.light_intensity = v.number; }},
    {"--view-dir", OptionUse::Load, "X,Y,Z",
     "model files: the direction from the model's centre to the eye",
     "0.6,0.45,1: front, right, above; +y is up", custom_rule(direction_expectation),
     [](RenderArgs& r, const FlagValue& v) {
         r.load_options.model.view_direction = parse_direction(v);
     }},
    {"--no-ground", OptionUse::Load, nullptr, "model files: no ground square under the model",
     nullptr, switch_rule(),
     [](RenderArgs& r, const FlagValue&) { r.load_options.model.ground = false; }},
    {"--camera", OptionUse::Load, "NAME|INDEX",
     "glTF files: the camera to use, by name or by its index in `rayo info`'s list, or auto (the "
     "automatic framing)",
     "the file's first camera, else auto; --view-dir alone chooses auto", text_rule(),
     [](RenderArgs& r, const FlagValue& v) { r.load_options.model.camera = v.text; }},
    {"--auto-lights", OptionUse::Load, nullptr,
     "model files: add the automatic key and fill lights even when the file has lights "
     "(KHR_lights_punctual) or emissive surfaces",
     nullptr, switch_rule(),
     [](RenderArgs& r, const FlagValue&) { r.load_options.model.auto_lights = true; }},
    {"--no-instances", OptionUse::Load, nullptr,
     "glTF files: flatten meshes that several nodes use instead of keeping them once as "
     "instances",
     nullptr, switch_rule(),
     [](RenderArgs& r, const FlagValue&) { r.load_options.model.instances = false; }},
    {"--environment", OptionUse::Load, "FILE",
     "an equirectangular image (HDR expected: .exr, .hdr) as the environment light, in place of "
     "the scene's; model files get no automatic lights with it (docs/path-tracing.md)",
     nullptr, text_rule(),
     [](RenderArgs& r, const FlagValue& v) {
         r.environment = v.text;
         r.load_options.model.environment_lit = true;
     }},
    {"--restrict-paths", OptionUse::Load, nullptr,
     "files the scene references (meshes, material libraries, glTF buffers) must lie in the "
     "scene's folder tree (untrusted scenes)",
     nullptr, switch_rule(),
     [](RenderArgs& r, const FlagValue&) { r.load_options.restrict_paths = true; }},
    {"--tile-size"},
    {"--sphere-method", OptionUse::Render, "M",
     "how spheres reach the hot path, as the scene's \"sphere_method\" (mesh:N: 20·4^N "
     "triangles per sphere; docs/sphere-methods.md)",
     "scene's, default auto", custom_rule(sphere_method_expectation),
     [](RenderArgs& r, const FlagValue& v) {
         SphereRepresentation method;
         refuse_flag(v, read_sphere_method(SettingValue::from_text(v.text), method));
         r.sphere_method = method;
     }},
    {"--sphere-math"},
    {"--max-error-px", OptionUse::Render, "E",
     "auto's error budget in pixels; the chord error of mesh shapes (--shape-method)", "0.5",
     real_rule(1e-6, 1e6), [](RenderArgs& r, const FlagValue& v) { r.max_error_px = v.number; }},
    {"--shape-method", OptionUse::Render, nullptr,
     "the method of every object with a mesh form (not spheres), over the scene's per-object "
     "\"method\" (the same names; docs/shape-methods.md)",
     "each object's, default analytic", words_rule(choice_words<kShapeMethodChoices>),
     [](RenderArgs& r, const FlagValue& v) { r.shape_method = chosen(kShapeMethodChoices, v); }},
    {"--flat-spheres", OptionUse::Render, nullptr,
     "mesh:N spheres with flat facets instead of smooth normals", nullptr, switch_rule(),
     [](RenderArgs& r, const FlagValue&) { r.flat_spheres = true; }},
    {"--single-rays", OptionUse::Render, nullptr,
     "trace camera and shadow rays one by one instead of as coherent Embree streams per tile "
     "(same image; for comparisons)",
     nullptr, switch_rule(), [](RenderArgs& r, const FlagValue&) { r.single_rays = true; }},
    {"--aa"},
    {"--aa-threshold"},
    {"--aa-depth"},
    {"--gi"},
    {"--gi-view", OptionUse::Render, nullptr,
     "radiosity: the solution as vertex colours (smooth) or flat patches", "smooth",
     words_rule(choice_words<kGiViewChoices>),
     [](RenderArgs& r, const FlagValue& v) { r.gi_view_patches = chosen(kGiViewChoices, v); }},
    {"--gi-log", OptionUse::Command, "FILE",
     "radiosity: write the unshot energy after every shot (CSV)", nullptr, text_rule(),
     [](RenderArgs& r, const FlagValue& v) { r.gi_log = v.text; }},
    {"--texture-cache"},
    {"--texture-filter"},
    {"--display", OptionUse::Output, "D", "OCIO display and view for PNG/TIFF/JPEG",
     "config defaults", text_rule(),
     [](RenderArgs& r, const FlagValue& v) { r.output_options.display = v.text; }},
    {"--view", OptionUse::Output, "V", nullptr, nullptr, text_rule(),
     [](RenderArgs& r, const FlagValue& v) { r.output_options.view = v.text; }},
    {"--range", OptionUse::Output, nullptr,
     "display-referred values above 1: clamped, or normalize divides by the image maximum", "clamp",
     words_rule(choice_words<kRangeChoices>),
     [](RenderArgs& r, const FlagValue& v) { r.output_options.range = chosen(kRangeChoices, v); }},
    {"--half", OptionUse::Output, nullptr, "write EXR as half float", nullptr, switch_rule(),
     [](RenderArgs& r, const FlagValue&) { r.output_options.half_float_exr = true; }},
    {"--exr-compression", OptionUse::Output, "C",
     "EXR compression, lossless or lossy (which is which, and their costs: "
     "docs/performance.md)",
     "zip", words_rule(exr_compression_list),
     [](RenderArgs& r, const FlagValue& v) { r.output_options.exr_compression = v.text; }},
    {"--image-writer", OptionUse::Output, "W",
     "what writes PNG and EXR: libpng and OpenEXR directly, or OpenImageIO (the reference "
     "writer, loaded as the image module: ~0.25 s more; docs/performance.md)",
     "direct", words_rule(choice_words<kImageWriterChoices>),
     [](RenderArgs& r, const FlagValue& v) {
         r.output_options.writer = chosen(kImageWriterChoices, v);
     }},
    {"--stream", OptionUse::Command, nullptr,
     "write the file as tiles finish, in memory that does not grow with the image (tiled EXR; "
     "PNG/TIFF/JPEG rows in order), or hold the whole image and write it at the end",
     "stream above 1024x1024; docs/high-resolution.md", switch_rule(),
     [](RenderArgs& r, const FlagValue&) { r.stream = StreamMode::Always; }},
    {"--no-stream", OptionUse::Command, nullptr, nullptr, nullptr, switch_rule(),
     [](RenderArgs& r, const FlagValue&) { r.stream = StreamMode::Never; }},
    {"--resume", OptionUse::Command, nullptr,
     "continue the interrupted render of the same output: render only the tiles missing from "
     "OUTPUT.rayo-partial (same scene and settings; docs/high-resolution.md)",
     nullptr, switch_rule(), [](RenderArgs& r, const FlagValue&) { r.resume = true; }},
    {"--no-journal", OptionUse::Command, nullptr,
     "keep no OUTPUT.rayo-partial: Ctrl-C ends at once, not resumable", nullptr, switch_rule(),
     [](RenderArgs& r, const FlagValue&) { r.journal = false; }},
    {"--journal-after", OptionUse::Command, "S",
     "keep tiles in OUTPUT.rayo-partial from S seconds into the render on: shorter renders write "
     "none, an interrupt loses at most S seconds of work; 0 keeps every tile",
     "2", real_rule(0.0, 1e6),
     [](RenderArgs& r, const FlagValue& v) { r.journal_after_s = v.number; }},
    {"--quiet", OptionUse::Command, nullptr, "no progress bar and no summary line", nullptr,
     switch_rule(), [](RenderArgs& r, const FlagValue&) { r.quiet = true; }, "-q"},
    {"--stats", OptionUse::Command, nullptr, "print the full statistics table", nullptr,
     switch_rule(), [](RenderArgs& r, const FlagValue&) { r.stats = true; }},
    {"--integrator", OptionUse::Render, "NAME", "the integrator, one of the list below",
     "scene's, default whitted", text_rule(),
     [](RenderArgs& r, const FlagValue& v) {
         integrator_flag(v.text);
         r.integrator = v.text;
     }},
};

const RenderOption* render_option(const std::string& flag) {
    return find_flag(kRenderOptions, flag);
}

std::string render_help() {
    std::string out =
        "usage: rayo render [SCENE] [options]\n  render SCENE; the built-in scene without "
        "one\n\nrender options:\n";
    std::set<std::string> placed;
    out += flags_help(kRenderOptions, [&](const RenderOption& o) {
        placed.insert(o.flag);
        return setting_help(o.flag);
    });
    // A declared render setting the list does not place still has its line.
    for (const std::string& flag : render_setting_flags()) {
        if (!placed.count(flag)) out += setting_help(flag);
    }
    return out + "\n" + integrators_help();
}

// `rayo texture NAME [options]` (seed 003 ch. 3 maps).
struct TextureArgs {
    std::optional<std::string> name, output;
    int width = 512, height = 512;
    std::optional<float> scale;
    uint32_t seed = 0;
};

// What --size takes: WxH, each side within the declared image bounds (as --width/--height).
std::string texture_size_expectation() {
    return "WxH, each " + rule_text(resolution_rule("width"), nullptr);
}

const CommandFlag<TextureArgs> kTextureFlags[] = {
    {"--output", "-o", "FILE", "output image, as for render", "NAME.png", text_rule(),
     [](TextureArgs& t, const FlagValue& v) { t.output = v.text; }},
    {"--size", nullptr, "WxH", "image size in pixels (64 pixels per world unit)", "512x512",
     custom_rule(texture_size_expectation),
     [](TextureArgs& t, const FlagValue& v) {
         const size_t x = v.text.find('x');
         if (x == std::string::npos) {
             refuse_flag(v, "expected " + texture_size_expectation() + ", got '" + v.text + "'");
         }
         t.width = read_flag_value(v.flag + " width", resolution_rule("width"), v.text.substr(0, x))
                       .integer;
         t.height =
             read_flag_value(v.flag + " height", resolution_rule("height"), v.text.substr(x + 1))
                 .integer;
     }},
    {"--scale", nullptr, "S", "world units per feature", "1: the seed's 64-pixel cells",
     real_rule(1e-6, 1e6), [](TextureArgs& t, const FlagValue& v) { t.scale = v.number; }},
    {"--seed", nullptr, "N", "the seed of the noise textures' hash", "0",
     integer_rule(0, std::numeric_limits<int32_t>::max()),
     [](TextureArgs& t, const FlagValue& v) { t.seed = static_cast<uint32_t>(v.integer); }},
};

std::string texture_help() {
    return "usage: rayo texture NAME [options]\n"
           "  write a procedural texture flat (the plane z = 0)\n\n"
           "texture NAME is one of (docs/textures.md):\n  " +
           texture_kind_list() + "\ntexture options:\n" + flags_help(kTextureFlags) + "\n";
}

// `rayo bench accuracy`: the sphere- and shape-method studies, or one of them.
enum class Study { Both, Spheres, Shapes };
const std::initializer_list<Choice<Study>> kStudyChoices = {{"spheres", Study::Spheres},
                                                            {"shapes", Study::Shapes}};

struct AccuracyArgs {
    std::optional<std::string> dir;
    int size = kAccuracyImageSize;
    Study only = Study::Both;
};

const CommandFlag<AccuracyArgs> kAccuracyFlags[] = {
    {"--output", "-o", "DIR", "write the CSV files and charts (gnuplot) there (required)", nullptr,
     text_rule(), [](AccuracyArgs& a, const FlagValue& v) { a.dir = v.text; }},
    {"--size", nullptr, "N", "scenes of N×N pixels", "384",
     integer_rule(kAccuracySizeRange.min, kAccuracySizeRange.max),
     [](AccuracyArgs& a, const FlagValue& v) { a.size = v.integer; }},
    {"--only", nullptr, nullptr, "only the sphere-method or the shape-method study", nullptr,
     words_rule(choice_words<kStudyChoices>),
     [](AccuracyArgs& a, const FlagValue& v) { a.only = chosen(kStudyChoices, v); }},
};

// `rayo bench suite`: the SPD scenes as a benchmark (bench/lab/spd_suite.h).
struct SuiteArgs {
    SuiteOptions options;
    bool write_nff = false;
    bool size_given = false;
};

// --procedure: the SPD's testing procedure (bench/lab/spd_procedure.h).
std::vector<std::string> suite_procedure_words() {
    return {"spd"};
}

// What --scenes takes: names of the suite's scenes (bench/lab/spd_scenes.h), comma-separated.
std::string suite_scenes_expectation() {
    std::string names;
    for (const std::string& n : spd_scene_names()) names += (names.empty() ? "" : ",") + n;
    return "a comma-separated list of " + names;
}

const CommandFlag<SuiteArgs> kSuiteFlags[] = {
    {"--output", "-o", "DIR", "write the files there (and --povray's scenes and logs)", nullptr,
     text_rule(), [](SuiteArgs& s, const FlagValue& v) { s.options.dir = v.text; }},
    {"--size", nullptr, "N", "SPD size of every scene", "3",
     integer_rule(kSuiteSizeRange.min, kSuiteSizeRange.max),
     [](SuiteArgs& s, const FlagValue& v) {
         s.options.size = v.integer;
         s.size_given = true;
     }},
    {"--procedure", nullptr, nullptr,
     "the SPD's testing procedure: every database at its default size, rays through the pixel "
     "corners, depth 5, no adaptive cutoff; ray counts beside the SPD Readme's, exit 1 when one "
     "is more than 10% off (docs/performance.md)",
     nullptr, words_rule(suite_procedure_words),
     [](SuiteArgs& s, const FlagValue&) { s.options.spd_procedure = true; }},
    {"--repetitions", nullptr, "N",
     "render each scene N times: times as median (min-max), and "
     "suite.json's aggregates",
     "1", integer_rule(kSuiteRepetitionsRange.min, kSuiteRepetitionsRange.max),
     [](SuiteArgs& s, const FlagValue& v) { s.options.repetitions = v.integer; }},
    {"--width", nullptr, "W", "images of W×W pixels", "512",
     integer_rule(kSuiteWidthRange.min, kSuiteWidthRange.max),
     [](SuiteArgs& s, const FlagValue& v) { s.options.width = v.integer; }},
    {"--threads", nullptr, "N", "worker threads", "all cores",
     integer_rule(kSuiteThreadsRange.min, kSuiteThreadsRange.max),
     [](SuiteArgs& s, const FlagValue& v) { s.options.threads = v.integer; }},
    {"--scenes", nullptr, "A,B", "only these scenes", nullptr,
     custom_rule(suite_scenes_expectation),
     [](SuiteArgs& s, const FlagValue& v) {
         const std::vector<std::string>& known = spd_scene_names();
         std::istringstream list(v.text);
         for (std::string name; std::getline(list, name, ',');) {
             if (std::find(known.begin(), known.end(), name) == known.end()) {
                 refuse_flag(v, "expected " + suite_scenes_expectation() + ", got '" + v.text +
                                    "' ('" + name + "')");
             }
             s.options.only.push_back(name);
         }
     }},
    {"--povray", nullptr, nullptr,
     "also time POV-Ray 3.7 on the same scenes (its files in DIR, or in a temporary folder "
     "without -o)",
     nullptr, switch_rule(), [](SuiteArgs& s, const FlagValue&) { s.options.povray = true; }},
    {"--write-nff", nullptr, nullptr, "write DIR/NAME_SIZE.nff for each scene instead of rendering",
     nullptr, switch_rule(), [](SuiteArgs& s, const FlagValue&) { s.write_nff = true; }},
};

// `rayo bench convergence`: path tracing against radiosity, error against seconds
// (bench/lab/convergence_study.h).
static_assert(kConvergenceSppRange.max == kMaxSpp, "--reference-spp takes render.spp's bounds");

std::string patch_sizes_expectation() {
    return "a comma-separated list of numbers > 0 (scene units)";
}

const CommandFlag<ConvergenceOptions> kConvergenceFlags[] = {
    {"--output", "-o", "DIR", "write the files and the chart there (required)", nullptr,
     text_rule(), [](ConvergenceOptions& c, const FlagValue& v) { c.dir = v.text; }},
    {"--width", nullptr, "N", "images N pixels wide, as high as the scene's aspect says", "128",
     integer_rule(kConvergenceWidthRange.min, kConvergenceWidthRange.max),
     [](ConvergenceOptions& c, const FlagValue& v) { c.width = v.integer; }},
    {"--reference-spp", nullptr, "N", "samples per pixel of the path-traced reference", "4096",
     integer_rule(kConvergenceSppRange.min, kConvergenceSppRange.max),
     [](ConvergenceOptions& c, const FlagValue& v) { c.reference_spp = v.integer; }},
    {"--max-spp", nullptr, "N",
     "path at 1, 4, 16, ... samples per pixel up to N (below --reference-spp)", "1024",
     integer_rule(kConvergenceSppRange.min, kConvergenceSppRange.max),
     [](ConvergenceOptions& c, const FlagValue& v) { c.max_spp = v.integer; }},
    {"--whitted-spp", nullptr, "N", "samples per pixel of the Whitted + radiosity renders", "256",
     integer_rule(kConvergenceSppRange.min, kConvergenceSppRange.max),
     [](ConvergenceOptions& c, const FlagValue& v) { c.whitted_spp = v.integer; }},
    {"--patch-sizes", nullptr, "A,B,...", "radiosity patch sizes",
     "the scene's patch_size x 4, 2, 1, or its bounds' diagonal / 4, 8, 16",
     custom_rule(patch_sizes_expectation),
     [](ConvergenceOptions& c, const FlagValue& v) {
         std::istringstream list(v.text);
         c.patch_sizes.clear();
         for (std::string item; std::getline(list, item, ',');) {
             char* end = nullptr;
             const double size = std::strtod(item.c_str(), &end);
             if (item.empty() || *end != '\0' || !std::isfinite(size) || size <= 0.0) {
                 refuse_flag(v, "expected " + patch_sizes_expectation() + ", got '" + v.text + "'");
             }
             c.patch_sizes.push_back(size);
         }
         if (c.patch_sizes.empty()) {
             refuse_flag(v, "expected " + patch_sizes_expectation() + ", got '" + v.text + "'");
         }
     }},
    {"--threads", nullptr, "N", "worker threads", "all cores",
     integer_rule(kSuiteThreadsRange.min, kSuiteThreadsRange.max),
     [](ConvergenceOptions& c, const FlagValue& v) { c.threads = v.integer; }},
};

std::string bench_help() {
    return "usage: rayo bench accuracy -o DIR [options]\n"
           "       rayo bench suite [options]\n"
           "       rayo bench convergence [SCENE] -o DIR [options]\n\n"
           "bench accuracy options (docs/stability.md, docs/shape-methods.md):\n" +
           flags_help(kAccuracyFlags) + "\nbench suite options:\n" + flags_help(kSuiteFlags) +
           "\nbench convergence (docs/path-tracing.md, \"Convergence\"): the path integrator at 1, "
           "4, 16, ...\nsamples per pixel and Whitted + radiosity at three patch sizes, each "
           "measured against a\npath-traced reference: RMS error / the reference's mean "
           "luminance against seconds\n(render + radiosity solve). SCENE: any scene or model "
           "file; without one, the Cornell\nbox of scenes/cornell_box.json (built in).\n"
           "bench convergence options:\n" +
           flags_help(kConvergenceFlags) + "\n";
}

const char* option_use_text(OptionUse use) {
    switch (use) {
        case OptionUse::Load:
            return "an option of reading the scene";
        case OptionUse::Render:
            return "an option of the render";
        case OptionUse::Output:
            return "an option of writing the image";
        case OptionUse::Command:
            return "an option of the command line only";
    }
    return "";
}

// `rayo render`'s arguments; with `only`, an option of another use is a UsageError (the library
// callers of apps/cli/render_options.h).
RenderArgs parse_render_args(const std::vector<std::string>& args,
                             std::optional<OptionUse> only = std::nullopt) {
    RenderArgs r;
    ArgCursor cursor(args);
    auto check_use = [&](const std::string& flag, OptionUse use) {
        if (only && use != *only) {
            throw UsageError(flag + ": " + option_use_text(use) + ", not " +
                             option_use_text(*only));
        }
    };
    while (cursor.next()) {
        const std::string& a = cursor.current();
        if (const FlagArity arity = setting_flag_arity(a); arity != FlagArity::None) {
            check_use(a, OptionUse::Render);
            SettingFlag flag{a, arity == FlagArity::Value ? cursor.value() : std::string()};
            check_setting_flag(flag);  // refused here, before the scene is read
            r.settings.push_back(std::move(flag));
        } else if (const RenderOption* option = render_option(a)) {
            check_use(a, option->use);
            const bool takes_value = option->rule.kind != FlagRule::Kind::Switch;
            option->apply(
                r, read_flag_value(a, option->rule, takes_value ? cursor.value() : std::string()));
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option '" + a + "' (see rayo render --help)");
        } else if (!r.scene_path) {
            r.scene_path = a;
        } else {
            throw UsageError("unexpected argument '" + a + "': only one scene per render");
        }
    }
    return r;
}

void apply_environment(const RenderArgs& args, SceneDescription& d);

// Command-line values override the scene's. One of width/height alone keeps the aspect ratio.
void apply_overrides(const RenderArgs& args, SceneDescription& d) {
    CameraDesc& camera = d.scene.camera;
    if (args.width && args.height) {
        camera.width = *args.width;
        camera.height = *args.height;
    } else if (args.width || args.height) {
        const double aspect = static_cast<double>(camera.width) / camera.height;
        if (args.width) {
            camera.width = *args.width;
            camera.height = std::max(1, static_cast<int>(std::lround(*args.width / aspect)));
        } else {
            camera.height = *args.height;
            camera.width = std::max(1, static_cast<int>(std::lround(*args.height * aspect)));
        }
    }
    apply_setting_flags(args.integrator, args.settings, d.settings);
    if (args.sphere_method) d.settings.spheres = *args.sphere_method;
    if (args.flat_spheres) d.settings.spheres.mesh_smooth = false;
    if (args.single_rays) d.settings.coherent = false;
    if (args.max_error_px) d.settings.max_error_px = *args.max_error_px;
    if (args.shape_method) d.settings.shape_method = *args.shape_method;
    if (args.gi_view_patches) d.settings.gi_view_patches = true;
    apply_environment(args, d);
}

// --environment FILE: in place of the scene's environment light, or added.
void apply_environment(const RenderArgs& args, SceneDescription& d) {
    if (args.environment) {
        EnvironmentLight environment;
        FileAccess logged;
        logged.keep_log();
        environment.map = read_environment_image(*args.environment, "--environment", logged);
        for (InputFileRecord& r : logged.log()) d.input_files.push_back(std::move(r));
        if (d.shading.environment >= 0) {
            d.shading.lights[size_t(d.shading.environment)] = environment;
        } else {
            d.shading.environment = static_cast<int32_t>(d.shading.lights.size());
            if (d.light_names.size() == d.shading.lights.size()) {
                d.light_names.push_back("environment");
            }
            d.shading.lights.push_back(environment);
        }
    }
}

std::string default_output_path(const RenderArgs& args) {
    if (!args.scene_path) return "default.png";
    return std::filesystem::path(*args.scene_path).stem().string() + ".png";
}

std::string human_count(double n) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(n >= 1e9 ? 2 : 1);
    if (n >= 1e9) {
        s << n / 1e9 << "G";
    } else if (n >= 1e6) {
        s << n / 1e6 << "M";
    } else if (n >= 1e3) {
        s << n / 1e3 << "k";
    } else {
        s << std::setprecision(0) << n;
    }
    return s.str();
}

// "3 spheres, 0 cones, 0 disks, 0 boxes, 12 triangles".
std::string shape_summary(const Scene& scene) {
    std::string text;
    for (const auto& [name, count] : scene.shape_counts()) {
        text += std::to_string(count) + " " + name + ", ";
    }
    return text + std::to_string(scene.triangle_count()) + " triangles";
}

// "stratified, 4 spp" or "adaptive, threshold 0.3, depth 3".
std::string aa_summary(const RenderSettings& s) {
    std::ostringstream text;
    if (s.aa == AntiAliasing::Adaptive) {
        text << "adaptive, threshold " << s.adaptive.threshold << ", depth " << s.adaptive.depth;
    } else if (s.aa == AntiAliasing::Corners) {
        text << "corners, the four of each pixel averaged";
    } else {
        text << "stratified, " << s.spp << " spp";
    }
    return text.str();
}

// "64spp (16 passes, noise 1.92%, stopped by the noise target)": a progressive render's
// samples per pixel and why it stopped (core/progressive.h).
std::string progressive_summary(const ProgressiveResult& p) {
    std::ostringstream text;
    text << p.spp << "spp (" << p.passes << (p.passes == 1 ? " pass" : " passes");
    if (!std::isnan(p.noise)) {
        text.precision(2);
        text << ", noise " << std::fixed << p.noise * 100.0 << "%";
    }
    text << ", stopped by " << progressive_stop_name(p.stop) << ")";
    return text.str();
}

// What decides the pixels of a render (core/image/partial_render.h): a resumed render must
// match it. Threads, streaming, --single-rays (the same bits by design) and the output's
// encoding (applied to the saved floats at the end) may change between runs.
RenderFingerprint render_fingerprint(const RenderArgs& args, const SceneDescription& d) {
    std::string contents = "the built-in scene";
    if (args.scene_path) {
        std::string bytes =
            read_input_file(*args.scene_path, *args.scene_path, "scene file", kMaxSceneFileBytes);
        const size_t size = bytes.size();
        bytes.resize((size + 7) / 8 * 8, '\0');
        std::ostringstream text;
        text << size << " bytes, checksum " << std::hex << checksum64(bytes.data(), bytes.size());
        contents = text.str();
    }
    const RenderSettings& s = d.settings;
    std::ostringstream light;
    if (args.load_options.nff.light_intensity) {
        light << *args.load_options.nff.light_intensity;
    } else {
        light << "default";
    }
    auto text = [](auto value) {
        std::ostringstream out;
        out << value;
        return out.str();
    };
    std::ostringstream framing;  // model files only (--view-dir, --no-ground)
    const ModelFraming& model = args.load_options.model;
    if (model.view_direction) {
        framing << "view " << model.view_direction->x << "," << model.view_direction->y << ","
                << model.view_direction->z;
    } else {
        framing << "default view";
    }
    framing << (model.ground ? ", ground" : ", no ground");
    if (model.camera) framing << ", camera " << *model.camera;
    if (model.auto_lights) framing << ", auto lights";
    if (!model.instances) framing << ", no instances";
    if (args.environment) framing << ", environment " << *args.environment;
    std::vector<std::pair<std::string, std::string>> entries = {
        {"rayo version", RAYO_VERSION},
        {"scene contents", contents},
        {"resolution",
         std::to_string(d.scene.camera.width) + "x" + std::to_string(d.scene.camera.height)},
        {"sphere method", sphere_method_name(s.spheres) + (s.spheres.mesh_smooth ? "" : " flat")},
        {"max error px", text(s.max_error_px)},
        {"gi view", s.gi_view_patches ? "patches" : "smooth"},
        {"nff light intensity", light.str()},
        {"shape method", s.shape_method ? shape_method_name(*s.shape_method) : "per object"},
        {"model framing", framing.str()},
    };
    // The declared settings (spp, antialiasing, the integrator and its own, ...).
    for (auto& entry : describe_settings(s)) entries.push_back(std::move(entry));
    // Every file the scene referenced (meshes, textures, images, ...), by size and modification
    // time: a resume after one changed would mix the old and the new in one image.
    for (const InputFileRecord& file : d.input_files) {
        entries.push_back({"file " + file.path, std::to_string(file.bytes) + " bytes, modified " +
                                                    std::to_string(file.modified_ns) + " ns"});
    }
    return entries;
}

// Destroys a stream whose render was interrupted, which removes its temporary file. Closing
// an unfinished PNG makes libpng print "No IDATs written into file" on stderr: the file is
// thrown away, so stderr is muted meanwhile (the workers are idle: nothing else prints).
void discard_unfinished(std::unique_ptr<TileStream>& stream) {
    if (!stream) return;
    std::fflush(stderr);
    const int saved = ::dup(STDERR_FILENO);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved >= 0 && null >= 0) ::dup2(null, STDERR_FILENO);
    stream.reset();
    if (saved >= 0 && null >= 0) ::dup2(saved, STDERR_FILENO);
    if (null >= 0) ::close(null);
    if (saved >= 0) ::close(saved);
}

// RAYO_TEST_INTERRUPT_PASSES=K (for tests): a progressive render raises SIGINT once K passes
// are kept, as a user's Ctrl-C would then.
void apply_test_interrupt_passes(PassJournal& journal) {
    const char* value = std::getenv("RAYO_TEST_INTERRUPT_PASSES");
    if (value == nullptr || *value == '\0') return;
    journal.interrupt_after(std::atoi(value));
}

// RAYO_TEST_INTERRUPT=K[:TERM] (for tests): the render raises SIGINT (SIGTERM) once K tiles are
// in the partial render, as a user's Ctrl-C would at that point.
void apply_test_interrupt(PartialRender& partial) {
    const char* value = std::getenv("RAYO_TEST_INTERRUPT");
    if (value == nullptr || *value == '\0') return;
    const std::string text = value;
    const size_t colon = text.find(':');
    const int tiles = std::atoi(text.substr(0, colon).c_str());
    const bool term = colon != std::string::npos && text.substr(colon + 1) == "TERM";
    if (tiles > 0) partial.raise_after(tiles, term ? SIGTERM : SIGINT);
}

// "N image(s) (M as MIP maps; E MB encoded, D MB decoded), memory U MB used, peak P MB, limit L
// MB": the MIP maps' bytes and OpenImageIO's cache together (shading/image_texture.h).
std::string texture_summary(const RenderResult& r) {
    const ImageTextureStats& t = r.textures;
    const auto mb = [](int64_t bytes) {
        std::ostringstream text;
        text << std::fixed << std::setprecision(1)
             << static_cast<double>(bytes) / (1024.0 * 1024.0);
        return text.str();
    };
    std::ostringstream text;
    text << t.textures << " image(s) (" << t.mip_mapped << " as MIP maps; " << mb(t.encoded_bytes)
         << " MB encoded, " << mb(t.image_bytes) << " MB decoded), memory " << mb(t.memory_used)
         << " MB used, peak " << mb(t.memory_peak) << " MB, limit " << std::fixed
         << std::setprecision(0) << t.limit_mb << " MB";
    return text.str();
}

}  // namespace

// One line of `rayo info` (and of --stats for a model file) about a light: its kind, then what
// the light says of itself (its describe(), shading/light_text.h).
std::string describe_light(const Light& light) {
    std::ostringstream out;
    std::visit(
        [&](const auto& l) {
            out << std::decay_t<decltype(l)>::kName;
            l.describe(out);
        },
        light);
    return out.str();
}

namespace {

// Where the camera stands and looks: "eye X Y Z, look_at X Y Z, up X Y Z" (the image's
// rayo:camera metadata, the `view` lines of `rayo info` and --stats): with the field of view,
// what another renderer needs to show the same view (scripts/model_gallery.sh).
std::string view_text(const CameraDesc& cam) {
    std::ostringstream text;
    text << "eye " << cam.eye.x << " " << cam.eye.y << " " << cam.eye.z << ", look_at "
         << cam.look_at.x << " " << cam.look_at.y << " " << cam.look_at.z << ", up " << cam.up.x
         << " " << cam.up.y << " " << cam.up.z;
    return text.str();
}

// The --stats table's times: milliseconds below a minute (measurements, bench/*.sh), else as
// the progress line's.
std::string stats_seconds(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0 || seconds >= 60.0) {
        return format_duration(seconds);
    }
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3fs", seconds);
    return buffer;
}

void print_stats_table(std::ostream& out, const SceneDescription& d, const RenderResult& r,
                       double parse_s, double write_s, bool streamed) {
    const RayCounters& c = r.counters;
    const double mrays = r.render_seconds > 0 ? c.total_rays() / r.render_seconds / 1e6 : 0.0;
    out << "statistics\n"
        << "  scene                       " << d.source << "\n"
        << "  resolution                  " << d.scene.camera.width << "x" << d.scene.camera.height
        << ", " << d.settings.spp << " spp, tile " << d.settings.tile_size << "\n"
        << "  camera                      " << projection_name(d.scene.camera.projection)
        << (d.scene.camera.lens_radius > 0.0f ? ", thin lens" : "") << "\n"
        << "  view                        " << view_text(d.scene.camera);
    if (d.scene.camera.projection == Projection::Perspective) {
        const Camera camera = Camera::create(d.scene.camera, d.source + "#/camera");
        out << ", fov " << camera.hfov_degrees() << "x" << camera.vfov_degrees() << " degrees";
    }
    out << "\n"
        << "  antialiasing                " << aa_summary(d.settings) << "\n"
        << "  threads                     " << r.threads << "\n"
        << "  sphere method               " << sphere_method_name(r.spheres.spheres) << " ("
        << sphere_math_name(r.spheres.math) << "): " << r.spheres.reason << "\n"
        << "  ray batches                 "
        << (r.coherent ? "coherent Embree streams per tile (camera, shadow)" : "single rays")
        << "\n"
        << "  primitives                  " << r.primitives << " (" << shape_summary(d.scene)
        << ")\n";
    for (const std::string& line : shape_method_lines(r.shapes)) {
        out << "  shape method                " << line << "\n";
    }
    for (const std::string& line : d.method_choices) {
        out << "  shape method                " << line << "\n";
    }
    if (r.instances > 0) {
        out << "  instances                   " << r.instances << " of " << d.scene.groups.size()
            << " group(s): " << r.stored_primitives << " primitives stored, "
            << d.scene.instanced_object_count() << " objects placed through instances\n";
    }
    out << "  materials, lights           " << d.shading.materials.size() << ", "
        << d.shading.lights.size() << "\n";
    // A model file's lights by name (the automatic key and fill, the file's, its emitters), as
    // the render used them (--view-dir turns the key and fill with the camera).
    for (size_t i = 0; i < d.light_names.size() && i < d.shading.lights.size(); ++i) {
        out << "  light " << std::left << std::setw(22) << i << std::right << "'"
            << d.light_names[i] << "' " << describe_light(d.shading.lights[i]) << "\n";
    }
    if (r.textures.textures > 0)
        out << "  image textures              " << texture_summary(r) << "\n";
    if (r.cutout_meshes > 0) {
        out << "  cutout meshes               " << r.cutout_meshes
            << " (Embree hit filters: alpha below the cutoff is no hit)\n";
    }
    out << ""
        << "  integrator                  " << integrator_summary(d.settings.integrator) << "\n"
        << "  time parse                  " << stats_seconds(parse_s) << "\n"
        << "  time BVH build              " << stats_seconds(r.bvh_seconds) << "\n"
        << "  time render                 " << stats_seconds(r.render_seconds) << "\n"
        << "  time write                  "
        << (streamed ? std::to_string(write_s) + " s after the last tile (streamed output)"
                     : stats_seconds(write_s))
        << "\n"
        << "  rays camera                 " << c.camera << "\n"
        << "  rays shadow                 " << c.shadow << "\n"
        << "  rays shadow, filtered       " << c.shadow_filtered << "\n"
        << "  rays reflection             " << c.reflection << "\n"
        << "  rays refraction             " << c.refraction << "\n"
        << "  rays total                  " << c.total_rays() << "\n"
        << "  total internal reflections  " << c.total_internal_reflections << "\n"
        << "  paths cut by depth          " << c.depth_cut << "\n"
        << "  paths cut by contribution   " << c.contribution_cut << "\n"
        << "  throughput                  " << std::fixed << std::setprecision(2) << mrays
        << " Mrays/s\n";
    // Per kind, where the integrator timed its stream calls (the path wavefront).
    const auto kind_rate = [&](const char* label, uint64_t rays, double seconds) {
        if (seconds <= 0.0) return;
        out << "  " << std::left << std::setw(28) << label << std::right << std::fixed
            << std::setprecision(2) << rays / seconds / 1e6
            << " Mrays/s per thread in Embree and hit records\n";
    };
    kind_rate("trace rate camera", c.camera, c.camera_trace_seconds);
    kind_rate("trace rate bounce", c.reflection + c.refraction, c.bounce_trace_seconds);
    kind_rate("trace rate shadow", c.shadow, c.shadow_trace_seconds);
    for (size_t rank = 0; r.processes.size() > 1 && rank < r.processes.size(); ++rank) {
        const ProcessWork& w = r.processes[rank];
        out << "  rank " << std::left << std::setw(23) << rank << std::right << w.tiles
            << " tiles, " << w.counters.total_rays() << " rays, " << std::fixed
            << std::setprecision(2)
            << (w.seconds > 0 ? w.counters.total_rays() / w.seconds / 1e6 : 0.0) << " Mrays/s\n";
    }
    if (r.radiosity) {
        const RadiosityStats& rs = r.radiosity_stats;
        out << "  radiosity patches           " << r.radiosity_patches << "\n"
            << "  radiosity shots             " << rs.shots << "\n"
            << "  radiosity unshot energy     " << std::scientific << std::setprecision(3)
            << rs.unshot_fraction << " of the emitted\n"
            << std::defaultfloat << "  radiosity form-factor rays  " << rs.form_factor_rays << "\n"
            << "  time radiosity solve        " << stats_seconds(rs.seconds) << "\n";
    }
}

// The render threads first, then, when the image written at the end needs the image module
// (core/image/image_writers.h), its load beside the work: the load holds the dynamic loader's
// lock, which creating a thread takes (docs/performance.md "Fixed costs"). render_command does
// the two apart, with the journal's and the stream's threads between them.
void start_threads_then_image_module(int threads, const std::string& output,
                                     const OutputOptions& options) {
    start_worker_threads(threads);
    if (writer_needs_image_library(output, options.writer)) preload_image_library();
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// `rayo render`, in one process or as one rank of several (`distribution` set: only rank 0
// checks and writes the output and prints; docs/distributed.md).
int render_command(const std::vector<std::string>& arg_list, std::ostream& out, std::ostream& err,
                   std::optional<MpiTileDistribution>& distribution) {
    const RenderArgs args = parse_render_args(arg_list);
    const auto total_start = std::chrono::steady_clock::now();
    auto start = total_start;
    SceneDescription d = args.scene_path ? load_scene_file(*args.scene_path, args.load_options)
                                         : make_default_scene();
    const double parse_s = seconds_since(start);
    const bool writes_image = MpiWorld::rank() == 0;
    if (!args.quiet && writes_image) {
        for (const std::string& w : d.warnings) err << "rayo: warning: " << w << "\n";
        if (args.load_options.nff.light_intensity &&
            (!args.scene_path || lower_extension(*args.scene_path) != ".nff")) {
            err << "rayo: warning: --nff-light-intensity applies to NFF scenes only; ignored\n";
        }
        const ModelFraming default_framing;
        const ModelFraming& model = args.load_options.model;
        if ((model.view_direction || model.ground != default_framing.ground || model.camera ||
             model.auto_lights != default_framing.auto_lights ||
             model.instances != default_framing.instances) &&
            (!args.scene_path || !is_model_file(*args.scene_path))) {
            err << "rayo: warning: --view-dir, --no-ground, --camera, --auto-lights and "
                   "--no-instances apply to model files only; ignored\n";
        }
    }
    apply_overrides(args, d);
    if (!args.quiet && writes_image && d.settings.gi == GlobalIllumination::Radiosity) {
        // Shape types without a tessellation (no pieces: the general quadric, blobs, CSG) only
        // occlude in the solve (docs/radiosity.md).
        d.scene.shapes.for_each([&](const auto& shapes) {
            using S = ShapeOf<decltype(shapes)>;
            if (shapes.empty()) return;
            SurfacePieces pieces;
            shapes.front().pieces(pieces);
            if (!pieces.empty()) return;
            err << "rayo: warning: radiosity: " << shapes.size() << " " << S::kName
                << "(s) have no tessellation: they occlude but neither shoot nor receive "
                   "(docs/radiosity.md)\n";
        });
        if (!d.scene.voxels.empty()) {
            err << "rayo: warning: radiosity: " << d.scene.voxels.size()
                << " voxel grid(s) are not in the solve: surface grids occlude, composite grids "
                   "are not seen (docs/voxels.md)\n";
        }
    }
    const std::string output = args.output ? *args.output : default_output_path(args);
    if (writes_image) check_output(output, args.output_options);  // before the render

    const bool progress = !args.quiet && ProgressReporter::stderr_is_terminal();
    const CameraDesc& cam = d.scene.camera;
    const bool streaming =
        choose_streaming(output, cam.width, cam.height, args.output_options, args.stream);
    const int threads = args.threads.value_or(0);
    if (MpiWorld::distributed()) {
        distribution.emplace(threads > 0 ? threads : default_thread_count());
    }
    TileDistribution* const ranks = distribution ? &*distribution : nullptr;

    OutputOptions options = args.output_options;
    options.metadata["rayo:scene"] = d.source;
    options.metadata["rayo:camera"] = view_text(cam);
    if (d.settings.aa != AntiAliasing::Stratified) {
        options.metadata["rayo:antialiasing"] = aa_summary(d.settings);
    } else {
        options.metadata["rayo:spp"] = std::to_string(d.settings.spp);
    }
    const ProgressiveSettings& progressive = d.settings.progressive;
    if (progressive.enabled()) {
        // Known only after the last pass: set again below where the file is written then.
        options.metadata["rayo:spp"] = "progressive, passes of " +
                                       std::to_string(progressive.pass_spp) + ", at most " +
                                       std::to_string(progressive.max_spp);
    }
    options.metadata["rayo:threads"] =
        std::to_string(threads > 0 ? threads : default_thread_count());
    if (MpiWorld::distributed()) options.metadata["rayo:ranks"] = std::to_string(MpiWorld::size());

    // The partial render (docs/high-resolution.md, "Interrupt and resume"): every finished tile
    // is kept on the disk until the output is complete, and the first SIGINT/SIGTERM during
    // the render stops the hand-out of tiles instead of ending rayo. Not under MPI.
    if (args.resume && MpiWorld::distributed()) {
        throw UsageError("--resume: not available under mpirun; resume in one process");
    }
    if (args.resume && !args.journal)
        throw UsageError("--resume and --no-journal exclude each other");
    if (args.journal_after_s && !args.journal)
        throw UsageError("--journal-after and --no-journal exclude each other");
    if (args.journal_after_s && args.resume) {
        throw UsageError(
            "--journal-after: a resumed render keeps every tile; the delay is for a "
            "new render");
    }
    // Every thread the render needs is started before the image module starts loading: the
    // load holds the dynamic loader's lock, which creating a thread takes (TBB's workers here,
    // the journal's and the streamed output's writer below).
    if (writes_image) start_worker_threads(threads);
    std::unique_ptr<PartialRender> partial;
    std::unique_ptr<PassJournal> passes;  // a progressive render's (core/image/pass_journal.h)
    std::vector<int> missing;
    if (args.journal && !MpiWorld::distributed()) {
        const TileGrid grid(cam.width, cam.height, d.settings.tile_size);
        const RenderFingerprint fingerprint = render_fingerprint(args, d);
        const auto keep_after = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(args.journal_after_s.value_or(kJournalAfterSeconds)));
        if (progressive.enabled()) {
            // The passes are kept, not tiles (its tiles come after the last pass): the partial
            // render only tells an interrupted render from a finished one. The stopping rule
            // does not decide a pass's pixels: a resume may change it (go on for longer).
            RenderFingerprint pass_fingerprint;
            for (const auto& entry : fingerprint) {
                if (entry.first != "time limit" && entry.first != "noise target" &&
                    entry.first != "max spp")
                    pass_fingerprint.push_back(entry);
            }
            passes = args.resume ? PassJournal::resume(output, pass_fingerprint, keep_after)
                                 : PassJournal::create(output, pass_fingerprint, keep_after);
            partial = PartialRender::create(output, grid, fingerprint, keep_after);
            apply_test_interrupt_passes(*passes);
            if (args.resume && !args.quiet) {
                err << "rayo: resuming " << passes->path() << ": " << passes->passes_kept()
                    << " passes (" << passes->spp_kept() << " spp) done\n";
            }
        } else {
            partial = args.resume ? PartialRender::resume(output, grid, fingerprint)
                                  : PartialRender::create(output, grid, fingerprint, keep_after);
            apply_test_interrupt(*partial);
            if (args.resume && !args.quiet) {
                err << "rayo: resuming " << partial->path() << ": " << partial->tiles_done()
                    << " of " << partial->tile_count() << " tiles done, "
                    << partial->missing_tiles().size() << " to render\n";
            }
        }
        missing = partial->missing_tiles();
    }

    double write_s = 0.0;
    RenderResult result;
    std::unique_ptr<TileStream> stream;
    std::optional<Film> film;
    {
        std::optional<GracefulInterrupt> graceful;
        if (partial) graceful.emplace();
        // The header is written before the first tile: no rayo:render_seconds in a streamed
        // file. Only the rank that writes the image opens it.
        TileSink* sink = nullptr;
        if (streaming && writes_image) {
            stream = TileStream::open(output, cam.width, cam.height, d.settings.tile_size, options);
            sink = stream.get();
        } else if (partial) {
            film.emplace(cam.width, cam.height);
            sink = &*film;
        }
        std::unique_ptr<TileSink> recorder;
        if (partial) recorder = partial->recording_sink(*sink);
        // The image module, when the output's writer needs it (TIFF, JPEG, --image-writer oiio;
        // core/image/image_writers.h), loads (~0.3 s, docs/performance.md "Fixed costs") while
        // the render runs; a streamed output's writer thread has started it already.
        if (writes_image && !stream && writer_needs_image_library(output, options.writer))
            preload_image_library();
        result = render_scene(d, threads, progress, recorder ? recorder.get() : sink, ranks,
                              partial ? &missing : nullptr, passes.get());
    }
    if (partial) {
        partial->flush();
        const std::string failure = partial->failure();
        if (!failure.empty() && !args.quiet) {
            err << "rayo: warning: " << failure << "; the render went on without keeping its "
                << "tiles (" << partial->tiles_done() << " of " << partial->tile_count()
                << " kept)\n";
        }
    }
    if (partial && !partial->complete()) {  // a stop request ended the hand-out of tiles
        discard_unfinished(stream);         // nothing under the output's name
        if (result.progressive) {
            err << "rayo: interrupted in pass " << result.progressive->passes + 1 << "; ";
            if (passes && passes->passes_kept() > 0) {
                err << passes->passes_kept() << " passes (" << passes->spp_kept()
                    << " spp) kept in " << passes->path() << ": resume with --resume\n";
            } else {
                err << "nothing kept (passes are kept from --journal-after seconds into a "
                       "render on)\n";
            }
            return 128 + stop_signal();
        }
        const int done = partial->tiles_done();
        err << "rayo: interrupted: " << done << " of " << partial->tile_count() << " tiles done; "
            << (done > 0 ? "resume with --resume (the tiles are kept in " + partial->path() + ")"
                         : std::string(args.journal_after_s && *args.journal_after_s == 0.0
                                           ? "nothing kept (no tile had finished)"
                                           : "nothing kept (tiles are kept from --journal-after "
                                             "seconds into a render on)"))
            << "\n";
        return 128 + stop_signal();
    }
    if (!writes_image) return 0;
    if (streaming) {
        write_s = stream->finish_seconds();
    } else {
        options.metadata["rayo:render_seconds"] = std::to_string(result.render_seconds);
        if (result.progressive) {
            options.metadata["rayo:spp"] = std::to_string(result.progressive->spp);
        }
        start = std::chrono::steady_clock::now();
        write_image(film ? *film : result.film, output, options);
        write_s = seconds_since(start);
    }
    if (partial) partial->remove();  // the output is complete
    if (passes) passes->remove();

    if (args.gi_log && result.radiosity) {
        // The chart of docs/radiosity.md: unshot energy (a fraction of the emitted) per shot.
        std::ofstream log(*args.gi_log);
        log << "shot,unshot_fraction\n" << std::setprecision(9);
        const std::vector<double>& history = result.radiosity_stats.history;
        for (size_t i = 0; i < history.size(); ++i) log << i + 1 << "," << history[i] << "\n";
        if (!log) throw std::runtime_error("--gi-log: cannot write '" + *args.gi_log + "'");
    }
    if (args.stats) print_stats_table(out, d, result, parse_s, write_s, streaming);
    if (!args.quiet) {
        const RayCounters& c = result.counters;
        const double mrays =
            result.render_seconds > 0 ? c.total_rays() / result.render_seconds / 1e6 : 0.0;
        out << "rayo: " << output << " " << cam.width << "x" << cam.height << " "
            << (d.settings.aa == AntiAliasing::Adaptive  ? "adaptive"
                : d.settings.aa == AntiAliasing::Corners ? "corners"
                : result.progressive                     ? progressive_summary(*result.progressive)
                                                         : std::to_string(d.settings.spp) + "spp")
            << (d.settings.integrator.index() == 0
                    ? std::string()
                    : std::string(" ") + integrator_name(d.settings.integrator))
            << " " << result.threads << " threads"
            << (result.processes.size() > 1
                    ? " x " + std::to_string(result.processes.size()) + " ranks"
                    : std::string())
            << " | parse " << format_duration(parse_s) << ", bvh "
            << format_duration(result.bvh_seconds) << ", render "
            << format_duration(result.render_seconds) << ", write " << format_duration(write_s)
            << (streaming ? " after the last tile (streamed)" : "") << " | rays "
            << human_count(c.total_rays()) << " (camera " << human_count(c.camera) << ", shadow "
            << human_count(c.shadow) << ", reflect " << human_count(c.reflection) << ", refract "
            << human_count(c.refraction) << ") " << std::fixed << std::setprecision(2) << mrays
            << " Mrays/s | total " << format_duration(seconds_since(total_start)) << "\n";
        if (args.stats && result.textures.textures > 0) {
            out << "rayo: textures " << texture_summary(result) << "\n";
        }
        if (result.radiosity) {
            const RadiosityStats& rs = result.radiosity_stats;
            out << "rayo: radiosity " << result.radiosity_patches << " patches | solve "
                << format_duration(rs.seconds) << ", " << rs.shots << " shots, unshot "
                << std::scientific << std::setprecision(2) << rs.unshot_fraction
                << " of the emitted energy, form-factor rays " << human_count(rs.form_factor_rays)
                << "\n"
                << std::defaultfloat;
        }
    }
    return 0;
}

// The exit status and the message line of an exception thrown by a command.
int describe_error(std::exception_ptr error, std::string& message) {
    try {
        std::rethrow_exception(error);
    } catch (const UsageError& e) {
        message = std::string("rayo: error: ") + e.what() + "\n";
        return kExitUsage;
    } catch (const std::bad_alloc&) {
        message = "rayo: error: out of memory\n";
        return kExitInput;
    } catch (const std::exception& e) {  // InputError and every other failure
        message = std::string("rayo: error: ") + e.what() + "\n";
        return kExitInput;
    }
}

int run_render(const std::vector<std::string>& arg_list, std::ostream& out, std::ostream& err) {
    std::optional<MpiTileDistribution> distribution;
    if (!MpiWorld::distributed()) return render_command(arg_list, out, err, distribution);
    // One rank of several: an error before the ranks exchange tiles is agreed on, so that it is
    // printed once (by the lowest failing rank) and every rank exits with its status. After
    // that only rank 0 runs (writing the image); errors during the exchange end all ranks.
    try {
        return render_command(arg_list, out, err, distribution);
    } catch (const PeerFailure& failure) {
        return failure.exit_code;
    } catch (...) {
        std::string message;
        const int code = describe_error(std::current_exception(), message);
        if (distribution && distribution->agreed()) {
            err << message;
            return code;
        }
        return MpiWorld::agree_on_failure(true, message, code, err);
    }
}

// `rayo texture NAME [options]`: the flags by kTextureFlags.
int run_texture(const std::vector<std::string>& args, std::ostream& out) {
    TextureArgs t;
    parse_flags(kTextureFlags, args, 0, "texture", t, [&](const std::string& word) {
        if (t.name) throw UsageError("unexpected argument '" + word + "': one texture per command");
        t.name = word;
    });
    const std::optional<std::string>& name = t.name;
    const int width = t.width, height = t.height;
    const uint32_t seed = t.seed;
    const std::vector<std::string>& names = texture_kind_names();
    const std::string known = texture_kind_list();
    if (!name) throw UsageError("texture: expected a texture name (" + known + ")");
    if (std::find(names.begin(), names.end(), *name) == names.end()) {
        throw UsageError("texture: unknown texture '" + *name + "' (expected one of: " + known +
                         ")");
    }
    check_film_size(width, height, "--size");
    const std::string path = t.output ? *t.output : *name + ".png";
    OutputOptions options;
    start_threads_then_image_module(0, path, options);
    Texture texture = make_texture(*name);
    if (t.scale) texture.scale = *t.scale;
    texture.seed = seed;
    const Film film = texture_image(texture, width, height);
    options.metadata["rayo:texture"] = *name;
    options.metadata["rayo:texture_scale"] = std::to_string(texture.scale);
    options.metadata["rayo:texture_seed"] = std::to_string(seed);
    write_image(film, path, options);
    out << "rayo: " << path << " " << width << "x" << height << " texture " << *name << " scale "
        << texture.scale << " seed " << seed << "\n";
    return 0;
}

// `rayo preview [SCENE] [-o OUT] [--width W] [--height H] [--over-render] ...`: the wireframe
// of the scene from its camera (apps/scene/preview.h), for framing a long render.
struct PreviewArgs {
    RenderArgs render;  // the scene, output and the flags preview shares with render
    bool over_render = false;
};

// Preview takes --over-render and, with render's meaning and parsing, the render flags below;
// it refuses the other render flags (samples, sphere methods, ...) as unknown. Whether a shared
// flag takes a value is its render entry's (kRenderOptions).
PreviewArgs parse_preview_args(const std::vector<std::string>& args) {
    static const std::set<std::string> kShared = {
        "--output",  "--width", "--height", "--threads", "--nff-light-intensity",
        "--display", "--view",  "--quiet"};
    PreviewArgs p;
    std::vector<std::string> render_args;
    bool scene_seen = false;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--over-render") {
            p.over_render = true;
        } else if (const RenderOption* o = render_option(a); o && kShared.count(o->flag)) {
            render_args.push_back(a);
            const bool takes_value = o->rule.kind != FlagRule::Kind::Switch;
            if (takes_value && i + 1 < args.size()) render_args.push_back(args[++i]);
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option '" + a + "' (see rayo preview --help)");
        } else if (!scene_seen) {
            scene_seen = true;
            render_args.push_back(a);
        } else {
            throw UsageError("unexpected argument '" + a + "': only one scene per preview");
        }
    }
    p.render = parse_render_args(render_args);
    return p;
}

int run_preview(const std::vector<std::string>& arg_list, std::ostream& out, std::ostream& err) {
    const PreviewArgs args = parse_preview_args(arg_list);
    const RenderArgs& r = args.render;
    const std::string output =
        r.output ? *r.output
                 : (r.scene_path ? std::filesystem::path(*r.scene_path).stem().string()
                                 : std::string("default")) +
                       "-preview.png";
    start_threads_then_image_module(r.threads.value_or(0), output, r.output_options);
    const auto total_start = std::chrono::steady_clock::now();
    SceneDescription d =
        r.scene_path ? load_scene_file(*r.scene_path, r.load_options) : make_default_scene();
    const double parse_s = seconds_since(total_start);
    if (!r.quiet) {
        for (const std::string& w : d.warnings) err << "rayo: warning: " << w << "\n";
    }
    apply_overrides(r, d);
    check_output(output, r.output_options);  // before the work, as for render

    PreviewOptions options;
    options.over_render = args.over_render;
    options.threads = r.threads.value_or(0);
    const PreviewResult result = render_preview(d, options);

    OutputOptions output_options = r.output_options;
    output_options.metadata["rayo:scene"] = d.source;
    output_options.metadata["rayo:preview"] =
        args.over_render ? "wireframe over a darkened 1 spp render" : "wireframe";
    const auto write_start = std::chrono::steady_clock::now();
    write_image(result.film, output, output_options);
    const double write_s = seconds_since(write_start);

    if (!r.quiet) {
        const WireframeStats& s = result.stats;
        const CameraDesc& cam = d.scene.camera;
        const auto ms = [](double seconds) {
            std::ostringstream text;
            text << std::fixed << std::setprecision(seconds < 0.01 ? 1 : 0) << seconds * 1e3
                 << " ms";
            return text.str();
        };
        out << "rayo: " << output << " " << cam.width << "x" << cam.height << " preview | "
            << s.objects << " objects (" << shape_summary(d.scene) << ", " << d.scene.meshes.size()
            << " meshes) | segments " << s.segments << ": " << s.drawn << " drawn (" << s.cut
            << " cut at the window or the eye), " << s.clipped_away() << " clipped away ("
            << s.outside << " outside the window, " << s.behind << " behind the eye) | parse "
            << ms(parse_s);
        if (args.over_render) out << ", render " << ms(result.render_seconds);
        out << ", lines " << ms(result.draw_seconds) << ", write " << ms(write_s) << " | total "
            << ms(seconds_since(total_start)) << "\n";
    }
    return 0;
}

size_t vertex_count(const Scene& scene) {
    size_t n = 0;
    for (const TriangleMesh& m : scene.meshes) n += m.positions.size();
    return n;
}

int run_info(const std::vector<std::string>& args, std::ostream& out) {
    if (args.size() != 1) throw UsageError("info: expected exactly one scene file");
    // A model file is described as it is: without the ground square that framing adds.
    SceneLoadOptions options;
    options.model.ground = false;
    const SceneDescription d = load_scene_file(args[0], options);
    const Camera camera = Camera::create(d.scene.camera, d.source + "#/camera");
    out << "scene " << d.source << "\n"
        << "resolution " << camera.width() << "x" << camera.height() << "\n"
        << "fov " << camera.hfov_degrees() << "x" << camera.vfov_degrees() << " degrees\n"
        << "view " << view_text(camera.desc()) << "\n";
    for (const auto& [name, count] : d.scene.shape_counts()) out << name << " " << count << "\n";
    out << "meshes " << d.scene.meshes.size() << "\n"
        << "triangles " << d.scene.triangle_count() << "\n"
        << "vertices " << vertex_count(d.scene) << "\n"
        << "voxel_grids " << d.scene.voxels.size() << "\n"
        << "heightfields " << d.scene.heightfields.size() << "\n"
        << "materials " << d.shading.materials.size() << "\n"
        << "lights " << d.shading.lights.size() << "\n"
        << "skipped_triangles " << d.skipped_triangles << "\n";
    if (const std::optional<Bounds3> box = scene_bounds(d.scene)) {
        out << "bounds " << box->lower.x << " " << box->lower.y << " " << box->lower.z << "  "
            << box->upper.x << " " << box->upper.y << " " << box->upper.z << "\n";
    }
    if (!d.scene.groups.empty()) {
        // Groups' objects are stored once; instanced_objects counts them once per instance.
        out << "groups " << d.scene.groups.size() << "\n"
            << "instances " << d.scene.instances.size() << "\n"
            << "instanced_objects " << d.scene.instanced_object_count() << "\n";
    }
    // Model files: the cameras the file defines and the lights with their names.
    for (size_t i = 0; i < d.file_cameras.size(); ++i) {
        const GltfCamera& c = d.file_cameras[i];
        out << "camera " << i << " '" << c.name << "' "
            << (c.orthographic ? "orthographic" : "perspective") << " position " << c.position.x
            << " " << c.position.y << " " << c.position.z << " direction " << c.forward.x << " "
            << c.forward.y << " " << c.forward.z;
        if (c.orthographic) {
            out << " xmag " << c.xmag << " ymag " << c.ymag << "\n";
        } else {
            out << " yfov " << glm::degrees(c.yfov_radians) << " degrees";
            if (c.aspect_ratio > 0.0f) out << " aspect " << c.aspect_ratio;
            out << "\n";
        }
    }
    // Every light, with the name the file gives it (model files), else none.
    for (size_t i = 0; i < d.shading.lights.size(); ++i) {
        out << "light " << i;
        if (i < d.light_names.size()) out << " '" << d.light_names[i] << "'";
        out << " " << describe_light(d.shading.lights[i]) << "\n";
    }
    for (const std::string& w : d.warnings) out << "warning: " << w << "\n";
    return 0;
}

int run_bench_suite(const std::vector<std::string>& args, std::ostream& out) {
    SuiteArgs parsed;
    parse_flags(kSuiteFlags, args, 1, "bench", parsed, [](const std::string& word) {
        throw UsageError("bench suite: unexpected argument '" + word + "'");
    });
    const SuiteOptions& options = parsed.options;
    const bool write_nff = parsed.write_nff;
    if (write_nff && options.dir.empty()) throw UsageError("bench suite: --write-nff needs -o DIR");
    if (options.spd_procedure && parsed.size_given) {
        throw UsageError(
            "bench suite: --size with --procedure spd: the procedure renders each database at "
            "its default size");
    }
    if (write_nff) {
        write_spd_nff_files(options, out);
        return 0;
    }
    const std::vector<SuiteRow> rows = run_spd_suite(options, out);
    const MachineInfo machine = machine_info();
    print_suite_table(out, rows, machine, false);
    if (!options.dir.empty()) {
        write_suite_files(options, rows, machine);
        out << "wrote suite.csv, suite.json, suite.md, suite.gp and suite.png in " << options.dir
            << "\n";
    }
    if (!options.spd_procedure) return 0;
    const std::vector<std::string> failures = spd_count_failures(rows);
    for (const std::string& failure : failures) {
        out << "rayo bench suite --procedure spd: FAILED: " << failure << "\n";
    }
    if (!failures.empty()) return 1;
    out << "rayo bench suite --procedure spd: every ray count within 10% of the SPD Readme's\n";
    return 0;
}

int run_bench_convergence(const std::vector<std::string>& args, std::ostream& out) {
    ConvergenceOptions options;
    bool has_scene = false;
    parse_flags(kConvergenceFlags, args, 1, "bench", options, [&](const std::string& word) {
        if (has_scene) throw UsageError("bench convergence: unexpected argument '" + word + "'");
        options.scene = word;
        has_scene = true;
    });
    if (options.dir.empty()) throw UsageError("bench convergence: -o DIR is required");
    check_convergence_spp(options.max_spp, options.reference_spp);
    const ConvergenceStudy study = run_convergence_study(options, out);
    print_convergence_table(out, study, false);
    write_convergence_files(options, study);
    out << "wrote convergence.csv, convergence.json, convergence.md, convergence.gp and "
           "convergence.png/.svg in "
        << options.dir << "\n";
    return 0;
}

int run_bench(const std::vector<std::string>& args, std::ostream& out) {
    if (!args.empty() && args[0] == "suite") return run_bench_suite(args, out);
    if (!args.empty() && args[0] == "convergence") return run_bench_convergence(args, out);
    if (args.empty() || args[0] != "accuracy") {
        throw UsageError(
            "bench: expected 'rayo bench accuracy -o DIR [options]', 'rayo bench suite "
            "[options]' or 'rayo bench convergence [SCENE] -o DIR [options]' (see rayo bench "
            "--help)");
    }
    AccuracyArgs parsed;
    parse_flags(kAccuracyFlags, args, 1, "bench", parsed, [](const std::string& word) {
        throw UsageError("bench accuracy: unexpected argument '" + word + "'");
    });
    const std::optional<std::string>& dir = parsed.dir;
    const int size = parsed.size;
    if (!dir) throw UsageError("bench accuracy: -o DIR is required");
    if (parsed.only != Study::Shapes) run_accuracy_bench(*dir, out, size);
    if (parsed.only != Study::Spheres) run_shape_method_bench(*dir, out, size);
    return 0;
}

}  // namespace

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.empty()) {
            err << usage();
            return kExitUsage;
        }
        const std::string command = args[0];
        args.erase(args.begin());
        if (command == "--help" || command == "-h" || command == "help") {
            out << usage();
            return 0;
        }
        if (command == "--version") {
            out << "rayo " << RAYO_VERSION << "\n";
            return 0;
        }
        for (const std::string& a : args) {
            if (a == "--help" || a == "-h") {
                out << command_help(command);
                return 0;
            }
        }
        if (command == "render") return run_render(args, out, err);
        if (command == "info") return run_info(args, out);
        if (command == "bench") return run_bench(args, out);
        if (command == "texture") return run_texture(args, out);
        if (command == "preview") return run_preview(args, out, err);
        throw UsageError("unknown command '" + command + "' (see rayo --help)");
    } catch (...) {
        std::string message;
        const int code = describe_error(std::current_exception(), message);
        err << message;
        return code;
    }
}

std::vector<RenderOptionInfo> render_option_list() {
    std::vector<RenderOptionInfo> list;
    for (const RenderOption& o : kRenderOptions) {
        if (!o.apply) continue;  // the declared settings follow
        list.push_back({o.flag, o.use, o.rule.kind != FlagRule::Kind::Switch,
                        help_lines(flag_spelling(o), flag_help_text(o))});
    }
    std::vector<std::string> declared = render_setting_flags();
    for (const std::string& flag : integrator_setting_flags()) {
        if (std::find(declared.begin(), declared.end(), flag) == declared.end()) {
            declared.push_back(flag);
        }
    }
    for (const std::string& flag : declared) {
        list.push_back({flag, OptionUse::Render, setting_flag_arity(flag) == FlagArity::Value,
                        setting_help(flag)});
    }
    return list;
}

SceneDescription load_scene_with_options(const std::optional<std::string>& path,
                                         const std::vector<std::string>& words) {
    const RenderArgs args = parse_render_args(words, OptionUse::Load);
    SceneDescription d = path ? load_scene_file(*path, args.load_options) : make_default_scene();
    apply_environment(args, d);
    return d;
}

int apply_render_options(const std::vector<std::string>& words, SceneDescription& d) {
    const RenderArgs args = parse_render_args(words, OptionUse::Render);
    apply_overrides(args, d);
    return args.threads.value_or(0);
}

OutputOptions output_options_from(const std::vector<std::string>& words) {
    return parse_render_args(words, OptionUse::Output).output_options;
}

}  // namespace rayo
