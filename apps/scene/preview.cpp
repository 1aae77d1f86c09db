#include "apps/scene/preview.h"

#include <chrono>

#include "apps/scene/renderer.h"
#include "core/error.h"

namespace rayo {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PreviewResult render_preview(const SceneDescription& description, const PreviewOptions& options) {
    const Camera camera = Camera::create(description.scene.camera, description.source + "#/camera");
    if (camera.projection() != Projection::Perspective) {
        // Seed 003's synthetic camera projects onto a plane; straight edges stay straight only
        // there, and the outlines are polylines of straight segments.
        throw InputError(description.source + "#/camera/projection",
                         std::string("rayo preview draws perspective cameras only (the seed 003 "
                                     "synthetic camera); this scene's is '") +
                             projection_name(camera.projection()) + "'");
    }
    check_film_size(camera.width(), camera.height(), description.source + "#/camera");
    PreviewResult result;
    if (options.over_render) {
        SceneDescription one_sample = description;
        one_sample.settings.spp = 1;
        RenderResult render = render_scene(one_sample, options.threads, false);
        result.render_seconds = render.bvh_seconds + render.render_seconds;
        result.film = std::move(render.film);
        std::vector<float>& rgba = result.film.rgba();
        for (size_t i = 0; i < rgba.size(); i += 4) {
            for (size_t c = 0; c < 3; ++c) rgba[i + c] *= options.render_gain;
        }
    } else {
        result.film = Film(camera.width(), camera.height());
        // Opaque black, as a render's background is opaque.
        for (size_t i = 3; i < result.film.rgba().size(); i += 4) result.film.rgba()[i] = 1.0f;
    }
    const auto start = std::chrono::steady_clock::now();
    result.stats = draw_wireframe(description.scene, camera, result.film, options.line_rgb);
    result.draw_seconds = seconds_since(start);
    return result;
}

}  // namespace rayo
