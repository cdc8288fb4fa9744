// notes.h — the speaker's notes: where the lecture is, what to say, what comes next and the time.
// Two faces of one model: a strip over the model for a single screen (S), and the whole of a
// window of its own for the laptop's screen while the lab fills the projector (Shift+S; the
// desktop's second window, platform/notes_window.h, draws it with notesScreen()).
// ImGui only.
#pragma once

#include <string>

namespace lab::ui {

struct NotesModel {
    std::string position; // "Slide 5 of 12: Full Phong"; "05-full-phong.json" off a deck
    std::string notes;    // the slide's notes, else the preset's own; empty: none
    std::string next;     // the next slide's title; empty at the last
    std::string clock;    // "14:05"
    bool operator==(const NotesModel& o) const {
        return position == o.position && notes == o.notes && next == o.next && clock == o.clock;
    }
    bool operator!=(const NotesModel& o) const { return !(*this == o); }
};

// The local time as "14:05" (not strftime: its locale tables weigh on the page).
std::string wallClock();

// The strip over the model's lower left, (x, y) its lower left corner: the room sees it too, so keep it short.
void notesWindow(const NotesModel& notes, bool& open, float x, float y, float width);

// The whole of the current ImGui display: the position and the clock on top, the notes as large as
// they fit (never cut: the text shrinks, down to a readable size, then scrolls), the next slide at the foot.
void notesScreen(const NotesModel& notes);

} // namespace lab::ui
