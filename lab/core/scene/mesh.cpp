// mesh.cpp — built-in shapes and the flat-shading expansion.
#include "core/scene/mesh.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>

namespace lab {

namespace {

constexpr float kTau = glm::two_pi<float>();

// Adds a (cols+1) × (rows+1) vertex grid from f(u, v) -> {position, normal}, u, v in [0, 1], and
// its two triangles per cell, counter-clockwise when u runs right and v runs up as seen from
// the front.
template <typename F>
void addGrid(Mesh& m, int cols, int rows, F f) {
    auto base = static_cast<std::uint32_t>(m.positions.size());
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i <= cols; ++i) {
            auto [p, n] = f(static_cast<float>(i) / static_cast<float>(cols), static_cast<float>(j) / static_cast<float>(rows));
            m.positions.push_back(p);
            m.normals.push_back(n);
        }
    }
    auto at = [&](int i, int j) { return base + static_cast<std::uint32_t>(j * (cols + 1) + i); };
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < cols; ++i) {
            m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
}

} // namespace

Mesh makeSphere(int slices, int stacks) {
    Mesh m;
    // u runs around the y axis, v from the south pole (v = 0) to the north pole.
    addGrid(m, slices, stacks, [](float u, float v) {
        float phi = u * kTau;
        float theta = v * glm::pi<float>();
        // Exactly on the axis at the poles, so the pole triangles are exactly degenerate.
        float s = (v <= 0.0f || v >= 1.0f) ? 0.0f : std::sin(theta);
        glm::vec3 n(-s * std::cos(phi), -std::cos(theta), s * std::sin(phi));
        return std::pair{n, n};
    });
    // Drop the degenerate triangles at the poles (two corners on the same pole).
    std::vector<std::uint32_t> kept;
    kept.reserve(m.indices.size());
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3& a = m.positions[m.indices[t]];
        const glm::vec3& b = m.positions[m.indices[t + 1]];
        const glm::vec3& c = m.positions[m.indices[t + 2]];
        if (glm::length(glm::cross(b - a, c - a)) > 1e-9f) {
            kept.insert(kept.end(), {m.indices[t], m.indices[t + 1], m.indices[t + 2]});
        }
    }
    m.indices = std::move(kept);
    return m;
}

Mesh makeCube(int nx, int ny) {
    Mesh m;
    // Each face: normal n, and two in-plane axes s, t with s × t = n (counter-clockwise front).
    const glm::vec3 faces[6][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    for (const auto& f : faces) {
        glm::vec3 n = f[0], s = f[1], t = f[2];
        addGrid(m, nx, ny, [&](float u, float v) { return std::pair{n + s * (2 * u - 1) + t * (2 * v - 1), n}; });
    }
    return m;
}

Mesh makePlane(int nx, int nz) {
    Mesh m;
    // u along +x, v along -z: x × (-z) = +y, so the front faces up.
    addGrid(m, nx, nz, [](float u, float v) {
        return std::pair{glm::vec3(2 * u - 1, 0, 1 - 2 * v), glm::vec3(0, 1, 0)};
    });
    return m;
}

Mesh makeTorus(int major, int minor) {
    Mesh m;
    constexpr float R = 0.7f, r = 0.3f;
    // u around the y axis, v around the tube; the orientation is chosen so the winding faces out.
    addGrid(m, major, minor, [](float u, float v) {
        float a = -u * kTau, b = v * kTau;
        glm::vec3 ring(std::cos(a), 0, std::sin(a));
        glm::vec3 n = ring * std::cos(b) + glm::vec3(0, std::sin(b), 0);
        return std::pair{ring * R + n * r, n};
    });
    return m;
}

Mesh makeBuiltin(Builtin builtin, glm::ivec2 s) {
    switch (builtin) {
    case Builtin::Sphere: return makeSphere(s.x, s.y);
    case Builtin::Cube: return makeCube(s.x, s.y);
    case Builtin::Plane: return makePlane(s.x, s.y);
    case Builtin::Torus: return makeTorus(s.x, s.y);
    }
    return {};
}

std::vector<FlatVertex> expandFlat(const Mesh& mesh) {
    std::vector<FlatVertex> out;
    out.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3& a = mesh.positions[mesh.indices[t]];
        const glm::vec3& b = mesh.positions[mesh.indices[t + 1]];
        const glm::vec3& c = mesh.positions[mesh.indices[t + 2]];
        glm::vec3 n = glm::cross(b - a, c - a);
        float len = glm::length(n);
        n = len > 0.0f ? n / len : mesh.normals[mesh.indices[t]];
        glm::vec3 centroid = (a + b + c) / 3.0f;
        out.push_back({a, n, centroid});
        out.push_back({b, n, centroid});
        out.push_back({c, n, centroid});
    }
    return out;
}

std::vector<glm::vec3> computeVertexNormals(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices) {
    // In double: the cross product of any two float-range edges fits, where float would overflow
    // to infinity for models of very large coordinates (found by fuzz_gltf).
    std::vector<glm::dvec3> sum(positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        std::uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
        glm::dvec3 p0(positions[i0]);
        glm::dvec3 n = glm::cross(glm::dvec3(positions[i1]) - p0, glm::dvec3(positions[i2]) - p0);
        sum[i0] += n;
        sum[i1] += n;
        sum[i2] += n;
    }
    std::vector<glm::vec3> normals(positions.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
        double len = glm::length(sum[i]);
        normals[i] = len > 0.0 && std::isfinite(len) ? glm::vec3(sum[i] / len) : glm::vec3(0, 0, 1);
    }
    return normals;
}

} // namespace lab
