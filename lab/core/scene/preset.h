// preset.h — the scene as plain data, and its JSON file format ("lighting-lab-preset" v1).
//
// The preset is the scene: the renderer draws a Preset, `lab check` renders one, and the GUI
// edits one in place. There is no second copy of the state.
//
// This file owns: the Preset struct with the documented defaults, loading with full
// validation (every problem reported with its JSON path), and atomic saving of every key.
// It does not load meshes (mesh.h, core/gltf/model_loader.h) or touch GL.
#pragma once

#include "core/io/diagnostics.h"
#include "core/scene/file_header.h"
#include "core/scene/limits.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

inline constexpr std::string_view kPresetFormat = kPresetFile.format; // "lighting-lab-preset" (file_header.h)
inline constexpr int kPresetVersion = kPresetFile.version;
using limits::kMaxLights; // core/scene/limits.h holds every range a preset is validated against

enum class Builtin { Sphere, Cube, Plane, Torus };
enum class Shading { Flat, Gouraud, Phong };
enum class NormalMatrixMode { InverseTranspose, ModelView };
enum class BrdfModel { Phong, BlinnPhong, CookTorrance };
enum class Distribution { Beckmann, Gaussian, Ggx };
enum class FresnelMode { Schlick, Full };
enum class LightType { Point, Directional, Spot };

struct Model {
    // Exactly one source: a built-in (gltf empty) or a glTF path relative to the preset file.
    Builtin builtin = Builtin::Sphere;
    std::string gltf;
    glm::ivec2 subdivisions{64, 32}; // sphere [slices, stacks], plane [nx, nz], torus [major, minor], cube [n, n] per face
    glm::vec3 scale{1.0f};
    glm::vec3 rotateDeg{0.0f};
    glm::vec3 translate{0.0f};
    bool operator==(const Model&) const = default;
};

struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 4.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovyDeg = 45.0f;
    float near = 0.1f;
    float far = 100.0f;
    bool operator==(const Camera&) const = default;
};

struct CookTorrance {
    Distribution distribution = Distribution::Beckmann;
    float roughness = 0.3f;
    FresnelMode fresnel = FresnelMode::Schlick;
    float ior = 1.5f;
    bool geometry = true;
    bool operator==(const CookTorrance&) const = default;
};

struct MaterialDesc {
    glm::vec3 emissive{0.0f};
    glm::vec3 ambient{0.2f};
    glm::vec3 diffuse{0.8f};
    glm::vec3 specular{1.0f};
    float shininess = 32.0f;
    bool operator==(const MaterialDesc&) const = default;
};

// A light that moves by itself (core/scene/light_orbit.h): it circles the axis through the model's
// centre at a constant speed, starting from the preset's position (and direction). Only the live
// view moves; screenshots, `lab render` and `lab check` show the preset's position.
struct LightOrbit {
    bool on = false;
    glm::vec3 axis{0.0f, 1.0f, 0.0f}; // at least kMinDirectionLength long (it is normalized)
    float degreesPerSecond = 30.0f;   // limits::kOrbitSpeed; negative turns the other way
    bool operator==(const LightOrbit&) const = default;
};

struct LightDesc {
    LightType type = LightType::Point;
    glm::vec3 position{2.0f, 2.0f, 2.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};
    glm::vec3 ambient{0.0f};
    glm::vec3 diffuse{1.0f};
    glm::vec3 specular{1.0f};
    glm::vec3 attenuation{1.0f, 0.0f, 0.0f}; // c0, c1, c2
    float cutoffDeg = 30.0f;
    float exponent = 8.0f;
    bool enabled = true;
    LightOrbit orbit = {}; // saved only when it differs from the defaults
    bool operator==(const LightDesc&) const = default;
};

struct TermSwitches {
    bool emissive = true;
    bool ambient = true;
    bool diffuse = true;
    bool specular = true;
    bool operator==(const TermSwitches&) const = default;
};

// How `lab check` compares this preset (its optional `check` block, limits.h's ranges): each
// tolerance given replaces the command line's for this preset's render, sweep cells and plot.
// Saved only when given. It changes no picture.
// A view `lab check` renders too (core/scene/view_mode.h), against <name>.<view>.png (and
// <name>.<view>.light<N>.png for a light other than the first): written "d", or
// {"view": "spot", "light": 2}. The name is checked when read; whether the view applies to the
// preset (its BRDF, its lights) where it is checked, as for `sweep`.
struct CheckView {
    std::string view;
    int light = 1; // from 1
    bool operator==(const CheckView&) const = default;
};

struct CheckSettings {
    std::optional<int> pixelTolerance;  // pixel_tolerance
    std::optional<float> maxFailing;    // max_failing (a share: 0.001 is 0.1%)
    std::optional<float> maxMean;       // max_mean (levels)
    std::optional<float> plotTolerance; // plot_tolerance (absolute, for the lobe CSV)
    std::vector<CheckView> views;       // views
    bool empty() const { return !pixelTolerance && !maxFailing && !maxMean && !plotTolerance && views.empty(); }
    bool operator==(const CheckSettings&) const = default;
};

// How the lab first shows the preset (its optional `display` block): the view, the factor view's
// light, compare mode, the wipe and the wireframe. Opening the preset or a deck's slide sets the
// lab's display to this; what it leaves out is the default (the lit model, no wipe, no wireframe;
// compare mode when the preset has `compare`). `lab render` draws its view and compare mode. The
// view's name is checked when read; whether it applies to the preset where it is shown.
// The plots window's tabs as `display.plots` names them, in the window's order (ui/plots/plots.h).
inline constexpr std::string_view kPlotTabNames[] = {"plane", "lobe3d", "energy", "slice"};

