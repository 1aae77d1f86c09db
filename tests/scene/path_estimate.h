#pragma once
// The mean of the path integrator's radiance along one ray over many camera samples of one
// pixel, with its standard error: what the statistical tests of tests/scene/path_test.cpp and
// environment_test.cpp compare against closed forms and against each other.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "apps/scene/scene_description.h"
#include "core/accel.h"
#include "shading/integrators/path.h"

namespace rayo_test {

struct Estimate {
    double mean = 0.0;
    double standard_error = 0.0;
};

// Channel `channel` of the radiance along origin + t·direction, samples 0 … samples − 1 of
// pixel (x, y); the scene's integrator must be path.
inline Estimate estimate_along(const rayo::SceneDescription& d, const rayo::Vec3& origin,
                               const rayo::Vec3& direction, uint32_t samples, int channel = 0,
                               uint32_t x = 3, uint32_t y = 5) {
    using namespace rayo;
    const Accel accel(d.scene, AccelOptions{});
    const IntegratorContext context{accel, d.shading};
    const PathIntegrator integrator(context, std::get<PathSettings>(d.settings.integrator));
    Ray ray;
    ray.origin = origin;
    ray.direction = glm::normalize(direction);
    RayCounters counters;
    double sum = 0.0, sum2 = 0.0;
    for (uint32_t s = 0; s < samples; ++s) {
        const double value =
            integrator.radiance(ray, PixelSample{x, y, s, samples}, counters)[channel];
        sum += value;
        sum2 += value * value;
    }
    const double mean = sum / samples;
    return {mean, std::sqrt(std::max(0.0, sum2 / samples - mean * mean) / samples)};
}

}  // namespace rayo_test
