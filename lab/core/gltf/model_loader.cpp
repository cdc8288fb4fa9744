// model_loader.cpp — builtin or glTF, through the same checks as preset loading; framing.
#include "core/gltf/model_loader.h"

#include "core/gltf/reader.h"
#include "core/scene/transforms.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace lab {

std::string modelCacheKey(const Model& model, const std::filesystem::path& folder) {
    if (model.gltf.empty()) {
        return std::string(toString(model.builtin)) + ":" + std::to_string(model.subdivisions.x) + "x" +
               std::to_string(model.subdivisions.y);
    }
    std::error_code ec;
    std::filesystem::path file = std::filesystem::weakly_canonical(folder / model.gltf, ec);
    // The file-time count is 128 bits wide in the browser build's libc++: narrow it explicitly.
    auto size = static_cast<unsigned long long>(std::filesystem::file_size(file, ec));
    auto time = static_cast<long long>(std::filesystem::last_write_time(file, ec).time_since_epoch().count());
    return "gltf:" + file.string() + ":" + std::to_string(ec ? 0ull : size) + ":" + std::to_string(ec ? 0ll : time);
}

std::optional<Mesh> loadModel(const Model& model, const std::filesystem::path& folder, Diagnostics& diagnostics,
                              std::vector<std::string>* notes) {
    if (model.gltf.empty()) {
        return makeBuiltin(model.builtin, model.subdivisions);
    }
    std::string error;
    std::optional<std::filesystem::path> path = resolveModelPath(model.gltf, folder, error);
    if (!path) {
        diagnostics.push_back({"", "model.gltf", error});
        return std::nullopt;
    }
    std::optional<GltfResult> result = loadGltf(*path, model.gltf, diagnostics);
    if (!result) {
        return std::nullopt;
    }
    if (notes) {
        for (std::string& n : result->notes) {
            notes->push_back(model.gltf + ": " + n);
        }
    }
    return std::move(result->mesh);
}

namespace {

constexpr float kMinRadius = 1.0e-3f; // the smallest model lights are placed for

glm::vec3 clampToCoordinates(glm::vec3 p) {
    return glm::clamp(p, glm::vec3(limits::kCoordinate.min), glm::vec3(limits::kCoordinate.max));
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

std::optional<std::vector<glm::vec3>> drawnPositions(const Mesh& mesh, const Model& model) {
    if (mesh.positions.empty()) {
        return std::nullopt;
    }
    const glm::mat4 m = modelMatrix(model);
    std::vector<glm::vec3> drawn;
    drawn.reserve(mesh.positions.size());
    glm::vec3 lo(limits::kUnbounded), hi(-limits::kUnbounded);
    for (const glm::vec3& p : mesh.positions) {
        drawn.push_back(glm::vec3(m * glm::vec4(p, 1.0f)));
        lo = glm::min(lo, drawn.back());
        hi = glm::max(hi, drawn.back());
    }
    if (!finite(lo) || !finite(hi) || !finite(hi - lo)) {
        return std::nullopt; // coordinates that overflow float once scaled: nothing to frame
    }
    return drawn;
}

// Two passes over the mesh, no copy of it: the orbiting lights' centre is found this way on every
// change of the model's transform (app/orbit_clock.cpp), a slider drag's every frame.
std::optional<Sphere> drawnBounds(const Mesh& mesh, const Model& model) {
    if (mesh.positions.empty()) {
        return std::nullopt;
    }
    const glm::mat4 m = modelMatrix(model);
    auto drawn = [&](const glm::vec3& p) { return glm::vec3(m * glm::vec4(p, 1.0f)); };
    glm::vec3 lo(limits::kUnbounded), hi(-limits::kUnbounded);
    for (const glm::vec3& p : mesh.positions) {
        glm::vec3 q = drawn(p);
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    Sphere s{(lo + hi) * 0.5f, 0.0f};
    float farthest2 = 0.0f;
    for (const glm::vec3& p : mesh.positions) {
        glm::vec3 d = drawn(p) - s.center;
        farthest2 = std::max(farthest2, glm::dot(d, d));
    }
    s.radius = std::sqrt(farthest2);
    if (!std::isfinite(s.radius) || !finite(s.center) || !finite(hi - lo)) {
        return std::nullopt; // coordinates that overflow float once scaled: nothing to frame
    }
    return s;
}

void frameOmitted(LoadedPreset& loaded, const Mesh& mesh) {
    OmittedKeys omitted = std::exchange(loaded.omitted, OmittedKeys{});
    Preset& p = loaded.preset;
    if (p.model.gltf.empty() || !omitted.camera) {
        return;
    }
    std::optional<std::vector<glm::vec3>> drawn = drawnPositions(mesh, p.model);
    std::optional<Sphere> bounds = drawnBounds(mesh, p.model);
    if (!drawn || !bounds) {
        return;
    }
    p.camera = framedCamera(Camera{}, *drawn, threeQuarterDirection());
    if (omitted.lights) {
        p.lights = Preset{}.lights;
        for (LightDesc& light : p.lights) {
            light.position = clampToCoordinates(bounds->center + light.position * std::max(bounds->radius, kMinRadius));
        }
    }
}

void carryLights(std::vector<LightDesc>& lights, const Sphere& from, const Sphere& to) {
    const float k = std::max(to.radius, kMinRadius) / std::max(from.radius, kMinRadius);
    for (LightDesc& light : lights) {
        if (light.type == LightType::Directional) {
            continue;
        }
        light.position = clampToCoordinates(to.center + (light.position - from.center) * k);
        glm::vec3 a = light.attenuation;
        glm::vec3 scaled(a.x, limits::clamp(limits::kAttenuation, a.y / k), limits::clamp(limits::kAttenuation, a.z / (k * k)));
        if (scaled != glm::vec3(0.0f)) { // (never all three 0, which the validator refuses: k far out of range)
            light.attenuation = scaled;
        }
    }
}

} // namespace lab
