#include "apps/scene/stl_reader.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

#include "apps/scene/mesh_text.h"
#include "core/error.h"
#include "core/scene_limits.h"

namespace rayo {
namespace {

constexpr uint64_t kBinaryHeaderBytes = 84;  // 80 bytes of text, the 32-bit triangle count
constexpr uint64_t kBinaryTriangleBytes = 50;

// The words of an ASCII STL, one after another across lines, each with its line.
class StlWords {
  public:
    StlWords(std::string_view text, const std::string& path) : m_lines(text), m_path(path) {}

    // The next word; false at the end of the text.
    bool next(std::string_view& word) {
        while (m_word == m_words.size()) {
            std::string_view line;
            if (!m_lines.next(line)) return false;
            split_words(line, m_words);
            m_word = 0;
        }
        word = m_words[m_word++];
        return true;
    }
    // Drops the rest of the current line (a solid's name, what follows endsolid).
    void skip_line() { m_word = m_words.size(); }

    // The next word, which must be `keyword`.
    void expect(const char* keyword) {
        std::string_view word;
        if (!next(word)) {
            fail(std::string("the file ends where '") + keyword + "' was expected (truncated?)");
        }
        if (word != keyword) {
            fail(std::string("expected '") + keyword + "', got " + quote_word(word));
        }
    }

    // Three numbers after `what` ("vertex", "normal").
    Vec3 numbers(const char* what) {
        double xyz[3];
        for (double& value : xyz) {
            std::string_view word;
            const bool got = next(word);
            if (!got || !parse_number(word, value)) {
                fail(std::string("STL ") + what + ": expected 3 numbers, got " +
                     (got ? quote_word(word) : "''"));
            }
        }
        return Vec3(xyz[0], xyz[1], xyz[2]);
    }

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(m_path + ":" + std::to_string(m_lines.number()),
                         what.compare(0, 4, "STL ") == 0 ? what : "STL: " + what);
    }

  private:
    TextLines m_lines;
    const std::string& m_path;
    std::vector<std::string_view> m_words;
    size_t m_word = 0;
};

// Every facet of every solid; each facet's corners appended as they are (joined later).
void read_ascii(std::string_view text, const std::string& path, PolygonMesh& mesh) {
    StlWords words(text, path);
    std::string_view word;
    bool any_solid = false;
    while (words.next(word)) {
        if (word.substr(0, 5) != "solid") {
            words.fail(std::string(any_solid ? "expected 'solid' or the end of the file"
                                             : "expected 'solid'") +
                       ", got " + quote_word(word));
        }
        any_solid = true;
        words.skip_line();  // the solid's name
        for (;;) {
            if (!words.next(word)) {
                words.fail("the file ends inside a solid, before 'endsolid' (truncated?)");
            }
            if (word == "endsolid") {
                words.skip_line();
                break;
            }
            if (word != "facet") {
                words.fail("expected 'facet' or 'endsolid', got " + quote_word(word));
            }
            words.expect("normal");
            words.numbers("normal");  // dropped: the corners are joined instead
            words.expect("outer");
            words.expect("loop");
            for (int k = 0; k < 3; ++k) {
                words.expect("vertex");
                const Vec3 p = words.numbers("vertex");
                if (!point_within_scene_magnitude(p)) {
                    words.fail(std::string("STL vertex: coordinates must be ") +
                               kSceneMagnitudeRule);
                }
                mesh.corners.push_back(static_cast<uint32_t>(mesh.positions.size()));
                mesh.positions.push_back(p);
            }
            // A facet of four corners or more is not STL (assimp, which read it for rayo
            // before, skipped the fourth; a polygon would need a plane STL does not promise).
            if (!words.next(word)) {
                words.fail("the file ends where 'endloop' was expected (truncated?)");
            }
            if (word == "vertex") words.fail("a facet has 3 vertices, this one more");
            if (word != "endloop") words.fail("expected 'endloop', got " + quote_word(word));
            words.expect("endfacet");
            mesh.end_face();
        }
    }
}

float little_endian_float(const char* bytes) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes);
    const uint32_t bits =
        uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
    float value;
    std::memcpy(&value, &bits, 4);
    return value;
}

