#include "apps/scene/renderer.h"

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/accel.h"
#include "core/camera.h"
#include "core/embree_device.h"
#include "core/error.h"
#include "core/film.h"
#include "core/progressive.h"
#include "core/render.h"
#include "core/scene_bounds.h"
#include "shading/cutouts.h"
#include "shading/integrators/integrator.h"
#include "shading/radiosity_field.h"

namespace rayo {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Loaders validate as they read; this guards scenes built in code (and any loader slip) against
// material and texture ids that would index past their tables.
void check_material_ids(const SceneDescription& d) {
    const size_t count = d.shading.materials.size();
    auto check = [&](uint32_t id, const std::string& what) {
        if (id >= count) {
            throw InputError(d.source, what + " uses material " + std::to_string(id) +
                                           " but only " + std::to_string(count) + " are defined");
        }
    };
    // The scene's objects and every group's ("group NAME: sphere 3").
    auto check_objects = [&](const auto& objects, const std::string& prefix) {
        objects.shapes.for_each([&](const auto& shapes) {
            using S = ShapeOf<decltype(shapes)>;
            for (size_t i = 0; i < shapes.size(); ++i) {
                check(shapes[i].material, prefix + S::kName + " " + std::to_string(i));
            }
        });
        for (size_t m = 0; m < objects.meshes.size(); ++m) {
            const TriangleMesh& mesh = objects.meshes[m];
            if (mesh.materials.size() != mesh.triangles.size()) {
                throw InputError(d.source,
                                 prefix + "mesh " + std::to_string(m) + " has " +
                                     std::to_string(mesh.triangles.size()) + " triangles but " +
                                     std::to_string(mesh.materials.size()) + " material ids");
            }
            for (uint32_t id : mesh.materials) check(id, prefix + "mesh " + std::to_string(m));
        }
    };
    check_objects(d.scene, "");
    for (const ShapeGroup& group : d.scene.groups)
        check_objects(group, "group " + group.name + ": ");
    for (size_t i = 0; i < d.scene.instances.size(); ++i) {
        const Instance& instance = d.scene.instances[i];
        if (instance.group >= d.scene.groups.size()) {
            throw InputError(d.source, "instance " + std::to_string(i) + " names group " +
                                           std::to_string(instance.group) + " but only " +
                                           std::to_string(d.scene.groups.size()) + " exist");
        }
        if (instance.material != kNoMaterialOverride) {
            check(instance.material, "instance " + std::to_string(i));
        }
    }
    for (size_t f = 0; f < d.scene.heightfields.size(); ++f) {
        check(d.scene.heightfields[f].material, "heightfield " + std::to_string(f));
    }
    for (size_t v = 0; v < d.scene.voxels.size(); ++v) {
        check(d.scene.voxels[v].material, "voxels " + std::to_string(v));
    }
    const auto texture_count = static_cast<int32_t>(d.shading.textures.size());
    for (const Material& material : d.shading.materials) {
        const MaterialTextures& t = material.textures;
        for (int32_t id : {t.ka, t.kd, t.ks, t.bump}) {
            if (id != kNoTexture && (id < 0 || id >= texture_count)) {
                throw InputError(d.source, "material '" + material.name + "' uses texture " +
                                               std::to_string(id) + " but only " +
                                               std::to_string(texture_count) + " are defined");
            }
        }
    }
}

// Refuses a scene whose triangles lie beyond the range Embree's triangle test computes in
// (core/scene_bounds.h, kMaxTriangleProduct).
void check_triangle_range(const Scene& scene, bool spheres_as_triangles, const Vec3& eye,
                          const std::string& where) {
    const double triangles = largest_triangle_coordinate(scene, spheres_as_triangles);
    if (triangles == 0.0) return;
    const double eye_distance = max_abs_component(eye);
    const double product = (triangles + eye_distance) * (2.0 * triangles) * (2.0 * triangles);
    if (product <= kMaxTriangleProduct) return;
    std::ostringstream text;
    text << "triangles lie up to " << triangles << " from the origin and the eye " << eye_distance
         << ": Embree's triangle test multiplies a distance from the ray's origin by an edge "
            "squared, here up to "
         << product << ", beyond the " << kMaxTriangleProduct
         << " a float holds with its sums (docs/limits.md, \"Scale\"; at unit distance from "
            "the eye, triangles within about 2.9e12): scale the scene down or trace its shapes "
            "analytically";
    throw InputError(where, text.str());
}

}  // namespace

