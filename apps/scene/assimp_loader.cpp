#include "apps/scene/assimp_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/math.h"
#include "core/path_util.h"
#include "core/scene_limits.h"
#include "core/shapes/polygon_triangulation.h"

namespace rayo {
namespace {

std::string format_name(const std::string& ext) {
    if (ext == ".ply") return "PLY";
    if (ext == ".stl") return "STL";
    return "OFF";
}

// A PLY header's property: a scalar of `type`, or a list of `item_type` whose count is a `type`.
struct PlyProperty {
    std::string type;
    bool list = false;
    std::string item_type;
    std::string name;
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    size_t line = 0;
    std::vector<PlyProperty> properties;
};

// The bytes of a binary PLY scalar; 0 for a type PLY does not have.
uint64_t ply_scalar_bytes(const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
        type == "float32") {
        return 4;
    }
    if (type == "double" || type == "float64") return 8;
    return 0;
}

// The smallest number of bytes one instance of a PLY element can take: in ASCII every property
// is at least a digit and a separator, in binary its scalar's size (a list's count).
uint64_t min_element_bytes(const std::vector<PlyProperty>& properties, bool ascii) {
    uint64_t bytes = 0;
    for (const PlyProperty& p : properties) {
        const uint64_t size = ply_scalar_bytes(p.type);
        bytes += ascii ? 2 : (size > 0 ? size : 4);
    }
    return bytes > 0 ? bytes : 1;  // an element without properties still takes a line
}

// Whether `token` is one number, whole (strtod reads all of it: "1e-3", "-2", "nan", "inf").
bool is_number(const std::string& token) {
    char* end = nullptr;
    std::strtod(token.c_str(), &end);
    return !token.empty() && end == token.c_str() + token.size();
}

std::string ply_instance(const PlyElement& e, uint64_t i) {
    return "PLY element '" + e.name + "' instance " + std::to_string(i);
}

// A binary PLY body walked instance by instance, as assimp will read it: every list count is
// read (a negative one in a signed type is refused: assimp would reserve 2^32 − 5 items), and
// an instance that runs past the end of the file is refused at its index (assimp read on into
// zeros and reported a vertex index out of range). Unknown types are left to assimp.
void check_binary_ply_body(const std::string& bytes, uint64_t start,
                           const std::vector<PlyElement>& elements, bool big_endian,
                           const std::string& path) {
    uint64_t at = start;
    const uint64_t size = bytes.size();
    auto past_end = [&](const PlyElement& e, uint64_t i) {
        throw InputError(path, ply_instance(e, i) + " runs past the end of the file (" +
                                   std::to_string(size) + " bytes): truncated?");
    };
    for (const PlyElement& e : elements) {
        for (uint64_t i = 0; i < e.count; ++i) {
            for (const PlyProperty& p : e.properties) {
                const uint64_t scalar = ply_scalar_bytes(p.type);
                if (scalar == 0) return;
                if (at + scalar > size) past_end(e, i);
                if (!p.list) {
                    at += scalar;
                    continue;
                }
                const uint64_t item = ply_scalar_bytes(p.item_type);
                if (item == 0 || p.type == "float" || p.type == "float32" || p.type == "double" ||
                    p.type == "float64") {
                    return;
                }
                uint64_t raw = 0;
                for (uint64_t k = 0; k < scalar; ++k) {
                    const auto byte =
                        static_cast<uint8_t>(bytes[at + (big_endian ? k : scalar - 1 - k)]);
                    raw = (raw << 8) | byte;
                }
                at += scalar;
                const bool is_signed = p.type[0] != 'u';
                if (is_signed && (raw >> (8 * scalar - 1)) != 0) {
                    const long long count = static_cast<long long>(raw) - (1ll << (8 * scalar));
                    throw InputError(path, ply_instance(e, i) + ": list count " +
                                               std::to_string(count) + " is negative");
                }
                if (raw > (size - at) / item) past_end(e, i);
                at += raw * item;
            }
        }
    }
}

// An ASCII PLY body, line by line from `first_line`: a list count that is not a non-negative
// integer is refused at its line (assimp took −5 as a count of 2^32 − 5 and ran out of memory),
// and so is a value that is not a number (assimp threw on it and leaked the mesh it was building:
// LeakSanitizer, found by fuzz/mesh_fuzz.cpp). Lines that hold fewer values than one instance,
// and properties of types PLY does not have, are left to assimp.
void check_ascii_ply_lists(const std::string& bytes, uint64_t start, size_t first_line,
                           const std::vector<PlyElement>& elements, const std::string& path) {
    std::istringstream body(bytes.substr(start));
    std::string line, token;
    size_t number = first_line;
    for (const PlyElement& e : elements) {
        for (uint64_t i = 0; i < e.count; ++i, ++number) {
            if (!std::getline(body, line)) return;
            std::istringstream in(line);
            const auto value = [&](const std::string& type) {
                if (!(in >> token)) return false;
                if (ply_scalar_bytes(type) > 0 && !is_number(token)) {
                    throw InputError(path + ":" + std::to_string(number),
                                     ply_instance(e, i) + ": '" + token + "' is not a number");
                }
                return true;
            };
            for (const PlyProperty& p : e.properties) {
                if (!p.list) {
                    if (!value(p.type)) return;
                    continue;
                }
                if (!(in >> token)) return;
                if (token.find_first_not_of("0123456789") != std::string::npos ||
                    token.size() > 9) {
                    throw InputError(path + ":" + std::to_string(number),
                                     ply_instance(e, i) + ": list count '" + token +
                                         "' is not a count (an integer >= 0)");
                }
                for (long n = std::stol(token); n > 0; --n) {
                    if (!value(p.item_type)) return;
                }
            }
        }
    }
}

// A PLY header's element counts against the bytes that follow it: assimp reserves memory for
// every declared instance before reading one, so "element vertex 2000000000" in a small file
// would take gigabytes. A header without end_header is refused; other headers it cannot parse are
// left to assimp's own message.
void check_ply_header(const std::string& bytes, const std::string& path) {
    if (bytes.compare(0, 3, "ply") != 0) return;
    // assimp 5.2 read a binary body past a header without its end line (SIGSEGV, also for
    // "propeend_header"; found by fuzz/mesh_fuzz.cpp).
    size_t end = bytes.find("\nend_header");
    if (end != std::string::npos) ++end;
    if (end == std::string::npos) {
        throw InputError(path, "PLY header without its end_header line (truncated or corrupt)");
    }
    // The body starts on the next line: "end_header\x1a0 0 0" misplaced it here, and assimp took
    // a list count of -5 read where a vertex was (a hang; found by fuzz/mesh_fuzz.cpp).
    const size_t after = end + std::strlen("end_header");
    const size_t line_end = std::min(bytes.find('\n', after), bytes.size());
    if (bytes.find_first_not_of(" \t\r", after) < line_end) {
        throw InputError(path, "PLY header: end_header must end its line");
    }
    const size_t body_start = bytes.find('\n', end);
    const uint64_t body = body_start == std::string::npos ? 0 : bytes.size() - body_start - 1;
    std::istringstream header(bytes.substr(0, end));
    std::string line;
    std::string format;
    std::vector<PlyElement> elements;
    size_t number = 0;
    while (std::getline(header, line)) {
        ++number;
        std::istringstream in(line);
        std::string keyword;
        in >> keyword;
        // The header's words (the PLY format); assimp aborted on a line of another ("proper
        // alphaar red", "elrty ...": SIGABRT; found by fuzz/mesh_fuzz.cpp).
        if (number > 1 && keyword != "format" && keyword != "comment" && keyword != "obj_info" &&
            keyword != "element" && keyword != "property" && !keyword.empty()) {
            throw InputError(path + ":" + std::to_string(number),
                             "PLY header line starts with '" + keyword +
                                 "': expected format, comment, obj_info, element, property or "
                                 "end_header");
        }
        // Each element and property line holds its words and no more: assimp reads the header as
        // words, not lines ("property uchar blueAelement face 5" declared an element to it: a
        // 2 GB reservation; found by fuzz/mesh_fuzz.cpp).
        size_t words = 0;
        std::istringstream count_in(line);
        for (std::string word; count_in >> word;) ++words;
        const bool list = line.find(" list ") != std::string::npos;
        if ((keyword == "element" && words != 3) ||
            (keyword == "property" && words != (list ? 5u : 3u)) ||
            (keyword == "format" && words != 3)) {
            throw InputError(path + ":" + std::to_string(number),
                             "PLY header: expected " +
                                 std::string(keyword == "element"  ? "element NAME COUNT"
                                             : keyword == "format" ? "format TYPE VERSION"
                                             : list                ? "property list COUNT_TYPE "
                                                                     "ITEM_TYPE NAME"
                                                                   : "property TYPE NAME") +
                                 ", got '" + line + "'");
        }
        if (keyword == "format") {
            in >> format;
        } else if (keyword == "element") {
            PlyElement e;
            std::string count;
            in >> e.name >> count;
            // A name is a word: assimp read "2147483648face 2" as that many instances (a 48 GB
            // reservation; found by fuzz/mesh_fuzz.cpp).
            if (e.name.empty() ||
                !(std::isalpha(static_cast<unsigned char>(e.name[0])) || e.name[0] == '_')) {
                throw InputError(path + ":" + std::to_string(number),
                                 "PLY element name '" + e.name + "': expected a word");
            }
            if (count.empty() || count.find_first_not_of("0123456789") != std::string::npos ||
                count.size() > 18) {
                throw InputError(
                    path + ":" + std::to_string(number),
                    "PLY element '" + e.name + "': expected a count, got '" + count + "'");
            }
            e.count = std::stoull(count);
            e.line = number;
            elements.push_back(e);
        } else if (keyword == "property" && !elements.empty()) {
            PlyProperty property;
            in >> property.type;
            if (property.type == "list") {
                property.list = true;
                in >> property.type >> property.item_type;  // the count's type, the items'
            }
            in >> property.name;
            // A type PLY does not have: assimp read on with a size of its own (a 32 GB list;
            // found by fuzz/mesh_fuzz.cpp).
            std::vector<std::string> types{property.type};
            if (property.list) types.push_back(property.item_type);
            for (const std::string& type : types) {
                if (ply_scalar_bytes(type) > 0) continue;
                throw InputError(path + ":" + std::to_string(number),
                                 "PLY property type '" + type +
                                     "' is not a PLY type (char, uchar, short, ushort, int, uint, "
                                     "float, double, or int8 ... float64)");
            }
            elements.back().properties.push_back(property);
        }
    }
    // A format assimp does not know it read as binary (a 32 GB list; found by fuzz/mesh_fuzz.cpp).
    if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian") {
        throw InputError(path, "PLY format '" + format +
                                   "': expected ascii, binary_little_endian or binary_big_endian");
    }
    // assimp takes positions from an element named "vertex" only; without one (a misspelt name,
    // "vertccccex", found by fuzz/mesh_fuzz.cpp) it reserved gigabytes and failed with
    // std::bad_alloc, a message that says nothing of the file.
    const auto vertex = std::find_if(elements.begin(), elements.end(),
                                     [](const PlyElement& e) { return e.name == "vertex"; });
    const auto has = [&](const char* name) {
        return std::any_of(vertex->properties.begin(), vertex->properties.end(),
                           [&](const PlyProperty& p) { return !p.list && p.name == name; });
    };
    if (vertex == elements.end() || !has("x") || !has("y") || !has("z")) {
        throw InputError(path,
                         "PLY header: no element 'vertex' with properties x, y and z (the "
                         "positions a mesh needs)");
    }
    const bool ascii = format == "ascii";
    uint64_t needed = 0;
    for (const PlyElement& e : elements) {
        const uint64_t each = min_element_bytes(e.properties, ascii);
        if (e.count > (body - needed) / each) {
            throw InputError(path + ":" + std::to_string(e.line),
                             "PLY element '" + e.name + "' declares " + std::to_string(e.count) +
                                 " instances, more than the " + std::to_string(body) +
                                 " bytes after the header can hold (truncated file?)");
        }
        needed += e.count * each;
    }
    if (body_start == std::string::npos) return;
    if (format == "binary_little_endian" || format == "binary_big_endian") {
        check_binary_ply_body(bytes, body_start + 1, elements, format == "binary_big_endian", path);
    } else if (ascii) {
        check_ascii_ply_lists(bytes, body_start + 1, number + 2, elements, path);
    }
}

