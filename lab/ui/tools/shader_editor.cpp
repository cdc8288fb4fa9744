// shader_editor.cpp — the shader editor window: one tab per editable file, each a text box
// with a line-number gutter beside it, and the log of the last compile below.
//
// ImGui 1.86's InputTextMultiline has no line numbers and scrolls inside its own child window,
// where the gutter cannot follow it. So each tab is one scrolling child window holding the
// gutter and a text box tall enough for all of its text: the text box never scrolls, the child
// scrolls both, and the child follows the text cursor when it moves or the text changes.
#include "ui/tools/shader_editor.h"

#include "ui/widgets.h"

#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace lab::ui {

namespace {

constexpr const char* kFiles[] = {"lit.frag", "lit.vert", "lighting.glsl", "lighting_api.glsl"};

const ImU32 kErrorBand = IM_COL32(200, 40, 40, 110);
const ImU32 kErrorNumber = IM_COL32(255, 110, 100, 255);
const ImU32 kNumber = IM_COL32(130, 130, 140, 255);

struct Tab {
    const char* file;  // the file name, as the log names it
    const char* id;    // the text box's ImGui id and the child window's
    const char* mark;  // the widget name for the GUI tests
    std::string* text;
};

int lineCount(const std::string& text) { return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// The line (0-based) the text cursor is on, from InputText's callback.
int cursorCallback(ImGuiInputTextCallbackData* data) {
    const char* begin = data->Buf;
    *static_cast<int*>(data->UserData) = static_cast<int>(std::count(begin, begin + data->CursorPos, '\n'));
    return 0;
}

// One tab's text with the gutter: line numbers, and a red band on the lines the log names.
void editorWithGutter(ShaderEditorState& s, int index, const Tab& tab, const std::vector<int>& marked, float height) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float lineHeight = ImGui::GetFontSize(); // InputText advances one font size per line
    const int lines = lineCount(*tab.text);
    char digits[16];
    std::snprintf(digits, sizeof digits, " %d ", std::max(lines, 100));
    const float gutter = ImGui::CalcTextSize(digits).x;

    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::BeginChild(tab.id, ImVec2(-1, height), true);
    ImGui::PopStyleVar();
    const float visible = ImGui::GetWindowHeight();
    const float scroll = ImGui::GetScrollY();
    const ImVec2 origin = ImGui::GetCursorScreenPos(); // the top of the text box, scrolled
    const float textTop = style.FramePadding.y;         // line 0's top inside the text box

    // Tall enough never to scroll itself (one spare line for the frame a new line is typed in).
    float boxHeight = std::max(visible - style.ChildBorderSize * 2.0f, textTop * 3.0f + lineHeight * (lines + 1));
    ImGui::SetCursorPosX(gutter);
    int cursor = -1;
    std::string label = std::string("##") + tab.id;
    bool edited = ImGui::InputTextMultiline(label.c_str(), tab.text, ImVec2(-1, boxHeight),
                                            ImGuiInputTextFlags_AllowTabInput | ImGuiInputTextFlags_CallbackAlways,
                                            cursorCallback, &cursor);
    // Follow the cursor when it moves to another line or the text changes, not otherwise, so
    // the wheel can scroll away from it.
    if (ImGui::IsItemActive() && cursor >= 0 && (edited || cursor != s.cursorLine[index])) {
        float top = textTop + cursor * lineHeight;
        if (top < scroll) {
            ImGui::SetScrollY(std::max(0.0f, top - lineHeight));
        } else if (top + lineHeight > scroll + visible) {
            ImGui::SetScrollY(top + 2.0f * lineHeight - visible);
        }
        s.cursorLine[index] = cursor;
    }
    if (s.jumpLine > 0 && s.jumpFile == tab.file) {
        ImGui::SetScrollY(std::max(0.0f, textTop + (s.jumpLine - 1) * lineHeight - visible / 3.0f));
        s.jumpLine = 0;
        s.jumpFile.clear();
    }

    // The gutter, drawn over the rows that show.
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float right = origin.x + gutter - ImGui::CalcTextSize(" ").x;
    const float width = ImGui::GetWindowWidth();
    int first = std::max(0, static_cast<int>((scroll - textTop) / lineHeight) - 1);
    int last = std::min(lines, static_cast<int>((scroll + visible - textTop) / lineHeight) + 1);
    for (int i = first; i < last; ++i) {
        float y = origin.y + textTop + i * lineHeight;
        bool failing = std::binary_search(marked.begin(), marked.end(), i + 1);
        if (failing) {
            // The band shows through the text box's translucent frame too.
            dl->AddRectFilled(ImVec2(origin.x, y), ImVec2(origin.x + width, y + lineHeight), kErrorBand);
        }
        char number[16];
        std::snprintf(number, sizeof number, "%d", i + 1);
        dl->AddText(ImVec2(right - ImGui::CalcTextSize(number).x, y), failing ? kErrorNumber : kNumber, number);
    }
    ImGui::EndChild();
    mark(tab.mark);
}

} // namespace

