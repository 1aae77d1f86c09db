// Shape methods (apps/scene/shape_method_choice.h): the mesh form stays within the chord error
// the pixel budget allows of the analytic surface, auto picks what its rule says, the scene
// file's "method" is read and bad values are refused at their JSON pointer.
#include "apps/scene/shape_method_choice.h"

#include <gtest/gtest.h>

#include <cmath>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/accel.h"
#include "core/shapes/blob_mesh.h"
#include "tests/scene/json_error.h"

namespace rayo {
namespace {

SceneDescription frame(int size = 96) {
    SceneDescription d;
    d.scene.camera.eye = Vec3(0.8f, 1.2f, 5.0f);
    d.scene.camera.look_at = Vec3(0.0f);
    d.scene.camera.vfov_degrees = 40.0f;
    d.scene.camera.width = d.scene.camera.height = size;
    d.shading.materials.push_back(Material{});
    return d;
}

template <typename S>
SceneDescription with(const S& shape) {
    SceneDescription d = frame();
    d.scene.shapes.of<S>().push_back(shape);
    return d;
}

Cylinder a_cylinder() {
    Cylinder c;
    c.base = Vec3(-0.4f, -1.0f, 0.0f);
    c.top = Vec3(0.4f, 1.0f, 0.0f);
    c.radius = 0.6f;
    return c;
}

// Three elements blending into one body (their spheres alone: radii 0.54, 0.49, 0.43).
Blob a_blob() {
    Blob b;
    b.threshold = 0.35f;
    b.elements = {{Vec3(-0.6f, -0.2f, 0.2f), 1.0f, 1.0f},
                  {Vec3(0.0f, 0.3f, 0.0f), 0.9f, 1.0f},
                  {Vec3(0.6f, -0.1f, -0.2f), 0.8f, 1.0f}};
    return b;
}

// Every camera ray that hits both forms: the analytic hit lies within the chord budget of the
// plane of the facet hit (|Δt|·|cos θ|, θ against the facet's normal), at the object's nearest
// distance (where the budget is set); and few pixels are hit by one form only.
template <typename S>
void expect_mesh_within_budget(const S& shape, float budget_px) {
    SceneDescription d = with(shape);
    d.settings.max_error_px = budget_px;
    const Camera camera = Camera::create(d.scene.camera);
    const Accel analytic(d.scene);
    d.settings.shape_method = ShapeMethod::Mesh;
    const ShapeChoices choices = choose_shape_methods(d, camera);
    ASSERT_TRUE(choices.scene.has_value()) << S::kName;
    ASSERT_EQ(choices.objects.size(), 1u);
    EXPECT_EQ(choices.objects[0].chosen, ShapeMethod::Mesh);
    EXPECT_LE(choices.objects[0].chord_px, budget_px) << S::kName;
    EXPECT_EQ(choices.scene->shapes.of<S>().size(), 0u);
    ASSERT_EQ(choices.scene->meshes.size(), 1u);
    const Accel mesh(*choices.scene);
    const Bounds3 b = shape.bounds();
    const float nearest =
        glm::length(glm::clamp(camera.desc().eye, b.lower, b.upper) - camera.desc().eye);
    const float chord = chord_budget(budget_px, camera.pixel_angle(), nearest);
    int both = 0, one = 0;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const Ray ray = camera.generate_ray(float(x), float(y));
            SurfaceHit a, m;
            const bool hit_a = analytic.intersect(ray, a);
            const bool hit_m = mesh.intersect(ray, m);
            if (hit_a != hit_m) ++one;
            if (!hit_a || !hit_m) continue;
            ++both;
            EXPECT_EQ(m.shape, kTriangleShape);
            const float separation =
                std::abs(m.t - a.t) * std::abs(glm::dot(ray.direction, m.geometric_normal));
            EXPECT_LE(separation, chord * 1.01f + 1e-5f) << S::kName << " pixel " << x << "," << y;
        }
    }
    EXPECT_GT(both, camera.width() * camera.height() / 10) << S::kName;
    EXPECT_LT(one, camera.width() * camera.height() / 50) << S::kName;
}

