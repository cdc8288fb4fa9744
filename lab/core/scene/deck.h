// deck.h — a lecture as a file: its slides in order ("lighting-lab-deck" v1).
//
//   {"format": "lighting-lab-deck", "version": 1, "title": "Local illumination",
//    "slides": [{"preset": "../05-full-phong.json", "title": "Phong", "notes": ["Say this.", "Then this."],
//                "display": {"view": "r-dot-v"}},
//               {"preset": {"name": "Inline", "shading": "gouraud"}}]}
//
// A slide is a preset — a file's path relative to the deck's folder (it may name a file in the
// folder above, where a deck in presets/decks/ finds the shipped presets, and nowhere else), or a
// preset written inline — with an optional title (the preset's name otherwise), speaker notes (a
// text, or an array of lines), an opening display whose keys go over the preset's own (preset.h
// OpeningDisplay) and a prepared comparison (`compare`, as a preset's): a deck prepares its
// comparisons without touching the presets it names. Loading reads and checks every slide's preset, so a lecture never stops at a
// broken slide: a deck with one bad slide is refused whole, each problem named by its path
// ("slides[3].preset: ..."). The slides' models are loaded when the slide opens.
//
// A folder of presets is a deck too: deckOfFolder() makes one of its files in name order.
// No GL, no UI: the workspace steps through a deck (app/workspace_slides.cpp).
#pragma once

#include "core/io/diagnostics.h"
#include "core/scene/preset.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

inline constexpr std::size_t kMaxDeckBytes = 4u << 20;
inline constexpr std::size_t kMaxSlides = 200;

struct Slide {
    std::string title;          // the slide's title, else the preset's name
    LoadedPreset preset;        // as its file holds it (`file` empty for an inline preset)
    std::filesystem::path folder; // where its glTF paths resolve: its file's folder, the deck's for an inline one
    std::string notes;          // the slide's notes, else the preset's
    OpeningDisplay display;     // the preset's, with the slide's keys over it
    std::string compare;        // the slide's prepared comparison (a patch of its preset's fields,
                                // preset.h `compare`), else the preset's; "" none
};

struct Deck {
    std::string title;
    std::filesystem::path file; // the deck's file; empty for a folder's deck
    std::vector<Slide> slides;
};

// Whether `text` is a deck's (its "format" says so): how a file opened by path is told apart.
bool isDeckText(std::string_view text);

// Parses and checks a deck's text; `folder` is where its slides' paths resolve.
std::optional<Deck> parseDeck(std::string_view text, const std::string& displayName,
                              const std::filesystem::path& folder, Diagnostics& diagnostics);

// Reads a deck file (at most kMaxDeckBytes) and every preset it names.
std::optional<Deck> loadDeck(const std::filesystem::path& file, Diagnostics& diagnostics);

// A slide's title as the lab shows it: its own, else its preset's name, else its file's name.
std::string slideTitle(const Slide& slide);

} // namespace lab
