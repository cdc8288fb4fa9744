// panel.cpp — the control panel's sections.
#include "ui/panel/panel.h"

#include "core/io/safe_text.h"
#include "core/lighting/lighting.h"
#include "core/scene/camera.h"
#include "core/scene/limits.h"
#include "core/scene/field_path.h"
#include "core/scene/field_table.h"
#include "core/scene/light_orbit.h"
#include "core/scene/preset_choices.h"
#include "ui/panel/equation_panel.h"
#include "ui/panel/exercise_panel.h"
#include "ui/panel/field_widget.h"
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

// A command's button, named for the GUI tests (`name`, none when null), on the line before where it fits.
struct ButtonOf {
    Command command;
    const char* name = nullptr;
    bool enabled = true;
};

// Buttons one after another, each on the line of the one before where it fits (`first`: the first
// too, after what came before it).
void commandButtons(std::initializer_list<ButtonOf> buttons, std::vector<Request>& requests, bool first = false) {
    for (const ButtonOf& b : buttons) {
        if (first) {
            sameLineIfFits(commandRow(b.command).label);
        }
        first = true;
        commandButton(b.command, requests, b.enabled);
        if (b.name) {
            mark(b.name);
        }
    }
}

// Revert, Undo and Redo on one line, each enabled only when it would do something.
void historyButtons(const PanelInfo& info, std::vector<Request>& requests) {
    commandButtons({{Command::Revert, nullptr, info.dirty}, {Command::Undo, nullptr, info.canUndo},
                    {Command::Redo, nullptr, info.canRedo}},
                   requests);
}

void browserFilesSection(const PanelInfo& info, std::vector<Request>& requests) {
    commandButtons({{Command::DownloadPreset, "file.download"}, {Command::PickFile, "file.open"},
                    {Command::CopyLink, "file.copy-link"}},
                   requests);
    sameLineIfFits(commandRow(Command::Revert).label);
    historyButtons(info, requests);
    disabledWrapped("Drop a .json preset or a .glb model on the page.");
}

void filesSection(const PanelInfo& info, PanelState& state, std::vector<Request>& requests) {
    ImGui::TextWrapped("%s%s", info.documentName.c_str(), info.dirty ? "  (modified)" : ""); // a long name: never cut
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
    pathField("##open", "path/to/preset.json", state.openPath, Command::OpenPath, requests, "file.open-path");
    pathField("##saveas", "path/to/new.json", state.saveAsPath, Command::SaveAs, requests, "file.save-as-path");
}

