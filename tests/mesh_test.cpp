// mesh_test.cpp — the built-in shapes face outwards, and the flat expansion keeps the geometry.
#include "core/scene/mesh.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace lab {
namespace {

struct Shape {
    Builtin builtin;
    glm::ivec2 subdivisions;
    std::size_t triangles;
};

void PrintTo(const Shape& s, std::ostream* os) { *os << toString(s.builtin) << " " << s.subdivisions.x << "x" << s.subdivisions.y; }

class BuiltinMeshes : public testing::TestWithParam<Shape> {};

TEST_P(BuiltinMeshes, WindCounterClockwiseAroundOutwardUnitNormals) {
    const Shape& s = GetParam();
    Mesh m = makeBuiltin(s.builtin, s.subdivisions);
    EXPECT_EQ(m.triangleCount(), s.triangles);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        ASSERT_LT(m.indices[t + 2], m.positions.size());
        const glm::vec3 &a = m.positions[m.indices[t]], &b = m.positions[m.indices[t + 1]], &c = m.positions[m.indices[t + 2]];
        glm::vec3 face = glm::cross(b - a, c - a);
        glm::vec3 vertexNormals = m.normals[m.indices[t]] + m.normals[m.indices[t + 1]] + m.normals[m.indices[t + 2]];
        ASSERT_GT(glm::dot(face, vertexNormals), 0.0f) << "triangle " << t / 3 << " winds the wrong way";
    }
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        ASSERT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-5f);
        ASSERT_LE(glm::length(m.positions[i]), std::sqrt(3.0f) + 1e-5f); // fits in [-1, 1]^3
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, BuiltinMeshes,
                         testing::Values(Shape{Builtin::Sphere, {8, 4}, 8 * 4 * 2 - 2 * 8},
                                         Shape{Builtin::Sphere, {64, 32}, 64 * 32 * 2 - 2 * 64},
                                         Shape{Builtin::Cube, {1, 1}, 12}, Shape{Builtin::Cube, {3, 2}, 72},
                                         Shape{Builtin::Plane, {4, 5}, 40}, Shape{Builtin::Torus, {12, 6}, 144}));

TEST(Mesh, SpherePositionsAreOnTheUnitSphereWithRadialNormals) {
    Mesh m = makeSphere(16, 8);
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(m.positions[i]), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::distance(m.positions[i], m.normals[i]), 0.0f, 1e-6f);
    }
}

TEST(Mesh, FlatExpansionCarriesCentroidAndFaceNormal) {
    Mesh m = makeSphere(6, 3);
    std::vector<FlatVertex> flat = expandFlat(m);
    ASSERT_EQ(flat.size(), m.indices.size());
    for (std::size_t t = 0; t < flat.size(); t += 3) {
        glm::vec3 centroid = (flat[t].position + flat[t + 1].position + flat[t + 2].position) / 3.0f;
        glm::vec3 face = glm::normalize(glm::cross(flat[t + 1].position - flat[t].position, flat[t + 2].position - flat[t].position));
        for (std::size_t k = 0; k < 3; ++k) {
            EXPECT_NEAR(glm::distance(flat[t + k].centroid, centroid), 0.0f, 1e-6f);
            EXPECT_NEAR(glm::distance(flat[t + k].faceNormal, face), 0.0f, 1e-6f);
            EXPECT_EQ(flat[t + k].position, m.positions[m.indices[t + k]]);
        }
    }
}

} // namespace
} // namespace lab
