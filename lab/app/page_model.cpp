// page_model.cpp — the page's parallel DOM as data (page_model.h).
#include "app/page_model.h"

#include "core/exercise/exercise.h"
#include "core/lighting/probe.h"
#include "core/plots/describe.h"
#include "core/scene/field_edit.h"
#include "core/scene/field_path.h"
#include "core/scene/field_table.h"
#include "ui/widget_map.h"

#include "core/io/safe_text.h"

#include <iterator>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace lab {

namespace {

using G = FieldGroup;

// The page's JSON, written as it is made: a call a value, no temporaries. (nlohmann's templates,
// or a value type of strings, cost the page's WebAssembly tens of kilobytes for this file.)
class Writer {
public:
    Writer& open(char bracket) {
        comma();
        text += bracket;
        first_ = true;
        return *this;
    }
    Writer& close(char bracket) {
        text += bracket;
        first_ = false;
        return *this;
    }
    Writer& key(std::string_view k) {
        str(k);
        text += ':';
        first_ = true;
        return *this;
    }
    Writer& str(std::string_view v);
    Writer& num(double v);
    Writer& raw(std::string_view json) { // a value written by another writer
        comma();
        text += json;
        return *this;
    }
    Writer& flag(bool v) {
        comma();
        text += v ? "true" : "false";
        return *this;
    }
    std::string text;

private:
    void comma() {
        if (!first_) {
            text += ',';
        }
        first_ = false;
    }
    bool first_ = true;
};

Writer& Writer::str(std::string_view v) {
    comma();
    text += '"';
    for (char c : v) {
        if (c == '"' || c == '\\') {
            text += '\\';
            text += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
            text += buffer;
        } else {
            text += c;
        }
    }
    text += '"';
    return *this;
}

Writer& Writer::num(double v) {
    comma();
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.7g", std::isfinite(v) ? v : 0.0); // a float's digits: 0.001, not 0.0010000000474974513
    text += buffer;
    return *this;
}

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
constexpr const char* kKinds[] = {"number", "vec3", "color", "direction", "int2", "switch", "choice", "text"}; // FieldKind's order
static_assert(std::size(kKinds) == static_cast<std::size_t>(FieldKind::Text) + 1, "a name for every FieldKind");

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

void control(Writer& w, const FieldRow& row, Preset& p, LightDesc* light, const std::string& path) {
    w.open('{').key("path").str(path).key("label").str(row.label).key("kind").str(kKinds[static_cast<int>(row.kind)]);
    w.key("help").str(row.help).key("unit").str(row.unit);
    switch (row.kind) {
    case FieldKind::Number:
    case FieldKind::Vec3:
    case FieldKind::Color:
    case FieldKind::Direction: {
        const limits::Range& r = *row.range;
        w.key("min").num(r.min).key("max").num(r.max).key("step").num(stepOf(row));
        w.key("slider").flag(r.sliderMin == r.min && r.sliderMax == r.max).key("value");
        if (row.kind == FieldKind::Number) {
            w.num(fieldValue<float>(row, p, light));
        } else {
            const glm::vec3& v = fieldValue<glm::vec3>(row, p, light);
            w.open('[').num(v.x).num(v.y).num(v.z).close(']');
        }
        break;
    }
    case FieldKind::Int2: {
        glm::ivec2 v = fieldValue<glm::ivec2>(row, p, light);
        w.key("min").num(row.intRange->min).key("max").num(row.intRange->max).key("step").num(1);
        w.key("value").open('[').num(v.x).num(v.y).close(']');
        break;
    }
    case FieldKind::Switch: w.key("value").flag(fieldValue<bool>(row, p, light)); break;
    case FieldKind::Choice:
        w.key("value").str(choiceName(row.choices, choiceValue(row, p, light)));
        w.key("radios").flag((row.style & kStyleRadios) != 0).key("choices").open('[');
        for (const FieldChoice& choice : row.choices) {
            w.open('{').key("name").str(choice.name).key("label").str(choice.label).close('}');
        }
        w.close(']');
        break;
    case FieldKind::Text: w.key("value").str(printable(fieldValue<std::string>(row, p, light), true)); break;
    }
    w.close('}');
}

// The controls of `group` (of one light) that the panel would show, in the table's order; how many.
int controls(Writer& w, FieldGroup group, Preset& p, LightDesc* light, int lightIndex, const Exercise* exercise) {
    int count = 0;
    w.key("controls").open('[');
    for (const FieldRow& row : fieldRows()) {
        if (row.group != group || (row.style & kStyleHidden) || (row.custom && row.kind == FieldKind::Text) ||
            !applies(row, p, light)) {
            continue;
        }
        std::string path = fieldPath(row, lightIndex);
        if (!exercise || fieldIsOpen(*exercise, path)) { // the exercise's gate, as the panel's
            control(w, row, p, light, path);
            ++count;
        }
    }
    w.close(']');
    return count;
}

// A command's button; `index` its argument (a list's entry, `current` when it is the one shown);
// `pressed` 0 or 1 for a toggle's state, -1 for none.
void button(Writer& w, Command command, int index = -1, std::string_view label = {}, bool current = false,
            int pressed = -1) {
    const CommandRow& row = commandRow(command);
    w.open('{').key("command").num(static_cast<int>(command)).key("label").str(label.empty() ? row.label : label);
    if (row.key) {
        w.key("keys").str(keyName(row.key, row.modifiers));
    }
    if (index >= 0) {
        w.key("index").num(index).key("current").flag(current);
    }
    if (pressed >= 0) {
        w.key("pressed").flag(pressed == 1);
    }
    w.close('}');
}

void buttons(Writer& w, std::initializer_list<Command> commands) {
    w.key("buttons").open('[');
    for (Command c : commands) {
        button(w, c);
    }
    w.close(']');
}

void sectionStart(Writer& w, std::string_view id, std::string_view label, std::string_view tab) {
    w.open('{').key("id").str(id).key("label").str(label).key("tab").str(tab);
}

void fileSections(Writer& w, Workspace& ws, const ui::ExercisePanelModel* exercise, MovingLights motion) {
    sectionStart(w, "file", "File", "model");
    w.key("controls").open('[').close(']');
    if (exercise) { // an exercise is not made from an exercise
        buttons(w, {Command::Undo, Command::Redo, Command::PickFile, Command::DownloadPreset, Command::CopyLink,
                    Command::ToggleShareCode});
    } else {
        buttons(w, {Command::Undo, Command::Redo, Command::PickFile, Command::DownloadPreset, Command::CopyLink,
                    Command::ToggleShareCode, Command::MakeExercise});
    }
    w.close('}');
    sectionStart(w, "presets", "Presets", "model");
    w.key("controls").open('[').close(']').key("buttons").open('[');
    const std::vector<std::string> slides = ws.slideNames();
    for (std::size_t i = 0; i < slides.size(); ++i) {
        button(w, Command::OpenPresetAt, static_cast<int>(i), printable(slides[i], true),
               static_cast<int>(i) == ws.currentSlide());
    }
    for (std::size_t i = 0; i < ws.exerciseFiles().size(); ++i) {
        button(w, Command::OpenPath, static_cast<int>(i), "Exercise: " + printable(ws.exerciseFiles()[i].stem().string(), true));
    }
    w.close(']').close('}');
    sectionStart(w, "view", "View", "model");
    w.key("controls").open('[').close(']');
    w.key("buttons").open('[');
    for (Command c : {Command::OrbitLeft, Command::OrbitRight, Command::OrbitUp, Command::OrbitDown, Command::ZoomIn,
                      Command::ZoomOut, Command::FrameModel, Command::ResetCamera, Command::NextViewMode,
                      Command::ToggleCompare, Command::ToggleWireframe}) {
        button(w, c);
    }
    if (motion != MovingLights::None) { // a toggle button, pressed while the moving lights stand still
        button(w, Command::ToggleLightMotion, -1, {}, false, motion == MovingLights::Paused ? 1 : 0);
    }
    w.close(']').close('}');
}

void fieldSections(Writer& w, Preset& p, const Exercise* exercise) {
    for (const SectionSpec& s : kSections) {
        for (std::size_t i = 0; i < (s.group == G::Lights ? p.lights.size() : 1); ++i) {
            const bool light = s.group == G::Lights;
            const std::string n = std::to_string(i + 1);
            Writer section;
            sectionStart(section, light ? "light" + n : s.id, light ? "Light " + n : s.label, s.tab);
            const int count = controls(section, s.group, p, light ? &p.lights[i] : nullptr, static_cast<int>(i), exercise);
            if (count == 0 && s.group != G::Model) { // a section the exercise closes entirely is not there
                continue;
            }
            if (s.group == G::Model) {
                buttons(section, {Command::LoadModel});
            } else if (s.group == G::Plot) {
                buttons(section, {Command::ExportFigures});
            } else if (s.group == G::Brdf && !exercise) { // the fit goes into B (in an exercise B is the target)
                buttons(section, {Command::FitPhong, Command::FitBlinnPhong, Command::FitCookTorrance});
            } else {
                section.key("buttons").open('[').close(']');
            }
            w.raw(section.close('}').text);
        }
    }
}

void pictures(Writer& w, const Preset& p) {
    PlotWords plot = describePlanePlot(p, 5);
    w.open('{').key("description").str(describeScene(p)).key("plot").open('{').key("summary").str(plot.summary);
    w.key("rows").open('[');
    for (const PlotSample& s : plot.rows) {
        w.open('[').num(s.thetaOutDeg).num(s.diffuse).num(s.specular).num(s.total).close(']');
    }
    w.close(']').close('}').key("lobe").str(describeLobe(p)).key("slice").str(describeSlice(p)).close('}');
}

std::string join(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) {
        text += (text.empty() ? "" : "\n") + line;
    }
    return text;
}

} // namespace

