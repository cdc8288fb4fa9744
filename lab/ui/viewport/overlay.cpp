// overlay.cpp — the equation over the model and the room's pointer (overlay.h).
#include "ui/viewport/overlay.h"

#include "ui/widget_map.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace lab::ui {

namespace {

// The factors' colours, one each, high contrast on the dark band (and the names the factor views
// give them: N·L, R·V, N·H, D, F, G).
constexpr unsigned kPlain = IM_COL32(245, 245, 245, 255);
constexpr unsigned kNdotL = IM_COL32(120, 200, 255, 255);
constexpr unsigned kLobe = IM_COL32(255, 200, 80, 255);
constexpr unsigned kD = IM_COL32(255, 140, 110, 255);
constexpr unsigned kF = IM_COL32(140, 235, 140, 255);
constexpr unsigned kG = IM_COL32(220, 150, 255, 255);
constexpr unsigned kDim = IM_COL32(190, 190, 200, 255);

void add(std::vector<EquationPiece>& out, std::string text, unsigned color = kPlain, bool superscript = false) {
    out.push_back({std::move(text), color, superscript});
}

} // namespace

// README "The lighting model": Ke + Ia∘Ka + Σ_i [Ia_i∘Ka + Att_i·(Id_i∘Kd·max(0, N·L_i) + Is_i∘Ks·S_i)],
// Att with the spot factor in it, S by the BRDF; a term switched off is left out.
std::vector<EquationPiece> equationPieces(const Preset& p) {
    std::vector<EquationPiece> e;
    add(e, "I = ");
    std::vector<std::vector<EquationPiece>> outside;
    if (p.terms.emissive) {
        outside.push_back({{"Ke", kPlain, false}});
    }
    if (p.terms.ambient) {
        outside.push_back({{"Ka\u00b7Ia", kPlain, false}});
    }
    std::vector<EquationPiece> lit; // Att·(diffuse + specular)
    if (p.terms.diffuse) {
        add(lit, "Kd\u00b7Id\u00b7max(0, ");
        add(lit, "N\u00b7L", kNdotL);
        add(lit, ")");
    }
    if (p.terms.specular) {
        if (p.terms.diffuse) {
            add(lit, " + ");
        }
        add(lit, "Ks\u00b7Is\u00b7");
        switch (p.brdf) {
        case BrdfModel::Phong:
        case BrdfModel::BlinnPhong:
            add(lit, "max(0, ");
            add(lit, p.brdf == BrdfModel::Phong ? "R\u00b7V" : "N\u00b7H", kLobe);
            add(lit, ")");
            add(lit, "n", kLobe, true);
            break;
        case BrdfModel::CookTorrance:
            add(lit, "D", kD);
            add(lit, "\u00b7");
            add(lit, "F", kF);
            add(lit, "\u00b7");
            add(lit, "G", kG);
            add(lit, " / (4 N\u00b7V)");
            break;
        }
    }
    for (std::size_t i = 0; i < outside.size(); ++i) {
        if (i > 0) {
            add(e, " + ");
        }
        e.insert(e.end(), outside[i].begin(), outside[i].end());
    }
    if (p.terms.ambient || !lit.empty()) {
        add(e, outside.empty() ? "\u03a3 [" : " + \u03a3 [", kDim);
        if (p.terms.ambient) {
            add(e, "Ka\u00b7Ia,i");
            add(e, lit.empty() ? "" : " + ");
        }
        if (!lit.empty()) {
            add(e, "Att\u00b7(");
            e.insert(e.end(), lit.begin(), lit.end());
            add(e, ")");
        }
        add(e, "]", kDim);
    } else if (outside.empty()) {
        add(e, "0");
    }
    return e;
}

std::string equationText(const Preset& preset) {
    std::string text;
    for (const EquationPiece& piece : equationPieces(preset)) {
        text += (piece.superscript ? "^" : "") + piece.text;
    }
    return text;
}

