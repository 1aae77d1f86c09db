#include "apps/scene/mesh_loader.h"

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "apps/scene/gltf_draco.h"
#include "apps/scene/gltf_nodes.h"
#include "apps/scene/input_file.h"
#include "apps/scene/polygon_file_loader.h"
#include "apps/scene/texture_image.h"
#include "core/error.h"
#include "core/math.h"
#include "core/path_util.h"
#include "core/scene.h"
#include "core/scene_limits.h"
#include "core/shapes/mesh_tangents.h"
#include "core/shapes/polygon_triangulation.h"
#include "shading/metallic_roughness.h"

namespace rayo {

std::string file_name(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Trims trailing newlines and joins tinyobjloader/tinygltf's multi-line reports into one line.
std::string one_line(std::string text) {
    for (char& c : text) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

// "path:line" when a parser's message names a line, else the path.
std::string place_with_line(const std::string& path, const std::string& message) {
    static const std::regex line_pattern(R"(line:?\s*(\d+))");
    std::smatch match;
    if (std::regex_search(message, match, line_pattern)) return path + ":" + match[1].str();
    return path;
}

void check_mesh_not_empty(const TriangleMesh& mesh, const std::string& path,
                          const std::string& where) {
    if (mesh.triangles.empty()) {
        throw InputError(where, "mesh file '" + path + "' contains no (non-degenerate) triangles");
    }
}

namespace {

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void require_colour(const Vec3& c, const std::string& where, const std::string& what) {
    if (!finite(c) || c.x < 0.0f || c.y < 0.0f || c.z < 0.0f) {
        throw InputError(where, what + " must be finite and >= 0");
    }
}

// ---- OBJ / MTL ----------------------------------------------------------------------------

// MTL -> Phong (docs/scene-format.md "OBJ materials"): Ka, Kd, Ks, Ns -> ka, kd, ks, shininess
// (seed 000 eq. [24]); illum 3..7 (ray-traced reflection) -> reflect = Ks; d < 1 (or Tr > 0)
// -> transmit = 1 − d, Ni -> ior (seed 001 transmission).
Material material_from_mtl(const tinyobj::material_t& m, const std::string& where) {
    Material out;
    out.name = m.name;
    out.ka = Vec3(m.ambient[0], m.ambient[1], m.ambient[2]);
    out.kd = Vec3(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
    out.ks = Vec3(m.specular[0], m.specular[1], m.specular[2]);
    const std::string what = "material '" + m.name + "': ";
    require_colour(out.ka, where, what + "Ka");
    require_colour(out.kd, where, what + "Kd");
    require_colour(out.ks, where, what + "Ks");
    if (!std::isfinite(m.shininess) || m.shininess < 0.0f) {
        throw InputError(where, what + "Ns must be finite and >= 0");
    }
    out.shininess = m.shininess;
    if (m.illum >= 3 && m.illum <= 7) out.reflect = out.ks;
    if (!std::isfinite(m.dissolve)) throw InputError(where, what + "d/Tr must be finite");
    const float dissolve = std::clamp(static_cast<float>(m.dissolve), 0.0f, 1.0f);
    if (dissolve < 1.0f) out.transmit = Vec3(1.0f - dissolve);
    if (!std::isfinite(m.ior)) throw InputError(where, what + "Ni must be finite");
    out.ior = m.ior > 0.0f ? static_cast<float>(m.ior) : 1.0f;  // Ni <= 0: unset
    // Ke: the radiance the surface emits (a light-emitting surface, docs/models.md).
    out.emission = Vec3(m.emission[0], m.emission[1], m.emission[2]);
    require_colour(out.emission, where, what + "Ke");
    return out;
}

// One corner of an `f` statement: "v", "v/vt", "v//vn" or "v/vt/vn". OBJ indices are 1-based,
// or negative: relative to the elements read so far. 0 means "absent" (vn only).
struct FaceCorner {
    long long vertex = 0;
    long long normal = 0;  // 0 when the corner has none
    bool has_normal = false;
};

// Parses one corner; false when an index is not an integer (or the vertex index is missing).
bool parse_face_corner(const std::string& token, FaceCorner& corner) {
    auto integer = [](const std::string& text, long long& value) {
        if (text.empty()) return false;
        char* end = nullptr;
        errno = 0;
        value = std::strtoll(text.c_str(), &end, 10);
        return errno == 0 && end == text.c_str() + text.size();
    };
    const size_t first = token.find('/');
    const size_t second =
        first == std::string::npos ? std::string::npos : token.find('/', first + 1);
    corner = FaceCorner{};
    if (!integer(token.substr(0, first), corner.vertex)) return false;
    if (second == std::string::npos) return true;
    corner.has_normal = true;
    return integer(token.substr(second + 1), corner.normal);
}

// A corner's indices made absolute (1-based) against the counts read so far.
FaceCorner absolute(FaceCorner corner, long long vertices_so_far, long long normals_so_far) {
    if (corner.vertex < 0) corner.vertex += vertices_so_far + 1;
    if (corner.normal < 0) corner.normal += normals_so_far + 1;
    return corner;
}

// The first `f` line with an index beyond the file's totals (a forward reference is legal in
// OBJ, so positive indices can only be judged once the whole file has been counted).
size_t first_face_line_beyond(const std::string& obj_text, long long vertex_total,
                              long long normal_total) {
    std::istringstream file(obj_text);
    std::string line, tag, token;
    size_t number = 0;
    long long vertices = 0, normals = 0;
    while (std::getline(file, line)) {
        ++number;
        std::istringstream in(line);
        in >> tag;
        if (tag == "v") ++vertices;
        if (tag == "vn") ++normals;
        if (tag != "f") continue;
        FaceCorner corner;
        while (in >> token) {
            if (!parse_face_corner(token, corner)) continue;
            corner = absolute(corner, vertices, normals);
            if (corner.vertex > vertex_total || corner.normal > normal_total) return number;
        }
    }
    return 0;
}

// tinyobjloader reads a missing coordinate as 0 and "inf" or "1e39" as whatever its parser
// makes of them, and drops faces of fewer than 3 vertices without a word; so the loader checks
// the statements it uses first, each error naming "path:line" (the bad-input catalogue,
// tests/cli/bad_input_test.cpp).
void check_obj_text(const std::string& obj_text, const std::string& path) {
    std::istringstream file(obj_text);
    std::string line;
    size_t number = 0;
    auto fail = [&](const std::string& message) {
        throw InputError(path + ":" + std::to_string(number), message);
    };
    auto check_number = [&](const std::string& tag, const std::string& token) {
        const bool number_chars = token.find_first_not_of("0123456789+-.eE") == std::string::npos;
        char* end = nullptr;
        const double value = number_chars ? std::strtod(token.c_str(), &end) : 0.0;
        if (!number_chars || token.empty() || end != token.c_str() + token.size() ||
            !within_scene_magnitude(value)) {
            fail("'" + tag + "': expected " + kSceneMagnitudeRule + ", got '" + token + "'");
        }
    };
    long long vertices = 0, normals = 0, max_vertex = 0, max_normal = 0;
    auto check_corner = [&](const std::string& token) {
        FaceCorner corner;
        if (!parse_face_corner(token, corner)) {
            fail("expected a face corner v, v/vt, v//vn or v/vt/vn of integer indices, got '" +
                 token + "'");
        }
        if (corner.vertex == 0 || (corner.has_normal && corner.normal == 0)) {
            fail("face index 0 in '" + token + "': OBJ indices start at 1 (or count back from -1)");
        }
        corner = absolute(corner, vertices, normals);
        if (corner.vertex < 1 || (corner.has_normal && corner.normal < 1)) {
            fail("face index out of bounds: '" + token + "' counts back past the first element");
        }
        max_vertex = std::max(max_vertex, corner.vertex);
        max_normal = std::max(max_normal, corner.normal);
    };
    while (std::getline(file, line)) {
        ++number;
        for (const char c : line) {
            const auto byte = static_cast<unsigned char>(c);
            if (byte < 0x20 && c != '\t' && c != '\r' && c != '\f' && c != '\v') {
                char hex[8];
                std::snprintf(hex, sizeof hex, "0x%02X", byte);
                fail(std::string("binary data (control byte ") + hex + "): not an OBJ text file");
            }
        }
        std::istringstream in(line);
        std::string tag, token;
        in >> tag;
        std::vector<std::string> tokens;
        while (in >> token) tokens.push_back(token);
        if (tag == "v") {
            if (tokens.size() != 3 && tokens.size() != 4 && tokens.size() != 6) {
                fail("'v' expects 3 numbers (x y z; optionally w, or r g b), got " +
                     std::to_string(tokens.size()));
            }
            for (const std::string& t : tokens) check_number(tag, t);
        } else if (tag == "vn") {
            if (tokens.size() != 3) {
                fail("'vn' expects 3 numbers (x y z), got " + std::to_string(tokens.size()));
            }
            for (const std::string& t : tokens) check_number(tag, t);
        } else if (tag == "f") {
            if (tokens.size() < 3) {
                fail("a face needs at least 3 vertices, got " + std::to_string(tokens.size()));
            }
            if (tokens.size() > kMaxPolygonVertices) fail(polygon_vertex_limit_text(tokens.size()));
            for (const std::string& t : tokens) check_corner(t);
        }
        if (tag == "v") ++vertices;
        if (tag == "vn") ++normals;
    }
    // Found here, before tinyobjloader parses the whole file (10 s and 1.8 GB for 10 million
    // faces), and named by the first line that refers past the end.
    if (max_vertex > vertices || max_normal > normals) {
        number = first_face_line_beyond(obj_text, vertices, normals);
        fail("face index out of bounds (the file has " + std::to_string(vertices) +
             " vertices and " + std::to_string(normals) + " normals)");
    }
}

// tinyobjloader's `mtllib` reader, through read_input_file: a library must be a regular file of
// sane size that `access` allows (its own reader would read /dev/zero until memory runs out).
// A missing library is recorded in `missing` (load_obj warns about it; tinyobjloader's own
// warning is left out, so that its unknown-name warnings are told apart).
class MaterialLibraryReader : public tinyobj::MaterialReader {
  public:
    MaterialLibraryReader(const std::string& obj_path, const FileAccess& access)
        : m_obj_path(obj_path), m_dir(parent_directory(obj_path)), m_access(access) {}
    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warn,
                    std::string* err) override {
        const std::string path = join_path(m_dir, name);
        if (::access(path.c_str(), F_OK) != 0) {
            missing.push_back(name);
            return false;
        }
        std::istringstream text(
            read_input_file(path, m_obj_path, "material library", kMaxMaterialFileBytes, m_access));
        library_starts.emplace_back(materials->size(), parent_directory(path));
        tinyobj::LoadMtl(names, materials, &text, warn, err);
        return true;
    }

    // The folder of the library that defined material i: texture maps are relative to it.
    std::string directory_of(size_t material) const {
        std::string dir = parent_directory(m_obj_path);
        for (const auto& [first, folder] : library_starts) {
            if (first <= material) dir = folder;
        }
        return dir;
    }

    std::vector<std::string> missing;  // libraries named by `mtllib` that do not exist
    std::vector<std::pair<size_t, std::string>> library_starts;  // (first material, folder)

  private:
    std::string m_obj_path;
    std::string m_dir;
    const FileAccess& m_access;
};

// The colour of OBJ vertex v (the `v x y z r g b` extension): finite and >= 0.
Vec3 obj_vertex_color(const tinyobj::attrib_t& attrib, size_t v, const std::string& path) {
    const Vec3 c(attrib.colors[3 * v], attrib.colors[3 * v + 1], attrib.colors[3 * v + 2]);
    require_colour(c, path, "vertex " + std::to_string(v + 1) + " colour (r g b)");
    return c;
}

// A texture map a model file names (MTL map_Kd, a glTF image): null, with a warning naming the
// file and the material, when it is missing or unreadable; the material then shades with its
// factor (assets often travel without their textures).
std::shared_ptr<const ImageSource> model_texture(const std::string& file, const std::string& model,
                                                 const std::string& what, const FileAccess& access,
                                                 TextureImageCache& cache, MeshImportStats* stats) {
    try {
        return load_texture_image(file, model, access, &cache);
    } catch (const InputError& e) {
        if (stats) {
            stats->warnings.push_back(model + ": " + what + ": " + e.message() +
                                      "; shading with the material's factor");
        }
        return nullptr;
    }
}

// MTL maps (docs/textures.md): map_Kd multiplies Kd (kd = Kd·texel; the default ambient
// follows it when Ka equals Kd), map_Ks multiplies Ks, map_Ke multiplies Ke. Paths are relative to
// the library's folder (backslashes read as slashes); -s and -o scale and offset the coordinates,
// -clamp clamps them. The three maps are sRGB-encoded colour by convention. norm (a tangent-space
// normal map), map_bump/bump (a height map, -bm its multiplier) and map_d (a cutout: the image's
// alpha, or its luminance without one; a hole below 0.5) are linear data (docs/models.md).
void attach_mtl_images(Material& out, const tinyobj::material_t& m, const std::string& dir,
                       const std::string& path, const FileAccess& access, TextureImageCache& cache,
                       MeshImportStats* stats) {
    auto map_of = [&](const std::string& name, const tinyobj::texture_option_t& option,
                      const char* statement) {
        ImageMap map;
        if (name.empty()) return map;
        std::string file = name;
        std::replace(file.begin(), file.end(), '\\', '/');
        map.image = model_texture(join_path(dir, file), path,
                                  "material '" + m.name + "' " + statement + " '" + name + "'",
                                  access, cache, stats);
        map.encoding = TextureEncoding::Srgb;
        map.wrap_s = map.wrap_t = option.clamp ? TextureWrap::Clamp : TextureWrap::Repeat;
        // OBJ's v points up, the image's t down (TriangleMesh::uvs holds t = 1 − v):
        // s = su·u + ou, t = 1 − (sv·v + ov) = sv·t + 1 − sv − ov.
        const float su = option.scale[0], sv = option.scale[1];
        map.transform = glm::mat3(su, 0.0f, 0.0f, 0.0f, sv, 0.0f, option.origin_offset[0],
                                  1.0f - sv - option.origin_offset[1], 1.0f);
        return map;
    };
    out.images.base = map_of(m.diffuse_texname, m.diffuse_texopt, "map_Kd");
    if (out.images.base.used()) {
        out.images.kd = ImageTerm{true, Vec3(0.0f), out.kd};
        if (out.ka == out.kd) out.images.ka = ImageTerm{true, Vec3(0.0f), out.ka};
    }
    out.images.specular = map_of(m.specular_texname, m.specular_texopt, "map_Ks");
    out.images.emission = map_of(m.emissive_texname, m.emissive_texopt, "map_Ke");
    // Normal, height and coverage maps hold data, not colour: read linearly (docs/models.md).
    auto data_map_of = [&](const std::string& name, const tinyobj::texture_option_t& option,
                           const char* statement) {
        ImageMap map = map_of(name, option, statement);
        map.encoding = TextureEncoding::Linear;
        return map;
    };
    out.images.normal = data_map_of(m.normal_texname, m.normal_texopt, "norm");
    out.images.bump = data_map_of(m.bump_texname, m.bump_texopt, "map_bump");
    out.images.bump_scale = m.bump_texopt.bump_multiplier;
    MaterialCutout& cutout = out.images.cutout;
    cutout.image = data_map_of(m.alpha_texname, m.alpha_texopt, "map_d");
    cutout.enabled = cutout.image.used();
    cutout.luminance = true;  // an image without alpha: its luminance
}

}  // namespace

uint32_t default_material_index(std::vector<Material>& materials) {
    for (size_t i = 0; i < materials.size(); ++i) {
        if (materials[i].name == "default") return static_cast<uint32_t>(i);
    }
    Material fallback;
    fallback.name = "default";
    materials.push_back(fallback);
    return static_cast<uint32_t>(materials.size() - 1);
}

TriangleMesh load_obj(const std::string& path, std::vector<Material>& materials,
                      const std::string& where, MeshImportStats* stats, const FileAccess& access) {
    // One read: the checks and tinyobjloader parse this text; the material libraries it names
    // are looked up next to the file, through the same checks.
    const std::string text = read_input_file(path, where, "mesh file", kMaxMeshFileBytes, access);
    check_obj_text(text, path);
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> file_materials;
    std::string warn, err;
    std::istringstream stream(text);
    MaterialLibraryReader mtl_reader(path, access);
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &file_materials, &warn, &err, &stream,
                                     &mtl_reader, /*triangulate=*/true,
                                     /*default_vcols_fallback=*/false);
    if (!ok || !err.empty()) {
        const std::string message = one_line(err.empty() ? warn : err);
        throw InputError(place_with_line(path, message),
                         "malformed OBJ: " + (message.empty() ? "cannot parse" : message));
    }
    // A missing material library is a warning (assets often travel without theirs): its faces
    // take the default material. With every library present, an unknown `usemtl` name is an
    // error: it would silently change the picture.
    for (const std::string& name : mtl_reader.missing) {
        if (stats) {
            stats->warnings.push_back(path + ": material library '" + name + "' not found in " +
                                      parent_directory(path) +
                                      "; its materials are replaced by the default material");
        }
    }
    if (mtl_reader.missing.empty() && (warn.find("not found") != std::string::npos ||
                                       warn.find("Failed to load material") != std::string::npos)) {
        const std::string message = one_line(warn);
        throw InputError(place_with_line(path, message), "OBJ materials: " + message);
    }

    std::vector<Material> converted;
    TextureImageCache textures;
    for (size_t i = 0; i < file_materials.size(); ++i) {
        converted.push_back(material_from_mtl(file_materials[i], path));
        attach_mtl_images(converted.back(), file_materials[i], mtl_reader.directory_of(i), path,
                          access, textures, stats);
    }

    TriangleMesh mesh;
    mesh.name = file_name(path);
    const size_t vertex_count = attrib.vertices.size() / 3;
    const size_t normal_count = attrib.normals.size() / 3;
    for (size_t i = 0; i < vertex_count; ++i) {
        const Vec3 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1],
                     attrib.vertices[3 * i + 2]);
        if (!finite(p)) {
            throw InputError(path, "vertex " + std::to_string(i + 1) + " is not finite");
        }
    }