TEST(ShapeMethods, MeshFormsStayWithinTheChordBudgetOfTheAnalyticHits) {
    for (float budget : {2.0f, 0.5f}) {
        expect_mesh_within_budget(a_cylinder(), budget);
        Ellipsoid e;
        e.radii = Vec3(1.2f, 0.8f, 0.6f);
        expect_mesh_within_budget(e, budget);
        Cone cone;
        cone.base = Vec3(0.0f, -1.0f, 0.0f);
        cone.apex = Vec3(0.0f, 1.0f, 0.0f);
        cone.apex_radius = 0.25f;
        expect_mesh_within_budget(cone, budget);
        Paraboloid p;
        p.vertex = Vec3(0.0f, -1.0f, 0.0f);
        p.height = 2.0f;
        expect_mesh_within_budget(p, budget);
        Hyperboloid h;
        h.radius = 0.5f;
        h.semi_axis = 0.6f;
        expect_mesh_within_budget(h, budget);
        Disk disk;
        disk.normal = glm::normalize(Vec3(0.2f, 0.6f, 0.8f));
        expect_mesh_within_budget(disk, budget);
        expect_mesh_within_budget(Box{}, budget);
        expect_mesh_within_budget(a_blob(), budget);
    }
}

// A blob's mesh form is its marching tetrahedra, refined until blob_mesh_chord() is within the
// budget; that estimate bounds the separation the fan of camera rays above measures.
TEST(ShapeMethods, BlobMeshFormsRefineToTheirBudget) {
    SceneDescription d = with(a_blob());
    d.settings.shape_method = ShapeMethod::Mesh;
    const Camera camera = Camera::create(d.scene.camera);
    d.settings.max_error_px = 2.0f;
    const ShapeMethodChoice coarse = choose_shape_methods(d, camera).objects.at(0);
    d.settings.max_error_px = 0.1f;
    const ShapeMethodChoice fine = choose_shape_methods(d, camera).objects.at(0);
    EXPECT_EQ(fine.type, "blob");
    EXPECT_GT(fine.triangles, 4 * coarse.triangles);
    EXPECT_LE(coarse.chord_px, 2.0f);
    EXPECT_LE(fine.chord_px, 0.1f);
    EXPECT_GT(coarse.chord_px, 0.1f);
    // The estimate against the field itself: a mesh's chord is its vertices' and facets'
    // distance from F = T, which a coarser lattice makes larger.
    const Blob blob = a_blob();
    const double near_chord = blob_mesh_chord(blob, tessellate_blob(blob, 0.05));
    const double far_chord = blob_mesh_chord(blob, tessellate_blob(blob, 0.2));
    EXPECT_GT(near_chord, 0.0);
    EXPECT_GT(far_chord, 4.0 * near_chord);
    EXPECT_LT(far_chord, 0.2);
}

// A finer budget makes a finer mesh, with the chord error the budget asks for.
TEST(ShapeMethods, FinerBudgetsMakeFinerMeshes) {
    SceneDescription d = with(a_cylinder());
    d.settings.shape_method = ShapeMethod::Mesh;
    const Camera camera = Camera::create(d.scene.camera);
    d.settings.max_error_px = 2.0f;
    const ShapeMethodChoice coarse = choose_shape_methods(d, camera).objects.at(0);
    d.settings.max_error_px = 0.125f;
    const ShapeMethodChoice fine = choose_shape_methods(d, camera).objects.at(0);
    EXPECT_GT(fine.triangles, 2 * coarse.triangles);
    EXPECT_LE(fine.chord_px, 0.125f);
    EXPECT_GT(coarse.chord_px, 0.125f);
    EXPECT_EQ(fine.bytes, fine.triangles * kMeshBytesPerTriangle);
}

