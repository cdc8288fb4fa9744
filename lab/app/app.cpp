// app.cpp — the frame: input, UI, actions, undo steps, then the 3D view.
#include "app/app.h"

#include "app/document.h"
#include "core/camera.h"
#include "core/file_io.h"
#include "core/image.h"
#include "core/link.h"
#include "core/model_loader.h"
#include "core/probe.h"
#include "render/renderer.h"
#include "render/shader.h"
#include "ui/panel.h"
#include "ui/plots.h"
#include "ui/tools.h"
#include "ui/widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <functional>

namespace lab {

namespace fs = std::filesystem;
using ui::keys::Enter;

namespace {

// A GpuMesh together with what it was made from.
struct CachedMesh {
    std::string key;
    std::unique_ptr<GpuMesh> mesh;
};

std::vector<fs::path> listPresets(const fs::path& folder) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
        if (e.is_regular_file(ec) && e.path().extension() == ".json") {
            files.push_back(e.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

// The preset as the per-term view shows it (the document itself is not changed).
Preset viewed(const Preset& p, ui::ViewMode mode) {
    Preset v = p;
    switch (mode) {
    case ui::ViewMode::Emissive: v.terms = {p.terms.emissive, false, false, false}; break;
    case ui::ViewMode::Ambient: v.terms = {false, p.terms.ambient, false, false}; break;
    case ui::ViewMode::Diffuse: v.terms = {false, false, p.terms.diffuse, false}; break;
    case ui::ViewMode::Specular: v.terms = {false, false, false, p.terms.specular}; break;
    default: break;
    }
    return v;
}

bool hasExtension(const fs::path& p, std::initializer_list<const char*> extensions) {
    std::string e = p.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return std::any_of(extensions.begin(), extensions.end(), [&](const char* x) { return e == x; });
}

} // namespace

struct App::Impl {
    AppOptions options;
    Document doc;
    Renderer renderer;
    std::vector<CachedMesh> meshes;
    // The document's model as last resolved to a mesh: reused while the model and folder stay the
    // same, and restored when a model edit cannot be loaded. Loading any mesh clears `mesh`, since
    // the cache may have evicted it.
    struct {
        Model model;
        fs::path folder;
        GpuMesh* mesh = nullptr;
    } current;

    Preset compareB;
    ui::PanelModel panel;
    ui::PlotSettings plots;
    ui::ShaderEditorState shaderEditor;
    bool showPanels = true, showHelp = false, presenter = false;
    float presenterScale = 1.75f;

    std::optional<ProbeResult> probe;
    bool probeOpen = false;

    std::string errorTitle;
    std::vector<std::string> errorLines;
    bool errorPending = false;
    std::function<void()> pending; // waits for "discard unsaved changes?"
    std::string pendingWhat;
    bool confirmPending = false;
    std::string toast;
    float toastLeft = 0.0f;

    enum class Drag { None, Orbit, Pan, Light } drag = Drag::None;
    bool pressMoved = false;
    ImVec2 pressPos;
    int dragLight = -1;
    float frameMs = 0.0f;
    ui::Rect view{}, viewA{}, viewB{};
    unsigned long long frames = 0;
    int screenshots = 0;

    //------------------------------------------------------------------------------------
    // Errors and messages
    //------------------------------------------------------------------------------------

    void showError(std::string title, const Diagnostics& diagnostics) {
        errorTitle = std::move(title);
        errorLines.clear();
        for (const Diagnostic& d : diagnostics) {
            errorLines.push_back(d.str());
        }
        errorPending = true;
    }

    void showError(std::string title, std::string line) { showError(std::move(title), Diagnostics{{"", "", std::move(line)}}); }

    void say(std::string message) {
        toast = std::move(message);
        toastLeft = 4.0f;
    }

    // Runs `action` now, or after the user agrees to drop unsaved edits.
    void whenChangesAreSafe(std::string what, std::function<void()> action) {
        doc.commit(false);
        if (!doc.dirty()) {
            action();
            return;
        }
        pending = std::move(action);
        pendingWhat = std::move(what);
        confirmPending = true;
    }

    //------------------------------------------------------------------------------------
    // Meshes
    //------------------------------------------------------------------------------------

    // The GPU mesh of `model`, loading it if needed; nullptr (with diagnostics) if it cannot be.
    GpuMesh* meshFor(const Model& model, const fs::path& folder, Diagnostics& diagnostics) {
        std::string key = modelCacheKey(model, folder);
        for (CachedMesh& m : meshes) {
            if (m.key == key) {
                return m.mesh.get();
            }
        }
        std::vector<std::string> notes;
        std::optional<Mesh> mesh = loadModel(model, folder, diagnostics, &notes);
        if (!mesh) {
            return nullptr;
        }
        if (!notes.empty()) {
            say(notes.front());
        }
        current.mesh = nullptr;
        if (meshes.size() >= 6) {
            meshes.erase(meshes.begin());
        }
        meshes.push_back({key, std::make_unique<GpuMesh>(std::move(*mesh))});
        return meshes.back().mesh.get();
    }

    // The mesh of the document's model; a model edit that cannot load is undone with an error.
    GpuMesh* documentMesh() {
        if (current.mesh && doc.preset.model == current.model && doc.folder() == current.folder) {
            return current.mesh; // the common frame: nothing to look up
        }
        Diagnostics d;
        if (GpuMesh* m = meshFor(doc.preset.model, doc.folder(), d)) {
            current.model = doc.preset.model;
            current.folder = doc.folder();
            current.mesh = m;
            return m;
        }
        showError("Cannot load the model", d);
        doc.preset.model = current.model;
        current.mesh = meshFor(current.model, current.folder, d);
        return current.mesh;
    }

    //------------------------------------------------------------------------------------
    // Files
    //------------------------------------------------------------------------------------

    void refreshPresetList() {
        panel.presetFiles.clear();
        std::vector<fs::path> folders;
        if (!doc.file().empty()) {
            folders.push_back(doc.folder());
        }
        folders.insert(folders.end(), options.presetFolders.begin(), options.presetFolders.end());
        for (const fs::path& f : folders) {
            std::error_code ec;
            if (fs::is_directory(f, ec)) {
                panel.presetFiles = listPresets(f);
                if (!panel.presetFiles.empty()) {
                    break;
                }
            }
        }
        panel.currentPreset = -1;
        std::error_code ec;
        for (std::size_t i = 0; i < panel.presetFiles.size(); ++i) {
            if (!doc.file().empty() && fs::equivalent(panel.presetFiles[i], doc.file(), ec)) {
                panel.currentPreset = static_cast<int>(i);
            }
        }
    }

    // Loads and checks everything first; the scene changes only when all of it worked.
    void openPreset(const fs::path& file) {
        Diagnostics d;
        std::optional<LoadedPreset> loaded = loadPreset(file, d);
        if (!loaded) {
            showError("Cannot open " + file.filename().string() + " (nothing was changed)", d);
            return;
        }
        if (!meshFor(loaded->preset.model, loaded->folder(), d)) {
            showError("Cannot load the model of " + file.filename().string() + " (nothing was changed)", d);
            return;
        }
        whenChangesAreSafe("open " + file.filename().string(), [this, loaded = std::move(*loaded)]() {
            doc.reset(loaded.preset, loaded.file);
            compareB = doc.preset;
            probe.reset();
            refreshPresetList();
            say("Opened " + loaded.file.string());
        });
    }

    void stepPreset(int delta) {
        if (panel.presetFiles.empty()) {
            return;
        }
        int n = static_cast<int>(panel.presetFiles.size());
        int next = panel.currentPreset < 0 ? (delta > 0 ? 0 : n - 1) : (panel.currentPreset + delta + n) % n;
        openPreset(panel.presetFiles[static_cast<std::size_t>(next)]);
    }

    bool saveTo(const fs::path& file) {
        doc.commit(false);
        Preset toSave = doc.preset;
        if (!toSave.model.gltf.empty()) {
            // glTF paths are relative to the preset: rebase them onto the new folder.
            std::error_code ec;
            fs::path model = fs::weakly_canonical(doc.folder() / toSave.model.gltf, ec);
            fs::path folder = fs::weakly_canonical(file.parent_path().empty() ? fs::path(".") : file.parent_path(), ec);
            fs::path relative = model.lexically_relative(folder);
            if (relative.empty() || *relative.begin() == "..") {
                showError("Cannot save " + file.string(),
                          "the model " + model.string() + " would be outside the preset's folder " + folder.string() +
                              "; save the preset in the model's folder or above it");
                return false;
            }
            toSave.model.gltf = relative.generic_string();
        }
        Diagnostics d;
        if (!savePreset(toSave, file, d)) {
            showError("Cannot save " + file.string() + " (the old file is unchanged)", d);
            return false;
        }
        doc.preset = toSave;
        doc.commit(false);
        doc.markSaved(file);
        refreshPresetList();
        say("Saved " + file.string());
        return true;
    }

    void save() {
        if (options.saveByDownload) {
            download();
            return;
        }
        if (doc.file().empty()) {
            if (panel.saveAsPath.empty()) {
                showError("Nothing to save to", "this preset has no file yet: type a path in the \"Save as\" field");
                return;
            }
            saveTo(panel.saveAsPath);
            return;
        }
        saveTo(doc.file());
    }

    // A .gltf/.glb chosen by path or dropped: it becomes the model, relative to the preset.
    void useModel(const fs::path& path) {
        std::error_code ec;
        fs::path model = fs::weakly_canonical(fs::absolute(path, ec), ec);
        if (!fs::is_regular_file(model, ec)) {
            showError("Cannot load the model", path.string() + ": no such file");
            return;
        }
        if (doc.file().empty() && !doc.dirty()) {
            doc.setFolder(model.parent_path()); // an untitled scene adopts the model's folder
        }
        fs::path folder = fs::weakly_canonical(doc.folder(), ec);
        fs::path relative = model.lexically_relative(folder);
        if (relative.empty() || *relative.begin() == "..") {
            showError("Cannot use " + model.filename().string(),
                      "the model is outside this preset's folder " + folder.string() +
                          ". Save the preset next to the model first (Save as), or copy the model into that folder.");
            return;
        }
        Model candidate = doc.preset.model;
        candidate.gltf = relative.generic_string();
        Diagnostics d;
        if (!meshFor(candidate, folder, d)) {
            showError("Cannot load " + model.filename().string() + " (nothing was changed)", d);
            return;
        }
        doc.preset.model = candidate;
        say("Model " + candidate.gltf);
    }

    void dropped(const std::vector<std::string>& files) {
        for (const std::string& f : files) {
            if (hasExtension(f, {".json"})) {
                openPreset(f);
            } else if (hasExtension(f, {".gltf", ".glb"})) {
                useModel(f);
            } else {
                showError("Cannot open " + fs::path(f).filename().string(),
                          "drop a preset (.json) or a glTF model (.gltf, .glb)");
            }
        }
    }

    //------------------------------------------------------------------------------------
    // Screenshots
    //------------------------------------------------------------------------------------

    void screenshot(int framebufferWidth, float windowWidth, unsigned targetFramebuffer) {
        float toPixels = static_cast<float>(framebufferWidth) / windowWidth;
        int w = std::max(1, static_cast<int>(view.w * toPixels)), h = std::max(1, static_cast<int>(view.h * toPixels));
        Framebuffer target(w, h);
        if (!target.complete()) {
            showError("Screenshot failed", "cannot create a " + std::to_string(w) + "x" + std::to_string(h) + " framebuffer");
            return;
        }
        target.bind();
        drawViews(toPixels, static_cast<float>(h) / toPixels, -view.x, -view.y);
        Image image = target.readRgb();
        bindFramebuffer(targetFramebuffer);
        std::string stem = doc.file().empty() ? "lab" : doc.file().stem().string();
        fs::path file;
        std::error_code ec;
        fs::create_directories(options.screenshotFolder, ec);
        do {
            char name[64];
            std::snprintf(name, sizeof name, "-%03d.png", ++screenshots);
            file = options.screenshotFolder / (stem + name);
        } while (fs::exists(file, ec));
        if (options.saveByDownload) {
            pendingDownloads.push_back({file.filename().string(), encodePng(image)});
            say("Screenshot " + file.filename().string() + " downloaded");
            return;
        }
        std::string error;
        if (!writePng(image, file, error)) {
            showError("Screenshot failed", error);
            return;
        }
        say("Screenshot " + file.string());
    }

    //------------------------------------------------------------------------------------
    // Links (the browser's URL fragment and saved state)
    //------------------------------------------------------------------------------------

    fs::path bundledFolder() const { return options.presetFolders.empty() ? fs::path(".") : options.presetFolders.front(); }

    void openLink(const std::string& fragment) {
        Diagnostics d;
        auto parsed = parseLink(fragment, bundledFolder(), d);
        if (!parsed) {
            showError("Cannot open the link (nothing was changed)", d);
            return;
        }
        if (auto* name = std::get_if<LinkedPresetName>(&*parsed)) {
            fs::path file = bundledFolder() / (name->name + ".json");
            std::error_code ec;
            if (!fs::is_regular_file(file, ec)) {
                showError("Cannot open the link (nothing was changed)", "there is no bundled preset \"" + name->name + "\"");
                return;
            }
            openPreset(file);
            return;
        }
        Preset preset = std::get<Preset>(*parsed);
        if (!meshFor(preset.model, bundledFolder(), d)) {
            showError("Cannot load the linked preset's model (nothing was changed)", d);
            return;
        }
        whenChangesAreSafe("open the link", [this, preset]() {
            doc.reset(preset, {}, bundledFolder());
            compareB = doc.preset;
            probe.reset();
            refreshPresetList();
        });
    }

    // The fragment for the current scene, recomputed only when the scene changed.
    const std::string& currentLink() {
        if (!linkValid || linkedPreset != doc.preset || linkedFile != doc.file()) {
            std::optional<std::string> bundled;
            std::error_code ec;
            if (!doc.dirty() && !doc.file().empty() && fs::equivalent(doc.folder(), bundledFolder(), ec)) {
                bundled = doc.file().stem().string();
            }
            link = presetLink(doc.preset, bundled);
            linkedPreset = doc.preset;
            linkedFile = doc.file();
            linkValid = true;
        }
        return link;
    }

    void download() {
        doc.commit(false);
        std::string stem = doc.file().empty() ? doc.preset.name : doc.file().stem().string();
        std::string name;
        for (char c : stem) {
            name += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '-';
        }
        pendingDownloads.push_back({(name.empty() ? "preset" : name) + ".json", presetToJson(doc.preset)});
        doc.markSaved(doc.file());
        say("Downloaded " + pendingDownloads.back().name);
    }

    std::vector<Download> pendingDownloads;
    std::string link;
    Preset linkedPreset;
    fs::path linkedFile;
    bool linkValid = false;

    //------------------------------------------------------------------------------------
    // The 3D view
    //------------------------------------------------------------------------------------

    // Draws A (and B in compare mode) at the views' rectangles, shifted by (dx, dy) window units,
    // into a framebuffer whose height is `windowHeight` window units.
    void drawViews(float toPixels, float windowHeight, float dx, float dy) {
        auto viewport = [&](const ui::Rect& r) {
            return Viewport{static_cast<int>((r.x + dx) * toPixels),
                            static_cast<int>((windowHeight - (r.y + dy + r.h)) * toPixels),
                            std::max(1, static_cast<int>(r.w * toPixels)), std::max(1, static_cast<int>(r.h * toPixels))};
        };
        DrawOptions drawOptions{panel.viewMode == ui::ViewMode::Normals};
        if (GpuMesh* mesh = documentMesh()) {
            renderer.draw(viewed(doc.preset, panel.viewMode), *mesh, viewport(panel.compare ? viewA : view), drawOptions);
        }
        if (panel.compare) {
            compareB.camera = doc.preset.camera;
            Diagnostics d;
            GpuMesh* meshB = meshFor(compareB.model, doc.folder(), d);
            if (!meshB) {
                showError("Cannot load B's model", d);
                compareB.model = doc.preset.model;
                meshB = documentMesh();
            }
            if (meshB) {
                renderer.draw(viewed(compareB, panel.viewMode), *meshB, viewport(viewB), drawOptions);
            }
        }
    }

    // Screen position (window units) of a world point in view rectangle r; nullopt behind the eye.
    std::optional<ImVec2> project(const glm::vec3& world, const ui::Rect& r) const {
        Transforms t = computeTransforms(doc.preset, r.w / r.h);
        glm::vec4 clip = t.projection * t.view * glm::vec4(world, 1.0f);
        if (clip.w <= 1e-4f) {
            return std::nullopt;
        }
        glm::vec3 ndc = glm::vec3(clip) / clip.w;
        return ImVec2(r.x + (ndc.x * 0.5f + 0.5f) * r.w, r.y + (0.5f - ndc.y * 0.5f) * r.h);
    }

    void lightMarkers(ImDrawList* dl) {
        const ui::Rect& r = panel.compare ? viewA : view;
        for (std::size_t i = 0; i < doc.preset.lights.size(); ++i) {
            const LightDesc& l = doc.preset.lights[i];
            if (l.type == LightType::Directional) {
                continue;
            }
            std::optional<ImVec2> at = project(l.position, r);
            if (!at || at->x < r.x || at->y < r.y || at->x > r.x + r.w || at->y > r.y + r.h) {
                continue; // behind the eye or outside the view
            }
            glm::vec3 c = glm::clamp(l.diffuse, glm::vec3(0.0f), glm::vec3(1.0f));
            ImU32 fill = l.enabled ? ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, 1.0f)) : IM_COL32(60, 60, 60, 255);
            float radius = 7.0f * ImGui::GetFontSize() / 13.0f;
            dl->AddCircleFilled(*at, radius, fill);
            dl->AddCircle(*at, radius + 1.5f, dragLight == static_cast<int>(i) ? IM_COL32(255, 255, 0, 255) : IM_COL32(255, 255, 255, 200), 0, 2.0f);
            char label[24];
            std::snprintf(label, sizeof label, "%zu", i + 1);
            dl->AddText(ImVec2(at->x + radius + 3, at->y - radius - 3), IM_COL32(255, 255, 255, 220), label);
            ui::widgets().set("view.light" + std::to_string(i + 1), {at->x - radius, at->y - radius, 2 * radius, 2 * radius});
        }
    }

