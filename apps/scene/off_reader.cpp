#include "apps/scene/off_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "apps/scene/mesh_text.h"
#include "core/error.h"
#include "core/scene_limits.h"
#include "core/shapes/polygon_triangulation.h"

namespace rayo {
namespace {

// The lines of an OFF file that hold something: comments ('#' to the end of the line) removed,
// blank lines skipped.
class OffLines {
  public:
    explicit OffLines(std::string_view text) : m_lines(text) {}

    // The next line's words into words(); false at the end of the file.
    bool next() {
        std::string_view line;
        while (m_lines.next(line)) {
            line = line.substr(0, line.find('#'));
            split_words(line, m_words);
            if (!m_words.empty()) return true;
        }
        m_words.clear();
        return false;
    }
    const std::vector<std::string_view>& words() const { return m_words; }
    std::string place(const std::string& path) const {
        return path + ":" + std::to_string(m_lines.number());
    }
    size_t offset() const { return m_lines.offset(); }

  private:
    TextLines m_lines;
    std::vector<std::string_view> m_words;
};

// The numbers a vertex line holds in the variant [ST][C][N]OFF: x y z, then a normal, a colour of
// 3 or 4 numbers, texture coordinates (Geomview's order).
struct OffVariant {
    bool normals = false;
    bool colors = false;
    bool texture = false;