    bool any_normal = false;
    for (const auto& shape : shapes) {
        for (const auto& index : shape.mesh.indices) any_normal |= index.normal_index >= 0;
    }

    const auto first_material = static_cast<uint32_t>(materials.size());
    bool needs_default = false;
    constexpr uint32_t kNoMaterial = std::numeric_limits<uint32_t>::max();
    // Texture coordinates (`vt`), when every corner of every face has one.
    const size_t texcoord_count = attrib.texcoords.size() / 2;
    bool all_texcoords = texcoord_count > 0;
    for (const auto& shape : shapes) {
        for (const auto& index : shape.mesh.indices) {
            all_texcoords &= index.texcoord_index >= 0 &&
                             static_cast<size_t>(index.texcoord_index) < texcoord_count;
        }
    }
    // One rayo vertex per distinct (position, normal, texture coordinate): OBJ indexes them
    // separately.
    std::map<std::array<int, 3>, uint32_t> vertex_ids;
    for (const auto& shape : shapes) {
        const auto& indices = shape.mesh.indices;
        for (size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
            if (shape.mesh.num_face_vertices[face] != 3) {
                throw InputError(path, "face " + std::to_string(face + 1) + " of shape '" +
                                           shape.name + "' is not a triangle after triangulation");
            }
            std::array<uint32_t, 3> triangle{};
            for (size_t k = 0; k < 3; ++k) {
                const tinyobj::index_t& index = indices[3 * face + k];
                if (index.vertex_index < 0 ||
                    static_cast<size_t>(index.vertex_index) >= vertex_count ||
                    index.normal_index >= static_cast<int>(normal_count)) {
                    // check_obj_text has refused such files; this guards a mismatch.
                    throw InputError(path, "face index out of bounds (the file has " +
                                               std::to_string(vertex_count) + " vertices and " +
                                               std::to_string(normal_count) + " normals)");
                }
                const int normal_index = any_normal ? index.normal_index : -1;
                const int texcoord_index = all_texcoords ? index.texcoord_index : -1;
                const std::array<int, 3> key{index.vertex_index, normal_index, texcoord_index};
                auto found = vertex_ids.find(key);
                if (found == vertex_ids.end()) {
                    const auto v = static_cast<size_t>(index.vertex_index);
                    mesh.positions.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1],
                                                attrib.vertices[3 * v + 2]);
                    if (any_normal) {
                        Vec3 n(0.0f);  // zero: this corner has no normal, shade with Ng
                        if (normal_index >= 0) {
                            const auto ni = static_cast<size_t>(normal_index);
                            n = Vec3(attrib.normals[3 * ni], attrib.normals[3 * ni + 1],
                                     attrib.normals[3 * ni + 2]);
                            const float length = glm::length(n);
                            n = (std::isfinite(length) && length > 0.0f) ? n / length : Vec3(0.0f);
                        }
                        mesh.normals.push_back(n);
                    }
                    if (!attrib.colors.empty()) {
                        mesh.colors.push_back(obj_vertex_color(attrib, v, path));
                    }
                    if (all_texcoords) {
                        const auto ti = static_cast<size_t>(texcoord_index);
                        const glm::vec2 uv(attrib.texcoords[2 * ti], attrib.texcoords[2 * ti + 1]);
                        if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
                            throw InputError(path, "texture coordinate " + std::to_string(ti + 1) +
                                                       " is not finite");
                        }
                        mesh.uvs.emplace_back(uv.x, 1.0f - uv.y);  // OBJ's v points up
                    }
                    found =
                        vertex_ids.emplace(key, static_cast<uint32_t>(mesh.positions.size() - 1))
                            .first;
                }
                triangle[k] = found->second;
            }
            const int material =
                face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
            const bool named = material >= 0 && static_cast<size_t>(material) < converted.size();
            needs_default |= !named;
            mesh.triangles.push_back(triangle);
            // Faces without a material are patched once the default material's index is known.
            mesh.materials.push_back(named ? first_material + static_cast<uint32_t>(material)
                                           : kNoMaterial);
        }
    }

    materials.insert(materials.end(), converted.begin(), converted.end());
    if (needs_default) {
        const uint32_t default_id = default_material_index(materials);
        for (auto& id : mesh.materials) {
            if (id == kNoMaterial) id = default_id;
        }
    }
    const size_t dropped = drop_degenerate_triangles(mesh);
    complete_tangents(mesh, materials);
    if (stats) {
        stats->degenerate_triangles = dropped;
        stats->file_materials = converted.size();
    }
    check_mesh_not_empty(mesh, path, where);
    return mesh;
}

