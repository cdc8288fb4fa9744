// gen_models.cpp — writes the glTF model(s) the repository ships, so none is downloaded.
//
//   lab_gen_models OUT_FOLDER      writes OUT_FOLDER/trefoil.glb
//
// trefoil.glb: a tube around a trefoil knot, positions and indices only (the lab computes the
// normals, area-weighted, when it loads the file), under a parent node that rotates and a child
// node that scales, so loading exercises node transforms as well. Its positions and indices are
// stored with EXT_meshopt_compression (glb_writer.h GlbStorage::MeshoptExponential: the same
// triangles, some starting at another corner; the positions through the EXPONENTIAL filter, each
// within 5e-5 of the plain file's), which takes the page's copy from 51 KB to 16.4 KB gzip-compressed
// (29 KB with the codecs alone, issue 40); its render is within 1 level of the plain file's. The
// output is deterministic; a test regenerates it and compares it byte for byte with
// presets/models/trefoil.glb.
#include "core/io/file_io.h"
#include "glb_writer.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace lab {
namespace {

glm::vec3 knot(float t) {
    // The classic trefoil, scaled to fit in about [-1, 1].
    return glm::vec3(std::sin(t) + 2.0f * std::sin(2.0f * t), std::cos(t) - 2.0f * std::cos(2.0f * t),
                     -std::sin(3.0f * t)) / 3.2f;
}

std::string trefoilGlb() {
    constexpr int kAround = 192, kTube = 16;
    constexpr float kRadius = 0.14f;
    const float tau = glm::two_pi<float>();
    std::vector<glm::vec3> positions;
    for (int i = 0; i < kAround; ++i) {
        float t = tau * static_cast<float>(i) / kAround;
        constexpr float h = 1e-3f;
        glm::vec3 c = knot(t);
        glm::vec3 d1 = (knot(t + h) - knot(t - h)) / (2.0f * h);
        glm::vec3 d2 = (knot(t + h) - 2.0f * c + knot(t - h)) / (h * h);
        glm::vec3 T = glm::normalize(d1);
        glm::vec3 B = glm::normalize(glm::cross(d1, d2)); // Frenet frame: the trefoil's curvature never vanishes
        glm::vec3 N = glm::cross(B, T);
        for (int j = 0; j < kTube; ++j) {
            float a = tau * static_cast<float>(j) / kTube;
            positions.push_back(c + kRadius * (std::cos(a) * N + std::sin(a) * B));
        }
    }
    std::vector<std::uint32_t> indices;
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>((i % kAround) * kTube + (j % kTube)); };
    for (int i = 0; i < kAround; ++i) {
        for (int j = 0; j < kTube; ++j) {
            // Counter-clockwise seen from outside the tube: j turns from N towards B = T x N, so
            // (along j) x (along i) points out. (The first version had them the other way round, and
            // the lab computed normals that pointed into the tube: the knot looked lit from behind.)
            indices.insert(indices.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j)});
            indices.insert(indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1)});
        }
    }
    using Json = nlohmann::ordered_json;
    Json nodes = Json::array({{{"name", "turn"}, {"rotation", {0.0, 0.0, 0.38268343236, 0.92387953251}}, {"children", {1}}},
                              {{"name", "knot"}, {"mesh", 0}, {"scale", {1.0, 1.0, 1.25}}}});
    return tools::writeGlb({"trefoil", positions, {}, indices}, nodes, "Lighting Lab tools/gen_models.cpp",
                           tools::GlbStorage::MeshoptExponential);
}

} // namespace
} // namespace lab

int main(int argc, char** argv) {
    if (argc != 2 || std::strcmp(argv[1], "--help") == 0) {
        std::fprintf(stderr, "usage: lab_gen_models OUT_FOLDER\n");
        return 2;
    }
    std::string error;
    std::filesystem::path out = std::filesystem::path(argv[1]) / "trefoil.glb";
    if (!lab::writeFileAtomic(out, lab::trefoilGlb(), error)) {
        std::fprintf(stderr, "lab_gen_models: %s\n", error.c_str());
        return 1;
    }
    std::printf("%s\n", out.string().c_str());
    return 0;
}
