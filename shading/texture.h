#pragma once
// Solid procedural textures (seed 003 ch. 3): a closed set of scalar maps (std::variant,
// dispatched once per evaluation), coloured through a ramp with any number of stops, and the bump
// mapping the seed suggests (the shading normal perturbed by the texture's gradient).
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "core/film.h"
#include "core/math.h"
#include "shading/cellular.h"
#include "shading/noise.h"

namespace rayo {

// A colour ramp (seed 003 "color_agua", generalized): linear interpolation between stops sorted
// by position, the end colours beyond the ends.
struct ColorStop {
    float position = 0.0f;
    Vec3 color{0.0f};
};

class ColorRamp {
  public:
    ColorRamp();  // black at 0 to white at 1
    // Sorts the stops by position (stable). Throws std::invalid_argument when there are none.
    explicit ColorRamp(std::vector<ColorStop> stops);

    Vec3 eval(float t) const;
    const std::vector<ColorStop>& stops() const { return m_stops; }

  private:
    std::vector<ColorStop> m_stops;
};

// sRGB-encoded 8-bit value to scene-linear (the seed's colours are display RGB; the film is
// linear).
float srgb8_to_linear(int value);
Vec3 srgb8_to_linear(int r, int g, int b);

// The maps. Each returns a scalar in [0, 1] at q = p / scale.
struct ConstantMap {
    Vec3 color{0.5f};  // the texture's colour; its scalar value is 0 (no bump)
};
struct ValueNoiseMap {  // fBm of 3-D value noise (seed 003's "Perlin noise" map)
    FbmParams fbm{4, 0.5f, 2.0f};
};
struct PerlinMap {  // 0.5 + 0.5·fBm of gradient noise
    FbmParams fbm;
};
struct TurbulenceMap {  // Σ a_i |gradient noise| / Σ a_i
    FbmParams fbm;
};
enum class CellularFeature {
    F1,
    F2,
    F3,
    F2MinusF1,    // cell borders
    Combination,  // seed 003: 2·F1/(F2 + F3)
    CellId,       // a flat random value per cell
};
struct CellularMap {
    DistanceMetric metric = DistanceMetric::Euclidean;
    CellularFeature feature = CellularFeature::Combination;  // F values clamped to [0, 1]
};
struct MarbleMap {  // 0.5 + 0.5·sin(2π·frequency·q.x + distortion·turbulence(q)) (Perlin 1985)
    FbmParams fbm{5, 0.5f, 2.0f};
    float frequency = 1.0f;
    float distortion = 6.0f;
};
struct WarpedMap {  // domain warping: 0.5 + 0.5·fBm(q + warp·(fBm, fBm, fBm)(q))
    FbmParams fbm{5, 0.5f, 2.0f};
    float warp = 1.5f;
};
struct PoolBottomMap {   // seed 003 fig. 3.13, see texture.cpp
    float warp = 0.12f;  // fBm displacement of the cells, in units of the large cell
};

using TextureMap = std::variant<ConstantMap, ValueNoiseMap, PerlinMap, TurbulenceMap, CellularMap,
                                MarbleMap, WarpedMap, PoolBottomMap>;

struct Texture {
    std::string name;
    TextureMap map;
    float scale = 1.0f;  // world units per feature (one cell, one lattice step): q = p / scale
    uint32_t seed = 0;
    ColorRamp ramp;  // scalar -> colour (not used by ConstantMap)

    float value(const Vec3& p) const;  // in [0, 1]
    Vec3 color(const Vec3& p) const;
    // ∇value in world units, by central differences of step kGradientStep·scale.
    Vec3 gradient(const Vec3& p) const;
};

constexpr float kGradientStep = 1e-3f;

// The kinds by name ("constant", "value", "perlin", "turbulence", "cellular", "marble", "warped",
// "pool-bottom") and a texture of that kind with its default parameters and ramp (the pool
// bottom's water ramp RGB(40,100,162) -> RGB(91,187,201), a veined ramp for marble). Unknown
// names throw InputError("", ...) listing the known ones.
const std::vector<std::string>& texture_kind_names();
// The same names joined by ", ", for messages and the CLI's help.
std::string texture_kind_list();
Texture make_texture(const std::string& kind);

// Bump mapping (seed 003's suggested extension): the normal of the surface displaced along
// `normal` by strength·value, n' = normalize(n − strength·∇_t), where ∇_t is the part of
// `gradient` tangent to the surface. Returns `normal` unchanged where the tangential gradient is
// zero; the result stays strictly on the side of `facing_geometric` (lifted when n·Ng <
// kMinBumpCosine).
constexpr float kMinBumpCosine = 0.02f;
Vec3 perturb_normal(const Vec3& normal, const Vec3& gradient, float strength,
                    const Vec3& facing_geometric);
// The same with the texture's gradient, scaled by its feature size so that `strength` means
// height per unit of value relative to the feature size (independent of `scale`).
Vec3 bump_normal(const Texture& texture, float strength, const Vec3& position, const Vec3& normal,
                 const Vec3& facing_geometric);

// The texture laid flat on the plane z = 0, for inspection (`rayo texture`): pixel (i, j) shows
// the colour at ((i + 0.5)/ppu, (height − j − 0.5)/ppu, 0), +y up, so at the default 64 pixels
// per unit a texture of scale 1 has the seed's 64-pixel cells.
constexpr float kTexturePixelsPerUnit = 64.0f;
Film texture_image(const Texture& texture, int width, int height,
                   float pixels_per_unit = kTexturePixelsPerUnit);

}  // namespace rayo