// ---- glTF ---------------------------------------------------------------------------------

namespace {

// glTF metallicRoughness -> Phong (docs/scene-format.md "glTF materials").
Material material_from_gltf(const tinygltf::Material& m, size_t index, const std::string& where) {
    Material out;
    out.name = m.name.empty() ? "gltf material " + std::to_string(index) : m.name;
    const auto& pbr = m.pbrMetallicRoughness;
    const std::string what = "material '" + out.name + "': ";
    if (pbr.baseColorFactor.size() < 3) throw InputError(where, what + "baseColorFactor");
    for (size_t i = 0; i < 3; ++i) {
        if (!within_scene_magnitude(pbr.baseColorFactor[i]) || pbr.baseColorFactor[i] < 0.0) {
            throw InputError(where, what + "baseColorFactor must be finite and >= 0");
        }
    }
    if (pbr.baseColorFactor.size() == 4 &&
        !(pbr.baseColorFactor[3] >= 0.0 && pbr.baseColorFactor[3] <= 1.0)) {
        throw InputError(where, what + "baseColorFactor's alpha must be in [0, 1]");
    }
    if (m.alphaMode != "OPAQUE" && m.alphaMode != "MASK" && m.alphaMode != "BLEND") {
        throw InputError(
            where, what + "alphaMode must be OPAQUE, MASK or BLEND, got '" + m.alphaMode + "'");
    }
    if (!(m.alphaCutoff >= 0.0 && std::isfinite(m.alphaCutoff))) {
        throw InputError(where, what + "alphaCutoff must be finite and >= 0");
    }
    if (!std::isfinite(m.normalTexture.scale)) {
        throw InputError(where, what + "normalTexture's scale must be finite");
    }
    if (!std::isfinite(pbr.metallicFactor) || pbr.metallicFactor < 0.0 ||
        pbr.metallicFactor > 1.0 || !std::isfinite(pbr.roughnessFactor) ||
        pbr.roughnessFactor < 0.0 || pbr.roughnessFactor > 1.0) {
        throw InputError(where, what + "metallicFactor and roughnessFactor must be in [0, 1]");
    }
    const Vec3 base(static_cast<float>(pbr.baseColorFactor[0]),
                    static_cast<float>(pbr.baseColorFactor[1]),
                    static_cast<float>(pbr.baseColorFactor[2]));
    apply_metallic_roughness(out, base, static_cast<float>(pbr.metallicFactor),
                             pbr.roughnessFactor);
    // doubleSided (glTF 2.0 §3.9.5, default false): a one-sided material emits, and holds
    // radiosity patches, on its front only.
    out.double_sided = m.doubleSided;
    // emissiveFactor (× KHR_materials_emissive_strength) is the radiance the surface sends.
    if (m.emissiveFactor.size() == 3) {
        double strength = 1.0;
        const auto ext = m.extensions.find("KHR_materials_emissive_strength");
        if (ext != m.extensions.end() && ext->second.Has("emissiveStrength")) {
            strength = ext->second.Get("emissiveStrength").GetNumberAsDouble();
        }
        for (int i = 0; i < 3; ++i) {
            const double e = m.emissiveFactor[static_cast<size_t>(i)] * strength;
            if (!within_scene_magnitude(e) || e < 0.0) {
                throw InputError(where, what +
                                            "emissiveFactor × emissiveStrength must be finite "
                                            "and >= 0");
            }
            out.emission[i] = static_cast<float>(e);
        }
    }
    return out;
}

// Bytes of one accessor element, checked against its buffer view and buffer.
struct AccessorView {
    const unsigned char* data = nullptr;
    size_t count = 0;
    size_t stride = 0;
};

AccessorView view_accessor(const tinygltf::Model& model, int accessor_index, int component_type,
                           int type, const std::string& path, const std::string& what) {
    if (accessor_index < 0 || static_cast<size_t>(accessor_index) >= model.accessors.size()) {
        throw InputError(path,
                         what + ": accessor " + std::to_string(accessor_index) + " does not exist");
    }
    const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(accessor_index)];
    if (accessor.sparse.isSparse) {
        throw InputError(path, what + ": sparse accessors are not supported");
    }
    if (component_type >= 0 && accessor.componentType != component_type) {
        throw InputError(
            path, what + ": unsupported component type " + std::to_string(accessor.componentType));
    }
    if (accessor.type != type) {
        throw InputError(path,
                         what + ": unexpected accessor type " + std::to_string(accessor.type));
    }
    if (accessor.bufferView < 0 ||
        static_cast<size_t>(accessor.bufferView) >= model.bufferViews.size()) {
        throw InputError(path, what + ": accessor without a valid bufferView");
    }
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(accessor.bufferView)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
        throw InputError(path, what + ": bufferView without a valid buffer");
    }
    const tinygltf::Buffer& buffer = model.buffers[static_cast<size_t>(view.buffer)];
    const int component_size =
        tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType));
    const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
    if (component_size <= 0 || components <= 0) {
        throw InputError(path, what + ": invalid accessor component type or type");
    }
    const size_t element_size = static_cast<size_t>(component_size) * components;
    const size_t stride = view.byteStride > 0 ? view.byteStride : element_size;
    // glTF 2.0 (3.6.2.4): a stride is a multiple of 4 in [4, 252], and elements do not overlap.
    if (view.byteStride > 0 &&
        (stride < element_size || stride % 4 != 0 || stride < 4 || stride > 252)) {
        throw InputError(path, what + ": bufferView byteStride " + std::to_string(stride) +
                                   " (expected a multiple of 4 in [4, 252], at least the " +
                                   std::to_string(element_size) + " bytes of one element)");
    }
    if (view.byteOffset > buffer.data.size() ||
        view.byteLength > buffer.data.size() - view.byteOffset) {
        throw InputError(path, what + ": bufferView exceeds its buffer");
    }
    if (accessor.count > 0 &&
        (accessor.byteOffset > view.byteLength ||
         (accessor.count - 1) > (view.byteLength - accessor.byteOffset) / stride ||
         accessor.byteOffset + (accessor.count - 1) * stride + element_size > view.byteLength)) {
        throw InputError(path, what + ": accessor exceeds its bufferView");
    }
    AccessorView out;
    out.data = buffer.data.data() + view.byteOffset + accessor.byteOffset;
    out.count = accessor.count;
    out.stride = stride;
    return out;
}