    // Orbit, pan, zoom, light dragging and probing in the view.
    void viewInput() {
        ImGuiIO& io = ImGui::GetIO();
        const ui::Rect& r = panel.compare ? viewA : view;
        auto inside = [&](ImVec2 p, const ui::Rect& q) { return p.x >= q.x && p.y >= q.y && p.x < q.x + q.w && p.y < q.y + q.h; };
        bool hovered = !io.WantCaptureMouse && (inside(io.MousePos, view));
        if (hovered && io.MouseWheel != 0.0f) {
            zoomCamera(doc.preset.camera, std::pow(0.9f, io.MouseWheel));
        }
        if (hovered && drag == Drag::None && (ImGui::IsMouseClicked(0) || ImGui::IsMouseClicked(1))) {
            pressPos = io.MousePos;
            pressMoved = false;
            drag = ImGui::IsMouseClicked(1) ? Drag::Pan : Drag::Orbit;
            if (drag == Drag::Orbit) {
                float pick = 10.0f * ImGui::GetFontSize() / 13.0f;
                for (std::size_t i = 0; i < doc.preset.lights.size(); ++i) {
                    const LightDesc& l = doc.preset.lights[i];
                    std::optional<ImVec2> at = l.type == LightType::Directional ? std::nullopt : project(l.position, r);
                    if (at && std::hypot(at->x - io.MousePos.x, at->y - io.MousePos.y) < pick) {
                        drag = Drag::Light;
                        dragLight = static_cast<int>(i);
                    }
                }
            }
        }
        if (drag == Drag::None) {
            return;
        }
        ImVec2 delta = io.MouseDelta;
        if (std::hypot(io.MousePos.x - pressPos.x, io.MousePos.y - pressPos.y) > 3.0f) {
            pressMoved = true;
        }
        Camera& camera = doc.preset.camera;
        if (pressMoved && (delta.x != 0.0f || delta.y != 0.0f)) {
            if (drag == Drag::Orbit) {
                orbitCamera(camera, -delta.x * 0.35f, delta.y * 0.35f);
            } else if (drag == Drag::Pan) {
                panCamera(camera, delta.x / r.h, -delta.y / r.h);
            } else if (drag == Drag::Light && dragLight < static_cast<int>(doc.preset.lights.size())) {
                // In the plane through the light, parallel to the image.
                LightDesc& l = doc.preset.lights[static_cast<std::size_t>(dragLight)];
                glm::vec3 forward = glm::normalize(camera.target - camera.eye);
                glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
                glm::vec3 up = glm::cross(right, forward);
                float depth = glm::dot(l.position - camera.eye, forward);
                float perPixel = 2.0f * std::max(depth, 0.01f) * std::tan(glm::radians(camera.fovyDeg) / 2.0f) / r.h;
                l.position += (delta.x * right - delta.y * up) * perPixel;
            }
        }
        bool released = (drag == Drag::Pan) ? ImGui::IsMouseReleased(1) : ImGui::IsMouseReleased(0);
        if (released) {
            if (!pressMoved && drag == Drag::Orbit && inside(io.MousePos, r)) {
                probeAt(io.MousePos, r);
            }
            drag = Drag::None;
            dragLight = -1;
        }
    }

