#include "apps/scene/nff_loader.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <string_view>
#include <system_error>
#include <variant>
#include <vector>

#include "apps/scene/input_file.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/scene_limits.h"
#include "core/shapes/polygon_triangulation.h"

namespace rayo {
namespace {

// The longest NFF line has 9 tokens (`c` in its one-line form); more are counted, not kept.
constexpr int kMaxTokens = 12;

struct Line {
    std::string_view text;
    size_t number = 0;
};

// "source:line", built only when an error is thrown (no string work per parsed line).
struct Where {
    const std::string* source;
    size_t line;
    operator std::string() const { return *source + ":" + std::to_string(line); }
};

struct Tokens {
    std::array<std::string_view, kMaxTokens> items;
    int count = 0;  // all tokens on the line, even those beyond kMaxTokens
    std::string_view operator[](int i) const { return items[static_cast<size_t>(i)]; }
};

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

Tokens tokenize(std::string_view text) {
    Tokens tokens;
    size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && is_space(text[i])) ++i;
        if (i == text.size()) break;
        const size_t start = i;
        while (i < text.size() && !is_space(text[i])) ++i;
        if (tokens.count < kMaxTokens) {
            tokens.items[static_cast<size_t>(tokens.count)] = text.substr(start, i - start);
        }
        ++tokens.count;
    }
    return tokens;
}

std::string hex_byte(unsigned char c) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "0x%02X", static_cast<unsigned>(c));
    return buffer;
}

// Hands out the lines that carry content (blank lines and `#` comments are skipped), checking
// every line, comments included, for binary data.
class LineReader {
  public:
    LineReader(const std::string& text, const std::string& source)
        : m_text(text), m_source(source) {}

    // Next content line, or false at the end of the text.
    bool next(Line& line) {
        if (m_pending) {
            line = *m_pending;
            m_pending.reset();
            return true;
        }
        while (m_pos < m_text.size()) {
            const char* begin = m_text.data() + m_pos;
            const void* newline = std::memchr(begin, '\n', m_text.size() - m_pos);
            const size_t length =
                newline ? static_cast<size_t>(static_cast<const char*>(newline) - begin)
                        : m_text.size() - m_pos;
            m_pos += length + (newline ? 1 : 0);
            ++m_line;
            const std::string_view text(begin, length);
            const bool comment = check_text(text);
            if (comment) continue;
            size_t first = 0;
            while (first < text.size() && is_space(text[first])) ++first;
            if (first == text.size()) continue;
            line.text = text;
            line.number = m_line;
            return true;
        }
        return false;
    }

    // Gives back the line last returned by next(); the following next() returns it again.
    void unread(const Line& line) { m_pending = line; }

    // Number of the last line read from the text (the whole file once next() returned false).
    size_t last_line() const { return m_line; }

    Where where(size_t line) const { return Where{&m_source, line}; }

  private:
    // Rejects NUL and control bytes anywhere, and bytes >= 0x80 outside comments (NFF is ASCII;
    // comments may hold UTF-8). Returns whether the line is a comment.
    bool check_text(std::string_view text) const {
        bool comment = false, seen_content = false;
        for (const char ch : text) {
            const auto c = static_cast<unsigned char>(ch);
            if (c == 0) {
                throw InputError(where(m_line), "binary data (a NUL byte): not an NFF text file");
            }
            if ((c < 0x20 && !is_space(ch)) || c == 0x7F) {
                throw InputError(where(m_line), "binary data (control byte " + hex_byte(c) +
                                                    "): not an NFF text file");
            }
            if (!seen_content && !is_space(ch)) {
                seen_content = true;
                comment = ch == '#';
            }
            if (c >= 0x80 && !comment) {
                throw InputError(where(m_line), "non-ASCII byte " + hex_byte(c) +
                                                    " outside a comment: not an NFF text file");
            }
        }
        return comment;
    }

    const std::string& m_text;
    const std::string& m_source;
    size_t m_pos = 0;
    size_t m_line = 0;
    std::optional<Line> m_pending;
};

