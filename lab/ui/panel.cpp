// panel.cpp — the control panel's sections.
#include "ui/panel.h"

#include "ui/widgets.h"

#include <glm/glm.hpp>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>

namespace lab::ui {

const char* toString(ViewMode mode) {
    switch (mode) {
    case ViewMode::Lit: return "Lit (all terms)";
    case ViewMode::Emissive: return "Emissive only";
    case ViewMode::Ambient: return "Ambient only";
    case ViewMode::Diffuse: return "Diffuse only";
    case ViewMode::Specular: return "Specular only";
    case ViewMode::Normals: return "Normals as colours";
    }
    return "";
}

namespace {

template <typename E, std::size_t N>
bool enumCombo(const char* label, E& value, const E (&values)[N], const char* const (&names)[N]) {
    int current = 0;
    for (std::size_t i = 0; i < N; ++i) {
        if (values[i] == value) {
            current = static_cast<int>(i);
        }
    }
    bool changed = ImGui::Combo(label, &current, names, static_cast<int>(N));
    if (changed) {
        value = values[current];
    }
    return changed;
}

template <typename E, std::size_t N>
void enumRadios(const char* id, E& value, const E (&values)[N], const char* const (&names)[N]) {
    ImGui::PushID(id);
    for (std::size_t i = 0; i < N; ++i) {
        if (i > 0) {
            ImGui::SameLine();
        }
        if (ImGui::RadioButton(names[i], value == values[i])) {
            value = values[i];
        }
        mark(std::string(id) + "." + names[i]);
    }
    ImGui::PopID();
}

// Revert, Undo and Redo on one line, each enabled only when it would do something.
void historyButtons(const PanelModel& model, PanelActions& actions) {
    auto button = [](const char* label, bool enabled, bool& action) {
        ImGui::BeginDisabled(!enabled);
        if (ImGui::Button(label)) {
            action = true;
        }
        ImGui::EndDisabled();
    };
    button("Revert", model.dirty, actions.revert);
    ImGui::SameLine();
    button("Undo", model.canUndo, actions.undo);
    ImGui::SameLine();
    button("Redo", model.canRedo, actions.redo);
}

void browserFilesSection(PanelModel& model, PanelActions& actions) {
    ImGui::Text("%s%s", model.documentName.c_str(), model.dirty ? "  (modified)" : "");
    if (ImGui::Button("Download preset")) {
        actions.download = true;
    }
    mark("file.download");
    ImGui::SameLine();
    if (ImGui::Button("Open preset...")) {
        actions.pickFile = true;
    }
    mark("file.open");
    ImGui::SameLine();
    historyButtons(model, actions);
    ImGui::TextDisabled("Drop a .json preset or a .glb model on the page.");
}

void filesSection(PanelModel& model, PanelActions& actions) {
    if (model.browser) {
        browserFilesSection(model, actions);
        return;
    }
    ImGui::Text("%s%s", model.documentName.c_str(), model.dirty ? "  (modified)" : "");
    if (ImGui::Button("Save")) {
        actions.save = true;
    }
    mark("file.save");
    ImGui::SameLine();
    historyButtons(model, actions);

    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Open").x - ImGui::GetStyle().FramePadding.x * 2 -
                            ImGui::GetStyle().ItemSpacing.x);
    bool enter = ImGui::InputTextWithHint("##open", "path/to/preset.json", &model.openPath,
                                          ImGuiInputTextFlags_EnterReturnsTrue);
    mark("file.open-path");
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && !model.openPath.empty()) {
        actions.openPath = model.openPath;
    }
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Save as").x - ImGui::GetStyle().FramePadding.x * 2 -
                            ImGui::GetStyle().ItemSpacing.x);
    bool enterSave = ImGui::InputTextWithHint("##saveas", "path/to/new.json", &model.saveAsPath,
                                              ImGuiInputTextFlags_EnterReturnsTrue);
    mark("file.save-as-path");
    ImGui::SameLine();
    if ((ImGui::Button("Save as") || enterSave) && !model.saveAsPath.empty()) {
        actions.saveAs = model.saveAsPath;
    }
}

