// workspace_models.cpp — the workspace's models: A's and B's meshes looked up through the one
// cache, a glTF file made A's model, and the opens that wait for a file of the page's site (a
// bundled model, fetched the first time a preset names it: core/io/site_files.h).
#include "app/workspace.h"

#include "core/gltf/model_loader.h"
#include "core/io/paths.h"
#include "core/io/site_files.h"
#include "core/scene/camera.h"

namespace lab {

namespace fs = std::filesystem;

void Workspace::useModel(const fs::path& path) {
    waiting_.reset();
    std::error_code ec;
    if (waitsFor(fs::weakly_canonical(path, ec), "Cannot load the model", [this, path] { useModel(path); })) {
        return;
    }
    if (!fs::is_regular_file(path, ec)) {
        problem("Cannot load the model", path.string() + ": no such file");
        return;
    }
    // What the lights were placed for (before the folder may change): the built-ins fit the unit sphere.
    auto boundsOf = [this](Side side, const Preset& p) {
        std::shared_ptr<const Mesh> m = this->mesh(side);
        return (m ? drawnBounds(*m, p.model) : std::nullopt).value_or(Sphere{});
    };
    Sphere oldBounds = boundsOf(Side::A, doc_.preset), oldBoundsB = boundsOf(Side::B, doc_.compare);
    if (doc_.file().empty() && !doc_.dirty()) {
        doc_.setFolder(canonicalFolder(path.parent_path())); // an untitled scene adopts the model's folder
    }
    std::optional<fs::path> relative = relativeInside(doc_.folder(), path);
    if (!relative) {
        problem("Cannot use " + path.filename().string(),
                "the model is outside this preset's folder " + canonicalFolder(doc_.folder()).string() +
                    ". Save the preset next to the model first (Save as), or copy the model into that folder.");
        return;
    }
    Model candidate = doc_.preset.model;
    candidate.gltf = relative->generic_string();
    Diagnostics d;
    std::vector<std::string> notes;
    if (!meshes_.get(candidate, doc_.folder(), d, &notes)) {
        problem("Cannot load " + path.filename().string() + " (nothing was changed)", std::move(d));
        return;
    }
    // The model, the camera and the lights change in one frame: one undo step.
    doc_.preset.model = candidate;
    std::shared_ptr<const Mesh> mesh = this->mesh(Side::A);
    if (auto drawn = mesh ? drawnPositions(*mesh, doc_.preset.model) : std::nullopt) {
        doc_.preset.camera = framedCamera(Camera{}, *drawn, threeQuarterDirection());
    }
    if (std::optional<Sphere> bounds = mesh ? drawnBounds(*mesh, doc_.preset.model) : std::nullopt) {
        carryLights(doc_.preset.lights, oldBounds, *bounds);
        if (view.compare) { // B compares settings on the same model: it takes the model, its lights move alike
            doc_.compare.model = doc_.preset.model;
            carryLights(doc_.compare.lights, oldBoundsB, *bounds);
        }
    }
    notes_.push_back(notes.empty() ? "Model " + candidate.gltf : notes.front());
}

// A's camera moved to show all of A's model, looking the way it looks now (B follows A's camera).
void Workspace::frameModel() {
    std::shared_ptr<const Mesh> mesh = this->mesh(Side::A);
    if (auto drawn = mesh ? drawnPositions(*mesh, doc_.preset.model) : std::nullopt) {
        doc_.preset.camera = framedCamera(doc_.preset.camera, *drawn);
    }
}

// The mesh of `model`; looked up only when the model or the folder changed since `resolved`.
// A model that cannot load goes back to the last one that did, with a problem. (A bundled model
// the page has not fetched yet cannot be here: every open waits for it, waitsFor below.)
std::shared_ptr<const Mesh> Workspace::resolve(Model& model, Resolved& resolved, const char* which) {
    fs::path folder = doc_.folder();
    if (resolved.mesh && model == resolved.model && folder == resolved.folder) {
        return resolved.mesh; // the common frame: nothing to look up
    }
    Diagnostics d;
    std::vector<std::string> notes;
    if (std::shared_ptr<const Mesh> mesh = meshes_.get(model, folder, d, &notes)) {
        notes_.insert(notes_.end(), notes.begin(), notes.end());
        resolved = {model, folder, std::move(mesh)};
        return resolved.mesh;
    }
    problem(std::string("Cannot load ") + which, std::move(d));
    if (resolved.mesh) {
        model = resolved.model;
        return resolved.mesh;
    }
    Diagnostics ignored; // nothing loaded yet: fall back to the default built-in
    model = Model{};
    resolved = {model, folder, meshes_.get(model, folder, ignored)};
    return resolved.mesh;
}

// A file of the page's site that is not here yet (core/io/site_files.h) is fetched, and `again`
// waits for it (resumeWaiting): true while it waits. Anything else (a file on disk, one that does
// not exist) is the loader's to report.
bool Workspace::waitsFor(const fs::path& file, std::string title, std::function<void()> again) {
    SiteFile state = siteFile(file);
    if (state == SiteFile::Here) {
        return false;
    }
    fetchSiteFile(file); // (a failure told to no one is fetched again)
    notes_.push_back("Loading " + file.filename().string() + "…");
    waiting_ = Waiting{file, std::move(title), std::move(again)};
    return true;
}

bool Workspace::waitsFor(const Model& model, const fs::path& folder, std::string title, std::function<void()> again) {
    std::string error;
    std::optional<fs::path> file = model.gltf.empty() ? std::nullopt : resolveModelPath(model.gltf, folder, error);
    return file && waitsFor(*file, std::move(title), std::move(again));
}

void Workspace::resumeWaiting() {
    std::string why;
    SiteFile state = waiting_ ? siteFile(waiting_->file, &why) : SiteFile::Fetching;
    if (state == SiteFile::Fetching) {
        return;
    }
    Waiting w = std::move(*std::exchange(waiting_, std::nullopt));
    if (state == SiteFile::Failed) {
        problem(std::move(w.title),
                Diagnostics{{w.file.filename().string(), "", "could not be fetched from the page's site: " + why}});
        return;
    }
    w.again();
}

std::shared_ptr<const Mesh> Workspace::mesh(Side side) {
    return resolve(preset(side).model, resolved_[indexOf(side)], side == Side::A ? "the model" : "B's model");
}

} // namespace lab
