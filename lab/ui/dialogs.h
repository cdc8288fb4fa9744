// dialogs.h — the lab's modal questions: a problem to acknowledge, unsaved changes to decide on.
// ImGui only; the answers go back to the app, which carries them out.
#pragma once

#include "core/io/diagnostics.h"
#include "ui/actions.h"

#include <optional>
#include <string>

namespace lab::ui {

// Shows `problem` until the user closes it (OK, Enter or Escape); true on the frame it closes.
bool problemDialog(const Problem& problem);

// The question's sentence: "<document> has unsaved changes. Discard them to <what>?" (escaped).
std::string unsavedQuestionText(const std::string& documentName, const std::string& what);

// Closes a dialog's popup that is no longer asked (answered elsewhere: the page's buttons).
void closeAnsweredDialogs(bool problemShown, bool questionShown);

// "<document> has unsaved changes. Discard them to <what>?" Save first, Discard or Cancel;
// Enter is Save first, Esc Cancel.
std::optional<UnsavedAnswer> unsavedChangesDialog(const std::string& documentName, const std::string& what);

} // namespace lab::ui