    void probeAt(ImVec2 mouse, const ui::Rect& r) {
        Diagnostics d;
        GpuMesh* mesh = meshFor(doc.preset.model, doc.folder(), d);
        if (!mesh) {
            return;
        }
        glm::vec2 ndc(2.0f * (mouse.x - r.x) / r.w - 1.0f, 1.0f - 2.0f * (mouse.y - r.y) / r.h);
        probe = probePixel(viewed(doc.preset, panel.viewMode), mesh->cpu(), ndc, r.w / r.h);
        probeOpen = probe.has_value();
        if (!probe) {
            say("No surface under the mouse");
        }
    }

    //------------------------------------------------------------------------------------
    // Shortcuts
    //------------------------------------------------------------------------------------

    void shortcuts(const std::vector<KeyPress>& keys, FrameOutput& out) {
        ImGuiIO& io = ImGui::GetIO();
        Preset& edit = panel.compare && panel.editingB ? compareB : doc.preset;
        for (const KeyPress& k : keys) {
            if (k.key == ui::keys::F1) {
                showHelp = !showHelp;
            } else if (k.key == ui::keys::F11) {
                out.toggleFullscreen = true;
            } else if (k.key == ui::keys::F12) {
                screenshotRequested = true;
            } else if (k.ctrl) {
                ctrlShortcut(k);
            } else if (!io.WantTextInput && !k.alt) {
                plainShortcut(k.key, edit);
            }
        }
    }