void read_binary(std::string_view bytes, uint32_t count, const std::string& path,
                 PolygonMesh& mesh) {
    mesh.positions.reserve(3 * uint64_t(count));
    mesh.corners.reserve(3 * uint64_t(count));
    mesh.face_ends.reserve(count);
    for (uint32_t t = 0; t < count; ++t) {
        const char* corner = bytes.data() + kBinaryHeaderBytes + t * kBinaryTriangleBytes + 12;
        for (int k = 0; k < 3; ++k, corner += 12) {
            const Vec3 p(little_endian_float(corner), little_endian_float(corner + 4),
                         little_endian_float(corner + 8));
            if (!point_within_scene_magnitude(p)) {
                throw InputError(path, "binary STL triangle " + std::to_string(t) +
                                           ": coordinates must be " + kSceneMagnitudeRule);
            }
            mesh.corners.push_back(static_cast<uint32_t>(mesh.positions.size()));
            mesh.positions.push_back(p);
        }
        mesh.end_face();
    }
}

// One vertex per distinct position, numbered in the order of first use; the corners renumbered.
// Sorting (not hashing) keeps the memory to two indices per corner.
void join_identical_corners(PolygonMesh& mesh) {
    const std::vector<Vec3>& p = mesh.positions;
    std::vector<uint32_t> order(p.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto less = [&](uint32_t a, uint32_t b) {
        if (p[a].x != p[b].x) return p[a].x < p[b].x;
        if (p[a].y != p[b].y) return p[a].y < p[b].y;
        if (p[a].z != p[b].z) return p[a].z < p[b].z;
        return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    // first[i]: the first corner with corner i's position.
    std::vector<uint32_t> first(p.size());
    for (size_t k = 0; k < order.size();) {
        size_t end = k + 1;
        while (end < order.size() && p[order[end]] == p[order[k]]) ++end;
        for (size_t j = k; j < end; ++j) first[order[j]] = order[k];
        k = end;
    }
    std::vector<uint32_t>().swap(order);
    std::vector<Vec3> joined;
    std::vector<uint32_t> number(p.size());  // corner i's joined vertex
    for (size_t i = 0; i < p.size(); ++i) {
        if (first[i] == i) {
            number[i] = static_cast<uint32_t>(joined.size());
            joined.push_back(p[i]);
        } else {
            number[i] = number[first[i]];  // first[i] < i: numbered already
        }
    }
    for (uint32_t& c : mesh.corners) c = number[c];
    mesh.positions = std::move(joined);
}

}  // namespace

PolygonMesh read_stl(std::string_view bytes, const std::string& path) {
    PolygonMesh mesh;
    const size_t start = std::min(bytes.size(), bytes.find_first_not_of(" \t\r\n\v\f"));
    const bool says_solid = bytes.substr(start, 5) == "solid";
    uint32_t count = 0;
    if (bytes.size() >= kBinaryHeaderBytes) {
        const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + 80);
        count = uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
    }
    const uint64_t binary_size = kBinaryHeaderBytes + kBinaryTriangleBytes * uint64_t(count);
    if (says_solid && (bytes.size() < kBinaryHeaderBytes || bytes.size() != binary_size)) {
        read_ascii(bytes, path, mesh);
    } else {
        if (bytes.size() < kBinaryHeaderBytes) {
            throw InputError(path, "binary STL shorter than its 84-byte header (" +
                                       std::to_string(bytes.size()) + " bytes)");
        }
        if (bytes.size() < binary_size) {
            throw InputError(path, "binary STL declares " + std::to_string(count) +
                                       " triangles, which take " + std::to_string(binary_size) +
                                       " bytes, but the file has " + std::to_string(bytes.size()));
        }
        read_binary(bytes, count, path, mesh);
    }
    join_identical_corners(mesh);
    return mesh;
}

}  // namespace rayo