std::vector<Vec3> read_vec3(const tinygltf::Model& model, int accessor, const std::string& path,
                            const std::string& what) {
    const AccessorView view = view_accessor(model, accessor, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                            TINYGLTF_TYPE_VEC3, path, what);
    std::vector<Vec3> out(view.count);
    for (size_t i = 0; i < view.count; ++i) {
        float v[3];
        std::memcpy(v, view.data + i * view.stride, sizeof v);
        out[i] = Vec3(v[0], v[1], v[2]);
        if (!finite(out[i])) {
            throw InputError(path, what + ": element " + std::to_string(i) + " is not finite");
        }
    }
    return out;
}

// TANGENT: VEC4 floats, xyz a unit tangent and w = ±1 the bitangent's sign (glTF 2.0,
// "Meshes"); a tangent of zero length or a w that is not ±1 (rounded) gives the vertex none
// (w = 0: computed like a missing one, core/shapes/mesh_tangents.h).
std::vector<glm::vec4> read_tangents(const tinygltf::Model& model, int accessor,
                                     const std::string& path, const std::string& what) {
    const AccessorView view = view_accessor(model, accessor, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                            TINYGLTF_TYPE_VEC4, path, what);
    std::vector<glm::vec4> out(view.count);
    for (size_t i = 0; i < view.count; ++i) {
        float v[4];
        std::memcpy(v, view.data + i * view.stride, sizeof v);
        const Vec3 t(v[0], v[1], v[2]);
        if (!finite(t) || !std::isfinite(v[3])) {
            throw InputError(path, what + ": element " + std::to_string(i) + " is not finite");
        }
        const float length = glm::length(t);
        const float w = v[3] < 0.0f ? -1.0f : 1.0f;
        out[i] = length > 0.0f ? glm::vec4(t / length, w) : glm::vec4(0.0f);
    }
    return out;
}

// Component k of an accessor element: floats as they are, unsigned bytes and shorts normalized
// to [0, 1] (glTF 2.0, "Accessor data types"; colours and texture coordinates).
float normalized_component(const unsigned char* element, int component, int k) {
    if (component == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        float value;
        std::memcpy(&value, element + 4 * k, 4);
        return value;
    }
    if (component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE)
        return static_cast<float>(element[k]) / 255.0f;
    uint16_t value;
    std::memcpy(&value, element + 2 * k, 2);
    return static_cast<float>(value) / 65535.0f;
}

// COLOR_0: VEC3 or VEC4 (alpha ignored) of floats, or of normalized unsigned bytes or shorts
// (glTF 2.0, "Meshes": the colours are linear).
std::vector<Vec3> read_colors(const tinygltf::Model& model, int accessor, const std::string& path,
                              const std::string& what) {
    const bool exists = accessor >= 0 && static_cast<size_t>(accessor) < model.accessors.size();
    const int type = exists ? model.accessors[static_cast<size_t>(accessor)].type : -1;
    const int component =
        exists ? model.accessors[static_cast<size_t>(accessor)].componentType : -1;
    if (exists && type != TINYGLTF_TYPE_VEC3 && type != TINYGLTF_TYPE_VEC4) {
        throw InputError(path, what + ": expected VEC3 or VEC4 colours");
    }
    if (exists && component != TINYGLTF_COMPONENT_TYPE_FLOAT &&
        component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        throw InputError(path, what + ": expected float, unsigned byte or unsigned short colours");
    }
    const AccessorView view = view_accessor(model, accessor, component, type, path, what);
    std::vector<Vec3> out(view.count);
    for (size_t i = 0; i < view.count; ++i) {
        const unsigned char* element = view.data + i * view.stride;
        for (int k = 0; k < 3; ++k) out[i][k] = normalized_component(element, component, k);
        require_colour(out[i], path, what + ": element " + std::to_string(i));
    }
    return out;
}

// TEXCOORD_n: VEC2 of floats or of normalized unsigned bytes or shorts (glTF 2.0, "Meshes"),
// (0, 0) the image's top-left corner as in OpenImageIO.
std::vector<glm::vec2> read_texcoords(const tinygltf::Model& model, int accessor,
                                      const std::string& path, const std::string& what) {
    const bool exists = accessor >= 0 && static_cast<size_t>(accessor) < model.accessors.size();
    const int component =
        exists ? model.accessors[static_cast<size_t>(accessor)].componentType : -1;
    if (exists && component != TINYGLTF_COMPONENT_TYPE_FLOAT &&
        component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        throw InputError(path, what +
                                   ": expected float, unsigned byte or unsigned short "
                                   "texture coordinates");
    }
    const AccessorView view =
        view_accessor(model, accessor, component, TINYGLTF_TYPE_VEC2, path, what);
    std::vector<glm::vec2> out(view.count);
    for (size_t i = 0; i < view.count; ++i) {
        const unsigned char* element = view.data + i * view.stride;
        for (int k = 0; k < 2; ++k) out[i][k] = normalized_component(element, component, k);
        if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y)) {
            throw InputError(path, what + ": element " + std::to_string(i) + " is not finite");
        }
    }
    return out;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int accessor,
                                   const std::string& path, const std::string& what) {
    const AccessorView view = view_accessor(model, accessor, -1, TINYGLTF_TYPE_SCALAR, path, what);
    const int type = model.accessors[static_cast<size_t>(accessor)].componentType;
    std::vector<uint32_t> out(view.count);
    for (size_t i = 0; i < view.count; ++i) {
        const unsigned char* p = view.data + i * view.stride;
        switch (type) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                out[i] = *p;
                break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                uint16_t v;
                std::memcpy(&v, p, sizeof v);
                out[i] = v;
                break;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
                uint32_t v;
                std::memcpy(&v, p, sizeof v);
                out[i] = v;
                break;
            }
            default:
                throw InputError(path, what +
                                           ": indices must be unsigned byte/short/int, got "
                                           "component type " +
                                           std::to_string(type));
        }
    }
    return out;
}

// The node's matrix, or T * R * S from its translation, rotation and scale. The rotation must be
// a unit quaternion (glTF 2.0 §5.25); one within 1e-3 of unit length is normalised (exporters
// round), anything else is refused with the node (a zero quaternion cast to the identity).
glm::dmat4 node_local_transform(const tinygltf::Node& node, int index, const std::string& path) {
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (node.translation.size() == 3) {
        t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    }
    if (node.rotation.size() == 4) {  // glTF quaternions are (x, y, z, w)
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double length = glm::length(q);
        if (!(std::abs(length - 1.0) <= 1e-3)) {
            std::ostringstream text;
            text << "node " << index << ": rotation (" << q.x << ", " << q.y << ", " << q.z << ", "
                 << q.w << ") is not a unit quaternion (length " << length << ")";
            throw InputError(path, text.str());
        }
        r = glm::mat4_cast(q / length);
    }
    if (node.scale.size() == 3) {
        s = glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    }
    return t * r * s;  // glTF: M = T * R * S
}

struct GltfBuilder {
    GltfBuilder(const tinygltf::Model& m, const std::string& p, std::vector<Material>& mats)
        : model(m), path(p), materials(mats), first_material(static_cast<uint32_t>(mats.size())) {}

    const tinygltf::Model& model;
    const std::string& path;
    std::vector<Material>& materials;
    uint32_t first_material;
    TriangleMesh mesh;
    bool any_normals = false;
    bool any_colors = false;
    GltfNodes* nodes = nullptr;  // cameras and lights, and meshes kept for instancing
    std::vector<std::pair<int, glm::dmat4>> mesh_placements;  // (mesh, world), with instancing
    bool any_uvs = false;
    bool any_tangents = false;
    size_t shared_degenerate = 0;  // zero-area triangles dropped from shared meshes (once each)

