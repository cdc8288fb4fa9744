// deck.cpp — reading a deck and the presets it names (deck.h).
#include "core/scene/deck.h"

#include "core/io/file_io.h"
#include "core/io/json_text.h"
#include "core/io/paths.h"
#include "core/io/safe_text.h"
#include "core/scene/file_header.h"
#include "core/scene/preset_reader.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace lab {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using preset_detail::Reader;

namespace {

constexpr int kMaxDeckDepth = 40; // a slide's inline preset nests as a preset file does, 8 deeper
constexpr std::string_view kDeckKeys[] = {"format", "version", "title", "slides"};
constexpr std::string_view kSlideKeys[] = {"preset", "title", "notes", "display", "compare"};

// A slide's file: relative, a .json file inside the deck's folder or the folder above it.
std::optional<fs::path> slideFile(const std::string& path, const fs::path& folder, std::string& error) {
    if (fs::path(path).is_absolute()) {
        error = inQuotes(path) + " is an absolute path; a slide's preset is named relative to the deck's folder";
        return std::nullopt;
    }
    const fs::path base = canonicalFolder(folder);
    std::error_code ec;
    const fs::path full = fs::weakly_canonical(base / path, ec);
    const fs::path root = base.has_parent_path() ? base.parent_path() : base;
    if (ec || !isInside(root, full)) {
        error = inQuotes(path) + " leaves the deck's folder and the folder above it (" + root.string() + ")";
        return std::nullopt;
    }
    if (full.extension() != ".json") {
        error = "expected a preset's .json file, got " + inQuotes(path);
        return std::nullopt;
    }
    return full;
}

// A slide's notes: a text, or an array of lines joined by newlines.
void readNotes(Reader& r, std::string& notes) {
    const Json* json = r.find("notes");
    if (!json) {
        return;
    }
    notes.clear(); // the slide's replace the preset's
    if (json->is_string()) {
        notes = json->get<std::string>();
        return;
    }
    if (json->is_array() && std::all_of(json->begin(), json->end(), [](const Json& l) { return l.is_string(); })) {
        for (const Json& line : *json) {
            notes += (notes.empty() ? "" : "\n") + line.get<std::string>();
        }
        return;
    }
    r.error("notes", "expected a text or an array of lines, got " + Reader::describe(*json));
}

// One slide: its preset (a path or inline), then its title, notes and display over the preset's.
std::optional<Slide> readSlide(Reader& r, const std::string& displayName, const fs::path& folder, Diagnostics& out) {
    Slide slide;
    const Json* preset = r.find("preset");
    const std::size_t before = r.problems();
    Diagnostics inner;
    if (!preset) {
        r.errorAt(r.pathOf("preset"), "missing; expected a preset's path or a preset object");
    } else if (preset->is_string()) {
        std::string error;
        if (std::optional<fs::path> file = slideFile(preset->get<std::string>(), folder, error); !file) {
            r.error("preset", error);
        } else if (std::optional<LoadedPreset> loaded = loadPreset(*file, inner)) {
            slide.preset = std::move(*loaded);
        }
    } else if (preset->is_object()) {
        if (std::optional<Preset> p = parseInlinePreset(preset->dump(), displayName, r.pathOf("preset"), folder, inner)) {
            slide.preset = {std::move(*p), {}, {}};
        }
    } else {
        r.error("preset", "expected a preset's path or a preset object, got " + Reader::describe(*preset));
    }
    out.insert(out.end(), inner.begin(), inner.end());
    slide.folder = slide.preset.file.empty() ? folder : slide.preset.folder();
    r.readString("title", slide.title);
    slide.notes = slide.preset.preset.notes;
    slide.display = slide.preset.preset.display;
    readNotes(r, slide.notes);
    preset_detail::readDisplay(r, slide.display); // its keys over the preset's
    slide.compare = slide.preset.preset.compare;
    if (const Json* compare = r.find("compare"); compare && inner.empty() && r.problems() == before) {
        // Read as the preset's own `compare` would be: on the slide's preset, at this slide's path.
        Json withCompare = Json::parse(std::string_view(presetToJson(slide.preset.preset))); // (one parser instantiation)
        withCompare["compare"] = *compare;
        if (std::optional<Preset> p = parseInlinePreset(withCompare.dump(), displayName, r.path(), slide.folder, inner)) {
            slide.compare = p->compare;
        }
        out.insert(out.end(), inner.begin(), inner.end());
    }
    r.finish(kSlideKeys);
    if (r.problems() != before || !inner.empty()) {
        return std::nullopt;
    }
    return slide;
}

} // namespace

bool isDeckText(std::string_view text) {
    if (!jsonNestingWithin(text, kMaxDeckDepth)) {
        return false;
    }
    Json json = Json::parse(text, nullptr, false);
    auto format = json.is_object() ? json.find("format") : json.end();
    return json.is_object() && format != json.end() && format->is_string() && format->get<std::string>() == kDeckFile.format;
}

std::optional<Deck> parseDeck(std::string_view text, const std::string& displayName, const fs::path& folder,
                              Diagnostics& diagnostics) {
    std::optional<Json> parsed = preset_detail::parseJsonObject(text, displayName, kMaxDeckDepth, "a deck", diagnostics);
    if (!parsed) {
        return std::nullopt;
    }
    const Json& json = *parsed;
    if (std::optional<HeaderProblem> header = fileHeaderProblem(json, kDeckFile)) {
        diagnostics.push_back({displayName, header->key, header->message});
        return std::nullopt;
    }
    Diagnostics out;
    Reader r(json, "", displayName, out);
    Deck deck;
    r.find("format");
    r.find("version");
    r.readString("title", deck.title);
    const Json* slides = r.find("slides");
    if (!slides || !slides->is_array() || slides->empty() || slides->size() > kMaxSlides) {
        r.error("slides", "expected an array of 1 to " + std::to_string(kMaxSlides) + " slides, got " +
                              (slides ? Reader::describe(*slides) : std::string("nothing")));
    } else {
        for (std::size_t i = 0; i < slides->size(); ++i) {
            const Json& item = (*slides)[i];
            if (!item.is_object()) {
                r.errorAt(r.elementPath("slides", i), "expected a slide object {\"preset\": ...}, got " + Reader::describe(item));
                continue;
            }
            Reader s = r.child(item, r.elementPath("slides", i));
            if (std::optional<Slide> slide = readSlide(s, displayName, folder, out)) {
                deck.slides.push_back(std::move(*slide));
            }
        }
    }
    r.finish(kDeckKeys);
    if (!out.empty()) {
        diagnostics.insert(diagnostics.end(), out.begin(), out.end());
        return std::nullopt;
    }
    return deck;
}

std::optional<Deck> loadDeck(const fs::path& file, Diagnostics& diagnostics) {
    std::string error;
    std::optional<std::string> text = readFile(file, kMaxDeckBytes, error);
    if (!text) {
        diagnostics.push_back({file.string(), "", error});
        return std::nullopt;
    }
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    std::optional<Deck> deck = parseDeck(*text, file.string(), folder, diagnostics);
    if (deck) {
        deck->file = file;
    }
    return deck;
}

std::string slideTitle(const Slide& slide) {
    if (!slide.title.empty()) {
        return slide.title;
    }
    if (!slide.preset.preset.name.empty() && slide.preset.preset.name != "Untitled") {
        return slide.preset.preset.name;
    }
    return slide.preset.file.empty() ? "Untitled" : slide.preset.file.stem().string();
}

} // namespace lab
