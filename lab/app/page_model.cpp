// page_model.cpp — the page's parallel DOM as data (page_model.h).
#include "app/page_model.h"

#include "core/exercise/preset_fields.h"
#include "core/lighting/probe.h"
#include "core/plots/describe.h"
#include "core/scene/field_edit.h"
#include "core/scene/field_path.h"
#include "core/scene/field_table.h"

#include "core/io/safe_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace lab {

namespace {

// The page's JSON, written as text as it is made. (nlohmann's templates, instantiated for this
// file, cost the page's WebAssembly more than the whole parallel DOM: 11 KB gzip.)
class Json {
public:
    Json(const char* s) : Json(std::string_view(s)) {}
    Json(const std::string& s) : Json(std::string_view(s)) {}
    Json(std::string_view s) : text_(quoted(s)) {}
    Json(double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.7g", std::isfinite(v) ? v : 0.0); // a float's digits
        text_ = buffer;
    }
    Json(int v) : text_(std::to_string(v)) {}
    Json(bool v) : text_(v ? "true" : "false") {}
    Json(std::initializer_list<std::pair<std::string_view, Json>> members) : text_("{}") {
        for (const auto& [key, value] : members) {
            set(key, value);
        }
    }
    static Json array(std::initializer_list<Json> items = {}) {
        Json a(0);
        a.text_ = "[]";
        for (const Json& item : items) {
            a.push_back(item);
        }
        return a;
    }
    void push_back(const Json& v) { text_.insert(text_.size() - 1, (count_++ ? "," : "") + v.text_); }
    void set(std::string_view key, const Json& v) {
        text_.insert(text_.size() - 1, (count_++ ? "," : "") + quoted(key) + ":" + v.text_);
    }
    bool empty() const { return count_ == 0; }
    const std::string& text() const { return text_; }

private:
    static std::string quoted(std::string_view s) {
        std::string out = "\"";
        for (char c : s) {
            if (c == '"' || c == '\\') {
                out += '\\';
                out += c;
            } else if (static_cast<unsigned char>(c) < 0x20) {
                char buffer[8];
                std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
                out += buffer;
            } else {
                out += c;
            }
        }
        return out + '"';
    }
    std::string text_;
    int count_ = 0;
};
using G = FieldGroup;

// The panel's sections of fields, in its order, and the compact layout's tab each is on.
struct SectionSpec {
    const char* id;
    const char* label;
    const char* tab;
    FieldGroup group;
};
constexpr SectionSpec kSections[] = {
    {"material", "Material", "material", G::Material},
    {"brdf", "Reflection model (BRDF)", "material", G::Brdf},
    {"shading", "Shading and terms", "material", G::Shading},
    {"lights", "Lights", "lights", G::Lights},
    {"model", "Model", "model", G::Model},
    {"camera", "Camera", "model", G::Camera},
    {"plot", "Plots", "plots", G::Plot},
};
constexpr const char* kTabs[][2] = {{"model", "Model"}, {"material", "Material"}, {"lights", "Lights"}, {"plots", "Plots"}};

const char* kindName(FieldKind k) {
    switch (k) {
    case FieldKind::Number: return "number";
    case FieldKind::Vec3: return "vec3";
    case FieldKind::Color: return "color";
    case FieldKind::Direction: return "direction";
    case FieldKind::Int2: return "int2";
    case FieldKind::Switch: return "switch";
    case FieldKind::Choice: return "choice";
    case FieldKind::Text: return "text";
    }
    return "?";
}

// A number's step: the row's, or the last digit its format shows ("%.3f": 0.001).
double stepOf(const FieldRow& row) {
    if (row.step > 0.0f) {
        return row.step;
    }
    int digits = 3;
    if (const char* dot = std::strchr(row.format, '.')) {
        digits = std::atoi(dot + 1);
    }
    return std::pow(10.0, -digits);
}

Json vec(const glm::vec3& v) { return Json::array({v.x, v.y, v.z}); }

Json control(const FieldRow& row, Preset& p, LightDesc* light, const std::string& path) {
    Json c = {{"path", path}, {"label", row.label}, {"kind", kindName(row.kind)}, {"help", row.help}, {"unit", row.unit}};
    switch (row.kind) {
    case FieldKind::Number:
    case FieldKind::Vec3:
    case FieldKind::Color:
    case FieldKind::Direction:
        c.set("min", row.range->min);
        c.set("max", row.range->max);
        c.set("slider", row.range->sliderMin == row.range->min && row.range->sliderMax == row.range->max);
        c.set("step", stepOf(row));
        c.set("value", row.kind == FieldKind::Number ? Json(fieldValue<float>(row, p, light))
                                                     : vec(fieldValue<glm::vec3>(row, p, light)));
        break;
    case FieldKind::Int2: {
        glm::ivec2 v = fieldValue<glm::ivec2>(row, p, light);
        c.set("min", row.intRange->min);
        c.set("max", row.intRange->max);
        c.set("step", 1);
        c.set("value", Json::array({v.x, v.y}));
        break;
    }
    case FieldKind::Switch: c.set("value", fieldValue<bool>(row, p, light)); break;
    case FieldKind::Choice:
        c.set("value", choiceName(row.choices, choiceValue(row, p, light)));
        c.set("radios", (row.style & kStyleRadios) != 0);
    {
        Json choices = Json::array();
        for (const FieldChoice& choice : row.choices) {
            choices.push_back({{"name", choice.name}, {"label", choice.label}});
        }
        c.set("choices", choices);
        break;
    }
    case FieldKind::Text: c.set("value", printable(fieldValue<std::string>(row, p, light), true)); break;
    }
    return c;
}

// Whether the exercise being solved lets the student change `path` (ui/panel FieldGate's rule).
bool open(const ui::ExercisePanelModel* exercise, const std::string& path) {
    return !exercise || alwaysFree(path) ||
           std::any_of(exercise->open.begin(), exercise->open.end(), [&](const std::string& o) { return covers(o, path); });
}

// The controls of `group` (of one light) that the panel would show, in the table's order.
Json controls(FieldGroup group, Preset& p, LightDesc* light, int lightIndex, const ui::ExercisePanelModel* exercise) {
    Json out = Json::array();
    for (const FieldRow& row : fieldRows()) {
        if (row.group != group || (row.style & kStyleHidden) || (row.custom && row.kind == FieldKind::Text) ||
            !applies(row, p, light)) {
            continue;
        }
        std::string path = fieldPath(row, lightIndex);
        if (open(exercise, path)) {
            out.push_back(control(row, p, light, path));
        }
    }
    return out;
}

Json button(Command command, int index = -1, std::string label = {}) {
    const CommandRow& row = commandRow(command);
    Json b = {{"command", static_cast<int>(command)}, {"label", label.empty() ? std::string(row.label) : label}};
    if (row.key) {
        b.set("keys", keyName(row.key, row.modifiers));
    }
    if (index >= 0) {
        b.set("index", index);
    }
    return b;
}

Json buttons(std::initializer_list<Command> commands) {
    Json out = Json::array();
    for (Command c : commands) {
        out.push_back(button(c));
    }
    return out;
}

Json section(const char* id, const char* label, const char* tab, Json controls, Json buttons = Json::array()) {
    return {{"id", id}, {"label", label}, {"tab", tab}, {"controls", std::move(controls)}, {"buttons", std::move(buttons)}};
}

void fileSections(Workspace& ws, const ui::ExercisePanelModel* exercise, Json& out) {
    Json file = buttons({Command::Undo, Command::Redo, Command::PickFile, Command::DownloadPreset, Command::CopyLink,
                         Command::ToggleShareCode});
    if (!exercise) {
        file.push_back(button(Command::MakeExercise));
    }
    out.push_back(section("file", "File", "model", Json::array(), file));
    Json presets = Json::array();
    for (std::size_t i = 0; i < ws.presetFiles().size(); ++i) {
        Json b = button(Command::OpenPresetAt, static_cast<int>(i), printable(ws.presetFiles()[i].stem().string(), true));
        b.set("current", static_cast<int>(i) == ws.currentPreset());
        presets.push_back(b);
    }
    for (std::size_t i = 0; i < ws.exerciseFiles().size(); ++i) {
        presets.push_back(button(Command::OpenPath, static_cast<int>(i), "Exercise: " + printable(ws.exerciseFiles()[i].stem().string(), true)));
    }
    out.push_back(section("presets", "Presets", "model", Json::array(), presets));
    out.push_back(section("view", "View", "model", Json::array(),
                          buttons({Command::OrbitLeft, Command::OrbitRight, Command::OrbitUp, Command::OrbitDown,
                                   Command::ZoomIn, Command::ZoomOut, Command::FrameModel, Command::ResetCamera,
                                   Command::NextViewMode, Command::ToggleCompare, Command::ToggleWireframe})));
}

void fieldSections(Preset& p, const ui::ExercisePanelModel* exercise, Json& out) {
    for (const SectionSpec& s : kSections) {
        if (s.group != G::Lights) {
            Json c = controls(s.group, p, nullptr, 0, exercise);
            if (!c.empty() || s.group == G::Model) {
                Json b = s.group == G::Model ? buttons({Command::LoadModel}) : Json::array();
                if (s.group == G::Plot) {
                    b = buttons({Command::ExportFigures});
                }
                out.push_back(section(s.id, s.label, s.tab, std::move(c), std::move(b)));
            }
            continue;
        }
        for (std::size_t i = 0; i < p.lights.size(); ++i) {
            Json c = controls(G::Lights, p, &p.lights[i], static_cast<int>(i), exercise);
            if (!c.empty()) {
                std::string id = "light" + std::to_string(i + 1);
                out.push_back(section(id.c_str(), ("Light " + std::to_string(i + 1)).c_str(), s.tab, std::move(c)));
            }
        }
    }
}

Json pictures(const Preset& p) {
    PlotWords plot = describePlanePlot(p, 5);
    Json rows = Json::array();
    for (const PlotSample& s : plot.rows) {
        rows.push_back(Json::array({s.thetaOutDeg, s.diffuse, s.specular, s.total}));
    }
    return {{"description", describeScene(p)}, {"plot", {{"summary", plot.summary}, {"rows", rows}}},
            {"lobe", describeLobe(p)}};
}

} // namespace