// Every face's vertex indices within its mesh, as read (assimp's importers do not all check), and
// every face with one at least;
// returns whether a face has three corners or more (post-processing drops points and lines).
bool check_face_indices(const aiScene& scene, const std::string& path) {
    bool any_polygon = false;
    for (unsigned int m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        for (unsigned int f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            any_polygon |= face.mNumIndices >= 3;
            // A PLY list count of 0: assimp's post-processing asserts on such a face (SIGABRT;
            // found by fuzz/mesh_fuzz.cpp).
            if (face.mNumIndices == 0) {
                throw InputError(path, "face " + std::to_string(f) + " has no vertices");
            }
            if (face.mNumIndices > kMaxPolygonVertices) {
                throw InputError(path, "face " + std::to_string(f) + ": " +
                                           polygon_vertex_limit_text(face.mNumIndices));
            }
            for (unsigned int k = 0; k < face.mNumIndices; ++k) {
                if (face.mIndices[k] >= mesh.mNumVertices) {
                    throw InputError(path, "face " + std::to_string(f) + ": vertex index " +
                                               std::to_string(face.mIndices[k]) +
                                               " out of range (the file has " +
                                               std::to_string(mesh.mNumVertices) + " vertices)");
                }
            }
        }
    }
    return any_polygon;
}