    void append_mesh(int mesh_index, const glm::dmat4& world) {
        const tinygltf::Mesh& gltf_mesh = model.meshes[static_cast<size_t>(mesh_index)];
        for (size_t p = 0; p < gltf_mesh.primitives.size(); ++p) {
            append_primitive(
                gltf_mesh.primitives[p], world,
                "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(p));
        }
    }

    // With instancing: meshes placed once are flattened as without; a mesh placed more than
    // once is built once in its own space, and each placement becomes a GltfNodes::Placement.
    void place_meshes() {
        std::map<int, size_t> uses;
        for (const auto& [m, world] : mesh_placements) ++uses[m];
        std::map<int, uint32_t> shared;  // glTF mesh -> index in nodes->shared_meshes
        for (const auto& [m, world] : mesh_placements) {
            if (uses[m] == 1) {
                append_mesh(m, world);
                continue;
            }
            auto it = shared.find(m);
            if (it == shared.end()) {
                TriangleMesh flat = std::move(mesh);
                const bool flat_normals = any_normals, flat_colors = any_colors, flat_uvs = any_uvs,
                           flat_tangents = any_tangents;
                mesh = TriangleMesh();
                any_normals = any_colors = any_uvs = any_tangents = false;
                append_mesh(m, glm::dmat4(1.0));
                mesh.name = model.meshes[static_cast<size_t>(m)].name.empty()
                                ? "mesh " + std::to_string(m)
                                : model.meshes[static_cast<size_t>(m)].name;
                shared_degenerate += drop_degenerate_triangles(mesh);
                it = shared.emplace(m, static_cast<uint32_t>(nodes->shared_meshes.size())).first;
                nodes->shared_meshes.push_back(std::move(mesh));
                mesh = std::move(flat);
                any_normals = flat_normals;
                any_colors = flat_colors;
                any_uvs = flat_uvs;
                any_tangents = flat_tangents;
            }
            nodes->placements.push_back({it->second, glm::mat4(world)});
        }
    }

    void append_primitive(const tinygltf::Primitive& primitive, const glm::dmat4& world,
                          const std::string& what) {
        const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES) {
            throw InputError(path, what + ": unsupported primitive mode " + std::to_string(mode) +
                                       " (only TRIANGLES, mode 4, is supported)");
        }
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) {
            throw InputError(path, what + ": primitive without POSITION");
        }
        TriangleMesh piece;
        piece.positions = read_vec3(model, position->second, path, what + " POSITION");
        // The rule every other mesh reader applies (a vertex at 3e38 was dropped with its
        // triangles and the file called "no (non-degenerate) triangles").
        for (size_t v = 0; v < piece.positions.size(); ++v) {
            if (!point_within_scene_magnitude(piece.positions[v])) {
                throw InputError(path, what + " POSITION " + std::to_string(v) +
                                           ": coordinates must be " + kSceneMagnitudeRule);
            }
        }
        const auto normal = primitive.attributes.find("NORMAL");
        if (normal != primitive.attributes.end()) {
            piece.normals = read_vec3(model, normal->second, path, what + " NORMAL");
            if (piece.normals.size() != piece.positions.size()) {
                throw InputError(path, what + ": NORMAL and POSITION counts differ");
            }
            for (auto& n : piece.normals) {
                const float length = glm::length(n);
                n = length > 0.0f ? n / length : Vec3(0.0f);
            }
        }
        const auto tangent = primitive.attributes.find("TANGENT");
        if (tangent != primitive.attributes.end()) {
            piece.tangents = read_tangents(model, tangent->second, path, what + " TANGENT");
            if (piece.tangents.size() != piece.positions.size()) {
                throw InputError(path, what + ": TANGENT and POSITION counts differ");
            }
        }
        const auto color = primitive.attributes.find("COLOR_0");
        if (color != primitive.attributes.end()) {
            piece.colors = read_colors(model, color->second, path, what + " COLOR_0");
            if (piece.colors.size() != piece.positions.size()) {
                throw InputError(path, what + ": COLOR_0 and POSITION counts differ");
            }
        }
        const auto texcoord = primitive.attributes.find("TEXCOORD_0");
        if (texcoord != primitive.attributes.end()) {
            piece.uvs = read_texcoords(model, texcoord->second, path, what + " TEXCOORD_0");
            if (piece.uvs.size() != piece.positions.size()) {
                throw InputError(path, what + ": TEXCOORD_0 and POSITION counts differ");
            }
        }
        std::vector<uint32_t> indices;
        if (primitive.indices >= 0) {
            indices = read_indices(model, primitive.indices, path, what + " indices");
        } else {
            indices.resize(piece.positions.size());
            for (size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<uint32_t>(i);
        }
        if (indices.size() % 3 != 0) {
            throw InputError(path, what + ": index count " + std::to_string(indices.size()) +
                                       " is not a multiple of 3");
        }
        uint32_t material;
        if (primitive.material >= 0 &&
            static_cast<size_t>(primitive.material) < model.materials.size()) {
            material = first_material + static_cast<uint32_t>(primitive.material);
        } else if (primitive.material < 0) {
            material = default_material_index(materials);
        } else {
            throw InputError(path, what + ": material " + std::to_string(primitive.material) +
                                       " does not exist");
        }
        for (size_t i = 0; i < indices.size(); i += 3) {
            for (size_t k = 0; k < 3; ++k) {
                if (indices[i + k] >= piece.positions.size()) {
                    throw InputError(
                        path, what + ": index " + std::to_string(indices[i + k]) + " out of range");
                }
            }
            piece.triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
            piece.materials.push_back(material);
        }
        transform_mesh(piece, world);
        append(piece);
    }

    void append(const TriangleMesh& piece) {
        const auto offset = static_cast<uint32_t>(mesh.positions.size());
        const bool piece_normals = !piece.normals.empty();
        if (piece_normals && !any_normals) {
            mesh.normals.assign(mesh.positions.size(), Vec3(0.0f));  // zero: shade with Ng
            any_normals = true;
        }
        if (!piece.colors.empty() && !any_colors) {
            mesh.colors.assign(mesh.positions.size(), Vec3(1.0f));  // white: no colour so far
            any_colors = true;
        }
        if (!piece.tangents.empty() && !any_tangents) {
            mesh.tangents.assign(mesh.positions.size(), glm::vec4(0.0f));  // w = 0: none
            any_tangents = true;
        }
        if (!piece.uvs.empty() && !any_uvs) {
            mesh.uvs.assign(mesh.positions.size(), glm::vec2(0.0f));  // (0, 0): none so far
            any_uvs = true;
        }
        mesh.positions.insert(mesh.positions.end(), piece.positions.begin(), piece.positions.end());
        if (any_uvs) {
            if (piece.uvs.empty()) {
                mesh.uvs.resize(mesh.positions.size(), glm::vec2(0.0f));
            } else {
                mesh.uvs.insert(mesh.uvs.end(), piece.uvs.begin(), piece.uvs.end());
            }
        }
        if (any_tangents) {
            if (piece.tangents.empty()) {
                mesh.tangents.resize(mesh.positions.size(), glm::vec4(0.0f));
            } else {
                mesh.tangents.insert(mesh.tangents.end(), piece.tangents.begin(),
                                     piece.tangents.end());
            }
        }
        if (any_colors) {
            if (piece.colors.empty()) {
                mesh.colors.resize(mesh.positions.size(), Vec3(1.0f));
            } else {
                mesh.colors.insert(mesh.colors.end(), piece.colors.begin(), piece.colors.end());
            }
        }
        if (any_normals) {
            if (piece_normals) {
                mesh.normals.insert(mesh.normals.end(), piece.normals.begin(), piece.normals.end());
            } else {
                mesh.normals.resize(mesh.positions.size(), Vec3(0.0f));
            }
        }
        for (const auto& t : piece.triangles) {
            mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
        }
        mesh.materials.insert(mesh.materials.end(), piece.materials.begin(), piece.materials.end());
    }

    void visit(int node_index, const glm::dmat4& parent, std::set<int>& on_path) {
        if (node_index < 0 || static_cast<size_t>(node_index) >= model.nodes.size()) {
            throw InputError(path, "node " + std::to_string(node_index) + " does not exist");
        }
        // The walk recurses once per level: a chain of tens of thousands of nodes would
        // overflow the stack (docs/limits.md, "glTF node depth").
        if (on_path.size() >= kMaxGltfNodeDepth) {
            throw InputError(path, "node " + std::to_string(node_index) + " lies " +
                                       std::to_string(on_path.size() + 1) +
                                       " levels deep; the limit is " +
                                       std::to_string(kMaxGltfNodeDepth) + " levels");
        }
        if (!on_path.insert(node_index).second) {
            throw InputError(path, "node " + std::to_string(node_index) + " is its own ancestor");
        }
        const tinygltf::Node& node = model.nodes[static_cast<size_t>(node_index)];
        const glm::dmat4 world = parent * node_local_transform(node, node_index, path);
        if (nodes) collect_gltf_node_items(model, node, node_index, world, path, *nodes);
        if (node.mesh >= 0) {
            if (static_cast<size_t>(node.mesh) >= model.meshes.size()) {
                throw InputError(path, "node " + std::to_string(node_index) + ": mesh " +
                                           std::to_string(node.mesh) + " does not exist");
            }
            if (nodes && nodes->instance_shared_meshes) {
                mesh_placements.emplace_back(node.mesh, world);
            } else {
                append_mesh(node.mesh, world);
            }
        }
        for (int child : node.children) visit(child, world, on_path);
        on_path.erase(node_index);
    }
};