std::string quoted(std::string_view token) {
    constexpr size_t kMaxShown = 40;
    std::string shown(token.substr(0, kMaxShown));
    if (token.size() > kMaxShown) shown += "...";
    return "'" + shown + "'";
}

// Full-token number parsing: std::from_chars (locale independent, no iostream), which takes
// "-.5" and "1.11022e-16"; a leading '+' is allowed as strtod allows it. NaN, infinities and
// values beyond float range are rejected.
float parse_float(std::string_view token, const Where& where, const char* what) {
    const char* begin = token.data();
    const char* end = begin + token.size();
    if (begin != end && *begin == '+' && end - begin > 1 && begin[1] != '-' && begin[1] != '+') {
        ++begin;
    }
    double value = 0.0;
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (error == std::errc::result_out_of_range) {
        throw InputError(where,
                         std::string(what) + ": number " + quoted(token) + " is out of range");
    }
    if (error != std::errc() || stop != end) {
        throw InputError(where, std::string(what) + ": expected a number, got " + quoted(token));
    }
    if (!within_scene_magnitude(value)) {
        throw InputError(where, std::string(what) + ": expected " + kSceneMagnitudeRule + ", got " +
                                    quoted(token));
    }
    return static_cast<float>(value);
}

long long parse_int(std::string_view token, const Where& where, const char* what) {
    const char* begin = token.data();
    const char* end = begin + token.size();
    if (begin != end && *begin == '+' && end - begin > 1 && begin[1] != '-' && begin[1] != '+') {
        ++begin;
    }
    long long value = 0;
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (error != std::errc() || stop != end) {
        throw InputError(where, std::string(what) + ": expected an integer, got " + quoted(token));
    }
    return value;
}

Vec3 parse_vec3(const Tokens& tokens, int first, const Where& where, const char* what) {
    return Vec3(parse_float(tokens[first], where, what),
                parse_float(tokens[first + 1], where, what),
                parse_float(tokens[first + 2], where, what));
}

void require_non_negative(const Vec3& v, const Where& where, const char* what) {
    if (v.x < 0.0f || v.y < 0.0f || v.z < 0.0f) {
        throw InputError(where, std::string(what) + " must be >= 0 in every channel");
    }
}

// The `f` line's eight numbers, kept to recognise a repeat of the previous `f`.
using NffMaterialValues = std::array<float, 8>;

// docs/nff.md (reference reader): ambient Ka = 0.1·colour (Ia = 1), diffuse
// Kd·colour, white Phong highlight Ks·(R·V)^Shine, mirror reflection Ks, transmission T.
Material nff_material(const NffMaterialValues& f, const std::string& name) {
    const Vec3 colour(f[0], f[1], f[2]);
    const float kd = f[3], ks = f[4], shine = f[5], transmit = f[6], ior = f[7];
    Material m;
    m.name = name;
    m.ka = 0.1f * colour;
    m.kd = kd * colour;
    m.ks = Vec3(ks);
    m.shininess = shine;
    m.specular_model = SpecularModel::Phong;  // seed 000 eq. [24]
    m.reflect = Vec3(ks);
    m.transmit = Vec3(transmit);
    // Without transmission the index is never used; SPD files then often write 0.
    m.ior = (transmit > 0.0f || ior > 0.0f) ? ior : 1.0f;
    return m;
}

// Objects that come before any `f` get the material of `f 1 1 1 1 0 1 0 1` (white, diffuse),
// as the reference reader would use a default rather than fail.
constexpr NffMaterialValues kDefaultMaterial = {1.0f, 1.0f, 1.0f, 1.0f, 0.0f, 1.0f, 0.0f, 1.0f};

const char* const kViewKeywords[] = {"from", "at", "up", "angle", "hither", "resolution"};
constexpr int kViewLines = 6;

int view_keyword_index(std::string_view keyword) {
    for (int i = 0; i < kViewLines; ++i) {
        if (keyword == kViewKeywords[i]) return i;
    }
    return -1;
}

class NffParser {
  public:
    NffParser(const std::string& text, const std::string& source, NffLoadInfo* info,
              const NffOptions& options)
        : m_reader(text, source), m_info(info), m_options(options) {
        m_out.source = source;
        m_out.settings.whitted().max_depth = 5;  // the project's default for NFF scenes
    }

