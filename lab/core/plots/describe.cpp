// describe.cpp — the text alternatives (describe.h).
#include "core/plots/describe.h"

#include "core/plots/energy.h"
#include "core/plots/slice.h"
#include "core/scene/field_table.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lab {

namespace {

std::string fixed(float v, int digits = 2) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, static_cast<double>(v));
    return buffer;
}

std::string label(std::string_view path, int value) {
    const FieldRow* row = fieldRow(path);
    for (const FieldChoice& c : row->choices) {
        if (c.value == value) {
            return c.label;
        }
    }
    return "?";
}

// The camera's right, up and towards-the-viewer axes.
struct CameraAxes {
    glm::vec3 right, up, back;
};
CameraAxes axesOf(const Camera& camera) {
    glm::vec3 forward = camera.target - camera.eye;
    forward = glm::length(forward) > 0.0f ? glm::normalize(forward) : glm::vec3(0, 0, -1);
    glm::vec3 right = glm::cross(forward, camera.up);
    right = glm::length(right) > 1e-6f ? glm::normalize(right) : glm::vec3(1, 0, 0);
    return {right, glm::cross(right, forward), -forward};
}

std::string colourWords(const glm::vec3& c) {
    float most = std::max({c.r, c.g, c.b});
    if (most <= 0.0f) {
        return "dark";
    }
    glm::vec3 n = c / most;
    if (std::min({n.r, n.g, n.b}) > 0.85f) {
        return "white";
    }
    return "coloured (" + fixed(c.r) + ", " + fixed(c.g) + ", " + fixed(c.b) + ")";
}

} // namespace

std::string directionWords(const Camera& camera, const glm::vec3& d, float side) {
    if (glm::length(d) < 1e-6f) {
        return "at the model's centre";
    }
    CameraAxes axes = axesOf(camera);
    glm::vec3 n = glm::normalize(d);
    float x = glm::dot(n, axes.right), y = glm::dot(n, axes.up), z = glm::dot(n, axes.back);
    std::string across = y > side ? "upper" : y < -side ? "lower" : "";
    std::string sideways = x > side ? "right" : x < -side ? "left" : "";
    std::string where = across.empty() ? sideways : sideways.empty() ? (y > 0 ? "above" : "below") : across + " " + sideways;
    std::string depth = z > side ? "in front" : z < -side ? "behind" : "";
    if (where.empty()) {
        return depth.empty() ? "beside the model" : depth == "in front" ? "straight ahead, in front" : "straight behind";
    }
    return depth.empty() ? where : where + ", " + depth;
}

std::string describeScene(const Preset& p) {
    const Model& m = p.model;
    std::string text = m.gltf.empty() ? "A " + label("model.builtin", static_cast<int>(m.builtin)) : "A glTF model";
    text += ", " + label("shading", static_cast<int>(p.shading)) + " shading, " +
            label("brdf", static_cast<int>(p.brdf)) + " BRDF, ";
    text += p.brdf == BrdfModel::CookTorrance ? "roughness " + fixed(p.cookTorrance.roughness)
                                               : "shininess " + fixed(p.material.shininess, 0);
    text += ", diffuse colour " + colourWords(p.material.diffuse) + ".";
    const glm::vec3 centre = m.translate;
    const glm::vec3 toViewer = glm::normalize(p.camera.eye - centre);
    int n = 0;
    for (const LightDesc& l : p.lights) {
        ++n;
        std::string name = "Light " + std::to_string(n);
        text += " " + name + ", " + label("lights[].type", static_cast<int>(l.type)) + (l.enabled ? ", on, " : ", off, ");
        glm::vec3 toLight = l.type == LightType::Directional ? -l.direction : l.position - centre;
        text += colourWords(l.diffuse) + ": " + directionWords(p.camera, toLight);
        if (l.type != LightType::Directional) {
            text += ", " + fixed(glm::length(toLight), 1) + " units from the model's centre";
        }
        text += l.orbit.on ? ", moving." : ".";
        if (!l.enabled || glm::length(toLight) < 1e-6f) {
            continue;
        }
        // On a sphere the highlight is where the normal halves the light and the viewer (Blinn's
        // H; Phong's R·V peaks there too).
        glm::vec3 h = glm::normalize(toLight) + toViewer;
        if (glm::length(h) < 1e-3f || glm::dot(glm::normalize(h), toViewer) <= 0.05f) {
            text += " The highlight of " + name + " is on the far side of the model.";
        } else {
            // On the sphere's silhouette a normal's sideways part is its place across the disc: a
            // third of the radius off the middle is seen as off the middle.
            std::string where = directionWords(p.camera, h, 0.3f);
            where = where.substr(0, where.find(','));
            text += " The highlight of " + name + " falls on the " +
                    (where == "straight ahead" ? std::string("middle") : where) + " of the model.";
        }
    }
    return text;
}