void presetsSection(PanelModel& model, PanelActions& actions) {
    float height = std::min(8.0f, static_cast<float>(model.presetFiles.size()) + 0.5f) * ImGui::GetTextLineHeightWithSpacing();
    if (ImGui::BeginListBox("##presets", ImVec2(-1, height))) {
        for (std::size_t i = 0; i < model.presetFiles.size(); ++i) {
            bool selected = static_cast<int>(i) == model.currentPreset;
            if (ImGui::Selectable(model.presetFiles[i].stem().string().c_str(), selected)) {
                actions.openPreset = static_cast<int>(i);
            }
            if (selected && ImGui::IsWindowAppearing()) {
                ImGui::SetScrollHereY();
            }
        }
        ImGui::EndListBox();
    }
    mark("presets.list");
    ImGui::TextDisabled("Left/Right: previous/next preset");
}

void materialSection(Preset& p) {
    colorEdit("emissive", p.material.emissive);
    mark("material.emissive");
    colorEdit("ambient", p.material.ambient);
    mark("material.ambient");
    colorEdit("diffuse", p.material.diffuse);
    mark("material.diffuse");
    colorEdit("specular", p.material.specular);
    mark("material.specular");
    ImGui::SliderFloat("shininess", &p.material.shininess, 1.0f, 1000.0f, "%.1f", ImGuiSliderFlags_Logarithmic);
    mark("material.shininess");
    p.material.shininess = std::max(p.material.shininess, 0.01f);
    helpMarker("The specular exponent n (logarithmic slider). Ctrl+click to type any value > 0.");
}