    SceneDescription parse() {
        Line line;
        while (m_reader.next(line)) {
            const Tokens tokens = tokenize(line.text);
            const std::string_view keyword = tokens[0];
            const Where where = m_reader.where(line.number);
            if (keyword == "s") {
                parse_sphere(tokens, where);
            } else if (keyword == "p" || keyword == "pp") {
                parse_polygon(tokens, line, keyword == "pp");
            } else if (keyword == "c") {
                parse_cone(tokens, line);
            } else if (keyword == "f") {
                parse_material(tokens, line);
            } else if (keyword == "l") {
                parse_light(tokens, where);
            } else if (keyword == "b") {
                expect_count(tokens, 4, where, "'b' expects 3 numbers (r g b)");
                const Vec3 background = parse_vec3(tokens, 1, where, "background colour");
                require_non_negative(background, where, "background colour");
                m_out.shading.background = background;
            } else if (keyword == "v") {
                parse_view(tokens, line);
            } else if (view_keyword_index(keyword) >= 0) {
                throw InputError(where, quoted(keyword) + " line outside a 'v' block");
            } else {
                throw InputError(where, "unknown entity " + quoted(keyword) +
                                            " (expected v, b, l, f, c, s, p, pp or #)");
            }
        }
        if (m_info) m_info->lines = m_reader.last_line();
        if (!m_view_line) {
            throw InputError(m_reader.where(std::max<size_t>(m_reader.last_line(), 1)),
                             "no viewpoint: the file has no 'v' block");
        }
        for (auto& mesh : m_meshes) {
            if (!mesh.triangles.empty()) m_out.scene.meshes.push_back(std::move(mesh));
        }
        scale_uncoloured_lights();
        return std::move(m_out);
    }

  private:
    static void expect_count(const Tokens& tokens, int count, const Where& where,
                             const char* expectation) {
        if (tokens.count != count) {
            throw InputError(where, std::string(expectation) + ", got " +
                                        std::to_string(tokens.count - 1) + " argument(s)");
        }
    }

    uint32_t current_material() {
        if (!m_material) {
            m_out.shading.materials.push_back(nff_material(kDefaultMaterial, "nff default"));
            m_material = static_cast<uint32_t>(m_out.shading.materials.size() - 1);
            m_material_values = kDefaultMaterial;
        }
        return *m_material;
    }

    void parse_view(const Tokens& tokens, const Line& v_line) {
        const Where v_where = m_reader.where(v_line.number);
        expect_count(tokens, 1, v_where, "'v' stands alone on its line (the view lines follow)");
        if (m_view_line) {
            throw InputError(v_where, "second 'v' block (the first is at line " +
                                          std::to_string(m_view_line) + ")");
        }
        std::array<bool, kViewLines> seen{};
        CameraDesc desc;
        desc.fov_spans_pixel_centres = true;  // NFF `angle` spans first to last pixel centres
        desc.distance = 1.0f;
        Line line;
        while (m_reader.next(line)) {
            const Tokens t = tokenize(line.text);
            const int index = view_keyword_index(t[0]);
            if (index < 0) {
                m_reader.unread(line);
                break;
            }
            const Where where = m_reader.where(line.number);
            if (seen[static_cast<size_t>(index)]) {
                throw InputError(where, "repeated " + quoted(t[0]) + " line in the 'v' block");
            }
            seen[static_cast<size_t>(index)] = true;
            switch (index) {
                case 0:
                    expect_count(t, 4, where, "'from' expects 3 numbers (x y z)");
                    desc.eye = parse_vec3(t, 1, where, "from");
                    break;
                case 1:
                    expect_count(t, 4, where, "'at' expects 3 numbers (x y z)");
                    desc.look_at = parse_vec3(t, 1, where, "at");
                    break;
                case 2:
                    expect_count(t, 4, where, "'up' expects 3 numbers (x y z)");
                    desc.up = parse_vec3(t, 1, where, "up");
                    break;
                case 3:
                    expect_count(t, 2, where, "'angle' expects 1 number (degrees)");
                    desc.vfov_degrees = parse_float(t[1], where, "angle");
                    break;
                case 4:
                    // Parsed and validated, then ignored: rayo has no near clipping plane.
                    expect_count(t, 2, where, "'hither' expects 1 number (distance)");
                    if (parse_float(t[1], where, "hither") < 0.0f) {
                        throw InputError(where, "hither must be >= 0");
                    }
                    break;
                case 5: {
                    expect_count(t, 3, where, "'resolution' expects 2 integers (width height)");
                    const long long w = parse_int(t[1], where, "resolution width");
                    const long long h = parse_int(t[2], where, "resolution height");
                    if (w <= 0 || h <= 0 || w > kMaxImageSide || h > kMaxImageSide) {
                        throw InputError(where, "resolution must be positive integers of at most " +
                                                    std::to_string(kMaxImageSide) + ", got " +
                                                    std::to_string(w) + " " + std::to_string(h));
                    }
                    desc.width = static_cast<int>(w);
                    desc.height = static_cast<int>(h);
                    break;
                }
            }
        }
        std::string missing;
        for (int i = 0; i < kViewLines; ++i) {
            if (!seen[static_cast<size_t>(i)]) missing += std::string(" ") + kViewKeywords[i];
        }
        if (!missing.empty()) {
            throw InputError(v_where, "incomplete 'v' block: missing" + missing +
                                          " (expected from, at, up, angle, hither, resolution)");
        }
        Camera::create(desc, v_where);  // eye = at, up parallel to the view, bad angle, ...
        m_out.scene.camera = desc;
        m_view_line = v_line.number;
    }

