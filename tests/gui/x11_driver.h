// x11_driver.h — real input for GUI tests: the X server's XTEST extension (what xdotool uses)
// for the mouse and keyboard, the XDND protocol for dropping files on a window, and XGetImage
// for screenshots of the screen. Everything goes through the X server, as a user's input would.
#pragma once

#include "core/io/image.h"

#include <string>

struct _XDisplay; // Xlib's Display, without including Xlib here

namespace lab::test {

class X11Driver {
public:
    X11Driver();
    ~X11Driver();
    X11Driver(const X11Driver&) = delete;
    X11Driver& operator=(const X11Driver&) = delete;

    bool connected() const { return display_ != nullptr; }

    // The top-level window whose title starts with `prefix`, waiting up to `seconds`; 0 if none.
    unsigned long findWindow(const std::string& prefix, double seconds);
    // Window coordinates to screen coordinates.
    void toScreen(unsigned long window, int& x, int& y);
    // A window's title ("" for none).
    std::string title(unsigned long window);
    // A window's rectangle on the screen; false when there is no such window (any more).
    bool screenRect(unsigned long window, int& x, int& y, int& width, int& height);

    void moveMouse(int x, int y);
    void button(int button, bool down);
    // A key by X keysym name ("Return", "F12", "a", "Control_L"), pressed or released.
    void key(const std::string& keysym, bool down);
    // Types ASCII text, holding Shift where a character needs it.
    void type(const std::string& text);

    // Drops `path` on `window` at window position (x, y) through XDND, as a file manager would.
    // False if the window does not take part in XDND or does not answer.
    bool dropFile(unsigned long window, const std::string& path, int x, int y, std::string& error);

    // The size of the default screen, in pixels.
    void screenSize(int& width, int& height);

    // The screen's pixels in a rectangle (screen coordinates).
    Image capture(int x, int y, int width, int height);

private:
    void flush();
    ::_XDisplay* display_ = nullptr;
};

} // namespace lab::test
