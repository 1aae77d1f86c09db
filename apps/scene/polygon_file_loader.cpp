#include "apps/scene/polygon_file_loader.h"

#include <utility>

#include "apps/scene/off_reader.h"
#include "apps/scene/ply_reader.h"
#include "apps/scene/polygon_mesh.h"
#include "apps/scene/stl_reader.h"
#include "core/error.h"
#include "core/path_util.h"

namespace rayo {

bool is_polygon_file(const std::string& path) {
    const std::string ext = lower_extension(path);
    return ext == ".ply" || ext == ".stl" || ext == ".off";
}

TriangleMesh load_polygon_file(const std::string& path, std::vector<Material>& materials,
                               const std::string& where, MeshImportStats* stats,
                               const FileAccess& access) {
    const std::string bytes = read_input_file(path, where, "mesh file", kMaxMeshFileBytes, access);
    const std::string ext = lower_extension(path);
    const char* format = ext == ".ply" ? "PLY" : ext == ".stl" ? "STL" : "OFF";
    if (bytes.empty()) throw InputError(path, std::string("empty ") + format + " file");
    PolygonMesh polygons = ext == ".ply"   ? read_ply(bytes, path)
                           : ext == ".stl" ? read_stl(bytes, path)
                                           : read_off(bytes, path);
    TriangleMesh mesh =
        triangulate_polygon_mesh(std::move(polygons), default_material_index(materials));
    mesh.name = file_name(path);
    const size_t dropped = drop_degenerate_triangles(mesh);
    if (stats) {
        stats->degenerate_triangles = dropped;
        stats->file_materials = 0;
    }
    check_mesh_not_empty(mesh, path, where);
    return mesh;
}

}  // namespace rayo