TEST(ShapeMethods, AutoFollowsItsRule) {
    auto pick = [](SceneDescription d, float budget = 0.5f) {
        d.settings.shape_method = ShapeMethod::Auto;
        d.settings.max_error_px = budget;
        const ShapeChoices c = choose_shape_methods(d, Camera::create(d.scene.camera));
        EXPECT_EQ(c.objects.size(), 1u);
        EXPECT_EQ(c.scene.has_value(), c.objects.at(0).chosen == ShapeMethod::Mesh);
        return c.objects.at(0);
    };
    // A clipped quadric whose mesh within the budget is small: the mesh.
    const ShapeMethodChoice cylinder = pick(with(a_cylinder()));
    EXPECT_EQ(cylinder.chosen, ShapeMethod::Mesh) << cylinder.reason;
    EXPECT_LE(cylinder.triangles, kAutoMeshMaxTriangles);
    // A budget whose mesh needs more triangles than the limit: analytic.
    Ellipsoid e;
    e.radii = Vec3(1.2f, 0.8f, 0.6f);
    EXPECT_EQ(pick(with(e)).chosen, ShapeMethod::Mesh);
    const ShapeMethodChoice fine = pick(with(e), 0.02f);
    EXPECT_EQ(fine.chosen, ShapeMethod::Analytic) << fine.reason;
    EXPECT_GT(fine.triangles, kAutoMeshMaxTriangles);
    EXPECT_LE(fine.chord_px, 0.02f);
    // A budget no mesh within kMeshFormMaxCells reaches: analytic.
    const ShapeMethodChoice unreachable = pick(with(a_cylinder()), 1e-5f);
    EXPECT_EQ(unreachable.chosen, ShapeMethod::Analytic) << unreachable.reason;
    EXPECT_GT(unreachable.chord_px, 1e-5f);
    // The camera inside its bounds: analytic.
    SceneDescription inside = with(a_cylinder());
    inside.scene.camera.eye = Vec3(0.0f, 0.0f, 0.1f);
    inside.scene.camera.look_at = Vec3(0.0f, 0.0f, 1.0f);
    EXPECT_EQ(pick(inside).chosen, ShapeMethod::Analytic);
    // Shapes whose own code is as fast as a mesh: analytic at any budget.
    Cone cone;
    EXPECT_EQ(pick(with(cone), 4.0f).chosen, ShapeMethod::Analytic);
    EXPECT_EQ(pick(with(Box{}), 4.0f).chosen, ShapeMethod::Analytic);
    EXPECT_EQ(pick(with(Disk{}), 4.0f).chosen, ShapeMethod::Analytic);
    // A blob whose mesh within the budget fits a lattice of kAutoBlobMeshMaxCells: the mesh;
    // one whose budget needs a finer lattice: analytic.
    const ShapeMethodChoice blob = pick(with(a_blob()));
    EXPECT_EQ(blob.chosen, ShapeMethod::Mesh) << blob.reason;
    EXPECT_LE(blob.triangles, kAutoBlobMeshMaxTriangles);
    EXPECT_LE(blob.chord_px, 0.5f);
    const ShapeMethodChoice fine_blob = pick(with(a_blob()), 0.002f);
    EXPECT_EQ(fine_blob.chosen, ShapeMethod::Analytic) << fine_blob.reason;
    EXPECT_GT(fine_blob.chord_px, 0.002f);
    EXPECT_NE(fine_blob.reason.find("with 128 cells a side"), std::string::npos)
        << fine_blob.reason;
}