void presetsSection(const PanelInfo& info, PanelState& state, std::vector<Request>& requests) {
    const std::vector<std::string>& files = info.presetNames;
    float height = std::min(8.0f, static_cast<float>(files.size()) + 0.5f) * ImGui::GetTextLineHeightWithSpacing();
    if (ImGui::BeginListBox("##presets", ImVec2(-1, height))) {
        for (std::size_t i = 0; i < files.size(); ++i) {
            bool selected = static_cast<int>(i) == info.currentPreset;
            // The row's place is its ID; the file's name (escaped: dropped files land in this list) is
            // drawn as it is, not as a label, where "##" would hide the rest of it.
            std::string id = "###preset" + std::to_string(i);
            // A deck's slides are numbered: the notes say "Slide 6 of 28".
            std::string name = (info.deckTitle.empty() ? "" : std::to_string(i + 1) + "  ") + printable(files[i], true);
            if (wrappedSelectable(id.c_str(), name, selected)) {
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
    disabledWrapped("Left/Right on the model: previous/next; R: the file's again");
    if (info.exerciseFiles && !info.exerciseFiles->empty()) {
        exerciseList(*info.exerciseFiles, requests);
    }
}

// The widgets of the rows of `object` ("material", "lights[]") that apply, in the table's order,
// each behind the gate; `after(row, path)` adds what a field has beside its widget. Rows without
// a widget of their own (kStyleHidden, custom) and those in `skip` are left to the caller.
template <typename After>
void fieldRowsOf(std::string_view object, Preset& p, LightDesc* light, int lightIndex, const FieldGate& gate,
                 After after, std::initializer_list<std::string_view> skip = {}) {
    for (const FieldRow& row : fieldRows()) {
        if (!covers(object, row.path) || (row.style & kStyleHidden) || row.custom || !applies(row, p, light) ||
            std::find(skip.begin(), skip.end(), fieldKey(row)) != skip.end()) {
            continue;
        }
        const std::string path = fieldPath(row, lightIndex);
        if (gate.field(path)) {
            fieldWidget(row, p, light, path);
            after(row, path);
        }
    }
}

void nothingAfter(const FieldRow&, const std::string&) {}

// Fit a model to this specular lobe (core/plots/fit.h): the fit goes into B, beside A in compare mode.
void fitRow(PanelState& state, std::vector<Request>& requests) {
    disabledWrapped("Fit a model to this specular lobe (least squares over the incident angles; the fit goes into B):");
    for (Command c : {Command::FitPhong, Command::FitBlinnPhong}) {
        if (c != Command::FitPhong) {
            sameLineIfFits(commandRow(c).label);
        }
        commandButton(c, requests);
        mark(c == Command::FitPhong ? "brdf.fit-phong" : "brdf.fit-blinn-phong");
    }
    const char* ct = commandRow(Command::FitCookTorrance).label;
    sameLineIfFits(ct);
    if (ImGui::Button(ct)) {
        requests.push_back({Command::FitCookTorrance, {}, state.fitDistribution});
    }
    mark("brdf.fit-cook-torrance");
    const float comboWidth = ImGui::CalcTextSize("Beckmann").x + ImGui::GetFrameHeight() * 2.0f;
    sameLineIfFits(comboWidth);
    ImGui::SetNextItemWidth(comboWidth);
    const char* names[] = {kDistributionChoices[0].label, kDistributionChoices[1].label, kDistributionChoices[2].label};
    ImGui::Combo("##fit-distribution", &state.fitDistribution, names, 3);
    mark("brdf.fit-distribution");
    itemTooltip("The distribution D of the fitted Cook-Torrance");
}

void materialSection(Preset& p, const FieldGate& gate) {
    // Shininess applies to Phong and Blinn-Phong only (the roughness m shapes Cook-Torrance's lobe).
    fieldRowsOf("material", p, nullptr, 0, gate, nothingAfter);
}

void brdfSection(Preset& p, const FieldGate& gate) {
    fieldRowsOf("brdf", p, nullptr, 0, gate, nothingAfter);
    if (p.brdf == BrdfModel::Phong) {
        ImGui::TextDisabled("S = max(0, R.V)^n");
    } else if (p.brdf == BrdfModel::BlinnPhong) {
        disabledWrapped("S = max(0, N.H)^n,  H = normalize(L + V)");
    } else {
        ImGui::TextDisabled("S = D F G / (4 N.V)");
    }
    fieldRowsOf("cook_torrance", p, nullptr, 0, gate, [&](const FieldRow& row, const std::string&) {
        if (fieldKey(row) == "ior") {
            char f0[32];
            std::snprintf(f0, sizeof f0, "F0 = %.3f", glsl::fresnelF0(p.cookTorrance.ior));
            sameLineIfFits(ImGui::CalcTextSize(f0).x);
            ImGui::TextDisabled("%s", f0);
        }
    });
}

void shadingSection(Preset& p, DisplaySettings& view, const FieldGate& gate) {
    fieldRowsOf("shading", p, nullptr, 0, gate, nothingAfter);
    fieldRowsOf("normal_matrix", p, nullptr, 0, gate, nothingAfter);
    if (gate.any({"terms"})) {
        ImGui::TextUnformatted("terms");
        for (const FieldRow& row : fieldRows()) {
            if (fieldObject(row) == "terms") {
                sameLineIfFitsRadio(row.label.data()); // a checkbox is as wide as a radio button
                if (gate.field(std::string(row.path))) {
                    fieldWidget(row, p, nullptr, std::string(row.path));
                }
            }
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
    fieldRowsOf("ambient_light", p, nullptr, 0, gate, nothingAfter);
    fieldRowsOf("background", p, nullptr, 0, gate, nothingAfter);
}

// The model's source: a built-in shape and its subdivisions, or the glTF file and a way back.
void modelSource(Preset& p, const PanelInfo& info, PanelState& state, std::vector<Request>& requests, const FieldGate& gate) {
    const FieldRow& builtinRow = *fieldRow("model.builtin");
    if (p.model.gltf.empty() && gate.field("model.builtin")) {
        Builtin before = p.model.builtin;
        fieldWidget(builtinRow, p, nullptr, "model.builtin");
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
    } else if (!p.model.gltf.empty()) {
        ImGui::Text("glTF: %s", p.model.gltf.c_str());
        if (ImGui::Button("Use a built-in shape")) {
            p.model.gltf.clear();
            p.model.subdivisions = defaultSubdivisions(p.model.builtin);
        }
    }
    if (!info.browser && !info.exercise) {
        pathField("##model", "model.glb (or drop one on the window)", state.modelPath, Command::LoadModel, requests, "model.path");
    }
}

void modelSection(Preset& p, const PanelInfo& info, PanelState& state, std::vector<Request>& requests, const FieldGate& gate) {
    modelSource(p, info, state, requests, gate);
    fieldRowsOf("model", p, nullptr, 0, gate, nothingAfter);
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

// A row of small buttons, each setting `value` to its choice; named `path`.<choice's name>.
struct Preset3 {
    const char* name;
    glm::vec3 value;
};
void presetButtons(std::span<const Preset3> choices, glm::vec3& value, const std::string& path) {
    for (std::size_t i = 0; i < choices.size(); ++i) {
        if (i > 0) {
            sameLineIfFits(ImGui::CalcTextSize(choices[i].name).x + ImGui::GetStyle().FramePadding.x * 2.0f);
        }
        if (ImGui::SmallButton(choices[i].name)) {
            value = choices[i].value;
        }
        mark(path + "." + std::string(choices[i].name).substr(0, std::string(choices[i].name).find(' '))); // no spaces
    }
}

// What a light's field has beside its widget: the direction's angles, one-click attenuations, the orbit's axes.
void lightFieldExtras(LightDesc& l, const FieldRow& row, const std::string& path) {
    std::string_view key = row.path.substr(std::string_view("lights[].").size());
    if (key == "direction") {
        glm::vec2 angles = toAngles(l.direction);
        if (ImGui::DragFloat2("theta, phi (deg)", &angles.x, 0.5f)) {
            angles.x = glm::clamp(angles.x, 0.0f, 180.0f);
            l.direction = fromAngles(angles) * glm::length(l.direction);
        }
        mark(path.substr(0, path.size() - key.size()) + "angles");
        helpMarker("theta from +y (0 points up, 180 straight down), phi around +y from +z towards +x.");
    } else if (key == "attenuation") {
        static const Preset3 choices[] = {{"none", {1, 0, 0}}, {"1/d", {0, 1, 0}}, {"1/d^2", {0, 0, 1}}, {"OpenGL", {1, 0.35f, 0.44f}}};
        presetButtons(choices, l.attenuation, path);
    } else if (key == "orbit.axis") {
        static const Preset3 axes[] = {{"x", {1, 0, 0}}, {"y (up)", {0, 1, 0}}, {"z", {0, 0, 1}}};
        presetButtons(axes, l.orbit.axis, path);
    }
}

// One light: enabled and its type on one line, then its other fields as the table orders them.
void lightEditor(Preset& p, int index, const FieldGate& gate) {
    LightDesc& l = p.lights[static_cast<std::size_t>(index)];
    const std::string prefix = "lights[" + std::to_string(index) + "].";
    if (gate.field(prefix + "enabled")) {
        fieldWidget(*fieldRow("lights[].enabled"), p, &l, prefix + "enabled");
        ImGui::SameLine();
    }
    if (gate.field(prefix + "type")) {
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
        fieldWidget(*fieldRow("lights[].type"), p, &l, prefix + "type");
    } else {
        ImGui::NewLine();
    }
    fieldRowsOf("lights[]", p, &l, index, gate,
                [&](const FieldRow& row, const std::string& path) { lightFieldExtras(l, row, path); }, {"enabled", "type"});
}

void lightsSection(Preset& p, PanelState& state, const FieldGate& gate) {
    if (!gate.any({"lights"})) {
        return;
    }
    if (gate.field("lights")) {
        if (ImGui::Button("Add light") && p.lights.size() < static_cast<std::size_t>(limits::kMaxLights)) {
            p.lights.push_back(LightDesc{});
            state.selectedLight = static_cast<int>(p.lights.size()) - 1;
        }
        mark("lights.add");
        sameLineIfFits("Remove");
        ImGui::BeginDisabled(p.lights.empty());
        if (ImGui::Button("Remove") && !p.lights.empty()) {
            p.lights.erase(p.lights.begin() + std::clamp(state.selectedLight, 0, static_cast<int>(p.lights.size()) - 1));
        }
        ImGui::EndDisabled();
        char count[32];
        std::snprintf(count, sizeof count, "%zu of %d", p.lights.size(), limits::kMaxLights);
        sameLineIfFits(ImGui::CalcTextSize(count).x);
        ImGui::TextDisabled("%s", count);
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
    lightEditor(p, state.selectedLight, gate);
    ImGui::PopID();
}

// Whenever a light orbits by itself: a box that pauses the motion (Command::ToggleLightMotion), so
// that it can always be stopped (reduced motion opens scenes with it ticked, app/orbit_clock.h).
void motionRow(const Preset& p, const PanelInfo& info, std::vector<Request>& requests) {
    if (!anyOrbit(p)) {
        return;
    }
    bool paused = info.lightsPaused;
    if (ImGui::Checkbox(commandRow(Command::ToggleLightMotion).label, &paused)) {
        requests.push_back({Command::ToggleLightMotion});
    }
    mark("lights.pause");
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("The moving light stands still where it is shown; untick to let it go on.");
    }
}

void cameraSection(Preset& p, std::vector<Request>& requests) {
    fieldRowsOf("camera", p, nullptr, 0, FieldGate{}, nothingAfter); // looking around is never an exercise's field
    commandButton(Command::ResetCamera, requests);
    sameLineIfFits(commandRow(Command::FrameModel).label);
    commandButton(Command::FrameModel, requests);
    disabledWrapped("Left drag: orbit  Right drag: pan  Wheel: zoom (a finger orbits, two pan and pinch)");
    // Keep the camera valid whatever was dragged.
    keepCameraValid(p.camera);
}

// Compare mode's switch, and which set the panel edits.
void compareRow(DisplaySettings& view, const PanelInfo& info, std::vector<Request>& requests) {
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
    commandButtons({{Command::ToggleShaderEditor}, {Command::ToggleSweep, "sweep.open"}, {Command::Screenshot, "screenshot"},
                    {Command::ExportFigures, "figures.export"}},
                   requests);
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
    commandButtons({{Command::ToggleHelp}}, requests, true);
    if (!solving) { // an exercise is not made from an exercise
        commandButtons({{Command::MakeExercise, "exercise.make"}}, requests, true);
    }
    commandButtons({{Command::ToggleShareCode, "share.code"}}, requests, true);
    // The theme: the UI's, the plots' and the exported figures' colours.
    ImGui::TextUnformatted("Theme");
    for (Theme t : kThemes) {
        const char* label = t == Theme::Dark ? "dark" : "light (projector)";
        sameLineIfFitsRadio(label);
        if (ImGui::RadioButton(label, state.theme == t)) {
            state.theme = t;
        }
        mark(t == Theme::Dark ? "theme.dark" : "theme.light");
    }
}

} // namespace

void controlPanel(Preset& preset, DisplaySettings& view, const PanelInfo& info, PanelState& state,
                  std::vector<Request>& requests, PanelPart part) {
    const bool all = part == PanelPart::All, model = all || part == PanelPart::Model,
               material = all || part == PanelPart::Material, lights = all || part == PanelPart::Lights;
    const FieldGate gate{info.exercise, info.exercise ? nullptr : info.draft};
    if (info.exercise && ImGui::CollapsingHeader("Exercise", ImGuiTreeNodeFlags_DefaultOpen)) {
        exerciseSection(*info.exercise, requests);
    }
    if (!info.exercise && info.draft && model && ImGui::CollapsingHeader("Make exercise", ImGuiTreeNodeFlags_DefaultOpen)) {
        draftSection(*info.draft, info.browser, state.exercisePath, requests);
    }
    if (model && ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) {
        filesSection(info, state, requests);
    }
    const std::string listTitle = info.deckTitle.empty() ? "Presets" : "Deck: " + printable(info.deckTitle, true);
    if (model && !info.presetNames.empty() && ImGui::CollapsingHeader((listTitle + "###presets").c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
        presetsSection(info, state, requests);
    }
    if (model) {
        if (!info.exercise) {
            compareRow(view, info, requests);
        }
        toolButtons(state, requests, info.exercise != nullptr);
    }
    if (material && gate.any({"material"}) && ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
        materialSection(preset, gate);
    }
    if (material && gate.any({"brdf", "cook_torrance"}) &&
        ImGui::CollapsingHeader("Reflection model (BRDF)", ImGuiTreeNodeFlags_DefaultOpen)) {
        brdfSection(preset, gate);
        if (!info.exercise && !view.editingB) { // A's lobe; in an exercise B is the target
            fitRow(state, requests);
        }
    }
    if (material && ImGui::CollapsingHeader("Shading and terms", ImGuiTreeNodeFlags_DefaultOpen)) {
        shadingSection(preset, view, gate);
    }
    if (lights && gate.any({"lights"}) && ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) {
        motionRow(preset, info, requests);
        lightsSection(preset, state, gate);
    } else if (lights && !gate.any({"lights"})) {
        motionRow(preset, info, requests); // an exercise that opens no light: its motion can still be paused
    }
    if (model && gate.any({"model"}) && ImGui::CollapsingHeader("Model", all ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) {
        modelSection(preset, info, state, requests, gate);
    }
    if (model && ImGui::CollapsingHeader("Camera")) {
        cameraSection(preset, requests);
    }
}

} // namespace lab::ui
