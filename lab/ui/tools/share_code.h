// share_code.h — the scene's link as a large QR code, for the students' phones (Q, presenter mode).
//
// The code fills most of the window's smaller side, black on white with its quiet zone, the link
// printed under it; or, when there is no code, why (no course address yet, a link too long).
#pragma once

#include "core/share/qr_code.h"
#include "ui/actions.h"

#include <optional>
#include <string>
#include <vector>

namespace lab::ui {

struct ShareCodeModel {
    const QrCode* code = nullptr; // null: `problem` says why
    std::string link;
    std::string problem;
    bool waiting = false; // `problem` says what is awaited (the page fetching the QR encoder), not a failure
    std::string title; // the scene's or the exercise's name
    // The course page's address as the window's field edits it (the desktop); null where the address
    // is the page's own. `addressProblem`: why the last one given was refused.
    std::string* address = nullptr;
    std::string addressProblem;
};

// A window over everything, centred; Q or its Close button asks to close it. With an editable
// address, a field for it under the code: Enter or Use asks for Command::SetShareBase.
void shareCodeWindow(const ShareCodeModel& model, std::vector<Request>& requests);

} // namespace lab::ui
