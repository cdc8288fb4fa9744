// panel.cpp — the control panel's sections.
#include "ui/panel.h"

#include "core/io/safe_text.h"
#include "core/lighting/lighting.h"
#include "core/scene/camera.h"
#include "core/scene/limits.h"
#include "core/scene/preset_choices.h"
#include "ui/equation_panel.h"
#include "ui/exercise_panel.h"
#include "ui/widgets.h"

#include <glm/glm.hpp>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lab::ui {

namespace {

// A combo over every value of an enumeration (core/scene/preset_choices.h), with one display name each.
template <typename E, std::size_t N>
bool enumCombo(const char* label, E& value, const std::array<E, N>& values, const char* const* names) {
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
void enumRadios(const char* id, E& value, const std::array<E, N>& values, const char* const (&names)[N]) {
    ImGui::PushID(id);
    for (std::size_t i = 0; i < N; ++i) {
        if (i > 0) {
            sameLineIfFitsRadio(names[i]);
        }
        if (ImGui::RadioButton(names[i], value == values[i])) {
            value = values[i];
        }
        mark(std::string(id) + "." + names[i]);
    }
    ImGui::PopID();
}

// Revert, Undo and Redo on one line, each enabled only when it would do something.
void historyButtons(const PanelInfo& info, std::vector<Request>& requests) {
    commandButton(Command::Revert, requests, info.dirty);
    sameLineIfFits(commandRow(Command::Undo).label);
    commandButton(Command::Undo, requests, info.canUndo);
    sameLineIfFits(commandRow(Command::Redo).label);
    commandButton(Command::Redo, requests, info.canRedo);
}

void browserFilesSection(const PanelInfo& info, std::vector<Request>& requests) {
    commandButton(Command::DownloadPreset, requests);
    mark("file.download");
    sameLineIfFits(commandRow(Command::PickFile).label);
    commandButton(Command::PickFile, requests);
    mark("file.open");
    sameLineIfFits(commandRow(Command::CopyLink).label);
    commandButton(Command::CopyLink, requests);
    mark("file.copy-link");
    sameLineIfFits(commandRow(Command::Revert).label);
    historyButtons(info, requests);
    disabledWrapped("Drop a .json preset or a .glb model on the page.");
}

void filesSection(const PanelInfo& info, PanelState& state, std::vector<Request>& requests) {
    ImGui::Text("%s%s", info.documentName.c_str(), info.dirty ? "  (modified)" : "");
    if (info.browser) {
        browserFilesSection(info, requests);
        return;
    }
    if (commandButton(Command::Save, requests)) {
        requests.back().path = state.saveAsPath; // where an untitled scene goes
    }
    mark("file.save");
    sameLineIfFits(commandRow(Command::Revert).label);
    historyButtons(info, requests);
    if (state.focusOpenPath) {
        ImGui::SetKeyboardFocusHere();
    }
    pathField("##open", "path/to/preset.json", state.openPath, Command::OpenPath, requests);
    mark("file.open-path");
    pathField("##saveas", "path/to/new.json", state.saveAsPath, Command::SaveAs, requests);
    mark("file.save-as-path");
}

void presetsSection(const PanelInfo& info, PanelState& state, std::vector<Request>& requests) {
    const std::vector<std::filesystem::path>& files = *info.presetFiles;
    float height = std::min(8.0f, static_cast<float>(files.size()) + 0.5f) * ImGui::GetTextLineHeightWithSpacing();
    if (ImGui::BeginListBox("##presets", ImVec2(-1, height))) {
        for (std::size_t i = 0; i < files.size(); ++i) {
            bool selected = static_cast<int>(i) == info.currentPreset;
            // The row's place is its ID; the file's name (escaped: dropped files land in this list) is
            // drawn as it is, not as a label, where "##" would hide the rest of it.
            std::string id = "###preset" + std::to_string(i);
            ImVec2 at = ImGui::GetCursorScreenPos(); // where the Selectable puts a label's text
            bool clicked = ImGui::Selectable(id.c_str(), selected);
            std::string name = printable(files[i].stem().string(), true);
            ImGui::GetWindowDrawList()->AddText(at, ImGui::GetColorU32(ImGuiCol_Text), name.c_str());
            if (clicked) {
                requests.push_back({Command::OpenPresetAt, {}, static_cast<int>(i)});
            }
            if (selected && (ImGui::IsWindowAppearing() || state.listScrolledTo != info.currentPreset)) {
                ImGui::SetScrollHereY(); // the list follows Left/Right through the presets
                state.listScrolledTo = info.currentPreset;
            }
        }
        ImGui::EndListBox();
    }
    mark("presets.list");
    ImGui::TextDisabled("Left/Right: previous/next preset");
    if (info.exerciseFiles && !info.exerciseFiles->empty()) {
        exerciseList(*info.exerciseFiles, requests);
    }
}

// A float slider over the range `r` allows (typed values too), clamped to what the validator accepts.
bool limitedSlider(const char* label, float& value, const limits::Range& r, const char* format,
                   ImGuiSliderFlags flags = ImGuiSliderFlags_None) {
    bool changed = ImGui::SliderFloat(label, &value, r.sliderMin, r.sliderMax, format, flags);
    value = limits::clamp(r, value);
    return changed;
}

void materialSection(Preset& p) {
    const std::pair<const char*, glm::vec3*> colors[] = {{"emissive", &p.material.emissive},
                                                         {"ambient", &p.material.ambient},
                                                         {"diffuse", &p.material.diffuse},
                                                         {"specular", &p.material.specular}};
    for (const auto& [name, color] : colors) {
        const std::string path = std::string("material.") + name;
        if (field(path)) {
            colorEdit(name, *color);
            mark(path);
        }
    }
    if (p.brdf == BrdfModel::CookTorrance) {
        return; // the exponent n has no effect there (the roughness m shapes the lobe), as m has none for Phong
    }
    if (field("material.shininess")) {
        limitedSlider("shininess", p.material.shininess, limits::kShininess, "%.1f", ImGuiSliderFlags_Logarithmic);
        mark("material.shininess");
        helpMarker("The specular exponent n (logarithmic slider). Ctrl+click to type any value > 0.");
    }
}

void brdfSection(Preset& p) {
    if (field("brdf")) {
        enumRadios("brdf", p.brdf, kBrdfModels, kBrdfLabels);
    }
    if (p.brdf == BrdfModel::Phong) {
        ImGui::TextDisabled("S = max(0, R.V)^n");
    } else if (p.brdf == BrdfModel::BlinnPhong) {
        disabledWrapped("S = max(0, N.H)^n,  H = normalize(L + V)");
    } else {
        ImGui::TextDisabled("S = D F G / (4 N.V)");
        static const char* const distributionNames[] = {"Beckmann", "Gaussian", "GGX"};
        if (field("cook_torrance.distribution")) {
            enumCombo("D: distribution", p.cookTorrance.distribution, kDistributions, distributionNames);
            mark("cook_torrance.distribution");
        }
        if (field("cook_torrance.roughness")) {
            limitedSlider("roughness m", p.cookTorrance.roughness, limits::kRoughness, "%.3f", ImGuiSliderFlags_Logarithmic);
            mark("cook_torrance.roughness");
        }
        static const char* const fresnelNames[] = {"Schlick", "full (unpolarized)"};
        if (field("cook_torrance.fresnel")) {
            enumCombo("F: Fresnel", p.cookTorrance.fresnel, kFresnelModes, fresnelNames);
            mark("cook_torrance.fresnel");
        }
        if (field("cook_torrance.ior")) {
            limitedSlider("ior", p.cookTorrance.ior, limits::kIor, "%.3f");
            mark("cook_torrance.ior");
            ImGui::SameLine();
            ImGui::TextDisabled("F0 = %.3f", glsl::fresnelF0(p.cookTorrance.ior));
        }
        if (field("cook_torrance.geometry")) {
            ImGui::Checkbox("G: geometry term", &p.cookTorrance.geometry);
            mark("cook_torrance.geometry");
        }
    }
}

void shadingSection(Preset& p, ViewSettings& view) {
    if (field("shading")) {
        enumRadios("shading", p.shading, kShadings, kShadingLabels);
    }
    static const char* const modeNames[] = {"inverse-transpose (correct)", "model-view (wrong)"};
    if (field("normal_matrix")) {
        enumCombo("normal matrix", p.normalMatrix, kNormalMatrixModes, modeNames);
        mark("normal_matrix");
    }
    if (anyField({"terms"})) {
        ImGui::TextUnformatted("terms");
    }
    const std::pair<const char*, bool*> terms[] = {{"emissive", &p.terms.emissive},
                                                   {"ambient", &p.terms.ambient},
                                                   {"diffuse", &p.terms.diffuse},
                                                   {"specular", &p.terms.specular}};
    for (const auto& [name, on] : terms) {
        if (!anyField({"terms"})) {
            break;
        }
        sameLineIfFitsRadio(name); // a checkbox is as wide as a radio button
        if (field(std::string("terms.") + name)) {
            ImGui::Checkbox((std::string(name) + "##t").c_str(), on);
            mark(std::string("terms.") + name);
        }
    }
    static const std::array<const char*, kViewModes.size()> viewNames = [] {
        std::array<const char*, kViewModes.size()> names{};
        for (std::size_t i = 0; i < kViewModes.size(); ++i) {
            names[i] = toString(kViewModes[i]);
        }
        return names;
    }();
    enumCombo("view (V)", view.mode, kViewModes, viewNames.data());
    mark("view_mode");
    helpMarker("Shows one contribution on the model without changing the preset.");
    ImGui::Separator();
    ImGui::TextDisabled("the equation on the model");
    equationSection(p, view);
    // The shading rate: where the lighting is evaluated (vertices) and along what (normals).
    ImGui::Checkbox("wireframe (W)", &view.wireframe);
    mark("view.wireframe");
    sameLineIfFitsRadio("vertex normals (N)");
    ImGui::Checkbox("vertex normals (N)", &view.vertexNormals);
    mark("view.vertex_normals");
    if (field("ambient_light")) {
        lightColorEdit("global ambient", p.ambientLight);
        mark("ambient_light");
    }
    if (field("background")) {
        colorEdit("background", p.background);
        mark("background");
    }
}

void modelSection(Preset& p, const PanelInfo& info, PanelState& state, std::vector<Request>& requests) {
    bool builtin = p.model.gltf.empty();
    static const char* const builtinNames[] = {"sphere", "cube", "plane", "torus"};
    if (builtin && field("model.builtin")) {
        Builtin before = p.model.builtin;
        enumCombo("built-in", p.model.builtin, kBuiltins, builtinNames);
        mark("model.builtin");
        if (p.model.builtin != before) {
            p.model.subdivisions = defaultSubdivisions(p.model.builtin);
        }
        bool round = p.model.builtin == Builtin::Sphere || p.model.builtin == Builtin::Torus;
        const limits::IntRange& range = round ? limits::kSubdivisionsRound : limits::kSubdivisions;
        const char* label = p.model.builtin == Builtin::Sphere  ? "slices, stacks"
                            : p.model.builtin == Builtin::Torus ? "major, minor"
                                                                : "grid";
        ImGui::SliderInt2(label, &p.model.subdivisions.x, range.min, 256);
        mark("model.subdivisions");
        p.model.subdivisions = {limits::clamp(range, p.model.subdivisions.x), limits::clamp(range, p.model.subdivisions.y)};
    } else if (!builtin) {
        ImGui::Text("glTF: %s", p.model.gltf.c_str());
        if (ImGui::Button("Use a built-in shape")) {
            p.model.gltf.clear();
            p.model.subdivisions = defaultSubdivisions(p.model.builtin);
        }
    }
    if (!info.browser && !info.exercise) {
        pathField("##model", "model.glb (or drop one on the window)", state.modelPath, Command::LoadModel, requests);
        mark("model.path");
    }
    glm::vec3 scale = p.model.scale;
    if (field("model.scale") && dragVec3("scale", scale, 0.01f, -10.0f, 10.0f)) {
        // A zero factor would make the normal matrix singular: step over it.
        for (int i = 0; i < 3; ++i) {
            if (std::abs(scale[i]) < 0.01f) {
                scale[i] = p.model.scale[i] >= 0.0f ? 0.01f : -0.01f;
            }
        }
        p.model.scale = scale;
    }
    mark("model.scale");
    if (field("model.rotate_deg")) {
        dragVec3("rotate (deg)", p.model.rotateDeg, 0.5f, limits::kRotationDeg.min, limits::kRotationDeg.max);
        mark("model.rotate");
    }
    if (field("model.translate")) {
        dragVec3("translate", p.model.translate, 0.01f, limits::kCoordinate.min, limits::kCoordinate.max);
        mark("model.translate");
    }
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

// Attenuation with one-click choices, and the spot cone.
void lightFalloffEditor(LightDesc& l, const std::string& prefix) {
    if (l.type != LightType::Directional && field(prefix + "attenuation")) {
        glm::vec3 c = l.attenuation;
        const limits::Range& r = limits::kAttenuation;
        if (ImGui::DragFloat3("c0, c1, c2", &c.x, 0.005f, r.sliderMin, r.sliderMax, "%.3f")) {
            c = {limits::clamp(r, c.x), limits::clamp(r, c.y), limits::clamp(r, c.z)};
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
                sameLineIfFits(ImGui::CalcTextSize(choices[i].name).x + ImGui::GetStyle().FramePadding.x * 2.0f);
            }
            if (ImGui::SmallButton(choices[i].name)) {
                l.attenuation = choices[i].c;
            }
            mark(prefix + "attenuation." + choices[i].name);
        }
    }
    if (l.type == LightType::Spot && field(prefix + "cutoff_deg")) {
        limitedSlider("cut-off (deg)", l.cutoffDeg, limits::kCutoffDeg, "%.1f");
        mark(prefix + "cutoff");
    }
    if (l.type == LightType::Spot && field(prefix + "exponent")) {
        limitedSlider("exponent", l.exponent, limits::kSpotExponent, "%.1f");
        mark(prefix + "exponent");
    }
}

// The moving light (core/scene/light_orbit.h): on, its speed and its axis. The position above stays
// where the orbit starts; only the live view moves.
void lightOrbitEditor(LightDesc& l, const std::string& prefix) {
    if (!field(prefix + "orbit")) {
        return;
    }
    ImGui::Checkbox("orbit the model", &l.orbit.on);
    mark(prefix + "orbit");
    helpMarker("The light circles the axis through the model's centre, starting from the position "
               "above, and pauses while you drag anything. Saved with the preset. Screenshots and "
               "lab render show the light at the position above (no motion).");
    if (!l.orbit.on) {
        return;
    }
    limitedSlider("speed (deg/s)", l.orbit.degreesPerSecond, limits::kOrbitSpeed, "%.0f");
    mark(prefix + "orbit.speed");
    glm::vec3 before = l.orbit.axis;
    if (dragVec3("axis", l.orbit.axis, 0.01f, limits::kCoordinate.min, limits::kCoordinate.max) &&
        glm::length(l.orbit.axis) < limits::kMinDirectionLength) {
        l.orbit.axis = before; // the validator's minimum length: keep the last valid axis
    }
    mark(prefix + "orbit.axis");
    static const struct {
        const char* name;
        glm::vec3 axis;
    } axes[] = {{"x", {1, 0, 0}}, {"y (up)", {0, 1, 0}}, {"z", {0, 0, 1}}};
    for (std::size_t i = 0; i < std::size(axes); ++i) {
        if (i > 0) {
            sameLineIfFits(ImGui::CalcTextSize(axes[i].name).x + ImGui::GetStyle().FramePadding.x * 2.0f);
        }
        if (ImGui::SmallButton(axes[i].name)) {
            l.orbit.axis = axes[i].axis;
        }
        mark(prefix + "orbit.axis." + std::string(1, axes[i].name[0])); // widget names have no spaces
    }
}

// Position, direction, colours of one light; `prefix` names its widgets ("lights[0].").
void lightEditor(LightDesc& l, const std::string& prefix) {
    if (field(prefix + "enabled")) {
        ImGui::Checkbox("enabled", &l.enabled);
        mark(prefix + "enabled");
        ImGui::SameLine();
    }
    static const char* const typeNames[] = {"point", "directional", "spot"};
    if (field(prefix + "type")) {
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
        enumCombo("type", l.type, kLightTypes, typeNames);
        mark(prefix + "type");
    } else {
        ImGui::NewLine();
    }
    if (l.type != LightType::Directional && field(prefix + "position")) {
        dragVec3("position", l.position, 0.02f, limits::kCoordinate.min, limits::kCoordinate.max);
        mark(prefix + "position");
    }
    if (l.type != LightType::Point && field(prefix + "direction")) {
        glm::vec3 before = l.direction;
        if (dragVec3("direction", l.direction, 0.01f, limits::kCoordinate.min, limits::kCoordinate.max) &&
            glm::length(l.direction) < limits::kMinDirectionLength) {
            l.direction = before; // the validator's minimum length: keep the last valid direction
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
    const std::pair<const char*, glm::vec3*> colors[] = {{"ambient", &l.ambient}, {"diffuse", &l.diffuse}, {"specular", &l.specular}};
    for (const auto& [name, color] : colors) {
        if (field(prefix + name)) {
            lightColorEdit(name, *color);
            mark(prefix + name);
        }
    }
    lightFalloffEditor(l, prefix);
    lightOrbitEditor(l, prefix);
}

void lightsSection(Preset& p, PanelState& state) {
    if (!anyField({"lights"})) {
        return;
    }
    if (field("lights")) {
        if (ImGui::Button("Add light") && p.lights.size() < static_cast<std::size_t>(limits::kMaxLights)) {
            p.lights.push_back(LightDesc{});
            state.selectedLight = static_cast<int>(p.lights.size()) - 1;
        }
        mark("lights.add");
        ImGui::SameLine();
        ImGui::BeginDisabled(p.lights.empty());
        if (ImGui::Button("Remove") && !p.lights.empty()) {
            p.lights.erase(p.lights.begin() + std::clamp(state.selectedLight, 0, static_cast<int>(p.lights.size()) - 1));
        }
        ImGui::EndDisabled();
        ImGui::SameLine();
        ImGui::TextDisabled("%zu of %d", p.lights.size(), limits::kMaxLights);
    }
    if (p.lights.empty()) {
        disabledWrapped("No lights: only emissive and global ambient remain.");
        return;
    }
    state.selectedLight = std::clamp(state.selectedLight, 0, static_cast<int>(p.lights.size()) - 1);
    if (ImGui::BeginTabBar("lights")) {
        for (std::size_t i = 0; i < p.lights.size(); ++i) {
            std::string tab = "Light " + std::to_string(i + 1) + (p.lights[i].enabled ? "" : " (off)");
            if (ImGui::BeginTabItem((tab + "###light" + std::to_string(i)).c_str())) {
                state.selectedLight = static_cast<int>(i);
                ImGui::EndTabItem();
            }
        }
        ImGui::EndTabBar();
    }
    ImGui::PushID(state.selectedLight);
    lightEditor(p.lights[static_cast<std::size_t>(state.selectedLight)], "lights[" + std::to_string(state.selectedLight) + "].");
    ImGui::PopID();
}

void cameraSection(Preset& p, std::vector<Request>& requests) {
    dragVec3("eye", p.camera.eye, 0.02f, limits::kCoordinate.min, limits::kCoordinate.max);
    dragVec3("target", p.camera.target, 0.02f, limits::kCoordinate.min, limits::kCoordinate.max);
    limitedSlider("fovy (deg)", p.camera.fovyDeg, limits::kFovyDeg, "%.1f");
    commandButton(Command::ResetCamera, requests);
    sameLineIfFits(commandRow(Command::FrameModel).label);
    commandButton(Command::FrameModel, requests);
    disabledWrapped("Left drag: orbit  Right drag: pan  Wheel: zoom (a finger orbits, two pan and pinch)");
    // Keep the camera valid whatever was dragged.
    keepCameraValid(p.camera);
}

// Compare mode's switch, and which set the panel edits.
void compareRow(ViewSettings& view, const PanelInfo& info, std::vector<Request>& requests) {
    std::string label = std::string("Compare: ") + (view.compare ? "on" : "off") + " (C)###compare";
    if (ImGui::Button(label.c_str())) {
        requests.push_back({Command::ToggleCompare});
    }
    mark("compare");
    if (view.compare) {
        const char* editA = info.compareStacked ? "edit A (top)" : "edit A (left)";
        const char* editB = info.compareStacked ? "edit B (bottom)" : "edit B (right)";
        sameLineIfFitsRadio(editA);
        if (ImGui::RadioButton(editA, !view.editingB)) {
            view.editingB = false;
        }
        sameLineIfFitsRadio(editB);
        if (ImGui::RadioButton(editB, view.editingB)) {
            view.editingB = true;
        }
        mark("compare.edit-b");
    }
}

void toolButtons(PanelState& state, std::vector<Request>& requests, bool solving) {
    commandButton(Command::ToggleShaderEditor, requests);
    sameLineIfFits(commandRow(Command::ToggleSweep).label);
    commandButton(Command::ToggleSweep, requests);
    mark("sweep.open");
    sameLineIfFits(commandRow(Command::Screenshot).label);
    commandButton(Command::Screenshot, requests);
    mark("screenshot");
    sameLineIfFits(commandRow(Command::ExportFigures).label);
    commandButton(Command::ExportFigures, requests);
    mark("figures.export");
    // The PNGs' scale beside it (the SVGs have none; the CSVs are numbers).
    char scale[32];
    std::snprintf(scale, sizeof scale, "PNG %gx", double(state.figureScale));
    const float scaleWidth = ImGui::CalcTextSize("PNG 4x").x + ImGui::GetFrameHeight() + ImGui::GetStyle().FramePadding.x * 2;
    sameLineIfFits(scaleWidth); // beside the button, or under it where the column is narrow
    ImGui::SetNextItemWidth(scaleWidth);
    if (ImGui::BeginCombo("##figure-scale", scale)) {
        for (float s : kFigureScales) {
            char item[64];
            std::snprintf(item, sizeof item, "PNG %gx (%d px wide)", double(s), static_cast<int>(720 * s));
            if (ImGui::Selectable(item, s == state.figureScale)) {
                state.figureScale = s;
            }
        }
        ImGui::EndCombo();
    }
    mark("figures.scale");
    sameLineIfFits(commandRow(Command::ToggleHelp).label);
    commandButton(Command::ToggleHelp, requests);
    if (!solving) { // an exercise is not made from an exercise
        sameLineIfFits(commandRow(Command::MakeExercise).label);
        commandButton(Command::MakeExercise, requests);
        mark("exercise.make");
    }
    sameLineIfFits(commandRow(Command::ToggleShareCode).label);
    commandButton(Command::ToggleShareCode, requests);
    mark("share.code");
}

} // namespace

void controlPanel(Preset& preset, ViewSettings& view, const PanelInfo& info, PanelState& state,
                  std::vector<Request>& requests, PanelPart part) {
    const bool all = part == PanelPart::All, model = all || part == PanelPart::Model,
               material = all || part == PanelPart::Material, lights = all || part == PanelPart::Lights;
    setFieldGate(info.exercise, info.exercise ? nullptr : info.draft);
    if (info.exercise && ImGui::CollapsingHeader("Exercise", ImGuiTreeNodeFlags_DefaultOpen)) {
        exerciseSection(*info.exercise, requests);
    }
    if (!info.exercise && info.draft && model && ImGui::CollapsingHeader("Make exercise", ImGuiTreeNodeFlags_DefaultOpen)) {
        draftSection(*info.draft, info.browser, state.exercisePath, requests);
    }
    if (model && ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) {
        filesSection(info, state, requests);
    }
    if (model && info.presetFiles && !info.presetFiles->empty() &&
        ImGui::CollapsingHeader("Presets", ImGuiTreeNodeFlags_DefaultOpen)) {
        presetsSection(info, state, requests);
    }
    if (model) {
        if (!info.exercise) {
            compareRow(view, info, requests);
        }
        toolButtons(state, requests, info.exercise != nullptr);
    }
    if (material && anyField({"material"}) && ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
        materialSection(preset);
    }
    if (material && anyField({"brdf", "cook_torrance"}) &&
        ImGui::CollapsingHeader("Reflection model (BRDF)", ImGuiTreeNodeFlags_DefaultOpen)) {
        brdfSection(preset);
    }
    if (material && ImGui::CollapsingHeader("Shading and terms", ImGuiTreeNodeFlags_DefaultOpen)) {
        shadingSection(preset, view);
    }
    if (lights && anyField({"lights"}) && ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) {
        lightsSection(preset, state);
    }
    if (model && anyField({"model"}) && ImGui::CollapsingHeader("Model", all ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) {
        modelSection(preset, info, state, requests);
    }
    if (model && ImGui::CollapsingHeader("Camera")) {
        cameraSection(preset, requests);
    }
}

} // namespace lab::ui