PageFacts openTools(ui::ShaderEditorState& shader, ui::SweepViewState& sweep) {
    PageFacts facts;
    facts.shader = shader.open ? &shader : nullptr;
    facts.sweep = sweep.open ? &sweep : nullptr;
    return facts;
}

// A tool window's text field: the shader editor's three files, the sweep's keys and values.
std::string* toolField(const std::string& path, const PageFacts& tools) {
    if (ui::ShaderEditorState* s = tools.shader; s && path.starts_with("shader.")) {
        return path == "shader.vertex" ? &s->vertex : path == "shader.fragment" ? &s->fragment
               : path == "shader.lighting" ? &s->lighting : nullptr;
    }
    if (ui::SweepViewState* s = tools.sweep; s && path.size() == 10 && (path[9] == '0' || path[9] == '1')) {
        const auto i = static_cast<std::size_t>(path[9] - '0');
        return path.starts_with("sweep.key") ? &s->key[i] : path.starts_with("sweep.val") ? &s->values[i] : nullptr;
    }
    return nullptr;
}

namespace {

void toolSections(Writer& w, const PageFacts& facts) {
    sectionStart(w, "tools", "Tools", "model");
    w.key("controls").open('[');
    const char* kShaderFiles[][2] = {{"shader.vertex", "lit.vert"}, {"shader.fragment", "lit.frag"}, {"shader.lighting", "lighting.glsl"}};
    for (const auto& [path, file] : kShaderFiles) {
        if (facts.shader) {
            w.open('{').key("path").str(path).key("label").str(file).key("kind").str("code").key("help");
            w.str("the shader's source; Compile runs it").key("unit").str("").key("value").str(*toolField(path, facts)).close('}');
        }
    }
    const char* kSweepFields[][2] = {{"sweep.key0", "columns' field"}, {"sweep.val0", "columns' values"},
                                     {"sweep.key1", "rows' field"}, {"sweep.val1", "rows' values"}};
    for (const auto& [path, label] : kSweepFields) {
        if (facts.sweep) {
            w.open('{').key("path").str(path).key("label").str(label).key("kind").str("text").key("help");
            w.str("a field's path, or its values separated by commas").key("unit").str("");
            w.key("value").str(*toolField(path, facts)).close('}');
        }
    }
    w.close(']').key("buttons").open('[');
    for (Command c : {Command::ToggleShaderEditor, Command::CompileShaders, Command::RevertShaders, Command::ToggleSweep,
                      Command::SaveSweep, Command::Screenshot}) {
        if ((c != Command::CompileShaders && c != Command::RevertShaders) || facts.shader) {
            button(w, c);
        }
    }
    w.close(']').key("log").str(facts.shader ? join(facts.shader->log) : facts.sweep ? facts.sweep->error : "");
    const ui::ShareCodeModel* share = facts.share;
    w.key("link").str(share ? share->link : "");
    w.key("linkProblem").str(share && !share->code ? printable(share->problem, true) : "").close('}');
}

} // namespace

