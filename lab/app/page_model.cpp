// page_model.cpp — the page's parallel DOM as data (page_model.h).
#include "app/page_model.h"

#include "core/exercise/preset_fields.h"
#include "core/lighting/probe.h"
#include "core/plots/describe.h"
#include "core/scene/field_edit.h"
#include "core/scene/field_path.h"
#include "core/scene/field_table.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace lab {

namespace {

using Json = nlohmann::json;
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

// A float as the page shows it: its shortest decimal within float precision (0.001, not 0.0010000000474974513).
double shown(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.7g", v);
    return std::strtod(buffer, nullptr);
}

Json vec(const glm::vec3& v) { return Json::array({shown(v.x), shown(v.y), shown(v.z)}); }

Json control(const FieldRow& row, Preset& p, LightDesc* light, const std::string& path) {
    Json c = {{"path", path}, {"label", std::string(row.label)}, {"kind", kindName(row.kind)},
              {"help", std::string(row.help)}, {"unit", std::string(row.unit)}};
    switch (row.kind) {
    case FieldKind::Number:
    case FieldKind::Vec3:
    case FieldKind::Color:
    case FieldKind::Direction:
        c["min"] = shown(row.range->min);
        c["max"] = shown(row.range->max);
        c["slider"] = row.range->sliderMin == row.range->min && row.range->sliderMax == row.range->max;
        c["step"] = shown(stepOf(row));
        c["value"] = row.kind == FieldKind::Number ? Json(shown(fieldValue<float>(row, p, light)))
                                                   : vec(fieldValue<glm::vec3>(row, p, light));
        break;
    case FieldKind::Int2: {
        glm::ivec2 v = fieldValue<glm::ivec2>(row, p, light);
        c["min"] = row.intRange->min;
        c["max"] = row.intRange->max;
        c["step"] = 1;
        c["value"] = Json::array({v.x, v.y});
        break;
    }
    case FieldKind::Switch: c["value"] = fieldValue<bool>(row, p, light); break;
    case FieldKind::Choice:
        c["value"] = std::string(choiceName(row.choices, choiceValue(row, p, light)));
        c["radios"] = (row.style & kStyleRadios) != 0;
        c["choices"] = Json::array();
        for (const FieldChoice& choice : row.choices) {
            c["choices"].push_back({{"name", std::string(choice.name)}, {"label", choice.label}});
        }
        break;
    case FieldKind::Text: c["value"] = fieldValue<std::string>(row, p, light); break;
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
        b["keys"] = keyName(row.key, row.modifiers);
    }
    if (index >= 0) {
        b["index"] = index;
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

Json fileSections(Workspace& ws, const ui::ExercisePanelModel* exercise) {
    Json out = Json::array();
    Json file = buttons({Command::Undo, Command::Redo, Command::PickFile, Command::DownloadPreset, Command::CopyLink,
                         Command::ToggleShareCode});
    if (!exercise) {
        file.push_back(button(Command::MakeExercise));
    }
    out.push_back(section("file", "File", "model", Json::array(), file));
    Json presets = Json::array();
    for (std::size_t i = 0; i < ws.presetFiles().size(); ++i) {
        Json b = button(Command::OpenPresetAt, static_cast<int>(i), ws.presetFiles()[i].stem().string());
        b["current"] = static_cast<int>(i) == ws.currentPreset();
        presets.push_back(b);
    }
    for (std::size_t i = 0; i < ws.exerciseFiles().size(); ++i) {
        presets.push_back(button(Command::OpenPath, static_cast<int>(i), "Exercise: " + ws.exerciseFiles()[i].stem().string()));
    }
    out.push_back(section("presets", "Presets", "model", Json::array(), presets));
    out.push_back(section("view", "View", "model", Json::array(),
                          buttons({Command::OrbitLeft, Command::OrbitRight, Command::OrbitUp, Command::OrbitDown,
                                   Command::ZoomIn, Command::ZoomOut, Command::FrameModel, Command::ResetCamera,
                                   Command::NextViewMode, Command::ToggleCompare, Command::ToggleWireframe})));
    return out;
}

Json fieldSections(Preset& p, const ui::ExercisePanelModel* exercise) {
    Json out = Json::array();
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
    return out;
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
    nlohmann::json page = {{"title", ws.document().displayName()}, {"tabs", Json::array()}, {"sections", Json::array()}};
    for (const auto& tab : kTabs) {
        page["tabs"].push_back({{"id", tab[0]}, {"label", tab[1]}});
    }
    for (Json& s : fileSections(ws, facts.exercise)) {
        page["sections"].push_back(std::move(s));
    }
    for (Json& s : fieldSections(p, facts.exercise)) {
        page["sections"].push_back(std::move(s));
    }
    if (const ui::ExercisePanelModel* e = facts.exercise) {
        page["exercise"] = {{"title", e->title}, {"instructions", e->instructions}, {"hints", e->hints},
                            {"score", e->score}, {"solved", e->solved},
                            {"buttons", buttons({Command::ExerciseHint, Command::ExerciseReset, Command::ExerciseLeave})}};
    }
    page["readouts"] = {{"probe", facts.probe}, {"legend", facts.legend}, {"orbiting", facts.orbiting}};
    page["messages"] = {{"toast", facts.toast}, {"problem", facts.problem}};
    if (!described_ || *described_ != ws.a()) {
        described_ = ws.a();
        pictures_ = pictures(ws.a()).dump(-1, ' ', false, Json::error_handler_t::replace);
    }
    json_ = page.dump(-1, ' ', false, Json::error_handler_t::replace);
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