void brdfSection(Preset& p) {
    static const BrdfModel models[] = {BrdfModel::Phong, BrdfModel::BlinnPhong, BrdfModel::CookTorrance};
    static const char* const modelNames[] = {"Phong", "Blinn-Phong", "Cook-Torrance"};
    enumRadios("brdf", p.brdf, models, modelNames);
    if (p.brdf == BrdfModel::Phong) {
        ImGui::TextDisabled("S = max(0, R.V)^n");
    } else if (p.brdf == BrdfModel::BlinnPhong) {
        ImGui::TextDisabled("S = max(0, N.H)^n,  H = normalize(L + V)");
    } else {
        ImGui::TextDisabled("S = D F G / (4 N.V)");
        static const Distribution distributions[] = {Distribution::Beckmann, Distribution::Gaussian, Distribution::Ggx};
        static const char* const distributionNames[] = {"Beckmann", "Gaussian", "GGX"};
        enumCombo("D: distribution", p.cookTorrance.distribution, distributions, distributionNames);
        mark("cook_torrance.distribution");
        ImGui::SliderFloat("roughness m", &p.cookTorrance.roughness, 0.01f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
        p.cookTorrance.roughness = std::max(p.cookTorrance.roughness, 1e-3f);
        mark("cook_torrance.roughness");
        static const FresnelMode fresnels[] = {FresnelMode::Schlick, FresnelMode::Full};
        static const char* const fresnelNames[] = {"Schlick", "full (unpolarized)"};
        enumCombo("F: Fresnel", p.cookTorrance.fresnel, fresnels, fresnelNames);
        mark("cook_torrance.fresnel");
        ImGui::SliderFloat("ior", &p.cookTorrance.ior, 1.0f, 3.0f, "%.3f");
        p.cookTorrance.ior = std::max(p.cookTorrance.ior, 1e-3f);
        mark("cook_torrance.ior");
        float f0 = ((p.cookTorrance.ior - 1) / (p.cookTorrance.ior + 1));
        ImGui::SameLine();
        ImGui::TextDisabled("F0 = %.3f", f0 * f0);
        ImGui::Checkbox("G: geometry term", &p.cookTorrance.geometry);
        mark("cook_torrance.geometry");
    }
}

void shadingSection(Preset& p, PanelModel& model) {
    static const Shading shadings[] = {Shading::Flat, Shading::Gouraud, Shading::Phong};
    static const char* const shadingNames[] = {"flat", "Gouraud", "Phong"};
    enumRadios("shading", p.shading, shadings, shadingNames);
    static const NormalMatrixMode modes[] = {NormalMatrixMode::InverseTranspose, NormalMatrixMode::ModelView};
    static const char* const modeNames[] = {"inverse-transpose (correct)", "model-view (wrong)"};
    enumCombo("normal matrix", p.normalMatrix, modes, modeNames);
    mark("normal_matrix");
    ImGui::TextUnformatted("terms");
    ImGui::SameLine();
    ImGui::Checkbox("emissive##t", &p.terms.emissive);
    mark("terms.emissive");
    ImGui::SameLine();
    ImGui::Checkbox("ambient##t", &p.terms.ambient);
    mark("terms.ambient");
    ImGui::SameLine();
    ImGui::Checkbox("diffuse##t", &p.terms.diffuse);
    mark("terms.diffuse");
    ImGui::SameLine();
    ImGui::Checkbox("specular##t", &p.terms.specular);
    mark("terms.specular");
    static const ViewMode views[] = {ViewMode::Lit,     ViewMode::Emissive, ViewMode::Ambient,
                                     ViewMode::Diffuse, ViewMode::Specular, ViewMode::Normals};
    static const char* const viewNames[] = {toString(ViewMode::Lit),     toString(ViewMode::Emissive),
                                            toString(ViewMode::Ambient), toString(ViewMode::Diffuse),
                                            toString(ViewMode::Specular), toString(ViewMode::Normals)};
    enumCombo("view (V)", model.viewMode, views, viewNames);
    mark("view_mode");
    helpMarker("Shows one contribution on the model without changing the preset.");
    lightColorEdit("global ambient", p.ambientLight);
    mark("ambient_light");
    colorEdit("background", p.background);
    mark("background");
}

void modelSection(Preset& p, PanelModel& model, PanelActions& actions) {
    bool builtin = p.model.gltf.empty();
    static const Builtin builtins[] = {Builtin::Sphere, Builtin::Cube, Builtin::Plane, Builtin::Torus};
    static const char* const builtinNames[] = {"sphere", "cube", "plane", "torus"};
    if (builtin) {
        Builtin before = p.model.builtin;
        enumCombo("built-in", p.model.builtin, builtins, builtinNames);
        mark("model.builtin");
        if (p.model.builtin != before) {
            p.model.subdivisions = defaultSubdivisions(p.model.builtin);
        }
        int lo = p.model.builtin == Builtin::Sphere || p.model.builtin == Builtin::Torus ? 3 : 1;
        const char* label = p.model.builtin == Builtin::Sphere  ? "slices, stacks"
                            : p.model.builtin == Builtin::Torus ? "major, minor"
                                                                : "grid";
        ImGui::SliderInt2(label, &p.model.subdivisions.x, lo, 256);
        mark("model.subdivisions");
        p.model.subdivisions = glm::clamp(p.model.subdivisions, glm::ivec2(lo, p.model.builtin == Builtin::Sphere ? 2 : lo),
                                          glm::ivec2(1024));
    } else {
        ImGui::Text("glTF: %s", p.model.gltf.c_str());
        if (ImGui::Button("Use a built-in shape")) {
            p.model.gltf.clear();
            p.model.subdivisions = defaultSubdivisions(p.model.builtin);
        }
    }
    if (!model.browser) {
        ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Load").x - ImGui::GetStyle().FramePadding.x * 2 -
                                ImGui::GetStyle().ItemSpacing.x);
        bool enter = ImGui::InputTextWithHint("##model", "model.glb (or drop one on the window)", &model.modelPath,
                                              ImGuiInputTextFlags_EnterReturnsTrue);
        mark("model.path");
        ImGui::SameLine();
        if ((ImGui::Button("Load") || enter) && !model.modelPath.empty()) {
            actions.loadModel = model.modelPath;
        }
    }
    glm::vec3 scale = p.model.scale;
    if (dragVec3("scale", scale, 0.01f, -10.0f, 10.0f)) {
        // A zero factor would make the normal matrix singular: step over it.
        for (int i = 0; i < 3; ++i) {
            if (std::abs(scale[i]) < 0.01f) {
                scale[i] = p.model.scale[i] >= 0.0f ? 0.01f : -0.01f;
            }
        }
        p.model.scale = scale;
    }
    mark("model.scale");
    dragVec3("rotate (deg)", p.model.rotateDeg, 0.5f);
    mark("model.rotate");
    dragVec3("translate", p.model.translate, 0.01f);
    mark("model.translate");
}