    void ctrlShortcut(const KeyPress& k) {
        ImGuiIO& io = ImGui::GetIO();
        switch (k.key) {
        case 'S':
            if (!k.shift) {
                save();
            } else if (!panel.saveAsPath.empty()) {
                saveTo(panel.saveAsPath);
            } else {
                showError("Save as", "type the new path in the \"Save as\" field, then press Enter");
            }
            break;
        case 'Z':
            if (!io.WantTextInput) {
                k.shift ? doc.redo() : doc.undo();
            }
            break;
        case 'Y':
            if (!io.WantTextInput) {
                doc.redo();
            }
            break;
        case 'O': focusOpenField = true; break;
        case 'E': shaderEditor.open = !shaderEditor.open; break;
        case ui::keys::Equal:
        case ui::keys::KeypadAdd:
            presenter = true;
            presenterScale = std::min(2.5f, presenterScale + 0.25f);
            break;
        case ui::keys::Minus:
        case ui::keys::KeypadSubtract: presenterScale = std::max(1.5f, presenterScale - 0.25f); break;
        default: break;
        }
    }

    void plainShortcut(int key, Preset& edit) {
        switch (key) {
        case ui::keys::Left: stepPreset(-1); break;
        case ui::keys::Right: stepPreset(+1); break;
        case '1': edit.shading = Shading::Flat; break;
        case '2': edit.shading = Shading::Gouraud; break;
        case '3': edit.shading = Shading::Phong; break;
        case 'B': edit.brdf = static_cast<BrdfModel>((static_cast<int>(edit.brdf) + 1) % 3); break;
        case 'M':
            edit.normalMatrix = edit.normalMatrix == NormalMatrixMode::InverseTranspose ? NormalMatrixMode::ModelView
                                                                                       : NormalMatrixMode::InverseTranspose;
            break;
        case 'V': panel.viewMode = static_cast<ui::ViewMode>((static_cast<int>(panel.viewMode) + 1) % 6); break;
        case 'C': toggleCompare(); break;
        case 'P': presenter = !presenter; break;
        case 'R': doc.preset.camera = doc.saved().camera; break;
        case ui::keys::Tab: showPanels = !showPanels; break;
        case ui::keys::Escape: showHelp = false; break;
        default: break;
        }
    }