    void parse_light(const Tokens& tokens, const Where& where) {
        if (tokens.count != 4 && tokens.count != 7) {
            throw InputError(where, "'l' expects 3 numbers (x y z) or 6 (x y z r g b), got " +
                                        std::to_string(tokens.count - 1) + " argument(s)");
        }
        PointLight light;
        light.position = parse_vec3(tokens, 1, where, "light position");
        if (tokens.count == 7) {
            light.color = parse_vec3(tokens, 4, where, "light colour");
            require_non_negative(light.color, where, "light colour");
        }
        light.intensity = 1.0f;  // uncoloured lights are scaled once all are known
        light.attenuation.kind = Attenuation::Kind::None;
        if (tokens.count == 4) m_uncoloured_lights.push_back(m_out.shading.lights.size());
        m_out.shading.lights.emplace_back(light);
    }

    // Each of the N lights without a colour gets intensity 1/sqrt(N) (N counts every light),
    // or the caller's NffOptions::light_intensity: the SPD's rule (SPD README: the generators
    // scale the lights of every format but NFF by 1/sqrt(N); an NFF reader does it itself).
    void scale_uncoloured_lights() {
        const size_t n = m_out.shading.lights.size();
        if (n == 0) return;
        const float intensity = m_options.light_intensity.value_or(
            static_cast<float>(1.0 / std::sqrt(static_cast<double>(n))));
        for (const size_t i : m_uncoloured_lights) {
            std::get<PointLight>(m_out.shading.lights[i]).intensity = intensity;
        }
    }

    void parse_material(const Tokens& tokens, const Line& line) {
        const Where where = m_reader.where(line.number);
        expect_count(tokens, 9, where, "'f' expects 8 numbers (r g b Kd Ks Shine T ior)");
        static const char* const kNames[] = {"f red", "f green", "f blue", "f Kd",
                                             "f Ks",  "f Shine", "f T",    "f index of refraction"};
        NffMaterialValues values;
        for (int i = 0; i < 8; ++i) {
            values[static_cast<size_t>(i)] = parse_float(tokens[i + 1], where, kNames[i]);
            if (values[static_cast<size_t>(i)] < 0.0f) {
                throw InputError(where, std::string(kNames[i]) + " must be >= 0");
            }
        }
        if (values[6] > 0.0f && !(values[7] > 0.0f)) {
            throw InputError(where, "index of refraction must be > 0 for a transmissive material");
        }
        if (m_material && values == m_material_values) return;  // repeat of the previous `f`
        m_out.shading.materials.push_back(
            nff_material(values, "f line " + std::to_string(line.number)));
        m_material = static_cast<uint32_t>(m_out.shading.materials.size() - 1);
        m_material_values = values;
    }

