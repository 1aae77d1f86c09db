#pragma once
// Adaptive antialiasing by corner subdivision, the recursive scheme of POV-Ray (its `+AM2`
// sampling method, docs/antialiasing.md): rays through the corners of every pixel, corners shared
// with the neighbours; a square whose corners differ by more than the threshold is split in four,
// up to `depth` times, and takes the mean of its quarters; an even square, the mean of its
// corners. Every sample sits on a fixed lattice of the image (2^depth steps per pixel) and its
// value depends only on its lattice position, so the image is the same for any tile size and
// thread count: a corner on a tile edge is traced by both tiles, identically.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/ray.h"
#include "core/sampler.h"
#include "core/sampling.h"
#include "core/stats.h"
#include "core/tile_border_corners.h"
#include "core/tile_grid.h"

namespace rayo {

// Corners: the mean of each pixel's four corners, every corner traced once, no subdivision (the
// SPD's testing procedure: (W + 1) × (H + 1) camera rays; core/tile_border_corners.h). Adaptive
// at depth 0 gives the same image but traces the corners on tile borders once per tile.
enum class AntiAliasing { Stratified, Adaptive, Corners };

struct AdaptiveSettings {
    float threshold = 0.3f;  // POV-Ray's default antialiasing threshold
    int depth = 3;           // POV-Ray's default recursion depth (+R3)
};
constexpr int kMaxAdaptiveDepth = 8;  // up to 2^8 × 2^8 sub-squares per pixel

// One lattice sample: the radiance and whether the camera had a ray there (alpha 1 or 0).
struct CornerSample {
    Vec3 rgb{0.0f};
    float alpha = 0.0f;
};

// POV-Ray's colour distance, the sum of the absolute channel differences (here with alpha as a
// fourth channel, so that the rim of a fisheye's image circle is refined too).
inline float corner_distance(const CornerSample& a, const CornerSample& b) {
    return std::abs(a.rgb.x - b.rgb.x) + std::abs(a.rgb.y - b.rgb.y) + std::abs(a.rgb.z - b.rgb.z) +
           std::abs(a.alpha - b.alpha);
}

// Renders one tile with adaptive antialiasing into `rgba` (tile-local, row-major RGBA). Rays are
// traced one at a time (Embree's packet kernels may round differently, and a corner's value must
// not depend on the batch it was traced in).
template <typename Camera, typename Integrator>
class AdaptiveTile {
  public:
    // With `borders`, the corners on tile borders are traced once for the image (aa "corners").
    AdaptiveTile(const Camera& camera, const Integrator& integrator,
                 const AdaptiveSettings& settings, RayCounters& counters,
                 TileBorderCorners<CornerSample>* borders = nullptr)
        : m_camera(camera),
          m_integrator(integrator),
          m_threshold(settings.threshold),
          m_depth(std::clamp(settings.depth, 0, kMaxAdaptiveDepth)),
          m_scale(1 << m_depth),
          m_counters(counters),
          m_borders(borders) {}

    void render(const Tile& tile, float* rgba) {
        // The pixel corners of the tile, (width + 1) × (height + 1), traced once per tile (those
        // on tile borders once per image, with m_borders).
        const int columns = tile.width + 1;
        m_corners.resize(static_cast<size_t>(columns) * (tile.height + 1));
        for (int cy = 0; cy <= tile.height; ++cy) {
            for (int cx = 0; cx <= tile.width; ++cx) {
                const int x = tile.x0 + cx, y = tile.y0 + cy;
                m_corners[static_cast<size_t>(cy) * columns + cx] =
                    m_borders && m_borders->shared(x, y)
                        ? m_borders->get(x, y, [&] { return trace(x * m_scale, y * m_scale); })
                        : trace(x * m_scale, y * m_scale);
            }
        }
        for (int py = 0; py < tile.height; ++py) {
            for (int px = 0; px < tile.width; ++px) {
                const CornerSample* top = &m_corners[static_cast<size_t>(py) * columns + px];
                const CornerSample* bottom = top + columns;
                const CornerSample value =
                    square((tile.x0 + px) * m_scale, (tile.y0 + py) * m_scale, m_scale, top[0],
                           top[1], bottom[0], bottom[1]);
                float* p = rgba + (static_cast<size_t>(py) * tile.width + px) * 4;
                p[0] = value.rgb.x;
                p[1] = value.rgb.y;
                p[2] = value.rgb.z;
                p[3] = value.alpha;
            }
        }
    }

  private:
    // The sample at lattice point (i, j): film position (i, j)/2^depth − 0.5 in pixel units (the
    // corners of pixel (x, y) are x ± 0.5, y ± 0.5), and a lens position hashed from (i, j).
    CornerSample trace(int i, int j) {
        const auto ui = static_cast<uint32_t>(i), uj = static_cast<uint32_t>(j);
        const float inverse_scale = 1.0f / static_cast<float>(m_scale);  // a power of two: exact
        const glm::vec2 film(static_cast<float>(i) * inverse_scale - 0.5f,
                             static_cast<float>(j) * inverse_scale - 0.5f);
        const glm::vec2 lens(sample_uniform(ui, uj, 0, kLensDimension),
                             sample_uniform(ui, uj, 0, kLensDimension + 1));
        CornerSample sample;
        Ray ray;
        if (!m_camera.generate_ray(film, lens, ray)) return sample;
        sample.rgb = m_integrator.radiance(ray, PixelSample{ui, uj, 0, 1}, m_counters);
        sample.alpha = 1.0f;
        return sample;
    }

    static CornerSample mean(const CornerSample& a, const CornerSample& b, const CornerSample& c,
                             const CornerSample& d) {
        CornerSample m;
        m.rgb = (a.rgb + b.rgb + c.rgb + d.rgb) * 0.25f;
        m.alpha = (a.alpha + b.alpha + c.alpha + d.alpha) * 0.25f;
        return m;
    }

    // The square of side `size` lattice steps with top-left lattice point (i, j) and corners
    // top-left, top-right, bottom-left, bottom-right.
    CornerSample square(int i, int j, int size, const CornerSample& tl, const CornerSample& tr,
                        const CornerSample& bl, const CornerSample& br) {
        const float spread =
            std::max({corner_distance(tl, tr), corner_distance(tl, bl), corner_distance(tl, br),
                      corner_distance(tr, bl), corner_distance(tr, br), corner_distance(bl, br)});
        if (size == 1 || !(spread > m_threshold)) return mean(tl, tr, bl, br);
        const int half = size / 2;
        const CornerSample top = trace(i + half, j), left = trace(i, j + half),
                           centre = trace(i + half, j + half), right = trace(i + size, j + half),
                           bottom = trace(i + half, j + size);
        return mean(square(i, j, half, tl, top, left, centre),
                    square(i + half, j, half, top, tr, centre, right),
                    square(i, j + half, half, left, centre, bl, bottom),
                    square(i + half, j + half, half, centre, right, bottom, br));
    }

    const Camera& m_camera;
    const Integrator& m_integrator;
    float m_threshold;
    int m_depth;
    int m_scale;  // lattice steps per pixel, 2^depth
    RayCounters& m_counters;
    TileBorderCorners<CornerSample>* m_borders;
    std::vector<CornerSample> m_corners;
};

}  // namespace rayo
