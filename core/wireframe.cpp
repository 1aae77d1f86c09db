#include "core/wireframe.h"

#include <algorithm>

#include "core/line_raster.h"
#include "core/shapes/outline.h"

namespace rayo {

SegmentFate project_segment(const SyntheticCamera& camera, const DVec3& a, const DVec3& b,
                            DVec2& pa, DVec2& pb) {
    DVec3 qa = camera.to_camera(a), qb = camera.to_camera(b);
    // The near plane: any depth > 0 projects; one a millionth of the segment's far depth keeps
    // the projected end points finite and the clip's arithmetic exact enough in double.
    const double near = 1e-6 * std::max(qa.z, qb.z);
    if (!(near > 0.0)) return SegmentFate::Behind;
    bool cut = false;
    if (qa.z < near) {
        qa += (near - qa.z) / (qb.z - qa.z) * (qb - qa);
        cut = true;
    } else if (qb.z < near) {
        qb += (near - qb.z) / (qa.z - qb.z) * (qa - qb);
        cut = true;
    }
    pa = camera.project_camera(qa);
    pb = camera.project_camera(qb);
    const DVec2 before_a = pa, before_b = pb;
    if (!clip_segment(camera.window(), pa, pb)) return SegmentFate::Outside;
    cut = cut || pa != before_a || pb != before_b;
    return cut ? SegmentFate::Cut : SegmentFate::Whole;
}

WireframeStats draw_wireframe(const Scene& scene, const Camera& camera, Film& film,
                              const Vec3& rgb) {
    const SyntheticCamera synthetic(camera);
    Outline outline(OutlineView{synthetic.position(), synthetic.pixel_angle()});
    WireframeStats stats;
    const auto draw = [&](const auto& object) {
        outline.clear();
        object.outline(outline);  // every registered shape has one (core/shapes/shape.h)
        ++stats.objects;
        stats.segments += outline.segments().size();
        for (const OutlineSegment& s : outline.segments()) {
            DVec2 pa, pb;
            switch (project_segment(synthetic, s.a, s.b, pa, pb)) {
                case SegmentFate::Behind:
                    ++stats.behind;
                    continue;
                case SegmentFate::Outside:
                    ++stats.outside;
                    continue;
                case SegmentFate::Cut:
                    ++stats.cut;
                    break;
                case SegmentFate::Whole:
                    break;
            }
            ++stats.drawn;
            draw_line(film, pa, pb, rgb);
        }
    };
    scene.shapes.for_each([&](const auto& shapes) {
        for (const auto& shape : shapes) draw(shape);
    });
    for (const TriangleMesh& mesh : scene.meshes) draw(mesh);
    for (const HeightField& field : scene.heightfields) draw(field);
    for (const VoxelGrid& grid : scene.voxels) draw(grid);  // the box
    return stats;
}

}  // namespace rayo