int default_thread_count() {
    return tbb::info::default_concurrency();
}

void start_worker_threads(int threads) {
    // At least two: TBB loads its thread server (libirml) and allocator with its first worker,
    // by dlopen, which waits for the same lock; with one render thread the worker stays idle.
    const int count = std::max(2, threads > 0 ? threads : default_thread_count());
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<size_t>(count));
    // One iteration per thread, each held until all have arrived (or 50 ms passed, should TBB
    // give fewer threads): every worker has then been created.
    std::atomic<int> arrived{0};
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(50);
    tbb::parallel_for(
        0, count,
        [&](int) {
            ++arrived;
            while (arrived.load() < count && std::chrono::steady_clock::now() < deadline) {
                std::this_thread::yield();
            }
        },
        tbb::simple_partitioner());
    embree_device();  // created here too, so that none of Embree's set-up falls inside the load
}

RenderResult render_scene(const SceneDescription& description, int threads, bool show_progress,
                          TileSink* sink, TileDistribution* distribution,
                          const std::vector<int>* tiles, ProgressiveCheckpoint* checkpoint) {
    const Camera camera = Camera::create(description.scene.camera, description.source + "#/camera");
    check_material_ids(description);
    const bool writes_image = distribution == nullptr || distribution->writes_image();
    if (sink == nullptr && writes_image) {
        check_film_size(camera.width(), camera.height(), description.source + "#/camera");
    }
    RenderResult result;
    result.threads = threads > 0 ? threads : default_thread_count();
    // Limits TBB and Embree's BVH build alike (docs/architecture.md: no task_scheduler_init in
    // oneTBB).
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<size_t>(result.threads));

    // Image textures: one texture system for the render, made only when a material names an
    // image (scenes without keep the integrator's settings bit for bit). Made before the accel:
    // the cutouts' holes (docs/models.md) are looked up while tracing.
    std::unique_ptr<ImageTextures> images;
    const auto& materials = description.shading.materials;
    if (std::any_of(materials.begin(), materials.end(),
                    [](const Material& m) { return m.images.any(); })) {
        images = std::make_unique<ImageTextures>(materials, description.settings.texture_cache_mb,
                                                 description.settings.texture_filter);
    }
    const MaterialCutouts cutouts(materials, images.get());

    auto start = std::chrono::steady_clock::now();
    result.spheres = choose_sphere_method(description, camera);
    // Objects with a mesh form, analytic or as triangles (docs/shape-methods.md): `scene` is the
    // loaded one unless some became meshes.
    ShapeChoices shape_choices = choose_shape_methods(description, camera);
    const Scene& scene = shape_choices.traced(description.scene);
    check_triangle_range(scene, result.spheres.spheres.method == SphereMethod::Mesh,
                         description.scene.camera.eye, description.source);
    AccelOptions accel_options;
    accel_options.spheres = result.spheres.spheres;
    accel_options.sphere_math = result.spheres.math;
    if (cutouts.any()) accel_options.cutouts = &cutouts;
    const Accel accel(scene, accel_options);
    result.bvh_seconds = seconds_since(start);
    result.cutout_meshes = accel.cutout_mesh_count();
    result.primitives = accel.primitive_count();
    result.instances = accel.instance_count();
    result.stored_primitives = accel.stored_primitive_count();
    result.shapes = std::move(shape_choices.objects);

    // Radiosity (seed 004), the first of two passes: the patches of the meshes and of the
    // tessellated analytic shapes exchange light through the accel's occlusion rays; the second
    // pass below shows the solution on diffuse surfaces and traces mirrors and glass through to
    // it.
    std::unique_ptr<RadiosityField> radiosity;
    if (description.settings.gi == GlobalIllumination::Radiosity) {
        const RadiositySettings& rs = description.settings.radiosity;
        radiosity =
            std::make_unique<RadiosityField>(scene, description.shading.materials, rs.patch_size);
        result.radiosity = true;
        result.radiosity_patches = radiosity->patches().size();
        // The bar follows the unshot energy on a log scale, from 1 down to the threshold.
        constexpr uint64_t kSteps = 1000;
        const double floor = std::log(std::clamp(rs.threshold, 1e-12, 0.5));
        uint64_t shown = 0;
        ProgressReporter progress(kSteps, "radiosity", show_progress);
        const std::vector<DVec3> b = solve_radiosity(
            radiosity->patches(), &accel, rs, result.radiosity_stats, [&](double unshot) {
                const double done = unshot > 0.0 ? std::log(unshot) / floor : 1.0;
                const auto steps = static_cast<uint64_t>(std::clamp(done, 0.0, 1.0) * kSteps);
                if (steps > shown) progress.add(steps - shown);
                shown = std::max(shown, steps);
            });
        radiosity->set_solution(b);
        radiosity->set_flat(description.settings.gi_view_patches);
    }

    IntegratorContext context{accel, description.shading, radiosity.get(), images.get()};
    const ProgressiveSettings& progressive = description.settings.progressive;
    if (progressive.enabled() && tiles != nullptr &&
        static_cast<int>(tiles->size()) !=
            TileGrid(camera.width(), camera.height(), description.settings.tile_size)
                .tile_count()) {
        // The CLI refuses this first (--resume); a library caller gets this.
        throw std::invalid_argument(
            "a progressive render (time_limit, noise_target) renders every tile");
    }
    if (progressive.enabled() &&
        int64_t(camera.width()) * camera.height() > kMaxProgressivePixels) {
        // The passes' sums take 32 bytes a pixel (core/progressive.h).
        throw InputError(description.source + "#/render",
                         std::to_string(camera.width()) + "x" + std::to_string(camera.height()) +
                             " is too large for a progressive render (time_limit, noise_target): "
                             "at most " +
                             std::to_string(kMaxProgressivePixels) +
                             " pixels, whose passes take 2 GiB; render a fixed spp");
    }
    if (images) {
        // The texture filter's footprint: a pixel over the samples' stratification.
        const int stratified_spp =
            progressive.enabled() ? progressive.pass_spp : description.settings.spp;
        context.pixel_spread = camera.pixel_angle() / std::sqrt(static_cast<float>(stratified_spp));
    }
    if (sink == nullptr && writes_image) result.film = Film(camera.width(), camera.height());
    TileSink& target = sink ? *sink : result.film;
    TileSettings settings;
    settings.spp = description.settings.spp;
    settings.tile_size = description.settings.tile_size;
    // Embree's built-in sphere kernel rounds differently in its packet and single-ray forms
    // (5% of balls_3's pixels change, docs/performance.md), so embree-point stays on single rays
    // to keep the promise that the coherent path changes no bits.
    settings.coherent =
        description.settings.coherent && result.spheres.spheres.method != SphereMethod::EmbreePoint;
    settings.aa = description.settings.aa;
    settings.adaptive = description.settings.adaptive;
    result.coherent = settings.coherent && settings.aa == AntiAliasing::Stratified;

    start = std::chrono::steady_clock::now();
    {
        const TileGrid grid(camera.width(), camera.height(), settings.tile_size);
        uint64_t pixels = static_cast<uint64_t>(camera.width()) * camera.height();
        if (tiles) {
            pixels = 0;
            for (const int index : *tiles) pixels += grid.tile(index).pixel_count();
        }
        ProgressReporter progress(
            pixels, "rendering",
            show_progress && writes_image && pixels > 0 && !progressive.enabled());
        if (tiles && tiles->empty()) {
            target.begin(grid);
            target.finish();
        } else {
            // The one dispatch of the render: the registered integrator's type picks the tile
            // loop's instantiation (shading/integrators/integrator.h); no virtual call per ray.
            std::visit(
                [&](const auto& integrator_settings) {
                    using Integrator =
                        typename std::decay_t<decltype(integrator_settings)>::Integrator;
                    const Integrator integrator(context, integrator_settings);
                    if (progressive.enabled()) {
                        result.progressive =
                            render_progressive(camera, integrator, settings, progressive,
                                               static_cast<uint32_t>(progressive.max_spp), target,
                                               show_progress && writes_image, distribution,
                                               &result.processes, checkpoint);
                        result.counters = result.progressive->counters;
                        return;
                    }
                    if (distribution == nullptr) {
                        result.counters =
                            render_tiles(camera, integrator, settings, target, &progress,
                                         tiles ? *tiles : std::vector<int>{});
                        return;
                    }
                    const auto render_chunk = [&](const std::vector<int>& list,
                                                  TileSink& chunk_sink) {
                        return render_tiles(camera, integrator, settings, chunk_sink, nullptr,
                                            list);
                    };
                    result.counters =
                        distribution->render(grid, {}, render_chunk, target, &progress);
                    result.processes = distribution->work();
                },
                description.settings.integrator);
        }
    }
    result.render_seconds = seconds_since(start);
    if (images) result.textures = images->stats();
    return result;
}

}  // namespace rayo