TEST(ShapeMethods, WithoutMethodsTheSceneIsTracedAsLoaded) {
    SceneDescription d = with(a_cylinder());
    d.scene.shapes.of<Sphere>().push_back({Vec3(2.0f, 0.0f, 0.0f), 0.5f, 0});
    const Camera camera = Camera::create(d.scene.camera);
    ShapeChoices c = choose_shape_methods(d, camera);
    EXPECT_TRUE(c.objects.empty());
    EXPECT_FALSE(c.scene.has_value());
    EXPECT_EQ(&c.traced(d.scene), &d.scene);
    // --shape-method mesh leaves spheres alone (they have --sphere-method).
    d.settings.shape_method = ShapeMethod::Mesh;
    c = choose_shape_methods(d, camera);
    ASSERT_EQ(c.objects.size(), 1u);
    EXPECT_EQ(c.objects[0].type, "cylinder");
    ASSERT_TRUE(c.scene.has_value());
    EXPECT_EQ(c.scene->shapes.of<Sphere>().size(), 1u);
    EXPECT_EQ(c.scene->shapes.of<Cylinder>().size(), 0u);
}

const char* kScene = R"({
  "rayo": 1,
  "camera": {"eye": [0, 1, 8], "look_at": [0, 0, 0], "vfov": 40, "width": 48, "height": 36},
  "lights": [{"type": "point", "position": [3, 5, 6]}],
  "objects": [
    {"type": "cylinder", "base": [-1, -1, 0], "top": [-1, 1, 0], "radius": 0.5,
     "method": "mesh"},
    {"type": "cylinder", "base": [1, -1, 0], "top": [1, 1, 0], "radius": 0.5},
    {"type": "ellipsoid", "center": [0, 0, -2], "radii": [1, 0.5, 0.5], "method": "auto"},
    {"type": "box", "min": [-3, -1, -1], "max": [-2, 0, 0], "method": "analytic"}
  ]
})";

TEST(ShapeMethods, SceneFilesNameAMethodPerObject) {
    const SceneDescription d = load_json_string(kScene, "s.json", ".");
    ASSERT_EQ(d.shape_methods.size(), 3u);
    EXPECT_EQ(d.shape_methods[0].type, Shapes::index_of<Cylinder>());
    EXPECT_EQ(d.shape_methods[0].index, 0u);
    EXPECT_EQ(d.shape_methods[0].method, ShapeMethod::Mesh);
    EXPECT_EQ(d.shape_methods[1].type, Shapes::index_of<Ellipsoid>());
    EXPECT_EQ(d.shape_methods[1].method, ShapeMethod::Auto);
    EXPECT_EQ(d.shape_methods[2].type, Shapes::index_of<Box>());
    EXPECT_EQ(d.shape_methods[2].method, ShapeMethod::Analytic);
    const SceneDescription b = load_json_string(R"({"rayo": 1, "objects": [
        {"type": "blob", "threshold": 0.5, "method": "auto",
         "elements": [{"center": [0, 0, 0], "radius": 1, "strength": 1}]},
        {"type": "blob", "threshold": 0.5, "method": "mesh",
         "elements": [{"center": [3, 0, 0], "radius": 1, "strength": 1}]}]})",
                                                "b.json", ".");
    ASSERT_EQ(b.shape_methods.size(), 2u);
    EXPECT_EQ(b.shape_methods[0].type, Shapes::index_of<Blob>());
    EXPECT_EQ(b.shape_methods[0].method, ShapeMethod::Auto);
    EXPECT_EQ(b.shape_methods[1].index, 1u);
    EXPECT_EQ(b.shape_methods[1].method, ShapeMethod::Mesh);
    const RenderResult r = render_scene(d, 1, false);
    // In registry order; the second cylinder has no method: not listed.
    ASSERT_EQ(r.shapes.size(), 3u);
    EXPECT_EQ(r.shapes[0].type, "box");
    EXPECT_EQ(r.shapes[0].chosen, ShapeMethod::Analytic);
    EXPECT_EQ(r.shapes[1].type, "ellipsoid");
    EXPECT_EQ(r.shapes[2].type, "cylinder");
    EXPECT_EQ(r.shapes[2].index, 0u);
    EXPECT_EQ(r.shapes[2].chosen, ShapeMethod::Mesh);
    EXPECT_GT(r.shapes[2].triangles, 0u);
    const std::vector<std::string> lines = shape_method_lines(r.shapes);
    ASSERT_EQ(lines.size(), 6u);  // 3 types, 3 objects
    EXPECT_EQ(lines[0], "box: 1 analytic");
    EXPECT_NE(lines[2].find("cylinder: 1 mesh ("), std::string::npos) << lines[2];
}

