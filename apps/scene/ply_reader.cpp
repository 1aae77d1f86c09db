#include "apps/scene/ply_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "apps/scene/input_file.h"
#include "apps/scene/mesh_text.h"
#include "core/error.h"
#include "core/scene_limits.h"
#include "core/shapes/polygon_triangulation.h"

namespace rayo {
namespace {

// Vertex and corner indices are 32-bit: a file within the size limit cannot declare more (a
// vertex takes three bytes at least, a binary corner one).
static_assert(kMaxMeshFileBytes < (uint64_t(1) << 32), "PLY indices must fit 32 bits");

// The scalar types of the PLY format (turk-1994), under both of their names.
enum class PlyType : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyTypeName {
    const char* name;
    PlyType type;
};
constexpr PlyTypeName kPlyTypeNames[] = {
    {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64}};

bool ply_type_named(std::string_view name, PlyType& type) {
    for (const PlyTypeName& t : kPlyTypeNames) {
        if (name == t.name) {
            type = t.type;
            return true;
        }
    }
    return false;
}

const char* name_of(PlyType type) {
    for (const PlyTypeName& t : kPlyTypeNames) {
        if (t.type == type) return t.name;  // the first name: the 1994 one
    }
    return "?";
}

size_t bytes_of(PlyType type) {
    switch (type) {
        case PlyType::Int8:
        case PlyType::UInt8:
            return 1;
        case PlyType::Int16:
        case PlyType::UInt16:
            return 2;
        case PlyType::Int32:
        case PlyType::UInt32:
        case PlyType::Float32:
            return 4;
        case PlyType::Float64:
            return 8;
    }
    return 8;
}

bool is_integer(PlyType type) {
    return type != PlyType::Float32 && type != PlyType::Float64;
}
bool is_signed(PlyType type) {
    return type == PlyType::Int8 || type == PlyType::Int16 || type == PlyType::Int32;
}

// The range of an integer type.
long long min_of(PlyType type) {
    return is_signed(type) ? -(1ll << (8 * bytes_of(type) - 1)) : 0;
}
long long max_of(PlyType type) {
    const size_t bits = 8 * bytes_of(type) - (is_signed(type) ? 1 : 0);
    return (1ll << bits) - 1;
}

// What the reader does with a property's values.
enum class Role : uint8_t { None, X, Y, Z, NX, NY, NZ, Red, Green, Blue, FaceIndices };
constexpr size_t kRoles = 10;  // the scalar roles, None included (the slots of one vertex)

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;  // a list's item type
    bool list = false;
    PlyType count_type = PlyType::UInt8;
    size_t line = 0;
    Role role = Role::None;
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    size_t line = 0;
    std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
    size_t body_offset = 0;        // the byte after end_header's line
    size_t end_line = 0;           // end_header's line number
    PlyElement* vertex = nullptr;  // in `elements`
    PlyElement* face = nullptr;
    bool normals = false;  // nx, ny and nz are all there
    bool colors = false;   // red, green and blue are all there
};

std::string line_place(const std::string& path, size_t line) {
    return path + ":" + std::to_string(line);
}

// The element and property lines, the format, and the end: each line is checked whole (a line
// of other words, or of too many, is refused at its number: assimp, which read PLY for rayo
// before, read the header as a stream of words and took "property uchar blueAelement face 5" as
// the declaration of an element; fuzz/mesh_fuzz.cpp).
PlyHeader read_header(std::string_view bytes, const std::string& path) {
    PlyHeader header;
    TextLines lines(bytes);
    std::string_view line;
    std::vector<std::string_view> words;
    lines.next(line);
    split_words(line, words);
    if (words.size() != 1 || words[0] != "ply") {
        throw InputError(line_place(path, 1),
                         "not a PLY file: its first line must be 'ply', got " + quote_word(line));
    }
    // A file cut inside its header, or one whose end line is damaged ("propeend_header"): said
    // so, not reported as whatever the first body bytes look like.
    if (bytes.find("\nend_header") == std::string_view::npos) {
        throw InputError(path, "PLY header without its end_header line (truncated or corrupt)");
    }
    bool has_format = false;
    while (lines.next(line)) {
        const size_t number = lines.number();
        const std::string place = line_place(path, number);
        split_words(line, words);
        if (words.empty()) continue;
        const std::string_view keyword = words[0];
        if (keyword.substr(0, 10) == "end_header") {
            // The body starts on the next line: "end_header\x1a0 0 0" would misplace it.
            if (words.size() != 1 || keyword.size() != 10) {
                throw InputError(place, "PLY header: end_header must end its line");
            }
            header.body_offset = lines.offset();
            header.end_line = number;
            break;
        }
        if (keyword == "comment" || keyword == "obj_info") continue;
        const bool list = words.size() > 1 && words[1] == "list";
        const bool element = keyword == "element", format = keyword == "format";
        const bool property = keyword == "property";
        if (!element && !format && !property) {
            throw InputError(place, "PLY header line starts with " + quote_word(keyword) +
                                        ": expected format, comment, obj_info, element, property "
                                        "or end_header");
        }
        if ((element && words.size() != 3) || (format && words.size() != 3) ||
            (property && words.size() != (list ? 5u : 3u))) {
            throw InputError(place, std::string("PLY header: expected ") +
                                        (element  ? "element NAME COUNT"
                                         : format ? "format TYPE VERSION"
                                         : list   ? "property list COUNT_TYPE ITEM_TYPE NAME"
                                                  : "property TYPE NAME") +
                                        ", got " + quote_word(line));
        }
        if (format) {
            if (has_format) throw InputError(place, "PLY header: a second format line");
            has_format = true;
            if (words[1] == "ascii") {
                header.format = PlyFormat::Ascii;
            } else if (words[1] == "binary_little_endian") {
                header.format = PlyFormat::BinaryLittleEndian;
            } else if (words[1] == "binary_big_endian") {
                header.format = PlyFormat::BinaryBigEndian;
            } else {
                throw InputError(place, "PLY format " + quote_word(words[1]) +
                                            ": expected ascii, binary_little_endian or "
                                            "binary_big_endian");
            }
        } else if (element) {
            PlyElement e;
            e.name = std::string(words[1]);
            e.line = number;
            // A name is a word ("2147483648face 2" is not an element of 2^31 instances).
            if (!(std::isalpha(static_cast<unsigned char>(e.name[0])) || e.name[0] == '_')) {
                throw InputError(place,
                                 "PLY element name " + quote_word(e.name) + ": expected a word");
            }
            long long count = -1;
            if (words[2].find_first_not_of("0123456789") != std::string_view::npos ||
                words[2].size() > 18 || !parse_integer(words[2], count)) {
                throw InputError(place, "PLY element '" + e.name + "': expected a count, got " +
                                            quote_word(words[2]));
            }
            e.count = static_cast<uint64_t>(count);
            for (const PlyElement& other : header.elements) {
                if (other.name == e.name && (e.name == "vertex" || e.name == "face")) {
                    throw InputError(place, "PLY header: a second element '" + e.name +
                                                "' (the first is at line " +
                                                std::to_string(other.line) + ")");
                }
            }
            header.elements.push_back(std::move(e));
        } else {
            if (header.elements.empty()) {
                throw InputError(place, "PLY header: a property before the first element");
            }
            PlyProperty p;
            p.line = number;
            p.list = list;
            p.name = std::string(words.back());
            const std::string_view type = words[list ? 3 : 1];
            const std::string_view count_type = list ? words[2] : type;
            for (const std::string_view t : {count_type, type}) {
                PlyType parsed;
                if (!ply_type_named(t, parsed)) {
                    throw InputError(place, "PLY property type " + quote_word(t) +
                                                " is not a PLY type (char, uchar, short, ushort, "
                                                "int, uint, float, double, or int8 ... float64)");
                }
            }
            ply_type_named(type, p.type);
            ply_type_named(count_type, p.count_type);
            if (list && !is_integer(p.count_type)) {
                throw InputError(place, "PLY list '" + p.name + "': its count type " +
                                            quote_word(count_type) +
                                            " must be an integer type (uchar, ushort, uint, ...)");
            }
            PlyElement& e = header.elements.back();
            for (const PlyProperty& other : e.properties) {
                if (other.name == p.name) {
                    throw InputError(place, "PLY element '" + e.name + "' has a second property '" +
                                                p.name + "' (the first is at line " +
                                                std::to_string(other.line) + ")");
                }
            }
            e.properties.push_back(std::move(p));
        }
    }
    if (!has_format) {
        throw InputError(path,
                         "PLY header without a format line (format ascii 1.0, "
                         "binary_little_endian 1.0 or binary_big_endian 1.0)");
    }
    return header;
}

// What the reader takes from the elements `vertex` and `face`, the positions required.
void assign_roles(PlyHeader& header, const std::string& path) {
    for (PlyElement& e : header.elements) {
        if (e.name == "vertex") header.vertex = &e;
        if (e.name == "face") header.face = &e;
    }
    const auto find = [](PlyElement* e, const char* name) -> PlyProperty* {
        if (e == nullptr) return nullptr;
        for (PlyProperty& p : e->properties) {
            if (p.name == name) return &p;
        }
        return nullptr;
    };
    PlyElement* vertex = header.vertex;
    PlyProperty* x = find(vertex, "x");
    PlyProperty* y = find(vertex, "y");
    PlyProperty* z = find(vertex, "z");
    if (!x || !y || !z || x->list || y->list || z->list) {
        throw InputError(path,
                         "PLY header: no element 'vertex' with properties x, y and z (the "
                         "positions a mesh needs)");
    }
    x->role = Role::X;
    y->role = Role::Y;
    z->role = Role::Z;
    // Normals and colours are all three or none; a list of that name is not one.
    const auto take = [&](std::array<const char*, 3> names, std::array<Role, 3> roles) {
        std::array<PlyProperty*, 3> found{};
        for (size_t k = 0; k < 3; ++k) {
            found[k] = find(vertex, names[k]);
            if (!found[k] || found[k]->list) return false;
        }
        for (size_t k = 0; k < 3; ++k) found[k]->role = roles[k];
        return true;
    };
    header.normals = take({"nx", "ny", "nz"}, {Role::NX, Role::NY, Role::NZ});
    header.colors = take({"red", "green", "blue"}, {Role::Red, Role::Green, Role::Blue});
    if (header.face != nullptr) {
        PlyElement* face = header.face;
        PlyProperty* indices = find(face, "vertex_indices");
        if (!indices) indices = find(face, "vertex_index");
        const std::string place = line_place(path, indices ? indices->line : header.face->line);
        if (!indices) {
            throw InputError(place,
                             "PLY element 'face' without its list of vertex indices (property "
                             "list uchar int vertex_indices)");
        }
        if (!indices->list || !is_integer(indices->type)) {
            throw InputError(place, "PLY face property '" + indices->name +
                                        "' must be a list of integers (property list uchar int " +
                                        indices->name + ")");
        }
        indices->role = Role::FaceIndices;
    }
}

// The fewest bytes one instance of `e` can take: in binary a scalar's size (a list's count's),
// in ASCII a digit and a blank per value.
uint64_t min_instance_bytes(const PlyElement& e, bool ascii) {
    uint64_t bytes = 0;
    for (const PlyProperty& p : e.properties) {
        bytes += ascii ? 2 : bytes_of(p.list ? p.count_type : p.type);
    }
    return bytes;
}

// Every element count against the bytes after the header, before anything is reserved:
// "element vertex 2000000000" in a small file is refused at its line.
void check_counts(const PlyHeader& header, uint64_t body, const std::string& path) {
    const bool ascii = header.format == PlyFormat::Ascii;
    if (ascii) ++body;  // the last line may go without its '\n'
    uint64_t needed = 0;
    for (const PlyElement& e : header.elements) {
        if (e.count > 0 && e.properties.empty()) {
            throw InputError(line_place(path, e.line), "PLY element '" + e.name + "' declares " +
                                                           std::to_string(e.count) +
                                                           " instances but no properties");
        }
        if (e.count == 0) continue;
        const uint64_t each = min_instance_bytes(e, ascii);
        if (e.count > (body - needed) / each) {
            throw InputError(line_place(path, e.line),
                             "PLY element '" + e.name + "' declares " + std::to_string(e.count) +
                                 " instances, more than the " +
                                 std::to_string(ascii ? body - 1 : body) +
                                 " bytes after the header can hold (truncated file?)");
        }
        needed += e.count * each;
    }
}

// The body, instance by instance, in either kind: values by their declared types, list counts
// checked before their items are read, errors naming the element and instance (and the line in
// ASCII).
class PlyBody {
  public:
    PlyBody(std::string_view bytes, const PlyHeader& header, const std::string& path)
        : m_bytes(bytes),
          m_path(path),
          m_ascii(header.format == PlyFormat::Ascii),
          m_big_endian(header.format == PlyFormat::BinaryBigEndian),
          m_at(header.body_offset),
          m_lines(bytes.substr(header.body_offset), header.end_line + 1) {}