    size_t numbers_without_alpha() const {
        return 3 + (normals ? 3 : 0) + (colors ? 3 : 0) + (texture ? 2 : 0);
    }
    std::string layout() const {
        return std::string("x y z") + (normals ? " nx ny nz" : "") + (colors ? " r g b [a]" : "") +
               (texture ? " s t" : "");
    }
};

// Whether `word` is a count: digits only, at most 18 of them (so that it fits 64 bits).
bool is_count(std::string_view word) {
    return !word.empty() && word.size() <= 18 &&
           word.find_first_not_of("0123456789") == std::string_view::npos;
}

}  // namespace

PolygonMesh read_off(std::string_view bytes, const std::string& path) {
    OffLines lines(bytes);
    if (!lines.next()) throw InputError(path, "OFF file without the keyword OFF (only comments)");
    const std::string_view keyword = lines.words()[0];
    const size_t off = keyword.find("OFF");
    OffVariant variant;
    {
        const std::string_view prefix = keyword.substr(0, off);
        size_t k = 0;
        if (prefix.substr(k, 2) == "ST") {
            variant.texture = true;
            k += 2;
        }
        if (prefix.substr(k, 1) == "C") {
            variant.colors = true;
            ++k;
        }
        if (prefix.substr(k, 1) == "N") {
            variant.normals = true;
            ++k;
        }
        const bool higher = k < prefix.size() && (prefix[k] == '4' || prefix[k] == 'n');
        if (off != std::string_view::npos && higher) {
            throw InputError(lines.place(path), "OFF variant " +
                                                    quote_word(keyword.substr(0, off + 3)) +
                                                    " (4-D or n-D vertices) is not read; "
                                                    "expected OFF, COFF, NOFF, CNOFF, STOFF, ...");
        }
        // Without the keyword the file is not taken for OFF: assimp, which read it for rayo
        // before, read on as if it were and crashed (SIGSEGV; fuzz/corpus/mesh/
        // off_keyword_only_in_a_comment.off).
        if (off == std::string_view::npos || k != prefix.size()) {
            throw InputError(lines.place(path),
                             "not an OFF file: expected the keyword OFF (or COFF, NOFF, CNOFF, "
                             "STOFF, ...) first, got " +
                                 quote_word(keyword));
        }
    }
    // The counts: after the keyword on its line, in the same word too ("OFF1167483648"), or on
    // the next line with content.
    std::vector<std::string_view> counts;
    if (keyword.size() > off + 3) counts.push_back(keyword.substr(off + 3));
    counts.insert(counts.end(), lines.words().begin() + 1, lines.words().end());
    if (!counts.empty() && counts[0] == "BINARY") {
        throw InputError(lines.place(path), "binary OFF is not read; write it as text");
    }
    if (counts.empty()) {
        if (!lines.next()) {
            throw InputError(lines.place(path), "the file ends before the vertex and face counts");
        }
        counts = lines.words();
    }
    const std::string counts_place = lines.place(path);
    const std::string_view vertex_word = counts[0];
    const std::string_view face_word = counts.size() > 1 ? counts[1] : std::string_view();
    long long vertices = -1, faces = -1;
    if (!is_count(vertex_word) || !is_count(face_word) || !parse_integer(vertex_word, vertices) ||
        !parse_integer(face_word, faces)) {
        throw InputError(counts_place,
                         "expected the vertex and face counts, got " +
                             quote_word(std::string(vertex_word) +
                                        (counts.size() > 1 ? " " + std::string(face_word) : "")));
    }
    // A vertex line takes 6 bytes at least ("0 0 0\n"), a face line 4 ("1 0\n"): counts the rest
    // of the file cannot hold are refused before anything is reserved (2^31 vertices in a small
    // file took assimp to std::bad_alloc).
    const uint64_t rest = bytes.size() - lines.offset() + 1;
    if (6 * uint64_t(vertices) + 4 * uint64_t(faces) > rest) {
        throw InputError(counts_place, "declares " + std::to_string(vertices) + " vertices and " +
                                           std::to_string(faces) + " faces, more than the file's " +
                                           std::to_string(bytes.size()) + " bytes can hold");
    }

    PolygonMesh mesh;
    mesh.positions.reserve(vertices);
    if (variant.normals) mesh.normals.reserve(vertices);
    if (variant.colors) mesh.colors.reserve(vertices);
    const size_t numbers = variant.numbers_without_alpha();
    bool integer_colors = true;  // every colour number an integer (then 0..255 if one exceeds 1)
    double largest_color = 0.0;
    for (long long v = 0; v < vertices; ++v) {
        if (!lines.next()) {
            throw InputError(lines.place(path), "the file ends after " + std::to_string(v) +
                                                    " of its " + std::to_string(vertices) +
                                                    " vertices (truncated?)");
        }
        const std::vector<std::string_view>& w = lines.words();
        const std::string vertex = "vertex " + std::to_string(v);
        if (w.size() != numbers && !(variant.colors && w.size() == numbers + 1)) {
            throw InputError(
                lines.place(path),
                vertex + ": expected " + std::to_string(numbers) +
                    (variant.colors ? " or " + std::to_string(numbers + 1) : std::string()) +
                    " numbers (" + variant.layout() + "), got " + std::to_string(w.size()));
        }
        double value[12];
        for (size_t k = 0; k < w.size(); ++k) {
            if (!parse_number(w[k], value[k])) {
                throw InputError(lines.place(path),
                                 vertex + ": " + quote_word(w[k]) + " is not a number");
            }
        }
        const Vec3 position(value[0], value[1], value[2]);
        if (!point_within_scene_magnitude(position)) {
            throw InputError(lines.place(path),
                             vertex + ": coordinates must be " + kSceneMagnitudeRule);
        }
        mesh.positions.push_back(position);
        size_t at = 3;
        if (variant.normals) {
            mesh.normals.push_back(
                unit_normal_or_zero(Vec3(value[at], value[at + 1], value[at + 2])));
            at += 3;
        }
        if (variant.colors) {
            // Finite as floats: "2551e38" is a double but not a float (found by
            // fuzz/mesh_fuzz.cpp: the colour became infinite).
            const Vec3 color(value[at], value[at + 1], value[at + 2]);
            for (size_t k = 0; k < 3; ++k) {
                long long integer = 0;
                integer_colors = integer_colors && parse_integer(w[at + k], integer);
                if (!std::isfinite(color[k]) || color[k] < 0.0f) {
                    throw InputError(lines.place(path),
                                     vertex + ": the colour (r, g, b) must be finite and >= 0");
                }
                largest_color = std::max(largest_color, value[at + k]);
            }
            mesh.colors.push_back(color);
        }
    }
    if (variant.colors && integer_colors && largest_color > 1.0) {
        for (Vec3& c : mesh.colors) c /= 255.0f;
    }
    for (long long f = 0; f < faces; ++f) {
        if (!lines.next()) {
            throw InputError(lines.place(path), "the file ends after " + std::to_string(f) +
                                                    " of its " + std::to_string(faces) +
                                                    " faces (truncated?)");
        }
        const std::vector<std::string_view>& w = lines.words();
        const std::string face = "face " + std::to_string(f);
        long long corners = 0;
        if (w[0].size() > 9 || w[0].find_first_not_of("0123456789") != std::string_view::npos ||
            !parse_integer(w[0], corners) || corners < 1) {
            throw InputError(lines.place(path), face + ": expected its vertex count (1 or more)");
        }
        if (static_cast<size_t>(corners) > kMaxPolygonVertices) {
            throw InputError(lines.place(path),
                             face + ": " + polygon_vertex_limit_text(size_t(corners)));
        }
        const size_t given = w.size() - 1;
        if (given < static_cast<size_t>(corners)) {
            throw InputError(lines.place(path), face + ": expected " + std::to_string(corners) +
                                                    " vertex indices, got " +
                                                    std::to_string(given));
        }
        for (long long c = 1; c <= corners; ++c) {
            long long index = -1;
            if (!parse_integer(w[c], index)) {
                throw InputError(lines.place(path), face + ": vertex index " + quote_word(w[c]) +
                                                        " is not an integer");
            }
            // assimp clamped an index past the vertices to the last one (issue 30, item 10).
            if (index < 0 || index >= vertices) {
                throw InputError(lines.place(path), face + ": vertex index " +
                                                        std::to_string(index) +
                                                        " out of range (the file has " +
                                                        std::to_string(vertices) + " vertices)");
            }
            mesh.corners.push_back(static_cast<uint32_t>(index));
        }
        mesh.end_face();
        // A colour may follow: a colour-map index, r g b, or r g b a (not read).
        const size_t extra = given - corners;
        if (extra == 2 || extra > 4) {
            throw InputError(lines.place(path), face + ": " + std::to_string(extra) +
                                                    " numbers after its " +
                                                    std::to_string(corners) +
                                                    " vertex indices; a face colour has 1, 3 or 4");
        }
        for (size_t k = corners + 1; k < w.size(); ++k) {
            double value = 0;
            if (!parse_number(w[k], value)) {
                throw InputError(lines.place(path),
                                 face + ": its colour " + quote_word(w[k]) + " is not a number");
            }
        }
    }
    return mesh;
}

}  // namespace rayo