struct OpeningDisplay {
    std::string view;             // a view_mode.h name; "" the lit model
    int light = 1;                // the factor view's light, from 1
    std::optional<bool> compare;  // none: compare mode when the preset has `compare`
    bool wipe = false;
    bool wireframe = false;
    std::string plots;            // a kPlotTabNames name; "": the tab stays as it is
    bool empty() const { return view.empty() && light == 1 && !compare && !wipe && !wireframe && plots.empty(); }
    bool operator==(const OpeningDisplay&) const = default;
};

struct Preset {
    std::string name = "Untitled";
    std::string description;
    Model model;
    Camera camera;
    Shading shading = Shading::Phong;
    NormalMatrixMode normalMatrix = NormalMatrixMode::InverseTranspose;
    BrdfModel brdf = BrdfModel::Phong;
    CookTorrance cookTorrance;
    MaterialDesc material;
    glm::vec3 ambientLight{0.1f};
    std::vector<LightDesc> lights{LightDesc{}};
    TermSwitches terms;
    glm::vec3 background{0.05f, 0.05f, 0.08f};
    float plotIncidentDeg = 45.0f;
    CheckSettings check;            // `check`, only when given
    std::vector<std::string> sweep; // `sweep`: one or two `lab render --sweep` arguments as typed
                                    // ("material.shininess=10,20,50"), checked by core/scene/sweep.h;
                                    // `lab check` compares the grid with <name>.sweep.png
    // For the lecture, each only when given (none of them changes set A's picture):
    OpeningDisplay display; // `display`: how the lab first shows it
    std::string notes;      // `notes`: the speaker's notes (the notes window, a deck's slide)
    // `compare`: a prepared comparison, set B as a patch of this preset's fields (the share link's
    // grammar, core/exercise/preset_fields.h mergePreset: objects key by key, lights element by
    // element), kept as its minified JSON text ("" none); comparedPreset() makes B of it.
    std::string compare;
    bool operator==(const Preset&) const = default;
};

// Default subdivisions of each built-in when the preset does not give them.
glm::ivec2 defaultSubdivisions(Builtin builtin);

// The keys a preset file left out whose defaults only suit a unit-size model. A glTF model in
// a file without `camera` is framed, and without `lights` either it is lit relative to its
// bounds (frameOmitted, core/gltf/model_loader.h), by whoever meets the preset with its mesh. That
// consumer clears these: from then on the preset holds an ordinary camera and lights.
struct OmittedKeys {
    bool camera = false;
    bool lights = false;
    bool operator==(const OmittedKeys&) const = default;
};

// A preset together with where it came from; the folder is what glTF paths are relative to.
struct LoadedPreset {
    Preset preset;
    std::filesystem::path file; // empty when parsed from memory
    OmittedKeys omitted = {};   // what the file left out (all false once framed)
    std::filesystem::path folder() const { return file.empty() ? std::filesystem::path{} : file.parent_path(); }
};

// Parses and validates preset JSON text. `displayName` prefixes every diagnostic ("red.json").
// `folder`, when given, is where a glTF model path is resolved and must stay inside; when
// absent, a glTF model is refused (nothing to resolve it against). `omitted`, when given,
// receives which of `camera` and `lights` the text left out.
std::optional<Preset> parsePreset(std::string_view text, const std::string& displayName,
                                  const std::optional<std::filesystem::path>& folder,
                                  Diagnostics& diagnostics, OmittedKeys* omitted = nullptr);

// An inline preset (an exercise's `start` and `target`, a link's scene): the JSON text of one
// object, read as a file's, each diagnostic's path under `where` ("start.material.shininess").
// "format" and "version" may be left out (those of the file around it hold); given, they are checked.
std::optional<Preset> parseInlinePreset(std::string_view objectText, const std::string& displayName,
                                        const std::string& where, const std::optional<std::filesystem::path>& folder,
                                        Diagnostics& diagnostics, OmittedKeys* omitted = nullptr);

// Set B of a preset with `compare`: `preset` (its display, notes and compare left out) with the
// patch applied, validated as the file was when it was read (a glTF path against `folder`); the
// preset itself when it has no `compare`. Diagnostics name "compare.<path>".
std::optional<Preset> comparedPreset(const Preset& preset, const std::optional<std::filesystem::path>& folder,
                                     Diagnostics& diagnostics);

// Reads, parses and validates a preset file (at most kMaxPresetBytes).
std::optional<LoadedPreset> loadPreset(const std::filesystem::path& file, Diagnostics& diagnostics);

// The preset as JSON text with every key, in the documented order. Never writes non-finite values.
std::string presetToJson(const Preset& preset);

// Writes presetToJson(preset) atomically (temporary file, flush, rename); refuses, writing nothing,
// a preset with non-finite numbers or one whose text would be over kMaxPresetBytes (no reader
// would open it).
bool savePreset(const Preset& preset, const std::filesystem::path& file, Diagnostics& diagnostics);

// Resolves a preset's glTF path against its folder, refusing absolute paths, paths that leave
// the folder (symbolic links included) and anything that is not an existing regular file.
std::optional<std::filesystem::path> resolveModelPath(const std::string& gltf,
                                                      const std::filesystem::path& folder,
                                                      std::string& error);

inline constexpr std::size_t kMaxPresetBytes = 1u << 20;

// Names as they appear in preset files, shared by the loader, the saver, the CLI and the GUI.
std::string_view toString(Builtin v);
std::string_view toString(Shading v);
std::string_view toString(NormalMatrixMode v);
std::string_view toString(BrdfModel v);
std::string_view toString(Distribution v);
std::string_view toString(FresnelMode v);
std::string_view toString(LightType v);

} // namespace lab