const std::string& PageModel::json(Workspace& ws, const PageFacts& facts) {
    Writer w;
    w.open('{').key("title").str(printable(ws.document().displayName(), true)).key("tabs").open('[');
    for (const auto& tab : kTabs) {
        w.open('{').key("id").str(tab[0]).key("label").str(tab[1]).close('}');
    }
    w.close(']').key("sections").open('[');
    fileSections(w, ws, facts.exercise, facts.motion);
    fieldSections(w, ws.edited(), ws.exercise() ? &ws.exercise()->exercise : nullptr);
    toolSections(w, facts);
    w.close(']');
    if (const ui::ExercisePanelModel* e = facts.exercise) {
        w.key("exercise").open('{').key("title").str(e->title).key("instructions").str(e->instructions).key("hints").open('[');
        for (const std::string& h : e->hints) {
            w.str(h);
        }
        w.close(']').key("score").str(e->score).key("solved").flag(e->solved);
        buttons(w, {Command::ExerciseHint, Command::ExerciseReset, Command::ExerciseLeave});
        w.close('}');
    }
    // The dialog the canvas shows, as the page's alertdialog with its buttons (web/access.js dialog).
    if (!facts.problem.empty() || !facts.question.empty()) {
        const bool problem = !facts.problem.empty();
        w.key("dialog").open('{').key("title").str(problem ? "Error" : "Unsaved changes");
        w.key("text").str(problem ? facts.problem : facts.question);
        if (problem) {
            buttons(w, {Command::CloseProblem});
        } else {
            buttons(w, {Command::AnswerSaveFirst, Command::AnswerDiscard, Command::AnswerCancel});
        }
        w.close('}');
    }
    // The speaker's notes the canvas shows (S), as the page's region (web/access.js notes): a student
    // stepping through a deck with a screen reader reads them too.
    if (facts.notes) {
        w.key("notes").open('{').key("position").str(facts.notes->position).key("text").str(facts.notes->notes);
        w.key("next").str(facts.notes->next).close('}');
    }
    w.key("readouts").open('{').key("probe").str(facts.probe).key("legend").str(facts.legend);
    w.close('}').key("theme").str(facts.theme);
    w.key("messages").open('{').key("problem").str(facts.problem).key("said").open('[');
    for (const std::string& text : facts.news.said) {
        w.str(text);
    }
    w.close(']').key("refused").open('[');
    for (const PageRefusal& r : facts.news.refused) {
        w.open('{').key("path").str(printable(r.path, true)).key("message").str(r.message).close('}');
    }
    w.close(']').close('}');
    if (!described_ || *described_ != ws.a()) {
        described_ = ws.a();
        Writer words;
        pictures(words, ws.a());
        pictures_ = std::move(words.text);
    }
    json_ = std::move(w.text);
    json_ += ",\"pictures\":" + pictures_ + "}";
    return json_;
}