    void begin(const PlyElement& e, uint64_t instance) {
        m_element = &e;
        m_instance = instance;
        if (!m_ascii) return;
        std::string_view line;
        do {
            if (!m_lines.next(line)) {
                throw InputError(m_path, prefix() + " is missing: the file ends at line " +
                                             std::to_string(m_lines.number()) + " (truncated?)");
            }
            split_words(line, m_words);
        } while (m_words.empty());
        m_word = 0;
    }

    void end() {
        if (!m_ascii || m_word == m_words.size()) return;
        fail(std::to_string(m_words.size() - m_word) + " values after its last property (" +
             quote_word(m_words[m_word]) + "...): the header declares fewer");
    }

    double scalar(const PlyProperty& p) {
        if (!m_ascii) {
            need(bytes_of(p.type));
            return binary_number(p.type);
        }
        return ascii_number(p.type, "property '" + p.name + "'");
    }

    // A list's count, its items checked to be there (bytes in binary, values on the line).
    uint64_t list_count(const PlyProperty& p) {
        if (!m_ascii) {
            need(bytes_of(p.count_type));
            const long long count = binary_integer(p.count_type);
            if (count < 0) {
                fail("list count " + std::to_string(count) + " is negative");
            }
            const uint64_t items = static_cast<uint64_t>(count);
            if (items > (m_bytes.size() - m_at) / bytes_of(p.type)) past_end();
            return items;
        }
        const std::string_view word = next_word("list '" + p.name + "'");
        long long count = -1;
        if (!parse_integer(word, count) || count < 0) {
            fail("list count " + quote_word(word) + " is not a count (an integer >= 0)");
        }
        const auto items = static_cast<uint64_t>(count);
        if (items > m_words.size() - m_word) {
            fail("list '" + p.name + "' counts " + std::to_string(items) +
                 " values, the line has " + std::to_string(m_words.size() - m_word) + " after it");
        }
        return items;
    }