// Images are decoded by the render's texture system (shading/image_texture.h): keep their
// encoded bytes (from a file, a buffer view or a data URI) as they are. tinygltf does not call
// this for a missing file: its image stays empty (a warning, the material's factor).
// An image in a bufferView is not read here: tinygltf hands over the view's range without
// checking it against its buffer (a byteOffset past the end is read there), so those bytes are
// copied by copy_buffer_view_images once the range is checked.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    if (image->bufferView != -1) return true;
    image->image.assign(bytes, bytes + size);
    return true;
}

// The encoded bytes of the images stored in bufferViews, each view's range checked against its
// buffer first (tinygltf has checked that the view and the buffer exist).
void copy_buffer_view_images(tinygltf::Model& model, const std::string& path) {
    for (size_t i = 0; i < model.images.size(); ++i) {
        tinygltf::Image& image = model.images[i];
        if (image.bufferView < 0) continue;
        const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(image.bufferView)];
        const tinygltf::Buffer& buffer = model.buffers[static_cast<size_t>(view.buffer)];
        if (view.byteOffset > buffer.data.size() ||
            view.byteLength > buffer.data.size() - view.byteOffset) {
            throw InputError(path, "image " + std::to_string(i) + ": bufferView " +
                                       std::to_string(image.bufferView) + " (bytes " +
                                       std::to_string(view.byteOffset) + " + " +
                                       std::to_string(view.byteLength) + ") runs past buffer " +
                                       std::to_string(view.buffer) + " of " +
                                       std::to_string(buffer.data.size()) + " bytes");
        }
        const unsigned char* first = buffer.data.data() + view.byteOffset;
        image.image.assign(first, first + view.byteLength);
    }
}

// glTF sampler wrap modes (glTF 2.0, "Samplers"): 33071 CLAMP_TO_EDGE, 33648 MIRRORED_REPEAT,
// 10497 REPEAT (the default).
TextureWrap gltf_wrap(int mode) {
    if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::Clamp;
    if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::Mirror;
    return TextureWrap::Repeat;
}

double value_number(const tinygltf::Value& object, const char* key, int index, double fallback) {
    if (!object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    if (index >= 0) {
        if (!v.IsArray() || v.ArrayLen() <= static_cast<size_t>(index)) return fallback;
        const tinygltf::Value& e = v.Get(index);
        return e.IsNumber() ? e.GetNumberAsDouble() : fallback;
    }
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

// The textures of a glTF file's materials: each image becomes one ImageSource the first time a
// material uses it.
struct GltfTextures {
    const tinygltf::Model& model;
    const std::string& path;
    MeshImportStats* stats;
    std::map<int, std::shared_ptr<const ImageSource>> images;
    // The files read_input_file refused while tinygltf loaded (path, reason): an image among
    // them is named with its reason, not as "not found".
    const std::vector<std::pair<std::string, std::string>>* refused = nullptr;

    void warn(const std::string& message) const {
        if (stats) stats->warnings.push_back(path + ": " + message);
    }

    // textureInfo -> ImageMap (no image, with a warning, when it cannot be used): the sampler's
    // wrap modes and KHR_texture_transform's offset, rotation and scale,
    // (s, t, 1) = T·R·S·(u, v, 1), R = (cos r, sin r; −sin r, cos r).
    template <typename Info>  // tinygltf::TextureInfo, NormalTextureInfo
    ImageMap map(const Info& info, const std::string& material, const char* slot) {
        ImageMap out;
        if (info.index < 0) return out;
        const std::string what = "material '" + material + "' " + slot;
        if (static_cast<size_t>(info.index) >= model.textures.size()) {
            throw InputError(path,
                             what + ": texture " + std::to_string(info.index) + " does not exist");
        }
        const tinygltf::Texture& texture = model.textures[static_cast<size_t>(info.index)];
        if (texture.source < 0 || static_cast<size_t>(texture.source) >= model.images.size()) {
            warn(what + ": texture " + std::to_string(info.index) +
                 " has no image rayo reads (only core glTF images); shading with the factor");
            return out;
        }
        int tex_coord = info.texCoord;
        glm::mat3 transform(1.0f);
        const auto ext = info.extensions.find("KHR_texture_transform");
        if (ext != info.extensions.end()) {
            const tinygltf::Value& t = ext->second;
            const auto offset =
                glm::vec2(value_number(t, "offset", 0, 0.0), value_number(t, "offset", 1, 0.0));
            const auto rotation = static_cast<float>(value_number(t, "rotation", -1, 0.0));
            const auto scale =
                glm::vec2(value_number(t, "scale", 0, 1.0), value_number(t, "scale", 1, 1.0));
            tex_coord = static_cast<int>(value_number(t, "texCoord", -1, tex_coord));
            const glm::mat3 translation(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
            const float c = std::cos(rotation), s = std::sin(rotation);
            // Rows (c, s; −s, c): the direction the extension's sample model
            // (TextureTransformTest) and three.js, its reference viewer, rotate in.
            const glm::mat3 rotate(c, -s, 0, s, c, 0, 0, 0, 1);
            const glm::mat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
            transform = translation * rotate * scaling;
            // Huge values overflow the float transform or the lookups after it (a rotation or
            // scale of 1e308, an offset of 1e38 gave NaN pixels): the scene's number limit.
            const double largest = std::max({std::abs(value_number(t, "rotation", -1, 0.0)),
                                             std::abs(value_number(t, "offset", 0, 0.0)),
                                             std::abs(value_number(t, "offset", 1, 0.0)),
                                             std::abs(value_number(t, "scale", 0, 1.0)),
                                             std::abs(value_number(t, "scale", 1, 1.0))});
            bool finite = largest <= kMaxSceneMagnitude;
            for (int column = 0; column < 3; ++column) {
                for (int row = 0; row < 3; ++row)
                    finite = finite && std::isfinite(transform[column][row]);
            }
            if (!finite) {
                throw InputError(path, what +
                                           ": KHR_texture_transform's offset, rotation and scale "
                                           "must be finite numbers of magnitude <= 1e18");
            }
        }
        if (tex_coord != 0) {
            warn(what + " uses TEXCOORD_" + std::to_string(tex_coord) +
                 "; rayo reads TEXCOORD_0 only and uses it instead");
        }
        out.image = image(texture.source, what);
        out.transform = transform;
        out.encoding = TextureEncoding::Srgb;  // base colour and emission: sRGB (glTF 2.0)
        if (texture.sampler >= 0 && static_cast<size_t>(texture.sampler) < model.samplers.size()) {
            const tinygltf::Sampler& sampler = model.samplers[static_cast<size_t>(texture.sampler)];
            out.wrap_s = gltf_wrap(sampler.wrapS);
            out.wrap_t = gltf_wrap(sampler.wrapT);
        }
        return out;
    }

    std::shared_ptr<const ImageSource> image(int index, const std::string& what) {
        const auto found = images.find(index);
        if (found != images.end()) return found->second;
        const tinygltf::Image& image = model.images[static_cast<size_t>(index)];
        const std::string name = !image.uri.empty() && image.uri.rfind("data:", 0) != 0
                                     ? join_path(parent_directory(path), image.uri)
                                     : file_name(path) + " image " + std::to_string(index) +
                                           (image.name.empty() ? "" : " '" + image.name + "'");
        std::shared_ptr<const ImageSource> source;
        if (image.image.empty()) {
            std::string reason = "not found";
            if (!image.uri.empty() && image.uri.front() == '/') {
                reason +=
                    " (a glTF image's uri is relative to the file: an absolute path is "
                    "looked for under the file's folder)";
            }
            for (size_t i = 0; refused && i < refused->size(); ++i) {
                const auto& [file, why] = (*refused)[i];
                if (file == name || (file.size() > image.uri.size() &&
                                     file.compare(file.size() - image.uri.size(), image.uri.size(),
                                                  image.uri) == 0)) {
                    reason = why;
                }
            }
            warn(what + ": image '" + name + "': " + reason + "; shading with the factor");
        } else {
            try {
                source = texture_image_from_bytes(
                    name, std::string(image.image.begin(), image.image.end()), path);
            } catch (const InputError& e) {
                warn(what + ": " + e.message() + "; shading with the factor");
            }
        }
        images.emplace(index, source);
        return source;
    }
};

// baseColorTexture and emissiveTexture (docs/textures.md): the texel multiplies the factor, so
// the metallic workflow's coefficients (material_from_gltf) are affine in it:
// kd = (1 − m)·f·c, ka = 0.1·f·c, ks = 0.04(1 − m) + m·f·c, reflect = g·ks.
void attach_gltf_images(Material& out, const tinygltf::Material& m, GltfTextures& textures) {
    const auto& pbr = m.pbrMetallicRoughness;
    out.images.base = textures.map(pbr.baseColorTexture, out.name, "baseColorTexture");
    if (out.images.base.used()) {
        const Vec3 factor(static_cast<float>(pbr.baseColorFactor[0]),
                          static_cast<float>(pbr.baseColorFactor[1]),
                          static_cast<float>(pbr.baseColorFactor[2]));
        const auto metallic = static_cast<float>(pbr.metallicFactor);
        const auto gloss =
            static_cast<float>((1.0 - pbr.roughnessFactor) * (1.0 - pbr.roughnessFactor));
        const Vec3 f0_offset(0.04f * (1.0f - metallic));
        out.images.kd = ImageTerm{true, Vec3(0.0f), (1.0f - metallic) * factor};
        out.images.ka = ImageTerm{true, Vec3(0.0f), 0.1f * factor};
        out.images.ks = ImageTerm{true, f0_offset, metallic * factor};
        out.images.reflect = ImageTerm{true, gloss * f0_offset, gloss * metallic * factor};
    }
    out.images.emission = textures.map(m.emissiveTexture, out.name, "emissiveTexture");
    // normalTexture: tangent-space, linear (docs/models.md, "Normal and bump maps").
    out.images.normal = textures.map(m.normalTexture, out.name, "normalTexture");
    out.images.normal.encoding = TextureEncoding::Linear;
    out.images.normal_scale = static_cast<float>(m.normalTexture.scale);
    // alphaMode MASK (docs/models.md, "Cutouts"): alpha = baseColorFactor.a ×
    // baseColorTexture.a, a hole below alphaCutoff. BLEND is read as MASK at 0.5 (rayo has no
    // partial coverage), with a warning.
    if (m.alphaMode == "MASK" || m.alphaMode == "BLEND") {
        MaterialCutout& cutout = out.images.cutout;
        cutout.enabled = true;
        cutout.image = out.images.base;
        cutout.factor =
            pbr.baseColorFactor.size() == 4 ? static_cast<float>(pbr.baseColorFactor[3]) : 1.0f;
        cutout.cutoff = m.alphaMode == "MASK" ? static_cast<float>(m.alphaCutoff) : 0.5f;
        if (m.alphaMode == "BLEND") {
            textures.warn("material '" + out.name +
                          "': alphaMode BLEND is rendered as MASK with alphaCutoff 0.5 (rayo has "
                          "no partial coverage)");
        }
    }
}

// metallicRoughnessTexture and occlusionTexture (docs/models.md): linear images, read with the
// sampler, texCoord and KHR_texture_transform as the base colour's; the factors they multiply
// are kept for the per-hit metallic workflow (shading/image_map.h PbrImages).
void attach_gltf_pbr_images(Material& out, const tinygltf::Material& m, GltfTextures& textures) {
    const auto& pbr = m.pbrMetallicRoughness;
    PbrImages& images = out.images.pbr;
    images.metallic_roughness =
        textures.map(pbr.metallicRoughnessTexture, out.name, "metallicRoughnessTexture");
    images.metallic_roughness.encoding = TextureEncoding::Linear;
    images.base_factor =
        Vec3(static_cast<float>(pbr.baseColorFactor[0]), static_cast<float>(pbr.baseColorFactor[1]),
             static_cast<float>(pbr.baseColorFactor[2]));
    images.metallic_factor = static_cast<float>(pbr.metallicFactor);
    images.roughness_factor = static_cast<float>(pbr.roughnessFactor);
    const tinygltf::OcclusionTextureInfo& occlusion = m.occlusionTexture;
    if (occlusion.index < 0) return;
    if (!std::isfinite(occlusion.strength) || occlusion.strength < 0.0 ||
        occlusion.strength > 1.0) {
        throw InputError(textures.path, "material '" + out.name +
                                            "': occlusionTexture.strength must be in [0, 1]");
    }
    tinygltf::TextureInfo info;  // the fields map() reads
    info.index = occlusion.index;
    info.texCoord = occlusion.texCoord;
    info.extensions = occlusion.extensions;
    images.occlusion = textures.map(info, out.name, "occlusionTexture");
    images.occlusion.encoding = TextureEncoding::Linear;
    images.occlusion_strength = static_cast<float>(occlusion.strength);
}

// tinygltf's file system, through read_input_file: buffers and images must be regular files of
// sane size that `access` allows (its own reader takes a directory for a huge file and reports
// "out of memory"). Paths are used as written (tinygltf's default expands them with wordexp).
struct GltfFiles {
    const std::string& gltf_path;  // the place named in messages
    const FileAccess& access;
    std::optional<InputError> refusal;  // the first read refused, reported if the load fails
    std::vector<std::pair<std::string, std::string>> refused;  // every read refused: path, why
};

bool gltf_file_exists(const std::string& path, void*) {
    return ::access(path.c_str(), F_OK) == 0;
}

std::string gltf_expand_path(const std::string& path, void*) {
    return path;
}

bool gltf_read_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                    void* user_data) {
    auto& files = *static_cast<GltfFiles*>(user_data);
    try {
        const std::string bytes = read_input_file(path, files.gltf_path, "glTF resource",
                                                  kMaxMeshFileBytes, files.access);
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const InputError& e) {
        if (!files.refusal) files.refusal = e;
        files.refused.emplace_back(path, e.message());
        if (err) *err = e.message();
        return false;
    }
}

bool gltf_refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&,
                       void*) {
    if (err) *err = "rayo does not write glTF files";
    return false;
}

// The JSON of a .gltf file, or of a .glb's first chunk (the glTF 2.0 binary layout: a 12-byte
// header, then the chunk's length and type "JSON"); empty when there is none.
std::string gltf_json_text(const std::string& bytes, bool binary) {
    if (!binary) return bytes;
    if (bytes.size() < 20 || std::memcmp(bytes.data() + 16, "JSON", 4) != 0) return {};
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);  // little-endian, as the format and x86 are
    return length <= bytes.size() - 20 ? bytes.substr(20, length) : std::string();
}