// An ASCII STL's facets, checked before assimp reads them: assimp 5.2 throws on a coordinate that
// is not a number, a vertex or normal cut short, or a solid whose vertices do not match its facet
// normals three to one, and leaks the mesh it was building each time (LeakSanitizer; found by
// fuzz/mesh_fuzz.cpp). Refused at `path:line`, as the other formats' errors are. As assimp reads
// them: a facet's vertices past its third are skipped, a normal counts (for three vertices) only
// right after "facet", a solid's name is the rest of its line, and the text ends at a NUL byte
// (assimp reads it as a C string).
void check_ascii_stl(const std::string& bytes, const std::string& path) {
    std::istringstream in(bytes.substr(0, bytes.find('\0')));
    std::string line, token, previous;
    size_t number = 0, solid_line = 0;
    bool in_solid = false;
    uint64_t positions = 0, normals = 0, facet_vertices = 3;  // vertices outside a facet: skipped
    const auto end_solid = [&] {
        if (in_solid && (positions == 0 || positions != normals)) {
            throw InputError(path + ":" + std::to_string(solid_line),
                             "STL solid without whole facets (" + std::to_string(positions) +
                                 " vertices for " + std::to_string(normals / 3) +
                                 " facet normals; each facet has a normal and 3 vertices)");
        }
        in_solid = false;
        positions = normals = 0;
    };
    while (std::getline(in, line)) {
        ++number;
        std::istringstream words(line);
        previous.clear();
        for (bool first = true; words >> token; first = false, previous = token) {
            if (first && token.compare(0, 5, "solid") == 0) {
                end_solid();
                in_solid = true;
                solid_line = number;
                break;
            }
            if (token == "endsolid") {
                end_solid();
                break;
            }
            if (token == "facet") facet_vertices = 0;
            const bool vertex = token == "vertex";
            if ((!vertex && token != "normal") || (vertex && facet_vertices >= 3)) continue;
            for (int k = 0; k < 3; ++k) {
                std::string value;
                if (!(words >> value) || !is_number(value)) {
                    throw InputError(path + ":" + std::to_string(number),
                                     "STL " + token + ": expected 3 numbers, got '" + value + "'");
                }
            }
            if (vertex) {
                ++facet_vertices;
                ++positions;
            } else if (previous == "facet") {
                normals += 3;
            }
        }
    }
    end_solid();
}