const std::string& PageModel::json(Workspace& ws, const PageFacts& facts) {
    Preset& p = ws.edited();
    Json tabs = Json::array();
    for (const auto& tab : kTabs) {
        tabs.push_back({{"id", tab[0]}, {"label", tab[1]}});
    }
    Json sections = Json::array();
    fileSections(ws, facts.exercise, sections);
    fieldSections(p, facts.exercise, sections);
    Json page = {{"title", printable(ws.document().displayName(), true)}, {"tabs", tabs}, {"sections", sections}};
    if (const ui::ExercisePanelModel* e = facts.exercise) {
        Json hints = Json::array();
        for (const std::string& h : e->hints) {
            hints.push_back(h);
        }
        page.set("exercise", {{"title", e->title}, {"instructions", e->instructions}, {"hints", hints},
                              {"score", e->score}, {"solved", e->solved},
                              {"buttons", buttons({Command::ExerciseHint, Command::ExerciseReset, Command::ExerciseLeave})}});
    }
    page.set("readouts", {{"probe", facts.probe}, {"legend", facts.legend}, {"orbiting", facts.orbiting}});
    page.set("messages", {{"toast", facts.toast}, {"problem", facts.problem}});
    if (!described_ || *described_ != ws.a()) {
        described_ = ws.a();
        pictures_ = pictures(ws.a()).text();
    }
    json_ = page.text();
    json_.pop_back(); // the object's '}': the pictures go last, as they were written
    json_ += ",\"pictures\":" + pictures_ + "}";
    return json_;
}