    // A list item that must be an integer (a face's vertex index).
    long long list_integer(const PlyProperty& p) {
        if (!m_ascii) return binary_integer(p.type);  // list_count checked the bytes
        const std::string_view word = m_words[m_word++];
        long long value = 0;
        if (!parse_integer(word, value)) {
            fail("list '" + p.name + "': " + quote_word(word) + " is not an integer");
        }
        return value;
    }

    void skip_list(const PlyProperty& p, uint64_t items) {
        if (!m_ascii) {
            m_at += items * bytes_of(p.type);  // list_count checked the bytes
            return;
        }
        for (uint64_t k = 0; k < items; ++k) ascii_number(p.type, "list '" + p.name + "'");
    }

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(m_ascii ? line_place(m_path, m_lines.number()) : m_path,
                         prefix() + ": " + what);
    }

  private:
    std::string prefix() const {
        return "PLY element '" + m_element->name + "' instance " + std::to_string(m_instance);
    }

    [[noreturn]] void past_end() const {
        throw InputError(m_path, prefix() + " runs past the end of the file (" +
                                     std::to_string(m_bytes.size()) + " bytes): truncated?");
    }

    void need(size_t bytes) const {
        if (bytes > m_bytes.size() - m_at) past_end();
    }

    // The next `bytes` bytes as an unsigned number in the file's byte order.
    uint64_t raw(size_t bytes) {
        uint64_t value = 0;
        const auto* p = reinterpret_cast<const unsigned char*>(m_bytes.data() + m_at);
        for (size_t k = 0; k < bytes; ++k) {
            value |= uint64_t(p[m_big_endian ? bytes - 1 - k : k]) << (8 * k);
        }
        m_at += bytes;
        return value;
    }

