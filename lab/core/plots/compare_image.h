// compare_image.h — compare mode's picture as one image: set A's render on the left, B's on the
// right, each under a label strip that names what tells them apart, as the GUI's compare view
// shows it (ui/viewport: the dark strips, A's label white, B's magenta, a line between the
// halves). `lab render` writes it for a preset with a prepared comparison (core/scene/preset.h
// `compare`), so slides and handouts get the lecture's picture. No GL: the renders come in.
#pragma once

#include "core/io/image.h"

#include <string>

namespace lab {

// The label strip's height for renders `height` pixels high.
int compareLabelHeight(int height);

// `a` and `b` (of one size) side by side with a 2-pixel line between them, each under its label
// ("A: normal matrix: model-view (wrong)"), cut with "..." where it is wider than its half.
Image composeComparison(const Image& a, const Image& b, const std::string& labelA, const std::string& labelB);

} // namespace lab
