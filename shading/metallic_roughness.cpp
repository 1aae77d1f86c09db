#include "shading/metallic_roughness.h"

#include <algorithm>

namespace rayo {

void apply_metallic_roughness(SurfaceCoefficients& c, const Vec3& base, float metallic,
                              double roughness) {
    // The metallic workflow (glTF 2.0 specification, Appendix B): the specular colour at normal
    // incidence is F0 = mix(0.04, baseColor, metallic) and only the dielectric part diffuses,
    // kd = (1 − metallic)·baseColor. F0 colours the Phong highlight, whose exponent matches a
    // GGX/Beckmann roughness α = r²: n = 2/α² − 2. A perfect mirror only approximates a smooth
    // surface, so its weight fades with roughness: reflect = F0·(1 − r)² (docs/scene-format.md).
    const Vec3 f0 = glm::mix(Vec3(0.04f), base, metallic);
    c.kd = (1.0f - metallic) * base;
    c.ka = 0.1f * base;
    c.ks = f0;
    const auto gloss = static_cast<float>((1.0 - roughness) * (1.0 - roughness));
    c.reflect = gloss * f0;
    const double r4 = roughness * roughness * roughness * roughness;
    const double exponent = r4 > 0.0 ? 2.0 / r4 - 2.0 : 10000.0;
    c.shininess = static_cast<float>(std::clamp(exponent, 1.0, 10000.0));
    c.metallic_roughness.used = true;
    c.metallic_roughness.base_color = base;
    c.metallic_roughness.metallic = metallic;
    c.metallic_roughness.roughness = static_cast<float>(roughness);
}

}  // namespace rayo
