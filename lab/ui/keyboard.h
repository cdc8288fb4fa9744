// keyboard.h — who has the keyboard: the model (the canvas) or a window's widget, through Dear
// ImGui 1.86's keyboard navigation.
//
// The model has it to start with: letters, digits and the arrows are the shortcuts of
// ui/actions.h, and ImGui's navigation is off, so an arrow never moves a focus that nobody sees.
// Tab (or Enter) gives the keyboard to the control panel (or to the tool window that has ImGui's
// focus: the help, the shader editor, the sweep, the probe), Ctrl+Tab to the next window (ImGui's
// window switcher).
// From then on the arrows move between widgets and a ring marks the widget that has the keys;
// Space presses it (on a slider: the arrows then change it), Tab goes to the next field that takes
// typing (a slider, a number, a path: ImGui 1.86's Tab skips buttons and boxes), and Esc
// ends what it can (a slider's change, a list, a tooltip) and at last gives the keyboard back to
// the model. A mouse press gives it back too, so a mouse user's shortcuts work after a click in
// the panel as they always did. A text field being typed in takes every key (KeyOwner::Typing).
//
// Not here: the shortcuts themselves (ui/actions.h), the events (the platform's ImGui host feeds
// them and calls this around ImGui::NewFrame). ImGui only, with its internal state.
#pragma once

#include "ui/actions.h"

#include <vector>

namespace lab::ui {

struct KeyPress {
    int key = 0;            // GLFW key code (ui/actions.h)
    unsigned modifiers = 0; // Modifier bits
    bool used = false;      // set when the keyboard's owner took it (an Esc that closed a tooltip): no one else sees it
};

class KeyboardFocus {
  public:
    // Before ImGui::NewFrame, with the frame's key presses (in order) and whether a mouse button
    // was pressed: who this frame's keys are for, decided from ImGui's state after the last frame.
    // Turns ImGui's keyboard navigation on while a window's widget has the keyboard and off while
    // the model has it. A Tab or an Enter from the model puts the ring on the window's last widget
    // (its first after an Esc) and is marked used; an Esc while a tooltip shows closes it (ui/tooltip.h) and is
    // marked used.
    KeyOwner beforeNewFrame(std::vector<KeyPress>& presses, bool mousePressed);
    // The browser: false, so that Tab leaves the canvas for the page's own controls (no keyboard
    // trap) and Enter alone enters the windows. On the desktop both do.
    void tabEntersWindows(bool on) { tabEnters_ = on; }
    // After ImGui::NewFrame: a window entered by Tab gets its ring; Tab from a widget goes on to the next one
    // (ImGui 1.86 goes back to the window's first widget unless the focused one is a text field being typed in).
    void afterNewFrame();

  private:
    bool window_ = false;   // a window's widget has the keyboard
    bool entering_ = false; // this frame's Tab or Enter enters a window from the model
    bool tabEnters_ = true;
};

// During the frame: names the rectangle of the widget with the keyboard's ring "focus" in the
// widget map (ui/widget_map.h), for the GUI tests; nothing while the model has the keyboard.
void markKeyboardFocus();

} // namespace lab::ui
