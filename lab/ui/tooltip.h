// tooltip.h — tooltips that a pointer can reach and a key can close (WCAG 2.1, 1.4.13).
//
// ImGui 1.86's tooltip follows the pointer and goes as soon as the item is not hovered, so the
// pointer can never reach it, and nothing closes it but moving away. These stay while the pointer
// is over the item or over the tooltip itself (which opens just below the item, touching it, and
// stays put), show while the item has the keyboard's ring (ui/keyboard.h), and Esc closes them
// until the pointer leaves the item and the keyboard moves on. One is shown at a time.
// ImGui only.
#pragma once

namespace lab::ui {

// The tooltip of the last item: `text`, wrapped at 30 characters' width.
void itemTooltip(const char* text);

// Before ImGui::NewFrame, for an Esc: closes the tooltip shown in the last frame; false when none
// was shown (the Esc is then someone else's).
bool closeTooltip();

} // namespace lab::ui