    void parse_sphere(const Tokens& tokens, const Where& where) {
        expect_count(tokens, 5, where, "'s' expects 4 numbers (x y z radius)");
        Sphere sphere;
        sphere.center = parse_vec3(tokens, 1, where, "sphere centre");
        sphere.radius = parse_float(tokens[4], where, "sphere radius");
        if (!(sphere.radius > 0.0f)) {
            throw InputError(where, "sphere radius must be > 0, got " + quoted(tokens[4]));
        }
        sphere.material = current_material();
        m_out.scene.shapes.of<Sphere>().push_back(sphere);
    }

    // `c` alone with the base and apex lines after it (the NFF specification), or all eight
    // numbers on the `c` line (as the SPD generators write it).
    void parse_cone(const Tokens& tokens, const Line& line) {
        const Where where = m_reader.where(line.number);
        Cone cone;
        Where base_where = where, apex_where = where;
        if (tokens.count == 9) {
            cone.base = parse_vec3(tokens, 1, where, "cone base");
            cone.base_radius = parse_float(tokens[4], where, "cone base radius");
            cone.apex = parse_vec3(tokens, 5, where, "cone apex");
            cone.apex_radius = parse_float(tokens[8], where, "cone apex radius");
        } else if (tokens.count == 1) {
            Line end_line;
            for (int end = 0; end < 2; ++end) {
                if (!m_reader.next(end_line)) {
                    throw InputError(where,
                                     "truncated file: 'c' needs a base line and an apex "
                                     "line (x y z radius) after it");
                }
                const Where end_where = m_reader.where(end_line.number);
                const Tokens t = tokenize(end_line.text);
                const char* what = end == 0 ? "cone base" : "cone apex";
                if (t.count != 4) {
                    throw InputError(end_where, std::string(what) +
                                                    " line expects 4 numbers (x y z radius), got " +
                                                    std::to_string(t.count) + " token(s)");
                }
                const Vec3 point = parse_vec3(t, 0, end_where, what);
                const float radius = parse_float(t[3], end_where, what);
                if (end == 0) {
                    cone.base = point;
                    cone.base_radius = radius;
                    base_where = end_where;
                } else {
                    cone.apex = point;
                    cone.apex_radius = radius;
                    apex_where = end_where;
                }
            }
        } else {
            throw InputError(where,
                             "'c' expects either nothing (base and apex lines follow) or 8 "
                             "numbers (base x y z radius, apex x y z radius), got " +
                                 std::to_string(tokens.count - 1) + " argument(s)");
        }
        if (cone.base_radius < 0.0f) throw InputError(base_where, "cone base radius must be >= 0");
        if (cone.apex_radius < 0.0f) throw InputError(apex_where, "cone apex radius must be >= 0");
        if (!(cone.base_radius > 0.0f || cone.apex_radius > 0.0f)) {
            throw InputError(where, "cone has both radii zero");
        }
        const Vec3 axis = cone.apex - cone.base;
        if (!(glm::length(DVec3(axis)) > 0.0)) {
            throw InputError(where, "cone axis has zero length (base = apex)");
        }
        cone.material = current_material();
        m_out.scene.shapes.of<Cone>().push_back(cone);
    }