// A binary STL's triangle count against its size (80-byte header, the count, 50 bytes per
// triangle), checked before assimp reads it: assimp takes a count the file cannot hold for an
// ASCII file and fails with a message about its own temporary name. A file that starts with
// "solid" and is not exactly the size of a binary one is ASCII (check_ascii_stl).
void check_stl_file(const std::string& bytes, const std::string& path) {
    constexpr uint64_t kHeader = 84, kTriangle = 50;
    const bool says_solid = bytes.compare(0, 5, "solid") == 0;
    if (bytes.size() < kHeader) {
        if (says_solid) return check_ascii_stl(bytes, path);
        throw InputError(path, "binary STL shorter than its 84-byte header (" +
                                   std::to_string(bytes.size()) + " bytes)");
    }
    uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, sizeof count);
    const uint64_t expected = kHeader + kTriangle * count;
    if (says_solid && bytes.size() != expected) return check_ascii_stl(bytes, path);
    if (bytes.size() < expected) {
        throw InputError(path, "binary STL declares " + std::to_string(count) +
                                   " triangles, which take " + std::to_string(expected) +
                                   " bytes, but the file has " + std::to_string(bytes.size()));
    }
}

// An OFF file's counts and face indices, checked before assimp reads it: assimp reserves
// the declared vertex count before reading (2^31 vertices in a small file: bad_alloc) and clamps
// an out-of-range face index to the last vertex (a silently different mesh). Refused at
// `path:line`, as PLY's are.
void check_off_file(const std::string& bytes, const std::string& path) {
    std::istringstream in(bytes);
    std::string line;
    size_t number = 0;
    // The next line with content, comments (#) removed; false at the end.
    const auto next = [&](std::istringstream& fields) {
        while (std::getline(in, line)) {
            ++number;
            const size_t hash = line.find('#');
            if (hash != std::string::npos) line.erase(hash);
            if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
            fields.clear();
            fields.str(line);
            return true;
        }
        return false;
    };
    std::istringstream fields;
    if (!next(fields)) return;
    std::string keyword;
    fields >> keyword;
    // OFF and its variants with colours, normals, texture coordinates or 4-D vertices (COFF,
    // NOFF, STOFF, 4OFF, ...: more numbers on a vertex's line): assimp died on a COFF face cut
    // short (SIGSEGV; found by fuzz/mesh_fuzz.cpp). nOFF (a dimension line first) is left to it.
    // assimp reads the counts right after "OFF", in the same word too ("OFF1167483648": a
    // 2 GB reservation; found by fuzz/mesh_fuzz.cpp).
    const size_t off = keyword.find("OFF");
    if (off == std::string::npos || keyword.find_first_not_of("STCN4") < off) return;
    std::string rest;
    std::getline(fields, rest);
    fields.clear();
    fields.str(keyword.substr(off + 3) + " " + rest);
    // The counts as words of digits: one past the range of long long failed to parse and was
    // left to assimp, which wrapped it (a 45 GB reservation; found by fuzz/mesh_fuzz.cpp).
    std::string vertex_count, face_count;
    if (!(fields >> vertex_count)) {
        if (!next(fields)) return;
        fields >> vertex_count;
    }
    fields >> face_count;
    const auto where = [&] { return path + ":" + std::to_string(number); };
    long long vertices = -1, faces = -1;
    for (auto [text, value] :
         {std::pair{&vertex_count, &vertices}, std::pair{&face_count, &faces}}) {
        if (text->empty() || text->size() > 18 ||
            text->find_first_not_of("0123456789") != std::string::npos) {
            throw InputError(where(), "expected the vertex and face counts, got '" + vertex_count +
                                          " " + face_count + "'");
        }
        *value = std::stoll(*text);
    }
    // Each vertex and face takes a line of at least 6 bytes ("0 0 0\n", "3 0 1 2" less one).
    if (static_cast<unsigned long long>(vertices) + static_cast<unsigned long long>(faces) >
        bytes.size() / 6) {
        throw InputError(where(), "declares " + std::to_string(vertices) + " vertices and " +
                                      std::to_string(faces) + " faces, more than the file's " +
                                      std::to_string(bytes.size()) + " bytes can hold");
    }
    // Vertices of three numbers and faces of as many indices as they count: assimp read on past
    // a face line cut short ("3t ...": SIGSEGV; found by fuzz/mesh_fuzz.cpp).
    for (long long v = 0; v < vertices; ++v) {
        if (!next(fields)) return;  // short files: assimp's message
        // Whole numbers: assimp read "1-5" or "1FF" otherwise than this walk would (SIGSEGV).
        std::string x, y, z;
        if (!(fields >> x >> y >> z) || !is_number(x) || !is_number(y) || !is_number(z)) {
            throw InputError(where(), "vertex " + std::to_string(v) + ": expected 3 coordinates");
        }
    }
    for (long long f = 0; f < faces; ++f) {
        if (!next(fields)) return;
        long long corners = 0;
        std::string word;
        if (!(fields >> word) || word.size() > 9 ||
            word.find_first_not_of("0123456789") != std::string::npos ||
            (corners = std::stoll(word)) < 1) {
            throw InputError(
                where(), "face " + std::to_string(f) + ": expected its vertex count (1 or more)");
        }
        for (long long c = 0; c < corners; ++c) {
            long long index = 0;
            if (!(fields >> word) || word.size() > 18 || word == "-" ||
                word.find_first_not_of("0123456789", word[0] == '-' ? 1 : 0) != std::string::npos) {
                throw InputError(where(), "face " + std::to_string(f) + ": expected " +
                                              std::to_string(corners) + " vertex indices");
            }
            index = std::stoll(word);
            if (index < 0 || index >= vertices) {
                throw InputError(where(), "face " + std::to_string(f) + ": vertex index " +
                                              std::to_string(index) +
                                              " out of range (the file has " +
                                              std::to_string(vertices) + " vertices)");
            }
        }
    }
}

}  // namespace

