// equation_panel.cpp — the equation with a button for each factor.
#include "ui/panel/equation_panel.h"

#include "ui/widget_map.h"
#include "ui/widgets.h"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <string_view>

namespace lab::ui {

namespace {

// Text of the equation, on the line so far while it fits, word by word (a space apart): a narrow
// panel (presenter mode's font) wraps it instead of cutting it. `newLine`: it starts a line.
void words(std::string_view text, bool newLine = false) {
    const float space = ImGui::CalcTextSize(" ").x;
    bool first = true;
    for (std::string_view word : spaceSeparated(text)) {
        if (!(first && newLine)) {
            sameLineIfFits(ImGui::CalcTextSize(word.data(), word.data() + word.size()).x, first ? -1.0f : space);
        }
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(word.data(), word.data() + word.size());
        first = false;
    }
}

// A factor's button: shows its view (or the lit model again, when it is shown), highlighted while
// shown, greyed where it does not apply (its tooltip says why).
void factor(const char* label, ViewMode mode, const Preset& preset, DisplaySettings& view, bool onTheLine = true) {
    if (onTheLine) {
        sameLineIfFits(label);
    }
    const bool shown = view.mode == mode;
    const std::string why = notApplicable(mode, preset, view.light);
    if (shown) {
        ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.95f, 0.75f, 0.2f, 1.0f));
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.0f, 0.0f, 0.0f, 1.0f));
    }
    ImGui::BeginDisabled(!why.empty() && !shown);
    if (ImGui::Button((std::string(label) + "##" + viewName(mode)).c_str())) {
        view.mode = shown ? ViewMode::Lit : mode;
    }
    ImGui::EndDisabled();
    if (shown) {
        ImGui::PopStyleColor(2);
    }
    mark(std::string("equation.") + viewName(mode));
    itemTooltip(why.empty() ? toString(mode) : why.c_str());
}

void lightChoice(const Preset& preset, DisplaySettings& view) {
    int count = static_cast<int>(preset.lights.size());
    view.light = std::clamp(view.light, 0, std::max(0, count - 1));
    if (count < 2) {
        return;
    }
    std::string current = "light " + std::to_string(view.light + 1);
    if (ImGui::BeginCombo("factors of", current.c_str())) {
        for (int i = 0; i < count; ++i) {
            const LightDesc& l = preset.lights[static_cast<std::size_t>(i)];
            std::string item = "light " + std::to_string(i + 1) + " (" + std::string(toString(l.type)) +
                               (l.enabled ? "" : ", off") + ")";
            if (ImGui::Selectable(item.c_str(), i == view.light)) {
                view.light = i;
            }
        }
        ImGui::EndCombo();
    }
    mark("equation.light");
}

// Palette and range: what a value view is drawn with.
void valueOptions(DisplaySettings& view) {
    int palette = view.palette == ValuePalette::Grey ? 1 : 0;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
    if (ImGui::Combo("palette", &palette, "viridis\0grey\0")) {
        view.palette = palette == 1 ? ValuePalette::Grey : ValuePalette::Viridis;
    }
    mark("equation.palette");
    bool automatic = !view.range;
    sameLineIfFitsRadio("automatic range");
    if (ImGui::Checkbox("automatic range", &automatic)) {
        view.range = automatic ? std::nullopt : std::optional<ValueRange>(ValueRange{0.0f, 1.0f});
    }
    mark("equation.auto-range");
    helpMarker("Automatic: from the smallest to the largest value on the model, found in a render of at most "
               "256 pixels a side as the view is drawn (one extra draw; a constant spans [0, 1]).");
    if (view.range) {
        float lohi[2] = {view.range->lo, view.range->hi};
        if (ImGui::InputFloat2("range", lohi, "%.4g") && lohi[0] < lohi[1]) {
            view.range = ValueRange{lohi[0], lohi[1]};
        }
        mark("equation.range");
    }
}

} // namespace

void equationSection(const Preset& p, DisplaySettings& view) {
    lightChoice(p, view);
    // I = Ke + Ia Ka + sum over the lights of Ia_i Ka + Att spot (Id Kd N.L + Is Ks S)
    words("I = Ke + Ia Ka + sum of  Ia Ka +", true);
    factor("Att", ViewMode::Attenuation, p, view);
    factor("spot", ViewMode::Spot, p, view);
    words("(Id Kd");
    factor("N.L", ViewMode::NdotL, p, view);
    words("+ Is Ks S )");
    switch (p.brdf) {
    case BrdfModel::Phong:
        words("S = max(0,");
        factor("R.V", ViewMode::RdotV, p, view);
        words(")^n");
        break;
    case BrdfModel::BlinnPhong:
        words("S = max(0,");
        factor("N.H", ViewMode::NdotH, p, view);
        words(")^n");
        break;
    case BrdfModel::CookTorrance:
        words("S =");
        factor("D", ViewMode::D, p, view);
        factor("F", ViewMode::F, p, view);
        factor("G", ViewMode::G, p, view);
        words("/");
        factor("4 max(N.V, 1e-4)", ViewMode::Denominator, p, view);
        factor("N.V", ViewMode::NdotV, p, view);
        ImGui::TextWrapped("The microfacet BRDF is D F G / (4 (N.L)(N.V)); times the incoming light's cosine N.L, "
                           "its N.L cancels: the lab divides by 4 N.V.");
        break;
    }
    words("Att = 1 / (c0 + c1");
    factor("d", ViewMode::Distance, p, view);
    words("+ c2 d^2)");
    factor("lit", ViewMode::Lit, p, view, false); // the views beside the factors start a line of their own
    factor("normals", ViewMode::Normals, p, view);
    factor("Gouraud error", ViewMode::GouraudError, p, view);
    if (showsValue(view.mode)) {
        valueOptions(view);
    }
    if (view.mode != ViewMode::Lit) {
        ImGui::Checkbox("wipe: the lit model left of a divider", &view.wipe);
        mark("equation.wipe");
    }
}

} // namespace lab::ui
