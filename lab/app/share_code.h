// share_code.h — the scene's link on the course page as a QR code (Q), for the share code window
// (ui/tools/share_code.h).
//
// It owns when the code is made again (only when the link changes) and why there is none. It does
// not make links or codes (core/share).
#pragma once

#include "app/workspace.h"
#include "core/share/qr_code.h"
#include "ui/tools/share_code.h"

#include <optional>
#include <string>

namespace lab {

// The scene's link on the course page (AppOptions::shareBase) as a QR code, made again only when
// the link changes; or why there is none (no address, a link too long for kMaxQrVersion).
class ShareCode {
public:
    bool shown = false;
    // The window's address field (the desktop: `editable`), and why the last address given was refused.
    std::string address, addressProblem;
    const ui::ShareCodeModel& update(const std::string& base, Workspace& workspace, bool editable);
    // Why there is no code, the first time it is so (then "" until the reason changes): for the
    // page's message log, since a screen reader does not read the window on the canvas. A wait (the
    // page fetching the QR encoder) is no reason.
    std::string newProblem();

private:
    std::string said_; // the last reason newProblem() gave
    std::string url_;
    bool made_ = false;
    std::string loadingFor_; // the link the page's QR encoder was last fetched for
    std::optional<QrCode> code_;
    ui::ShareCodeModel model_;
};

} // namespace lab
