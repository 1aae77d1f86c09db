#pragma once
// One render of a scene description: camera validation, the Embree BVH, the Whitted integrator
// in the TBB tile loop, into an in-memory film or a caller's tile sink. Returns the film (when
// it was used), ray counts and phase times.
#include "apps/scene/scene_description.h"
#include "apps/scene/shape_method_choice.h"
#include "apps/scene/sphere_method_choice.h"
#include "core/film.h"
#include "core/progressive_settings.h"
#include "core/stats.h"
#include "core/tile_distribution.h"
#include "core/tile_sink.h"
#include "shading/image_texture.h"

namespace rayo {

class ProgressiveCheckpoint;  // core/progressive.h

struct RenderResult {
    Film film{1, 1};
    RayCounters counters;
    double bvh_seconds = 0.0;
    double render_seconds = 0.0;
    size_t primitives = 0;         // instanced total: each instance counts its group's
    size_t instances = 0;          // Embree instances (core/instance.h)
    size_t stored_primitives = 0;  // each instanced group's primitives once
    size_t cutout_meshes = 0;      // meshes with holes (docs/models.md, "Cutouts")
    int threads = 0;
    SphereChoice spheres;                   // the sphere method and math that ran, and why
    std::vector<ShapeMethodChoice> shapes;  // the objects' methods, where not analytic by default
    bool coherent = false;                  // camera/shadow rays traced as per-tile Embree streams
    // The radiosity pre-pass, when render.gi is "radiosity" (docs/radiosity.md).
    bool radiosity = false;
    size_t radiosity_patches = 0;
    RadiosityStats radiosity_stats;
    // Under a distribution of several processes: what each did (docs/distributed.md).
    std::vector<ProcessWork> processes;
    // Image textures (docs/textures.md): how many, and the texture cache's memory.
    ImageTextureStats textures;
    // A progressive render's passes, samples and noise (core/progressive.h); else empty.
    std::optional<ProgressiveResult> progressive;
};

// threads = 0: all cores. Throws InputError for an invalid camera. The tiles go to `sink` when
// given (e.g. a file written as tiles finish, core/image/tile_stream.h; result.film stays 1×1),
// else to result.film. With a `distribution`, the tiles are shared out among its processes
// (every process loads the scene and builds the BVH); the sink or film is filled, and the
// progress shown, only where the distribution writes the image (pass no sink elsewhere).
// `tiles` (when given; not with a distribution) lists the tiles to render, e.g. those a resumed
// render still misses (core/image/partial_render.h): the progress bar and its ETA count only
// them, and an empty list renders nothing (the sink gets begin() and finish()).
// `checkpoint` (a progressive render in one process) starts the passes from those an earlier
// run kept and keeps each finished pass (core/image/pass_journal.h, --resume).
RenderResult render_scene(const SceneDescription& description, int threads, bool show_progress,
                          TileSink* sink = nullptr, TileDistribution* distribution = nullptr,
                          const std::vector<int>* tiles = nullptr,
                          ProgressiveCheckpoint* checkpoint = nullptr);

// The thread count TBB uses when none is given.
int default_thread_count();

// Starts TBB's worker threads for a render on `threads` threads (0: the default) now, instead of
// at the render's first parallel loop. Creating a thread takes the dynamic loader's lock, which
// the image module's background load (core/image_library.h) holds for its whole ~0.3 s: workers
// started before that load render during it (docs/performance.md "Fixed costs").
void start_worker_threads(int threads);

}  // namespace rayo
