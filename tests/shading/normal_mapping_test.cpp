// Image-driven shading normals (shading/normal_mapping.h): the tangent frame, the normal map's
// texel in it, Blinn's bump-mapped normal from height differences, and the bend toward the
// viewer.
#include "shading/normal_mapping.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rayo {
namespace {

void expect_near(const Vec3& actual, const Vec3& expected, float tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

const Vec3 kZ(0.0f, 0.0f, 1.0f);

TEST(NormalMapping, FlatTexelKeepsTheNormal) {
    expect_near(tangent_space_normal(kZ, glm::vec4(1, 0, 0, 1), Vec3(0.5f, 0.5f, 1.0f), 1.0f), kZ,
                1e-6f);
}

TEST(NormalMapping, TexelTiltsAlongTangentAndBitangentWithHandedness) {
    // m = (2·0.75 − 1, 0, 1) = (0.5, 0, 1): toward the tangent.
    const Vec3 x = tangent_space_normal(kZ, glm::vec4(1, 0, 0, 1), Vec3(0.75f, 0.5f, 1.0f), 1.0f);
    expect_near(x, glm::normalize(Vec3(0.5f, 0.0f, 1.0f)), 1e-6f);
    // Green tilts along B = w·(N × T): +y for w = +1, −y for w = −1.
    const Vec3 texel(0.5f, 0.75f, 1.0f);
    expect_near(tangent_space_normal(kZ, glm::vec4(1, 0, 0, 1), texel, 1.0f),
                glm::normalize(Vec3(0.0f, 0.5f, 1.0f)), 1e-6f);
    expect_near(tangent_space_normal(kZ, glm::vec4(1, 0, 0, -1), texel, 1.0f),
                glm::normalize(Vec3(0.0f, -0.5f, 1.0f)), 1e-6f);
    // scale multiplies x and y (glTF normalTexture.scale).
    expect_near(tangent_space_normal(kZ, glm::vec4(1, 0, 0, 1), texel, 2.0f),
                glm::normalize(Vec3(0.0f, 1.0f, 1.0f)), 1e-6f);
}

TEST(NormalMapping, TangentIsOrthogonalisedAgainstTheNormal) {
    // A tangent leaning out of the surface: Gram-Schmidt keeps its in-plane direction.
    const Vec3 n = tangent_space_normal(kZ, glm::vec4(1, 0, 3, 1), Vec3(1.0f, 0.5f, 0.5f), 1.0f);
    expect_near(n, Vec3(1.0f, 0.0f, 0.0f), 1e-6f);
    // No usable frame: the normal as it was.
    expect_near(tangent_space_normal(kZ, glm::vec4(0, 0, 1, 1), Vec3(1.0f, 0.5f, 0.5f), 1.0f), kZ,
                0.0f);
    expect_near(tangent_space_normal(kZ, glm::vec4(1, 0, 0, 0), Vec3(1.0f, 0.5f, 0.5f), 1.0f), kZ,
                0.0f);
}

TEST(NormalMapping, SurfaceTangentPointsUpTheImage) {
    // t grows down the image: with ∂p/∂v = −y the image's up is +y = z × x, so w = +1.
    const glm::vec4 up = surface_tangent(kZ, Vec3(1, 0, 0), Vec3(0, -1, 0));
    EXPECT_EQ(up, glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(surface_tangent(kZ, Vec3(1, 0, 0), Vec3(0, 1, 0)).w, -1.0f);
    EXPECT_EQ(surface_tangent(kZ, Vec3(0.0f), Vec3(0, 1, 0)), glm::vec4(0.0f));
}

TEST(NormalMapping, BumpTiltsAgainstTheHeightGradient) {
    // F rises along u (= +x) with slope 1: the normal leans back toward −x.
    const Vec3 expected = glm::normalize(Vec3(-1.0f, 0.0f, 1.0f));
    expect_near(bump_mapped_normal(kZ, Vec3(1, 0, 0), Vec3(0, -1, 0), 1.0f, 0.0f), expected, 1e-6f);
    // Either orientation of the parameterization gives the same surface's normal.
    expect_near(bump_mapped_normal(kZ, Vec3(1, 0, 0), Vec3(0, 1, 0), 1.0f, 0.0f), expected, 1e-6f);
    // F rising along v where ∂p/∂v = −y: the surface rises toward −y, the normal leans to +y.
    expect_near(bump_mapped_normal(kZ, Vec3(1, 0, 0), Vec3(0, -1, 0), 0.0f, 1.0f),
                glm::normalize(Vec3(0.0f, 1.0f, 1.0f)), 1e-6f);
    // Longer tangents (a larger surface per unit of u) make the same height difference gentler.
    expect_near(bump_mapped_normal(kZ, Vec3(2, 0, 0), Vec3(0, -1, 0), 1.0f, 0.0f),
                glm::normalize(Vec3(-0.5f, 0.0f, 1.0f)), 1e-6f);
    // A flat height keeps a smooth mesh's interpolated normal, whatever the triangle's tangents.
    const Vec3 smooth = glm::normalize(Vec3(0.2f, 0.0f, 1.0f));
    expect_near(bump_mapped_normal(smooth, Vec3(1, 0, 0), Vec3(0, -1, 0), 0.0f, 0.0f), smooth,
                1e-6f);
}

TEST(NormalMapping, NormalsFacingAwayAreBentTowardTheViewer) {
    const Vec3 to_eye = glm::normalize(Vec3(1.0f, 0.0f, 0.2f));
    const Vec3 away = glm::normalize(Vec3(-1.0f, 0.0f, 0.5f));
    const Vec3 bent = face_viewer(away, to_eye);
    EXPECT_GT(glm::dot(bent, to_eye), 0.0f);
    EXPECT_NEAR(glm::length(bent), 1.0f, 1e-6f);
    // Facing the viewer already: unchanged.
    EXPECT_EQ(face_viewer(kZ, to_eye), kZ);
}

}  // namespace
}  // namespace rayo