    void toggleCompare() {
        panel.compare = !panel.compare;
        if (panel.compare) {
            compareB = doc.preset;
            // A useful first comparison: the other shading mode.
            compareB.shading = doc.preset.shading == Shading::Phong ? Shading::Gouraud : Shading::Phong;
        }
        panel.editingB = false;
    }

    bool screenshotRequested = false;
    bool focusOpenField = false;
    bool quitNow = false;
    bool compareStacked = false;

    //------------------------------------------------------------------------------------
    // Popups
    //------------------------------------------------------------------------------------

    void popups() {
        if (errorPending) {
            ImGui::OpenPopup("Error");
            errorPending = false;
        }
        ImGuiIO& io = ImGui::GetIO();
        ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.4f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
        ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(io.DisplaySize.x * 0.8f, io.DisplaySize.y * 0.8f));
        if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::TextUnformatted(errorTitle.c_str());
            ImGui::Separator();
            ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 150, 140, 255));
            for (const std::string& line : errorLines) {
                ImGui::TextUnformatted(line.c_str());
            }
            ImGui::PopStyleColor();
            ui::widgets().set("error", {ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowSize().x, ImGui::GetWindowSize().y});
            if (ImGui::Button("OK", ImVec2(120, 0)) || ImGui::IsKeyPressed(Enter, false) || ImGui::IsKeyPressed(ui::keys::Escape, false)) {
                ImGui::CloseCurrentPopup();
            }
            ui::mark("error.ok");
            ImGui::EndPopup();
        }
        if (confirmPending) {
            ImGui::OpenPopup("Unsaved changes");
            confirmPending = false;
        }
        ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.4f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
        if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::Text("%s has unsaved changes. Discard them to %s?", doc.displayName().c_str(), pendingWhat.c_str());
            if (ImGui::Button("Save first")) {
                ImGui::CloseCurrentPopup();
                if (!doc.file().empty() && saveTo(doc.file()) && pending) {
                    pending();
                }
                pending = nullptr;
            }
            ui::mark("confirm.save");
            ImGui::SameLine();
            if (ImGui::Button("Discard")) {
                ImGui::CloseCurrentPopup();
                if (pending) {
                    pending();
                }
                pending = nullptr;
            }
            ui::mark("confirm.discard");
            ImGui::SameLine();
            if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ui::keys::Escape, false)) {
                ImGui::CloseCurrentPopup();
                pending = nullptr;
            }
            ui::mark("confirm.cancel");
            ImGui::EndPopup();
        }
    }
};