std::string applyPageEdits(Workspace& ws, const std::vector<PageEdit>& edits, std::vector<Request>& requests) {
    std::string problems;
    for (const PageEdit& e : edits) {
        if (e.path.empty()) {
            if (e.command < 0 || e.command > static_cast<int>(kLastCommand)) {
                continue;
            }
            auto command = static_cast<Command>(e.command);
            if (command == Command::OpenPath) { // the page's exercise list: by its index
                if (e.index >= 0 && static_cast<std::size_t>(e.index) < ws.exerciseFiles().size()) {
                    requests.push_back({command, ws.exerciseFiles()[static_cast<std::size_t>(e.index)].string()});
                }
            } else {
                requests.push_back({command, {}, e.index});
            }
            continue;
        }
        std::string path = canonicalPath(e.path);
        std::string problem;
        if (ws.exercise() && !alwaysFree(path) &&
            std::none_of(ws.exercise()->exercise.open.begin(), ws.exercise()->exercise.open.end(),
                         [&](const std::string& o) { return covers(o, path); })) {
            problem = path + ": this exercise does not let you change it";
        } else {
            problem = setFieldFromText(ws.edited(), path, e.value);
        }
        if (!problem.empty()) {
            problems += (problems.empty() ? "" : "\n") + problem;
        }
    }
    return problems;
}

std::optional<ui::PanelTab> panelTabOf(const std::string& path, int& selectedLight) {
    const FieldRow* row = fieldRow(path);
    if (!row) {
        return std::nullopt;
    }
    for (const SectionSpec& s : kSections) {
        if (s.group == row->group) {
            if (isLightRow(*row)) {
                selectedLight = static_cast<int>(parseFieldPath(path)->at(1).index);
            }
            const std::string_view tab = s.tab;
            return tab == "model" ? ui::PanelTab::Model : tab == "material" ? ui::PanelTab::Material
                   : tab == "lights" ? ui::PanelTab::Lights : ui::PanelTab::Plots;
        }
    }
    return std::nullopt;
}

std::string probeWords(const ProbeResult* probe) {
    if (!probe) {
        return {};
    }
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "Probe: colour %.3f, %.3f, %.3f; emissive and global ambient %.3f, %.3f, %.3f.",
                  probe->color.r, probe->color.g, probe->color.b, probe->emissive.r + probe->globalAmbient.r,
                  probe->emissive.g + probe->globalAmbient.g, probe->emissive.b + probe->globalAmbient.b);
    std::string text = buffer;
    for (const ProbeLight& l : probe->lights) {
        glm::vec3 sum = l.ambient + l.diffuse + l.specular;
        std::snprintf(buffer, sizeof buffer, " Light %d: N.L %.3f, attenuation %.3f, diffuse %.3f, specular %.3f, sum %.3f, %.3f, %.3f.",
                      l.index + 1, l.NoL, l.attenuation, (l.diffuse.r + l.diffuse.g + l.diffuse.b) / 3.0f,
                      (l.specular.r + l.specular.g + l.specular.b) / 3.0f, sum.r, sum.g, sum.b);
        text += buffer;
    }
    return text;
}

} // namespace lab