PlotWords describePlanePlot(const Preset& preset, int stepDeg) {
    PlotWords words;
    words.rows = reflectedIntensity(lobeInputs(preset, preset.plotIncidentDeg), stepDeg);
    auto peak = std::max_element(words.rows.begin(), words.rows.end(),
                                 [](const PlotSample& a, const PlotSample& b) { return a.total < b.total; });
    words.summary = "Reflected intensity in the plane of incidence, light at " + fixed(preset.plotIncidentDeg, 0) +
                    " degrees from the normal. ";
    if (peak == words.rows.end() || peak->total <= 0.0f) {
        words.summary += "Nothing is reflected.";
    } else {
        words.summary += "The total peaks at " + fixed(peak->thetaOutDeg, 0) + " degrees (" + fixed(peak->total, 3) +
                         "), the mirror direction is " + fixed(preset.plotIncidentDeg, 0) + " degrees.";
    }
    return words;
}

std::string describeLobe(const Preset& preset) {
    LobeInputs inputs = lobeInputs(preset, preset.plotIncidentDeg);
    std::vector<PlotSample> rows = reflectedIntensity(inputs, 1);
    auto peak = std::max_element(rows.begin(), rows.end(),
                                 [](const PlotSample& a, const PlotSample& b) { return a.specular < b.specular; });
    std::string text = peak == rows.end() || peak->specular <= 0.0f
                           ? "The specular lobe is empty."
                           : "The specular lobe peaks at " + fixed(peak->thetaOutDeg, 0) + " degrees in the plane of incidence (" +
                                 fixed(peak->specular, 3) + ").";
    if (std::optional<Albedo> a = albedo(inputs)) {
        text += " Albedo at " + fixed(preset.plotIncidentDeg, 0) + " degrees: diffuse " +
                fixed(albedoOf(*a, PlotComponent::Diffuse), 3) + ", specular " +
                fixed(albedoOf(*a, PlotComponent::Specular), 3) + ", total " + fixed(albedoOf(*a, PlotComponent::Total), 3) + ".";
    }
    return text;
}

std::string describeSlice(const Preset& preset) {
    const SliceImage image = sampleSlice(packSurfaceUniforms(preset));
    const std::vector<float>& values = image.component(PlotComponent::Specular);
    const float largest = image.largest(PlotComponent::Specular);
    if (!(largest > kNothingLit)) {
        return "The slice over the half angle and the difference angle: the specular term is 0 everywhere.";
    }
    const int n = image.side();
    int at = 0, reach = 0; // the largest value's sample; the largest half angle above half of it
    float spread = 0.0f;   // the most a column changes along the difference angle, over the largest
    for (int column = 0; column < n; ++column) {
        float lo = values[static_cast<std::size_t>(column)], hi = lo;
        for (int row = 0; row < n; ++row) {
            const int k = image.index(column, row);
            const float v = values[static_cast<std::size_t>(k)];
            at = v > values[static_cast<std::size_t>(at)] ? k : at;
            reach = v > 0.5f * largest ? std::max(reach, column) : reach;
            lo = row + 1 < n ? std::min(lo, v) : lo; // the 90 degree row is 0 (no light arrives): left out
            hi = row + 1 < n ? std::max(hi, v) : hi;
        }
        spread = column + 1 < n ? std::max(spread, (hi - lo) / largest) : spread;
    }
    const int step = image.stepDeg;
    std::string text = "The slice over the half angle theta h and the difference angle theta d (phi d 90 degrees), specular "
                       "term: largest " + fixed(largest, 3) + " at theta h " + std::to_string(at % n * step) +
                       ", theta d " + std::to_string(at / n * step) + " degrees; above half of it up to theta h " +
                       std::to_string(reach * step) + " degrees.";
    text += spread < 0.02f ? " It is the same at every theta d: vertical stripes, a function of N.H alone."
                           : " It changes with theta d as well as theta h.";
    return text;
}

} // namespace lab