std::vector<PageRefusal> applyPageEdits(Workspace& ws, const std::vector<PageEdit>& edits, const PageFacts& tools,
                                        std::vector<Request>& requests) {
    std::vector<PageRefusal> refused;
    for (const PageEdit& e : edits) {
        if (e.path.empty() && e.command < 0) { // a field edit without a path: refused, said (not dropped)
            refused.push_back({e.path, setFieldFromText(ws.edited(), e.path, e.value)});
            continue;
        }
        if (e.path.empty()) {
            if (e.command > static_cast<int>(kLastCommand)) {
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
        if (std::string* field = toolField(e.path, tools)) {
            *field = e.value;
        } else if (ws.exercise() && !fieldIsOpen(ws.exercise()->exercise, path)) {
            problem = pathInMessage(path) + ": this exercise does not let you change it";
        } else {
            problem = setFieldFromText(ws.edited(), path, e.value);
        }
        if (!problem.empty()) {
            refused.push_back({e.path, std::move(problem)});
        }
    }
    return refused;
}

namespace {

// (The page's message log keeps 30 too.)
template <typename T>
void keepLast30(std::vector<T>& list, T item) {
    list.push_back(std::move(item));
    if (list.size() > 30) {
        list.erase(list.begin());
    }
}

} // namespace

void PageNews::say(std::string text) { keepLast30(said, std::move(text)); }
void PageNews::refuse(PageRefusal refusal) { keepLast30(refused, std::move(refusal)); }

std::vector<Request> takePageInput(Workspace& ws, const std::vector<PageEdit>& edits,
                                   const std::optional<std::string>& focus, const PageFacts& tools, ui::PanelState& panel,
                                   PageNews& news) {
    std::vector<Request> requests;
    std::string said;
    for (PageRefusal& r : applyPageEdits(ws, edits, tools, requests)) {
        said += (said.empty() ? "" : "\n") + r.message;
        news.refuse(std::move(r));
    }
    if (!said.empty()) {
        ws.note(said);
    }
    if (focus && ui::widgets().focus(*focus) && !focus->empty()) {
        panel.tab = panelTabOf(*focus, panel.selectedLight).value_or(panel.tab);
    }
    return requests;
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