    long long binary_integer(PlyType type) {
        const size_t bytes = bytes_of(type);
        const uint64_t value = raw(bytes);
        if (is_signed(type) && (value >> (8 * bytes - 1)) != 0) {
            return static_cast<long long>(value) - (1ll << (8 * bytes));
        }
        return static_cast<long long>(value);
    }

    double binary_number(PlyType type) {
        if (type == PlyType::Float32) {
            const auto bits = static_cast<uint32_t>(raw(4));
            float value;
            std::memcpy(&value, &bits, 4);
            return value;
        }
        if (type == PlyType::Float64) {
            const uint64_t bits = raw(8);
            double value;
            std::memcpy(&value, &bits, 8);
            return value;
        }
        return static_cast<double>(binary_integer(type));
    }

    std::string_view next_word(const std::string& what) {
        if (m_word == m_words.size()) {
            fail("the line ends before " + what + " (the header declares more values)");
        }
        return m_words[m_word++];
    }

    double ascii_number(PlyType type, const std::string& what) {
        const std::string_view word = next_word(what);
        if (is_integer(type)) {
            long long value = 0;
            if (!parse_integer(word, value) || value < min_of(type) || value > max_of(type)) {
                fail(what + ": " + quote_word(word) + " is not a " + name_of(type) +
                     " (an integer from " + std::to_string(min_of(type)) + " to " +
                     std::to_string(max_of(type)) + ")");
            }
            return static_cast<double>(value);
        }
        double value = 0;
        if (!parse_number(word, value)) fail(what + ": " + quote_word(word) + " is not a number");
        return value;
    }