App::App(AppOptions options) : impl_(std::make_unique<Impl>()) {
    impl_->options = std::move(options);
    impl_->presenter = impl_->options.presenter;
}

App::~App() = default;

bool App::init(Diagnostics& diagnostics) {
    Impl& m = *impl_;
    if (!m.renderer.init(diagnostics)) {
        return false;
    }
    m.doc.reset(Preset{}, {}, fs::current_path());
    m.doc.preset.name = "Default";
    m.doc.reset(m.doc.preset, {}, fs::current_path());
    m.compareB = m.doc.preset;
    m.current.model = m.doc.preset.model;
    m.current.folder = m.doc.folder();
    StageSources builtin = builtinStageSources();
    m.shaderEditor.vertex = builtin.vertex;
    m.shaderEditor.fragment = builtin.fragment;
    m.refreshPresetList();
    if (m.options.preset) {
        m.openPreset(*m.options.preset);
    }
    return true;
}

FrameOutput App::frame(const FrameInput& in) {
    Impl& m = *impl_;
    FrameOutput out;
    ui::widgets().clear();
    m.frameMs = m.frameMs == 0.0f ? in.deltaTime * 1000.0f : m.frameMs * 0.95f + in.deltaTime * 50.0f;

    if (!in.droppedFiles.empty()) {
        m.dropped(in.droppedFiles);
    }
    if (in.openLink && !in.openLink->empty()) {
        m.openLink(*in.openLink);
    }
    if (in.closeRequested) {
        m.whenChangesAreSafe("quit", [&m]() { m.quitNow = true; });
    }
    m.shortcuts(in.keys, out);

    //--- layout: panel | view | plots (plots below the view on narrow windows) ----------
    const float s = ImGui::GetFontSize() / 13.0f;
    const float W = in.windowWidth, H = in.windowHeight;
    float panelW = m.showPanels ? std::min(360.0f * s, W * 0.4f) : 0.0f;
    float plotsW = m.showPanels ? std::min(380.0f * s, W * 0.35f) : 0.0f;
    bool stacked = m.showPanels && W - panelW - plotsW < 420.0f * s;
    ui::Rect plotsRect{};
    if (!m.showPanels) {
        m.view = {0, 0, W, H};
    } else if (stacked) {
        float plotsH = std::max(H * 0.42f, 200.0f);
        m.view = {panelW, 0, W - panelW, H - plotsH};
        plotsRect = {panelW, H - plotsH, W - panelW, plotsH};
    } else {
        m.view = {panelW, 0, W - panelW - plotsW, H};
        plotsRect = {W - plotsW, 0, plotsW, H};
    }
    m.view.w = std::max(m.view.w, 1.0f);
    m.view.h = std::max(m.view.h, 1.0f);
    // Compare: side by side, or one above the other where halves side by side would be narrow
    // (the field of view is vertical, so a narrow half would crop the model).
    m.compareStacked = m.view.w * 0.5f < m.view.h * 0.8f;
    m.panel.compareStacked = m.compareStacked;
    if (m.compareStacked) {
        m.viewA = {m.view.x, m.view.y, m.view.w, m.view.h * 0.5f};
        m.viewB = {m.view.x, m.view.y + m.view.h * 0.5f, m.view.w, m.view.h * 0.5f};
    } else {
        m.viewA = {m.view.x, m.view.y, m.view.w * 0.5f, m.view.h};
        m.viewB = {m.view.x + m.view.w * 0.5f, m.view.y, m.view.w * 0.5f, m.view.h};
    }

    //--- the panels --------------------------------------------------------------------
    ui::PanelActions actions;
    const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
    m.panel.documentName = m.doc.displayName();
    m.panel.dirty = m.doc.dirty();
    m.panel.canUndo = m.doc.canUndo();
    m.panel.canRedo = m.doc.canRedo();
    m.panel.browser = m.options.saveByDownload;
    Preset& edited = m.panel.compare && m.panel.editingB ? m.compareB : m.doc.preset;
    if (m.showPanels) {
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(panelW, H));
        std::string title = "Lighting Lab###panel";
        ImGui::Begin(title.c_str(), nullptr, fixed);
        if (m.focusOpenField) {
            ImGui::SetKeyboardFocusHere(1);
        }
        ui::controlPanel(edited, m.panel, actions);
        ImGui::End();

        ImGui::SetNextWindowPos(ImVec2(plotsRect.x, plotsRect.y));
        ImGui::SetNextWindowSize(ImVec2(plotsRect.w, plotsRect.h));
        ImGui::Begin("Reflected intensity###plots", nullptr, fixed);
        ui::plotsPanel(m.doc.preset, m.panel.compare ? &m.compareB : nullptr, m.plots, m.probe ? &*m.probe : nullptr);
        ImGui::End();
        ui::widgets().set("plots", plotsRect);
        ui::widgets().set("panel", {0, 0, panelW, H});
    }
    m.focusOpenField = false;
    ui::widgets().set("view", m.view);

    //--- tools, popups ---------------------------------------------------------------------
    ui::helpWindow(m.showHelp);
    if (m.probe) {
        ui::probeWindow(*m.probe, m.doc.preset, m.probeOpen, m.view.x + 10.0f, m.view.y + ImGui::GetFontSize() * 2.5f);
    }
    ui::ShaderEditorActions shaderActions;
    ui::shaderEditorWindow(m.shaderEditor, shaderActions, shaderSource("lighting.glsl"));
    m.popups();

    //--- what the UI asked for -------------------------------------------------------------
    if (actions.openPreset) {
        m.openPreset(m.panel.presetFiles[static_cast<std::size_t>(*actions.openPreset)]);
    }
    if (actions.openPath) {
        m.openPreset(*actions.openPath);
    }
    if (actions.loadModel) {
        m.useModel(*actions.loadModel);
    }
    if (actions.save) {
        m.save();
    }
    if (actions.saveAs) {
        m.saveTo(*actions.saveAs);
    }
    if (actions.revert) {
        m.doc.revert();
    }
    if (actions.undo) {
        m.doc.undo();
    }
    if (actions.redo) {
        m.doc.redo();
    }
    if (actions.resetCamera) {
        m.doc.preset.camera = m.doc.saved().camera;
    }
    if (actions.toggleCompare) {
        m.toggleCompare();
    }
    if (actions.openShaderEditor) {
        m.shaderEditor.open = true;
    }
    if (actions.showHelp) {
        m.showHelp = true;
    }
    if (actions.screenshot) {
        m.screenshotRequested = true;
    }
    if (actions.download) {
        m.download();
    }
    out.pickFile = actions.pickFile;
    if (shaderActions.compile || shaderActions.revert) {
        StageSources sources = shaderActions.revert ? builtinStageSources()
                                                    : StageSources{m.shaderEditor.vertex, m.shaderEditor.fragment};
        Diagnostics d;
        m.shaderEditor.log.clear();
        if (m.renderer.setStageSources(sources, d)) {
            m.shaderEditor.lastCompileFailed = false;
            m.shaderEditor.customActive = !shaderActions.revert;
            m.shaderEditor.log.push_back(shaderActions.revert ? "Built-in shaders restored." : "Compiled: the edited shaders are running.");
            if (shaderActions.revert) {
                m.shaderEditor.vertex = sources.vertex;
                m.shaderEditor.fragment = sources.fragment;
            }
        } else {
            m.shaderEditor.lastCompileFailed = true;
            m.shaderEditor.log.push_back("Compile failed; the previous shaders keep running:");
            for (const Diagnostic& x : d) {
                m.shaderEditor.log.push_back(x.str());
            }
        }
    }

    //--- the view: input, markers, overlay text ----------------------------------------------
    m.viewInput();
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    m.lightMarkers(dl);
    char info[160];
    std::snprintf(info, sizeof info, "%.1f ms", m.frameMs);
    ImVec2 infoSize = ImGui::CalcTextSize(info);
    dl->AddText(ImVec2(m.view.x + m.view.w - infoSize.x - 8, m.view.y + 6), IM_COL32(255, 255, 255, 200), info);
    ui::widgets().set("view.frame-time", {m.view.x + m.view.w - infoSize.x - 8, m.view.y + 6, infoSize.x, infoSize.y});
    std::snprintf(info, sizeof info, "%s%s  |  %s  |  %s", m.doc.displayName().c_str(), m.doc.dirty() ? " *" : "",
                  std::string(toString(m.doc.preset.shading)).c_str(), std::string(toString(m.doc.preset.brdf)).c_str());
    dl->AddText(ImVec2(m.view.x + 8, m.view.y + 6), IM_COL32(255, 255, 255, 200), info);
    if (m.panel.viewMode != ui::ViewMode::Lit) {
        dl->AddText(ImVec2(m.view.x + 8, m.view.y + 6 + ImGui::GetFontSize() * 1.3f), IM_COL32(255, 220, 120, 230),
                    ui::toString(m.panel.viewMode));
    }
    if (m.panel.compare) {
        dl->AddLine(ImVec2(m.viewB.x, m.viewB.y), m.compareStacked ? ImVec2(m.viewB.x + m.viewB.w, m.viewB.y) : ImVec2(m.viewB.x, m.viewB.y + m.viewB.h),
                    IM_COL32(255, 255, 255, 160), 2.0f);
        float line = ImGui::GetFontSize() * 1.5f;
        std::string b = "B: " + std::string(toString(m.compareB.shading)) + ", " + std::string(toString(m.compareB.brdf));
        dl->AddText(ImVec2(m.viewB.x + 8, m.viewB.y + m.viewB.h - line), IM_COL32(230, 90, 220, 255), b.c_str());
        std::string a = "A: " + std::string(toString(m.doc.preset.shading)) + ", " + std::string(toString(m.doc.preset.brdf));
        dl->AddText(ImVec2(m.viewA.x + 8, m.viewA.y + m.viewA.h - line), IM_COL32(255, 255, 255, 230), a.c_str());
    }
    if (m.toastLeft > 0.0f) {
        m.toastLeft -= in.deltaTime;
        ImVec2 size = ImGui::CalcTextSize(m.toast.c_str());
        ImVec2 at(m.view.x + (m.view.w - size.x) * 0.5f, m.view.y + m.view.h - size.y * 3.0f);
        dl->AddRectFilled(ImVec2(at.x - 8, at.y - 4), ImVec2(at.x + size.x + 8, at.y + size.y + 4), IM_COL32(0, 0, 0, 180), 4.0f);
        dl->AddText(at, IM_COL32(255, 255, 255, 255), m.toast.c_str());
    }

    //--- one undo step per gesture -------------------------------------------------------------
    bool gesture = ImGui::IsAnyItemActive() || m.drag != Impl::Drag::None;
    m.doc.commit(gesture);

    //--- draw --------------------------------------------------------------------------------
    if (m.screenshotRequested) {
        m.screenshotRequested = false;
        m.screenshot(in.framebufferWidth, W, in.targetFramebuffer);
    }
    bindFramebuffer(in.targetFramebuffer);
    clearFramebuffer(glm::vec3(0.09f, 0.09f, 0.11f), in.framebufferWidth, in.framebufferHeight);
    m.drawViews(static_cast<float>(in.framebufferWidth) / W, H, 0.0f, 0.0f);

    if (m.options.layoutFile) {
        // Rewritten every frame: the frame number lets a test wait for its input to be seen.
        std::string layout = ui::widgets().text();
        char window[96];
        std::snprintf(window, sizeof window, "window 0 0 %.0f %.0f\nframe %llu\n", W, H, ++m.frames);
        layout += window;
        std::string error;
        writeFileAtomic(*m.options.layoutFile, layout, error);
    }
    out.quit = m.quitNow;
    out.link = m.currentLink();
    out.downloads.swap(m.pendingDownloads);
    out.uiScale = m.presenter ? m.presenterScale : 1.0f;
    out.title = "Lighting Lab - " + m.doc.displayName() + (m.doc.dirty() ? " *" : "");
    return out;
}

} // namespace lab