// Direction as angles: θ from +y (0 = straight up), φ around +y from +z towards +x.
glm::vec2 toAngles(const glm::vec3& d) {
    glm::vec3 n = glm::normalize(d);
    return {glm::degrees(std::acos(glm::clamp(n.y, -1.0f, 1.0f))), glm::degrees(std::atan2(n.x, n.z))};
}

glm::vec3 fromAngles(const glm::vec2& a) {
    float t = glm::radians(a.x), f = glm::radians(a.y);
    return {std::sin(t) * std::sin(f), std::cos(t), std::sin(t) * std::cos(f)};
}

void lightsSection(Preset& p, PanelModel& model) {
    if (ImGui::Button("Add light") && p.lights.size() < kMaxLights) {
        p.lights.push_back(LightDesc{});
        model.selectedLight = static_cast<int>(p.lights.size()) - 1;
    }
    mark("lights.add");
    ImGui::SameLine();
    ImGui::BeginDisabled(p.lights.empty());
    if (ImGui::Button("Remove") && !p.lights.empty()) {
        p.lights.erase(p.lights.begin() + std::clamp(model.selectedLight, 0, static_cast<int>(p.lights.size()) - 1));
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::TextDisabled("%zu of %d", p.lights.size(), kMaxLights);
    if (p.lights.empty()) {
        ImGui::TextDisabled("No lights: only emissive and global ambient remain.");
        return;
    }
    model.selectedLight = std::clamp(model.selectedLight, 0, static_cast<int>(p.lights.size()) - 1);
    if (ImGui::BeginTabBar("lights")) {
        for (std::size_t i = 0; i < p.lights.size(); ++i) {
            std::string tab = "Light " + std::to_string(i + 1) + (p.lights[i].enabled ? "" : " (off)");
            if (ImGui::BeginTabItem((tab + "###light" + std::to_string(i)).c_str())) {
                model.selectedLight = static_cast<int>(i);
                ImGui::EndTabItem();
            }
        }
        ImGui::EndTabBar();
    }
    LightDesc& l = p.lights[static_cast<std::size_t>(model.selectedLight)];
    std::string prefix = "lights[" + std::to_string(model.selectedLight) + "].";
    ImGui::PushID(model.selectedLight);
    ImGui::Checkbox("enabled", &l.enabled);
    mark(prefix + "enabled");
    static const LightType types[] = {LightType::Point, LightType::Directional, LightType::Spot};
    static const char* const typeNames[] = {"point", "directional", "spot"};
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    enumCombo("type", l.type, types, typeNames);
    mark(prefix + "type");
    if (l.type != LightType::Directional) {
        dragVec3("position", l.position, 0.02f);
        mark(prefix + "position");
    }
    if (l.type != LightType::Point) {
        if (dragVec3("direction", l.direction, 0.01f) && l.direction == glm::vec3(0.0f)) {
            l.direction = {0.0f, -1.0f, 0.0f};
        }
        mark(prefix + "direction");
        glm::vec2 angles = toAngles(l.direction);
        if (ImGui::DragFloat2("theta, phi (deg)", &angles.x, 0.5f)) {
            angles.x = glm::clamp(angles.x, 0.0f, 180.0f);
            l.direction = fromAngles(angles) * glm::length(l.direction);
        }
        mark(prefix + "angles");
        helpMarker("theta from +y (0 points up, 180 straight down), phi around +y from +z towards +x.");
    }
    lightColorEdit("ambient", l.ambient);
    mark(prefix + "ambient");
    lightColorEdit("diffuse", l.diffuse);
    mark(prefix + "diffuse");
    lightColorEdit("specular", l.specular);
    mark(prefix + "specular");
    if (l.type != LightType::Directional) {
        glm::vec3 c = l.attenuation;
        if (ImGui::DragFloat3("c0, c1, c2", &c.x, 0.005f, 0.0f, 10.0f, "%.3f")) {
            c = glm::max(c, glm::vec3(0.0f));
            if (c != glm::vec3(0.0f)) { // all three zero is not a light
                l.attenuation = c;
            }
        }
        mark(prefix + "attenuation");
        helpMarker("Att = min(1, 1 / (c0 + c1 d + c2 d^2))");
        struct Choice {
            const char* name;
            glm::vec3 c;
        };
        static const Choice choices[] = {
            {"none", {1, 0, 0}}, {"1/d", {0, 1, 0}}, {"1/d^2", {0, 0, 1}}, {"OpenGL", {1, 0.35f, 0.44f}}};
        for (std::size_t i = 0; i < std::size(choices); ++i) {
            if (i > 0) {
                ImGui::SameLine();
            }
            if (ImGui::SmallButton(choices[i].name)) {
                l.attenuation = choices[i].c;
            }
            mark(prefix + "attenuation." + choices[i].name);
        }
    }
    if (l.type == LightType::Spot) {
        ImGui::SliderFloat("cut-off (deg)", &l.cutoffDeg, 0.0f, 90.0f, "%.1f");
        mark(prefix + "cutoff");
        ImGui::SliderFloat("exponent", &l.exponent, 0.0f, 128.0f, "%.1f");
        l.exponent = std::max(l.exponent, 0.0f);
        mark(prefix + "exponent");
    }
    ImGui::PopID();
}

void cameraSection(Preset& p, PanelActions& actions) {
    dragVec3("eye", p.camera.eye, 0.02f);
    dragVec3("target", p.camera.target, 0.02f);
    ImGui::SliderFloat("fovy (deg)", &p.camera.fovyDeg, 5.0f, 120.0f, "%.1f");
    if (ImGui::Button("Reset camera (R)")) {
        actions.resetCamera = true;
    }
    ImGui::TextDisabled("Left drag: orbit  Right drag: pan  Wheel: zoom");
    // Keep the camera valid whatever was dragged.
    if (glm::length(p.camera.eye - p.camera.target) < 1e-3f) {
        p.camera.eye = p.camera.target + glm::vec3(0, 0, 1e-3f);
    }
}

} // namespace

