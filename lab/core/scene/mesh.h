// mesh.h — triangle meshes on the CPU: the built-in shapes and the flat-shading expansion.
//
// A Mesh is indexed triangles with one normal per vertex, in model space. Built-ins are
// generated with counter-clockwise front faces and outward normals, and fit in [-1, 1]³.
// This file does not load files (core/gltf/model_loader.h) or upload to the GPU (render/renderer.h).
#pragma once

#include "core/scene/preset.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lab {

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; // one per position, unit length
    std::vector<std::uint32_t> indices; // three per triangle

    std::size_t triangleCount() const { return indices.size() / 3; }
};

// The vertex the flat-shading draw uses: each triangle de-indexed, every corner carrying the
// triangle's centroid and its geometric (face) normal, so the lighting is evaluated once per
// triangle there.
struct FlatVertex {
    glm::vec3 position;
    glm::vec3 faceNormal;
    glm::vec3 centroid;
};

Mesh makeSphere(int slices, int stacks);   // radius 1, poles on ±y
Mesh makeCube(int nx, int ny);             // side 2, each face an nx × ny grid
Mesh makePlane(int nx, int nz);            // [-1, 1]² in y = 0, facing +y
Mesh makeTorus(int major, int minor);      // in the xz-plane, radii 0.7 and 0.3
Mesh makeBuiltin(Builtin builtin, glm::ivec2 subdivisions);

std::vector<FlatVertex> expandFlat(const Mesh& mesh);

// Area-weighted average of the adjacent face normals (the cross product's length is twice the
// area, so summing unnormalized cross products weights by area). Vertices on no triangle, or on
// only degenerate ones, get +z.
std::vector<glm::vec3> computeVertexNormals(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices);

} // namespace lab