bool is_assimp_mesh_file(const std::string& path) {
    const std::string ext = lower_extension(path);
    return ext == ".ply" || ext == ".stl" || ext == ".off";
}

TriangleMesh load_assimp_mesh(const std::string& path, std::vector<Material>& materials,
                              const std::string& where, MeshImportStats* stats,
                              const FileAccess& access) {
    const std::string bytes = read_input_file(path, where, "mesh file", kMaxMeshFileBytes, access);
    const std::string ext = lower_extension(path);
    const std::string format = format_name(ext);
    if (bytes.empty()) throw InputError(path, "empty " + format + " file");
    if (ext == ".ply") check_ply_header(bytes, path);
    if (ext == ".off") check_off_file(bytes, path);
    if (ext == ".stl") check_stl_file(bytes, path);

    Assimp::Importer importer;
    // Points and lines (PLY point clouds, edges) are dropped; faces are triangulated.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    unsigned int flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                         aiProcess_SortByPType | aiProcess_PreTransformVertices;
    if (ext == ".stl") {
        // STL repeats every corner with its facet's normal: without the normals the corners
        // join, and the mesh is shaded flat (as the facet normals would) or smooth on request.
        importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS);
        flags |= aiProcess_RemoveComponent;
    }
    // Read without post-processing, the face indices checked, then processed: the steps index
    // vertices by the file's face indices unchecked (assimp's ValidateDataStructure would also
    // refuse an empty solid or a point cloud, which are not errors here).
    const aiScene* scene =
        importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, ext.c_str() + 1);
    if (scene != nullptr) {
        if (!check_face_indices(*scene, path)) {
            throw InputError(where, "mesh file '" + path +
                                        "' contains no (non-degenerate) triangles (only points "
                                        "or lines)");
        }
        scene = importer.ApplyPostProcessing(flags);
    }
    if (scene == nullptr) {
        const std::string message = one_line(importer.GetErrorString());
        throw InputError(
            place_with_line(path, message),
            "malformed " + format + ": " + (message.empty() ? "cannot parse" : message));
    }
    bool any_normals = false, any_colors = false;
    for (unsigned int m = 0; m < scene->mNumMeshes; ++m) {
        any_normals |= scene->mMeshes[m]->HasNormals();
        any_colors |= scene->mMeshes[m]->HasVertexColors(0);
    }
    const uint32_t material = default_material_index(materials);
    TriangleMesh mesh;
    mesh.name = file_name(path);
    for (unsigned int m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh& in = *scene->mMeshes[m];
        const auto offset = static_cast<uint32_t>(mesh.positions.size());
        for (unsigned int v = 0; v < in.mNumVertices; ++v) {
            const Vec3 p(in.mVertices[v].x, in.mVertices[v].y, in.mVertices[v].z);
            if (!point_within_scene_magnitude(p)) {
                throw InputError(path, "vertex " + std::to_string(offset + v) +
                                           ": coordinates must be " + kSceneMagnitudeRule);
            }
            mesh.positions.push_back(p);
            if (any_normals) {
                Vec3 n(0.0f);  // zero: no normal here, shade with the geometric normal
                if (in.HasNormals()) {
                    n = Vec3(in.mNormals[v].x, in.mNormals[v].y, in.mNormals[v].z);
                    const float length = glm::length(n);
                    n = (std::isfinite(length) && length > 0.0f) ? n / length : Vec3(0.0f);
                }
                mesh.normals.push_back(n);
            }
            if (any_colors) {
                Vec3 c(1.0f);  // white: this part of the file has no colours
                if (in.HasVertexColors(0)) {
                    const aiColor4D& a = in.mColors[0][v];
                    c = Vec3(a.r, a.g, a.b);
                    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) ||
                        c.x < 0.0f || c.y < 0.0f || c.z < 0.0f) {
                        throw InputError(path, "vertex " + std::to_string(offset + v) +
                                                   " colour must be finite and >= 0");
                    }
                }
                mesh.colors.push_back(c);
            }
        }
        for (unsigned int f = 0; f < in.mNumFaces; ++f) {
            const aiFace& face = in.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines: not surfaces
            std::array<uint32_t, 3> t{};
            for (unsigned int k = 0; k < 3; ++k) {
                t[k] = offset + face.mIndices[k];
            }
            mesh.triangles.push_back(t);
            mesh.materials.push_back(material);
        }
    }
    const size_t dropped = drop_degenerate_triangles(mesh);
    if (stats) {
        stats->degenerate_triangles = dropped;
        stats->file_materials = 0;
    }
    check_mesh_not_empty(mesh, path, where);
    return mesh;
}

}  // namespace rayo