void controlPanel(Preset& preset, PanelModel& model, PanelActions& actions) {
    if (ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) {
        filesSection(model, actions);
    }
    if (!model.presetFiles.empty() && ImGui::CollapsingHeader("Presets", ImGuiTreeNodeFlags_DefaultOpen)) {
        presetsSection(model, actions);
    }
    if (ImGui::Button(model.compare ? "Compare: on (C)" : "Compare: off (C)")) {
        actions.toggleCompare = true;
    }
    mark("compare");
    if (model.compare) {
        ImGui::SameLine();
        if (ImGui::RadioButton(model.compareStacked ? "edit A (top)" : "edit A (left)", !model.editingB)) {
            model.editingB = false;
        }
        ImGui::SameLine();
        if (ImGui::RadioButton(model.compareStacked ? "edit B (bottom)" : "edit B (right)", model.editingB)) {
            model.editingB = true;
        }
        mark("compare.edit-b");
    }
    if (ImGui::Button("Shader editor")) {
        actions.openShaderEditor = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Screenshot")) {
        actions.screenshot = true;
    }
    mark("screenshot");
    ImGui::SameLine();
    if (ImGui::Button("?")) {
        actions.showHelp = true;
    }
    if (ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
        materialSection(preset);
    }
    if (ImGui::CollapsingHeader("Reflection model (BRDF)", ImGuiTreeNodeFlags_DefaultOpen)) {
        brdfSection(preset);
    }
    if (ImGui::CollapsingHeader("Shading and terms", ImGuiTreeNodeFlags_DefaultOpen)) {
        shadingSection(preset, model);
    }
    if (ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) {
        lightsSection(preset, model);
    }
    if (ImGui::CollapsingHeader("Model")) {
        modelSection(preset, model, actions);
    }
    if (ImGui::CollapsingHeader("Camera")) {
        cameraSection(preset, actions);
    }
}

} // namespace lab::ui