    void parse_polygon(const Tokens& tokens, const Line& line, bool patch) {
        const Where where = m_reader.where(line.number);
        const char* keyword = patch ? "pp" : "p";
        if (tokens.count != 2) {
            throw InputError(where, std::string("'") + keyword +
                                        "' expects 1 integer (the vertex count), got " +
                                        std::to_string(tokens.count - 1) + " argument(s)");
        }
        const long long count = parse_int(tokens[1], where, "vertex count");
        if (count < 3) {
            throw InputError(where,
                             "polygon needs at least 3 vertices, got " + std::to_string(count));
        }
        if (static_cast<unsigned long long>(count) > kMaxPolygonVertices) {
            throw InputError(where, polygon_vertex_limit_text(static_cast<size_t>(count)));
        }
        m_vertices.clear();
        m_normals.clear();
        const int expected = patch ? 6 : 3;
        Line vertex_line;
        for (long long i = 0; i < count; ++i) {
            if (!m_reader.next(vertex_line)) {
                throw InputError(where, "truncated file: polygon declares " +
                                            std::to_string(count) +
                                            " vertices, the file ends after " + std::to_string(i));
            }
            const Where vertex_where = m_reader.where(vertex_line.number);
            const Tokens t = tokenize(vertex_line.text);
            if (t.count != expected) {
                throw InputError(vertex_where,
                                 "vertex " + std::to_string(i + 1) + " of " +
                                     std::to_string(count) + " (polygon at line " +
                                     std::to_string(line.number) + ") expects " +
                                     (patch ? "6 numbers (x y z nx ny nz)" : "3 numbers (x y z)") +
                                     ", got " + std::to_string(t.count) + " token(s)");
            }
            m_vertices.push_back(parse_vec3(t, 0, vertex_where, "vertex"));
            if (patch) {
                const Vec3 n = parse_vec3(t, 3, vertex_where, "vertex normal");
                const double length = glm::length(DVec3(n));
                if (!(length > 0.0)) {
                    throw InputError(vertex_where, "vertex normal has zero length");
                }
                m_normals.push_back(Vec3(DVec3(n) / length));
            }
        }
        const uint32_t material = current_material();
        // Polygons of transmissive materials are two-sided; the others are one-sided by their
        // winding (docs/nff.md).
        const bool two_sided = m_out.shading.materials[material].transmissive();
        TriangleMesh& mesh = m_meshes[(patch ? 2 : 0) + (two_sided ? 1 : 0)];
        // NFF polygons may be concave (only the first two edges must form a convex angle).
        if (!mesh.add_polygon(m_vertices, m_normals, material)) {
            if (patch) {
                // Tessellated surfaces collapse at poles and seams (SPD teapot_1 has four such
                // patches): skip them, as they cover no area.
                m_out.warnings.push_back(std::string(where) +
                                         ": degenerate patch (zero area) skipped");
                m_out.skipped_triangles += m_vertices.size() - 2;
                return;
            }
            throw InputError(where, "degenerate polygon: its vertices enclose zero area");
        }
    }

    LineReader m_reader;
    NffLoadInfo* m_info;
    NffOptions m_options;
    std::vector<size_t> m_uncoloured_lights;  // indices into m_out.shading.lights
    SceneDescription m_out;
    size_t m_view_line = 0;
    std::optional<uint32_t> m_material;
    NffMaterialValues m_material_values{};
    // One-sided polygons, two-sided polygons, one-sided patches, two-sided patches.
    std::array<TriangleMesh, 4> m_meshes = make_meshes();
    std::vector<Vec3> m_vertices, m_normals;  // reused per polygon

    static std::array<TriangleMesh, 4> make_meshes() {
        std::array<TriangleMesh, 4> meshes;
        const char* const names[] = {"nff polygons", "nff polygons (two-sided)", "nff patches",
                                     "nff patches (two-sided)"};
        for (size_t i = 0; i < meshes.size(); ++i) {
            meshes[i].name = names[i];
            meshes[i].one_sided = (i % 2) == 0;
        }
        return meshes;
    }
};

}  // namespace

SceneDescription load_nff_string(const std::string& text, const std::string& source_name,
                                 NffLoadInfo* info, const NffOptions& options) {
    if (info) *info = NffLoadInfo{};
    if (options.light_intensity &&
        !(std::isfinite(*options.light_intensity) && *options.light_intensity >= 0.0f)) {
        throw InputError(source_name, "NFF light intensity must be a finite number >= 0, got " +
                                          std::to_string(*options.light_intensity));
    }
    NffParser parser(text, source_name, info, options);
    return parser.parse();
}

SceneDescription load_nff_file(const std::string& path, NffLoadInfo* info,
                               const NffOptions& options) {
    const std::string text = read_input_file(path, path, "scene file", kMaxSceneFileBytes);
    return load_nff_string(text, path, info, options);
}

}  // namespace rayo