// The .glb `bytes` with its JSON chunk replaced by `json` (padded with spaces to 4 bytes, as
// the container requires); the chunks after it are kept as they are.
std::string replace_glb_json(const std::string& bytes, std::string json) {
    uint32_t old_length = 0;
    std::memcpy(&old_length, bytes.data() + 12, 4);  // gltf_json_text has checked the header
    while (json.size() % 4 != 0) json += ' ';
    const std::string rest = bytes.substr(20 + old_length);
    std::string out = bytes.substr(0, 12);
    const auto length = static_cast<uint32_t>(json.size());
    const auto total = static_cast<uint32_t>(20 + json.size() + rest.size());
    std::memcpy(&out[8], &total, 4);
    out.append(reinterpret_cast<const char*>(&length), 4);
    out += "JSON";
    return out + json + rest;
}

// The glTF extensions a file may require: the ones rayo implements.
const std::set<std::string> kSupportedRequiredExtensions = {kDracoExtension,
                                                            "KHR_texture_transform"};

// A glTF loader must refuse a file whose `extensionsRequired` names an extension it does not
// implement (glTF 2.0 specification, 3.12); each one is named.
void refuse_required_extensions(const nlohmann::json& root, const std::string& path) {
    if (!root.is_object()) return;  // tinygltf reports the malformed file
    const auto required = root.find("extensionsRequired");
    if (required == root.end() || !required->is_array() || required->empty()) return;
    std::string names;
    for (const auto& name : *required) {
        if (name.is_string() && kSupportedRequiredExtensions.count(name.get<std::string>())) {
            continue;
        }
        names += (names.empty() ? "" : ", ") +
                 (name.is_string() ? name.get<std::string>() : name.dump());
    }
    if (names.empty()) return;
    std::string supported;
    for (const std::string& name : kSupportedRequiredExtensions) {
        supported += (supported.empty() ? "" : ", ") + name;
    }
    throw InputError(path, "the file requires glTF extension(s) " + names +
                               ", which rayo does not support (it supports " + supported + ")");
}

// tinygltf holds about 1 KB a node (its record and its parse of the node's JSON), so the node
// count bounds what a small file of empty nodes can take (docs/limits.md, "glTF").
void refuse_too_many_nodes(const nlohmann::json& root, const std::string& path) {
    if (!root.is_object()) return;  // tinygltf reports the malformed file
    const auto nodes = root.find("nodes");
    if (nodes == root.end() || !nodes->is_array() || nodes->size() <= kMaxGltfNodes) return;
    throw InputError(path, "the file has " + std::to_string(nodes->size()) +
                               " nodes; the limit is " + std::to_string(kMaxGltfNodes) +
                               " (about 1 KB of memory each)");
}

}  // namespace