void equationOverlay(const Preset& preset, const Rect& view, const std::vector<Rect>& keepClear) {
    if (view.w <= 0.0f || view.h <= 0.0f) {
        return;
    }
    const std::vector<EquationPiece> pieces = equationPieces(preset);
    ImFont* font = ImGui::GetFont();
    const float pad = 0.5f * ImGui::GetFontSize();
    float size = 0.0f, widest = 0.0f, lineHeight = 0.0f, h = 0.0f;
    std::vector<std::vector<const EquationPiece*>> lines;
    auto advance = [&](const EquationPiece& piece) {
        return font->CalcTextSizeA(piece.superscript ? size * 0.65f : size, 1e9f, 0.0f, piece.text.c_str()).x;
    };
    // Lines broken between pieces where the next would not fit: never cut; the largest size (down
    // to 0.7 of the UI's) whose lines leave three quarters of the model to be seen.
    for (float scale : {1.15f, 1.0f, 0.9f, 0.8f, 0.7f}) {
        size = ImGui::GetFontSize() * scale;
        const float room = std::max(view.w - 4.0f * pad, size);
        lines.assign(1, {});
        float lineWidth = 0.0f;
        widest = 0.0f;
        for (const EquationPiece& piece : pieces) {
            const float w = advance(piece);
            if (lineWidth + w > room && !lines.back().empty() && !piece.superscript) {
                lines.emplace_back();
                lineWidth = size; // the next line is indented
            }
            lines.back().push_back(&piece);
            lineWidth += w;
            widest = std::max(widest, lineWidth);
        }
        lineHeight = size * 1.3f;
        h = lineHeight * static_cast<float>(lines.size()) + pad;
        if (h <= 0.25f * view.h) {
            break;
        }
    }
    const float x0 = view.x + std::max(pad, (view.w - widest) * 0.5f - pad);
    auto covered = [&](float y) {
        const Rect band{x0 - pad, y, widest + 2.0f * pad, h};
        return std::count_if(keepClear.begin(), keepClear.end(), [&](const Rect& r) { return band.overlaps(r); });
    };
    const float top = view.y + pad * 0.5f, bottom = view.y + view.h - h - pad * 0.5f;
    const float y0 = covered(top) > covered(bottom) ? bottom : top;
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    dl->PushClipRect(ImVec2(view.x, view.y), ImVec2(view.x + view.w, view.y + view.h), true);
    dl->AddRectFilled(ImVec2(x0 - pad, y0), ImVec2(x0 + widest + pad, y0 + h), IM_COL32(10, 10, 16, 215), 0.6f * pad);
    for (std::size_t l = 0; l < lines.size(); ++l) {
        float x = x0 + (l == 0 ? 0.0f : size);
        const float y = y0 + 0.5f * pad + lineHeight * static_cast<float>(l) + 0.15f * size;
        for (const EquationPiece* piece : lines[l]) {
            const float s = piece->superscript ? size * 0.65f : size;
            dl->AddText(font, s, ImVec2(x, piece->superscript ? y - 0.2f * size : y), piece->color, piece->text.c_str());
            x += advance(*piece);
        }
    }
    dl->PopClipRect();
    widgets().set("view.equation", {x0 - pad, y0, widest + 2.0f * pad, h}); // all of it: the tests check it fits
}

float pointerRadius() { return 2.2f * ImGui::GetFontSize(); }

void roomPointer(float x, float y, const Rect& view) {
    if (!view.contains(x, y)) {
        return;
    }
    ImGui::SetMouseCursor(ImGuiMouseCursor_None); // the ring is the pointer
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const float r = pointerRadius(), t = 0.18f * r;
    dl->AddCircle(ImVec2(x, y), r, IM_COL32(0, 0, 0, 255), 48, t + 4.0f);
    dl->AddCircle(ImVec2(x, y), r, IM_COL32(255, 235, 0, 255), 48, t);
    dl->AddCircleFilled(ImVec2(x, y), 0.18f * r, IM_COL32(0, 0, 0, 255), 16);
    dl->AddCircleFilled(ImVec2(x, y), 0.12f * r, IM_COL32(255, 235, 0, 255), 16);
    widgets().set("view.pointer", {x - r, y - r, 2.0f * r, 2.0f * r});
}

void pointerRing(Image& image, float cx, float cy, float radius) {
    const float t = 0.18f * radius, outline = t * 0.5f + 2.0f;
    const int x0 = std::max(0, static_cast<int>(cx - radius - outline - 1)), x1 = std::min(image.width, static_cast<int>(cx + radius + outline + 2));
    const int y0 = std::max(0, static_cast<int>(cy - radius - outline - 1)), y1 = std::min(image.height, static_cast<int>(cy + radius + outline + 2));
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const float d = std::hypot(static_cast<float>(x) + 0.5f - cx, static_cast<float>(y) + 0.5f - cy);
            const float ring = std::abs(d - radius);
            std::uint8_t* p = image.rgb.data() + (static_cast<std::size_t>(y) * image.width + x) * 3;
            if (ring <= t * 0.5f || d <= 0.12f * radius) {
                p[0] = 255, p[1] = 235, p[2] = 0;
            } else if (ring <= outline || d <= 0.18f * radius) {
                p[0] = p[1] = p[2] = 0;
            }
        }
    }
}

} // namespace lab::ui