TEST(ShapeMethods, BadMethodsAreRefusedAtTheirPointer) {
    auto scene = [](const std::string& object) {
        return R"({"rayo": 1, "objects": [)" + object + "]}";
    };
    EXPECT_NE(json_error_of(scene(R"({"type": "cylinder", "base": [0, 0, 0], "top": [0, 1, 0],
                                       "radius": 1, "method": "bvh"})"))
                  .find("s.json#/objects/0/method: expected one of \"analytic\", \"mesh\", "
                        "\"auto\", got the string \"bvh\""),
              std::string::npos);
    EXPECT_NE(json_error_of(scene(R"({"type": "disk", "center": [0, 0, 0], "radius": 1,
                                       "method": 3})"))
                  .find("s.json#/objects/0/method: expected one of"),
              std::string::npos);
    EXPECT_NE(json_error_of(scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                       "method": "mesh"})"))
                  .find("s.json#/objects/0/method: a sphere's method is the render's"),
              std::string::npos);
    EXPECT_NE(json_error_of(scene(R"({"type": "quadric",
                                       "coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, -1],
                                       "bounds": {"min": [-2, -2, -2], "max": [2, 2, 2]},
                                       "method": "mesh"})"))
                  .find("s.json#/objects/0/method: a quadric has no mesh form"),
              std::string::npos);
    const std::string grouped = R"({"rayo": 1, "groups": {"g": [
        {"type": "cylinder", "base": [0, 0, 0], "top": [0, 1, 0], "radius": 1,
         "method": "mesh"}]}, "objects": [{"type": "instance", "of": "g"}]})";
    EXPECT_NE(json_error_of(grouped).find("s.json#/groups/g/0/method: objects in groups"),
              std::string::npos)
        << json_error_of(grouped);
    const std::string blob = R"({"type": "blob", "threshold": 0.5,
        "elements": [{"center": [0, 0, 0], "radius": 1, "strength": 1}])";
    EXPECT_NE(json_error_of(scene(blob + R"(, "method": "dda"})"))
                  .find("s.json#/objects/0/method: expected one of \"analytic\", \"mesh\", "
                        "\"auto\", got the string \"dda\""),
              std::string::npos);
    const std::string grouped_blob =
        R"({"rayo": 1, "groups": {"g": [)" + blob +
        R"(, "method": "mesh"}]}, "objects": [{"type": "instance", "of": "g"}]})";
    EXPECT_NE(json_error_of(grouped_blob).find("s.json#/groups/g/0/method: objects in groups"),
              std::string::npos);
    // CSG children are traced by their intervals: no method, a blob's neither.
    EXPECT_NE(json_error_of(scene(R"({"type": "csg", "op": "union", "children": [)" + blob +
                                  R"(, "method": "analytic"},
                  {"type": "box", "min": [1, 0, 0], "max": [2, 1, 1]}]})"))
                  .find("s.json#/objects/0/children/0/method: unknown key"),
              std::string::npos);
    EXPECT_NE(json_error_of(scene(R"({"type": "csg", "op": "union", "children": [
                  {"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "method": "mesh"},
                  {"type": "box", "min": [1, 0, 0], "max": [2, 1, 1]}]})"))
                  .find("s.json#/objects/0/children/0/method: unknown key"),
              std::string::npos);
}

}  // namespace
}  // namespace rayo