    std::string_view m_bytes;
    const std::string& m_path;
    bool m_ascii;
    bool m_big_endian;
    size_t m_at;  // binary: the next byte
    TextLines m_lines;
    std::vector<std::string_view> m_words;  // ASCII: the instance's line
    size_t m_word = 0;
    const PlyElement* m_element = nullptr;
    uint64_t m_instance = 0;
};

}  // namespace

PolygonMesh read_ply(std::string_view bytes, const std::string& path) {
    PlyHeader header = read_header(bytes, path);
    assign_roles(header, path);
    check_counts(header, bytes.size() - header.body_offset, path);

    PolygonMesh mesh;
    const uint64_t vertices = header.vertex->count;
    mesh.positions.reserve(vertices);
    if (header.normals) mesh.normals.reserve(vertices);
    if (header.colors) mesh.colors.reserve(vertices);
    // A colour of an integer type is scaled by the type's largest value (uchar 255).
    std::array<double, 3> color_scale{1.0, 1.0, 1.0};
    for (const PlyProperty& p : header.vertex->properties) {
        if (p.role < Role::Red || p.role > Role::Blue || !is_integer(p.type)) continue;
        color_scale[static_cast<size_t>(p.role) - static_cast<size_t>(Role::Red)] =
            1.0 / static_cast<double>(max_of(p.type));
    }

    PlyBody body(bytes, header, path);
    std::array<double, kRoles> slot{};
    for (const PlyElement& e : header.elements) {
        const bool is_vertex = &e == header.vertex;
        for (uint64_t i = 0; i < e.count; ++i) {
            body.begin(e, i);
            for (const PlyProperty& p : e.properties) {
                if (!p.list) {
                    const double value = body.scalar(p);
                    if (p.role != Role::None) slot[static_cast<size_t>(p.role)] = value;
                    continue;
                }
                const uint64_t items = body.list_count(p);
                if (p.role != Role::FaceIndices) {
                    body.skip_list(p, items);
                    continue;
                }
                // A face of no corners stopped assimp's post-processing (SIGABRT); one of
                // 10^5 took ear clipping past 20 s (docs/limits.md, "Input files").
                if (items == 0) body.fail("a face of no vertices");
                if (items > kMaxPolygonVertices) body.fail(polygon_vertex_limit_text(items));
                for (uint64_t k = 0; k < items; ++k) {
                    const long long index = body.list_integer(p);
                    if (index < 0 || static_cast<uint64_t>(index) >= vertices) {
                        body.fail("vertex index " + std::to_string(index) +
                                  " out of range (the file has " + std::to_string(vertices) +
                                  " vertices)");
                    }
                    mesh.corners.push_back(static_cast<uint32_t>(index));
                }
                mesh.end_face();
            }
            body.end();
            if (!is_vertex) continue;
            const auto at = [&](Role r) { return slot[static_cast<size_t>(r)]; };
            const Vec3 position(at(Role::X), at(Role::Y), at(Role::Z));
            if (!point_within_scene_magnitude(position)) {
                body.fail(std::string("coordinates must be ") + kSceneMagnitudeRule);
            }
            mesh.positions.push_back(position);
            if (header.normals) {
                mesh.normals.push_back(
                    unit_normal_or_zero(Vec3(at(Role::NX), at(Role::NY), at(Role::NZ))));
            }
            if (header.colors) {
                const Vec3 color(at(Role::Red) * color_scale[0], at(Role::Green) * color_scale[1],
                                 at(Role::Blue) * color_scale[2]);
                if (!std::isfinite(color.x) || !std::isfinite(color.y) || !std::isfinite(color.z) ||
                    color.x < 0.0f || color.y < 0.0f || color.z < 0.0f) {
                    body.fail("the colour (red, green, blue) must be finite and >= 0");
                }
                mesh.colors.push_back(color);
            }
        }
    }
    return mesh;
}

}  // namespace rayo
