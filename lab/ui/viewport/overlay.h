// overlay.h — what the room sees over the model in a lecture: the lighting equation of the BRDF
// in use, typeset (N·H, n as a superscript, each factor in its own colour, the colours the
// factor views' legends name), and a large, high-contrast pointer the back row can follow.
// ImGui only: drawn on the foreground over the model's viewport; the screenshot draws the
// pointer into its image with pointerRing (app/app.cpp), so the picture shows what the room saw.
#pragma once

#include "core/io/image.h"
#include "core/scene/preset.h"
#include "ui/layout.h"

#include <string>
#include <vector>

namespace lab::ui {

// One piece of the typeset equation: its text, its colour, raised as a superscript or not.
struct EquationPiece {
    std::string text;
    unsigned color = 0xFFFFFFFFu; // ImGui's packed ABGR
    bool superscript = false;
};

// The equation of `preset`'s BRDF with the terms it has switched on: "I = Ke + Ka·Ia + Kd·Id·max(0,
// N·L) + Ks·Is·max(0, R·V)ⁿ" for Phong, N·H for Blinn-Phong, "D·F·G / (4 (N·L)(N·V))" for Cook-Torrance.
std::vector<EquationPiece> equationPieces(const Preset& preset);
// The same as plain text, for the page and the tests ("... max(0, R·V)^n").
std::string equationText(const Preset& preset);

// The equation across the top of `view` (across its bottom where that covers fewer of `keepClear`,
// the light markers), on a dark band, its lines at the largest size that leaves three quarters of
// the model to be seen (named "view.equation" for the GUI tests).
void equationOverlay(const Preset& preset, const Rect& view, const std::vector<Rect>& keepClear = {});

// The pointer at (x, y) window units, while it is over `view`: a ring of `pointerRadius()`.
void roomPointer(float x, float y, const Rect& view);
float pointerRadius();

// The same ring drawn into `image` at (x, y) pixels, `radius` pixels wide: the screenshot's.
void pointerRing(Image& image, float x, float y, float radius);

} // namespace lab::ui