TriangleMesh load_gltf(const std::string& path, std::vector<Material>& materials,
                       const std::string& where, MeshImportStats* stats, const FileAccess& access,
                       GltfNodes* nodes) {
    const std::string bytes = read_input_file(path, where, "mesh file", kMaxMeshFileBytes, access);
    GltfFiles files{path, access, {}, {}};
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_image_bytes, nullptr);
    loader.SetFsCallbacks(
        {&gltf_file_exists, &gltf_expand_path, &gltf_read_file, &gltf_refuse_write, &files});
    tinygltf::Model model;
    std::string err, warn;
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const std::string json_text = gltf_json_text(bytes, binary);
    std::string stripped;
    {
        // This parse is freed before tinygltf parses the text again: both at once were the
        // peak of a file of many nodes (docs/limits.md, "glTF").
        nlohmann::json root = nlohmann::json::parse(json_text, nullptr, /*allow_exceptions=*/false);
        refuse_required_extensions(root, path);
        refuse_too_many_nodes(root, path);
        // Draco-compressed primitives: tinygltf reads the file without their indices, and
        // decode_draco_primitives gives them decoded ones (apps/scene/gltf_draco.h).
        if (root.is_object() && strip_draco_indices(root)) {
            stripped = binary ? replace_glb_json(bytes, root.dump()) : root.dump();
        }
    }
    const std::string& input = stripped.empty() ? bytes : stripped;
    const auto size = static_cast<unsigned int>(input.size());  // < kMaxMeshFileBytes + padding
    const std::string dir = parent_directory(path);
    const bool ok =
        binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                             reinterpret_cast<const unsigned char*>(input.data()),
                                             size, dir)
               : loader.LoadASCIIFromString(&model, &err, &warn, input.data(), size, dir);
    if (!ok) {
        // A referenced file refused by read_input_file: its own message, not tinygltf's.
        if (files.refusal) throw *files.refusal;
        throw InputError(path, std::string("malformed glTF") + (binary ? " binary" : "") + ": " +
                                   one_line(err.empty() ? "cannot parse" : err));
    }

    copy_buffer_view_images(model, path);
    decode_draco_primitives(model, path);

    std::vector<Material> converted;
    GltfTextures textures{model, path, stats, {}, &files.refused};
    for (size_t i = 0; i < model.materials.size(); ++i) {
        converted.push_back(material_from_gltf(model.materials[i], i, path));
        attach_gltf_images(converted.back(), model.materials[i], textures);
        attach_gltf_pbr_images(converted.back(), model.materials[i], textures);
    }
    GltfBuilder builder(model, path, materials);
    materials.insert(materials.end(), converted.begin(), converted.end());
    builder.mesh.name = file_name(path);
    builder.nodes = nodes;

    std::vector<int> roots;
    if (!model.scenes.empty()) {
        const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (static_cast<size_t>(scene) >= model.scenes.size()) {
            throw InputError(path, "default scene " + std::to_string(scene) + " does not exist");
        }
        roots = model.scenes[static_cast<size_t>(scene)].nodes;
    } else {
        // No scene: every node that is no other node's child is a root.
        std::vector<bool> is_child(model.nodes.size(), false);
        for (const auto& node : model.nodes) {
            for (int child : node.children) {
                if (child >= 0 && static_cast<size_t>(child) < is_child.size()) {
                    is_child[static_cast<size_t>(child)] = true;
                }
            }
        }
        for (size_t i = 0; i < model.nodes.size(); ++i) {
            if (!is_child[i]) roots.push_back(static_cast<int>(i));
        }
    }
    std::set<int> on_path;
    for (int root : roots) builder.visit(root, glm::dmat4(1.0), on_path);
    builder.place_meshes();

    TriangleMesh mesh = std::move(builder.mesh);
    const size_t dropped = drop_degenerate_triangles(mesh);
    complete_tangents(mesh, materials);
    if (nodes) {
        for (TriangleMesh& shared : nodes->shared_meshes) complete_tangents(shared, materials);
    }
    if (stats) {
        stats->degenerate_triangles = dropped + builder.shared_degenerate;
        stats->file_materials = converted.size();
    }
    if (!nodes || nodes->shared_meshes.empty()) check_mesh_not_empty(mesh, path, where);
    return mesh;
}

// ---- Shared helpers -----------------------------------------------------------------------

const char* const kMeshFileKinds = ".obj, .gltf, .glb, .ply, .stl or .off";

bool is_mesh_file(const std::string& path) {
    const std::string ext = lower_extension(path);
    return ext == ".obj" || ext == ".gltf" || ext == ".glb" || is_polygon_file(path);
}

ImportedMesh import_mesh_file(const std::string& path, std::vector<Material>& materials,
                              const MeshImportOptions& options) {
    const std::string& where = options.where;
    const std::string ext = lower_extension(path);
    ImportedMesh out;
    if (ext == ".obj") {
        out.mesh = load_obj(path, materials, where, &out.stats, options.access);
    } else if (ext == ".gltf" || ext == ".glb") {
        out.mesh =
            load_gltf(path, materials, where, &out.stats, options.access, options.gltf_nodes);
    } else if (is_polygon_file(path)) {
        out.mesh = load_polygon_file(path, materials, where, &out.stats, options.access);
    } else {
        throw InputError(where, "unknown mesh file format '" + ext + "' of '" + path +
                                    "': expected " + kMeshFileKinds);
    }
    TriangleMesh& mesh = out.mesh;
    transform_mesh(mesh, options.transform);
    if (!options.transform_where.empty()) {
        for (const Vec3& p : mesh.positions) {
            if (!point_within_scene_magnitude(p)) {
                throw InputError(options.transform_where,
                                 std::string("the transformed mesh does not fit in floats: every "
                                             "coordinate must be ") +
                                     kSceneMagnitudeRule);
            }
        }
    }
    out.stats.degenerate_triangles += drop_degenerate_triangles(mesh);
    if (!options.gltf_nodes || options.gltf_nodes->shared_meshes.empty())
        check_mesh_not_empty(mesh, path, where);
    if (out.stats.degenerate_triangles > 0) {  // dropped, not refused: reported by the CLI
        out.stats.warnings.push_back(
            where + ": dropped " + std::to_string(out.stats.degenerate_triangles) +
            " degenerate (zero-area) triangle(s)" + (where == path ? "" : " of '" + path + "'"));
    }
    return out;
}

void transform_mesh(TriangleMesh& mesh, const glm::dmat4& transform) {
    for (auto& p : mesh.positions) {
        p = Vec3(transform * glm::dvec4(glm::dvec3(p), 1.0));
    }
    // Normals transform by the inverse transpose of the linear part.
    const glm::dmat3 linear(transform);
    const glm::dmat3 normal_matrix = glm::inverseTranspose(linear);
    for (auto& n : mesh.normals) {
        const glm::dvec3 m = normal_matrix * glm::dvec3(n);
        const double length = glm::length(m);
        n = (std::isfinite(length) && length > 0.0) ? Vec3(m / length) : Vec3(0.0f);
    }
    // Tangents are directions (M·t); a mirror flips the bitangent's sign (the frame's handedness).
    const float handedness = glm::determinant(linear) < 0.0 ? -1.0f : 1.0f;
    for (auto& t : mesh.tangents) {
        if (t.w == 0.0f) continue;
        const glm::dvec3 m = linear * glm::dvec3(t);
        const double length = glm::length(m);
        t = (std::isfinite(length) && length > 0.0) ? glm::vec4(Vec3(m / length), handedness * t.w)
                                                    : glm::vec4(0.0f);
    }
    if (glm::determinant(linear) < 0.0) {
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);  // a mirror reverses the winding
    }
}

void complete_tangents(TriangleMesh& mesh, const std::vector<Material>& materials) {
    for (uint32_t m : mesh.materials) {
        if (m < materials.size() && materials[m].images.normal.used()) {
            compute_tangents(mesh);
            return;
        }
    }
}

void compute_vertex_normals(TriangleMesh& mesh) {
    // Vertices split only by their texture coordinates (a seam of the texture map) are one
    // point of the surface: they share one normal, so the seam leaves no crease.
    std::vector<uint32_t> point(mesh.positions.size());
    for (size_t i = 0; i < point.size(); ++i) point[i] = static_cast<uint32_t>(i);
    if (!mesh.uvs.empty()) {
        std::map<std::array<float, 3>, uint32_t> first;
        for (size_t i = 0; i < point.size(); ++i) {
            const Vec3& p = mesh.positions[i];
            point[i] = first.emplace(std::array<float, 3>{p.x, p.y, p.z}, i).first->second;
        }
    }
    std::vector<glm::dvec3> sums(mesh.positions.size(), glm::dvec3(0.0));
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        const glm::dvec3 area_normal = glm::cross(b - a, c - a);  // length = 2 × area
        for (uint32_t v : t) sums[point[v]] += area_normal;
    }
    mesh.normals.assign(mesh.positions.size(), Vec3(0.0f));
    for (size_t i = 0; i < sums.size(); ++i) {
        const double length = glm::length(sums[point[i]]);
        if (length > 0.0) mesh.normals[i] = Vec3(sums[point[i]] / length);
    }
}

size_t drop_degenerate_triangles(TriangleMesh& mesh) {
    size_t kept = 0;
    const bool per_triangle_materials = mesh.materials.size() == mesh.triangles.size();
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        const Vec3& a = mesh.positions[t[0]];
        const Vec3& b = mesh.positions[t[1]];
        const Vec3& c = mesh.positions[t[2]];
        const float area2 = glm::length(glm::cross(b - a, c - a));
        if (!(std::isfinite(area2) && area2 > 0.0f)) continue;
        mesh.triangles[kept] = t;
        if (per_triangle_materials) mesh.materials[kept] = mesh.materials[i];
        ++kept;
    }
    const size_t dropped = mesh.triangles.size() - kept;
    mesh.triangles.resize(kept);
    if (per_triangle_materials) mesh.materials.resize(kept);
    return dropped;
}

}  // namespace rayo
