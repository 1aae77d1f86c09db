#include "apps/scene/scene_loader.h"

#include <sstream>

#include "apps/scene/json_loader.h"
#include "apps/scene/mesh_loader.h"
#include "apps/scene/nff_loader.h"
#include "core/error.h"
#include "core/path_util.h"
#include "core/scene_bounds.h"

namespace rayo {

namespace {

SceneDescription load_by_format(const std::string& path, const SceneLoadOptions& options,
                                const FileAccess& access) {
    const std::string extension = lower_extension(path);
    if (extension == ".json") return load_json_file(path, access);
    if (extension == ".nff") return load_nff_file(path, nullptr, options.nff);
    if (is_model_file(path)) return load_model_scene(path, options.model, access);
    throw InputError(path, "unknown scene format '" + extension +
                               "': expected a .json (rayo) or .nff (Neutral File Format) scene, "
                               "or a model file (" +
                               kMeshFileKinds + ")");
}

}  // namespace

SceneDescription load_scene_file(const std::string& path, const SceneLoadOptions& options) {
    FileAccess access = options.restrict_paths ? FileAccess::confined_to_scene(path) : FileAccess();
    access.keep_log();
    SceneDescription d = load_by_format(path, options, access);
    d.input_files = access.log();
    if (const size_t small = objects_below_float_resolution(d.scene)) {
        std::ostringstream text;
        text << small << " object(s) are smaller than " << kMinSizeToDistance
             << " of their distance from the origin: in float their shading positions and ray "
                "offsets are coarse for their size (docs/limits.md, \"Scale\"); move the scene "
                "near the origin";
        d.warnings.push_back(text.str());
    }
    return d;
}

}  // namespace rayo