std::optional<LogPlace> logPlace(std::string_view line) {
    std::optional<LogPlace> best;
    std::size_t bestAt = std::string_view::npos;
    for (std::string_view file : kFiles) {
        for (std::size_t at = line.find(file); at != std::string_view::npos; at = line.find(file, at + 1)) {
            std::size_t colon = at + file.size();
            // Not inside a longer name ("my_lit.frag"), followed by ":" and digits.
            bool alone = at == 0 || !(std::isalnum(static_cast<unsigned char>(line[at - 1])) || line[at - 1] == '_');
            if (!alone || colon + 1 >= line.size() || line[colon] != ':' ||
                !std::isdigit(static_cast<unsigned char>(line[colon + 1]))) {
                continue;
            }
            if (at < bestAt) {
                int number = 0;
                for (std::size_t k = colon + 1; k < line.size() && std::isdigit(static_cast<unsigned char>(line[k])); ++k) {
                    number = std::min(number * 10 + (line[k] - '0'), 1'000'000'000);
                }
                best = LogPlace{std::string(file), number};
                bestAt = at;
            }
            break;
        }
    }
    return best;
}

std::vector<int> linesNamed(const std::vector<std::string>& log, std::string_view file) {
    std::vector<int> lines;
    for (const std::string& line : log) {
        if (std::optional<LogPlace> p = logPlace(line); p && p->file == file && p->line > 0) {
            lines.push_back(p->line);
        }
    }
    std::sort(lines.begin(), lines.end());
    lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
    return lines;
}

void shaderEditorWindow(ShaderEditorState& s, std::vector<Request>& requests, std::string_view lightingSource) {
    if (!s.open) {
        return;
    }
    if (s.lighting.empty()) {
        s.lighting = lightingSource;
    }
    nextToolWindow(46, 36, 0.9f);
    if (ImGui::Begin("Shader editor", &s.open)) {
        commandButton(Command::CompileShaders, requests);
        mark("shader.compile");
        ImGui::SameLine();
        commandButton(Command::RevertShaders, requests);
        ImGui::SameLine();
        ImGui::TextDisabled(s.customActive ? "running: edited shaders" : "running: built-in shaders");
        if (s.customLighting) {
            ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "lighting.glsl is edited: the plots and the probe use the built-in model");
        }

        if (s.log != s.shownLog) {
            s.shownLog = s.log;
            // A new failure shows its first place in an editable file, in that file's tab.
            for (const std::string& line : s.log) {
                std::optional<LogPlace> place = logPlace(line);
                if (s.lastCompileFailed && place && place->file != "lighting_api.glsl") {
                    s.jumpFile = place->file;
                    s.jumpLine = place->line;
                    break;
                }
            }
        }
        const float logHeight = s.log.empty() ? 0.0f : ImGui::GetTextLineHeightWithSpacing() * 7.0f;
        const Tab tabs[] = {{"lit.frag", "frag", "shader.fragment", &s.fragment},
                            {"lit.vert", "vert", "shader.vertex", &s.vertex},
                            {"lighting.glsl", "lighting", "shader.lighting", &s.lighting}};
        if (ImGui::BeginTabBar("files")) {
            for (int i = 0; i < 3; ++i) {
                const Tab& tab = tabs[i];
                std::vector<int> marked = s.lastCompileFailed ? linesNamed(s.log, tab.file) : std::vector<int>{};
                // The label changes, the id (after ###) does not.
                std::string label = std::string(tab.file) + (marked.empty() ? "" : "  (error)") + "###" + tab.id;
                ImGuiTabItemFlags flags = s.jumpLine > 0 && s.jumpFile == tab.file ? ImGuiTabItemFlags_SetSelected : 0;
                if (ImGui::BeginTabItem(label.c_str(), nullptr, flags)) {
                    float height = ImGui::GetContentRegionAvail().y - logHeight;
                    editorWithGutter(s, i, tab, marked, std::max(height, ImGui::GetFontSize() * 4));
                    ImGui::EndTabItem();
                }
            }
            ImGui::EndTabBar();
        }
        if (!s.log.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, s.lastCompileFailed ? IM_COL32(255, 120, 110, 255) : IM_COL32(140, 220, 140, 255));
            ImGui::BeginChild("log", ImVec2(-1, 0), true);
            for (const std::string& line : s.log) {
                ImGui::TextWrapped("%s", line.c_str());
                // A line that names an editable file's line jumps there when clicked.
                std::optional<LogPlace> place = logPlace(line);
                bool editable = place && place->file != "lighting_api.glsl";
                if (editable && ImGui::IsItemHovered()) {
                    ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
                    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
                        s.jumpFile = place->file;
                        s.jumpLine = place->line;
                    }
                }
            }
            ImGui::EndChild();
            mark("shader.log");
            ImGui::PopStyleColor();
        }
    }
    ImGui::End();
}

} // namespace lab::ui
