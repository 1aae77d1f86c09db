#include "apps/scene/shape_method_choice.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "core/shapes/blob_mesh.h"
#include "core/shapes/mesh_form.h"

namespace rayo {
namespace {

// The distance from `eye` to the nearest point of `b`; 0 inside.
float distance_to(const Bounds3& b, const Vec3& eye) {
    return glm::length(glm::clamp(eye, b.lower, b.upper) - eye);
}

// The cells a side of a shape's mesh form at most: a piece's grid (core/shapes/mesh_form.h), a
// blob's lattice across (core/shapes/blob_mesh.h; auto's is smaller, see
// kAutoBlobMeshMaxCells).
template <typename S>
int max_cells(ShapeMethod requested) {
    if constexpr (std::is_same_v<S, Blob>) {
        return requested == ShapeMethod::Auto ? kAutoBlobMeshMaxCells : kBlobMeshMaxCells;
    } else {
        return int(kMeshFormMaxCells);
    }
}

// The shape's mesh form within `max_chord` (world units).
template <typename S>
MeshForm mesh_form_of(const S& shape, float max_chord, ShapeMethod requested) {
    if constexpr (std::is_same_v<S, Blob>) {
        return blob_mesh_form(shape, max_chord, max_cells<S>(requested));
    } else {
        SurfacePieces pieces;
        shape.pieces(pieces);
        return mesh_form(pieces, max_chord, shape.material);
    }
}

// `mesh_bytes`: the scene's mesh forms so far (auto's memory budget).
template <typename S>
void choose(const S& shape, uint32_t index, ShapeMethod requested, const SceneDescription& d,
            const Camera& camera, size_t mesh_bytes, ShapeMethodChoice& choice, MeshForm& form) {
    choice.type = S::kName;
    choice.index = index;
    choice.requested = requested;
    choice.chosen = ShapeMethod::Analytic;
    if (requested == ShapeMethod::Analytic) {
        choice.reason = "as requested";
        return;
    }
    const float budget_px = d.settings.max_error_px;
    const float pixel_angle = camera.pixel_angle();
    const float distance = distance_to(shape.bounds(), camera.desc().eye);
    std::ostringstream reason;
    if (requested == ShapeMethod::Auto) {
        if (!auto_may_mesh<S>()) {
            choice.reason = "analytic: its own intersection is as fast as a mesh";
            return;
        }
        if (!(distance > 0.0f)) {
            choice.reason = "analytic: the camera is inside its bounds, no mesh is within budget";
            return;
        }
    }
    // Inside the bounds an explicit mesh takes the budget at the bounds' size: as fine as the
    // cells allow, its reported error says what that reaches.
    const Bounds3 b = shape.bounds();
    const float at = distance > 0.0f ? distance : max_abs_component(b.upper - b.lower);
    form = mesh_form_of(shape, chord_budget(budget_px, pixel_angle, at), requested);
    choice.triangles = form.mesh.triangle_count();
    choice.bytes = choice.triangles * kMeshBytesPerTriangle;
    choice.chord_px = distance > 0.0f ? form.chord / (distance * pixel_angle) : 0.0f;
    if (requested == ShapeMethod::Mesh) {
        choice.chosen = ShapeMethod::Mesh;
        choice.reason = "as requested";
        return;
    }
    // Auto (docs/shape-methods.md): the mesh form when it is within the budget, small enough to
    // trace faster than the analytic code and within the memory limit.
    if (choice.chord_px > budget_px) {
        reason << "analytic: a mesh reaches only " << choice.chord_px << " px (> budget "
               << budget_px << " px) with " << max_cells<S>(requested) << " cells a side";
    } else if (choice.triangles > auto_mesh_max_triangles<S>()) {
        reason << "analytic: the mesh within " << budget_px << " px needs " << choice.triangles
               << " triangles (> " << auto_mesh_max_triangles<S>() << ": slower than analytic)";
    } else if (mesh_bytes + choice.bytes > kAutoMeshSceneBytes) {
        reason << "analytic: the scene's mesh forms would pass " << (kAutoMeshSceneBytes >> 20)
               << " MB";
    } else {
        choice.chosen = ShapeMethod::Mesh;
        reason << "mesh: " << choice.triangles << " triangles (<= " << auto_mesh_max_triangles<S>()
               << ") within " << budget_px << " px";
    }
    choice.reason = reason.str();
}

}  // namespace

ShapeChoices choose_shape_methods(const SceneDescription& d, const Camera& camera) {
    ShapeChoices out;
    // Each object's method: --shape-method over its own "method".
    std::map<std::pair<uint32_t, uint32_t>, ShapeMethod> requested;
    for (const ShapeMethodRequest& r : d.shape_methods) requested[{r.type, r.index}] = r.method;
    if (requested.empty() && !d.settings.shape_method) return out;

    // Per registered type, which of its objects become meshes, and those meshes.
    std::vector<std::vector<bool>> meshed(AnalyticShapes::kCount);
    std::vector<TriangleMesh> forms;
    size_t mesh_bytes = 0;
    d.scene.shapes.for_each([&](const auto& shapes) {
        using S = ShapeOf<decltype(shapes)>;
        constexpr uint32_t type = Shapes::index_of<S>();
        meshed[type].assign(shapes.size(), false);
        for (uint32_t i = 0; i < shapes.size(); ++i) {
            const S& shape = shapes[i];
            std::optional<ShapeMethod> method = d.settings.shape_method;
            if (!method) {
                const auto it = requested.find({type, i});
                if (it != requested.end()) method = it->second;
            }
            if (!method || !has_mesh_form(shape)) continue;
            ShapeMethodChoice choice;
            MeshForm form;
            choose(shape, i, *method, d, camera, mesh_bytes, choice, form);
            if (choice.chosen == ShapeMethod::Mesh) {
                mesh_bytes += choice.bytes;
                form.mesh.name = std::string(S::kName) + " " + std::to_string(i);
                forms.push_back(std::move(form.mesh));
                meshed[type][i] = true;
            }
            out.objects.push_back(std::move(choice));
        }
    });
    if (forms.empty()) return out;
    // The loaded meshes keep their indices; the meshed objects follow them.
    out.scene = d.scene;
    out.scene->shapes.for_each([&](auto& shapes) {
        using S = ShapeOf<decltype(shapes)>;
        const std::vector<bool>& gone = meshed[Shapes::index_of<S>()];
        std::vector<S> kept;
        for (size_t i = 0; i < shapes.size(); ++i) {
            if (!gone[i]) kept.push_back(shapes[i]);
        }
        shapes = std::move(kept);
    });
    for (TriangleMesh& m : forms) out.scene->meshes.push_back(std::move(m));
    return out;
}

std::vector<std::string> shape_method_lines(const std::vector<ShapeMethodChoice>& choices) {
    struct Tally {
        size_t meshes = 0, analytic = 0, triangles = 0, bytes = 0;
        float worst_px = 0.0f;
    };
    std::vector<std::pair<std::string, Tally>> types;  // in the order met (registry order)
    for (const ShapeMethodChoice& c : choices) {
        if (types.empty() || types.back().first != c.type) types.push_back({c.type, Tally{}});
        Tally& t = types.back().second;
        if (c.chosen == ShapeMethod::Mesh) {
            ++t.meshes;
            t.triangles += c.triangles;
            t.bytes += c.bytes;
            t.worst_px = std::max(t.worst_px, c.chord_px);
        } else {
            ++t.analytic;
        }
    }
    std::vector<std::string> lines;
    for (const auto& [type, t] : types) {
        std::ostringstream line;
        line << type << ": ";
        if (t.meshes > 0) {
            line << t.meshes << " mesh (" << t.triangles << " triangles, ~" << t.bytes / 1024
                 << " KB, chord <= " << t.worst_px << " px)" << (t.analytic > 0 ? ", " : "");
        }
        if (t.analytic > 0) line << t.analytic << " analytic";
        lines.push_back(line.str());
    }
    if (choices.size() <= kShapeMethodLinesPerObject) {
        for (const ShapeMethodChoice& c : choices) {
            std::ostringstream line;
            line << c.type << " " << c.index << " (" << shape_method_name(c.requested)
                 << "): " << shape_method_name(c.chosen) << ", " << c.reason;
            lines.push_back(line.str());
        }
    }
    return lines;
}

}  // namespace rayo
