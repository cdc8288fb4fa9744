// field_table.cpp — the rows of the preset's fields (field_table.h).
#include "core/scene/field_table.h"

#include "core/scene/field_path.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lab {

//----------------------------------------------------------------------------------------
// Choices
//----------------------------------------------------------------------------------------

namespace {

constexpr FieldChoice kBuiltins[] = {{int(Builtin::Sphere), "sphere", "sphere"},
                                     {int(Builtin::Cube), "cube", "cube"},
                                     {int(Builtin::Plane), "plane", "plane"},
                                     {int(Builtin::Torus), "torus", "torus"}};
constexpr FieldChoice kShadings[] = {{int(Shading::Flat), "flat", "flat"},
                                     {int(Shading::Gouraud), "gouraud", "Gouraud"},
                                     {int(Shading::Phong), "phong", "Phong"}};
constexpr FieldChoice kNormalMatrices[] = {
    {int(NormalMatrixMode::InverseTranspose), "inverse-transpose", "inverse-transpose (correct)"},
    {int(NormalMatrixMode::ModelView), "model-view", "model-view (wrong)"}};
constexpr FieldChoice kBrdfs[] = {{int(BrdfModel::Phong), "phong", "Phong"},
                                  {int(BrdfModel::BlinnPhong), "blinn-phong", "Blinn-Phong"},
                                  {int(BrdfModel::CookTorrance), "cook-torrance", "Cook-Torrance"}};
constexpr FieldChoice kDistributions[] = {{int(Distribution::Beckmann), "beckmann", "Beckmann"},
                                          {int(Distribution::Gaussian), "gaussian", "Gaussian"},
                                          {int(Distribution::Ggx), "ggx", "GGX"}};
constexpr FieldChoice kFresnels[] = {{int(FresnelMode::Schlick), "schlick", "Schlick"},
                                     {int(FresnelMode::Full), "full", "full (unpolarized)"}};
constexpr FieldChoice kLightTypes[] = {{int(LightType::Point), "point", "point"},
                                       {int(LightType::Directional), "directional", "directional"},
                                       {int(LightType::Spot), "spot", "spot"}};

} // namespace

const std::span<const FieldChoice> kBuiltinChoices = kBuiltins, kShadingChoices = kShadings,
                                   kNormalMatrixChoices = kNormalMatrices, kBrdfChoices = kBrdfs,
                                   kDistributionChoices = kDistributions, kFresnelChoices = kFresnels,
                                   kLightTypeChoices = kLightTypes;

std::string_view choiceName(std::span<const FieldChoice> choices, int value) {
    for (const FieldChoice& c : choices) {
        if (c.value == value) {
            return c.name;
        }
    }
    return "?";
}

//----------------------------------------------------------------------------------------
// Where each field lives, when it applies, and its rules
//----------------------------------------------------------------------------------------

namespace {

template <auto Member>
void* top(Preset& p, LightDesc*) {
    return &(p.*Member);
}
template <auto Section, auto Member>
void* in(Preset& p, LightDesc*) {
    return &((p.*Section).*Member);
}
template <auto Member>
void* light(Preset&, LightDesc* l) {
    return &(l->*Member);
}
template <auto Member>
void* orbit(Preset&, LightDesc* l) {
    return &(l->orbit.*Member);
}

bool builtinModel(const Preset& p, const LightDesc*) { return p.model.gltf.empty(); }
bool gltfModel(const Preset& p, const LightDesc*) { return !p.model.gltf.empty(); }
bool cookTorrance(const Preset& p, const LightDesc*) { return p.brdf == BrdfModel::CookTorrance; }
bool phongLobe(const Preset& p, const LightDesc*) { return p.brdf != BrdfModel::CookTorrance; }
bool notDirectional(const Preset&, const LightDesc* l) { return l->type != LightType::Directional; }
bool notPoint(const Preset&, const LightDesc* l) { return l->type != LightType::Point; }
bool spot(const Preset&, const LightDesc* l) { return l->type == LightType::Spot; }
bool orbiting(const Preset&, const LightDesc* l) { return l->orbit.on; }
// Presets without motion are written as they were before it existed.
bool orbitGiven(const Preset&, const LightDesc* l) { return l->orbit != LightOrbit{}; }

void scaleRule(const Preset& p, const LightDesc*, std::vector<FieldProblem>& problems) {
    const glm::vec3& s = p.model.scale;
    if (std::abs(s.x) < limits::kMinScale || std::abs(s.y) < limits::kMinScale || std::abs(s.z) < limits::kMinScale) {
        problems.push_back({"scale", "scale factors must be at least 0.0001 in magnitude (at 0 the normal matrix would not exist)"});
    }
}

// The camera once its keys are read: far beyond near, an up that is a direction and not along the view.
void cameraRule(const Preset& p, const LightDesc*, std::vector<FieldProblem>& problems) {
    const Camera& camera = p.camera;
    if (camera.far <= camera.near) {
        problems.push_back({"far", "must be greater than near"});
    }
    glm::vec3 forward = camera.target - camera.eye;
    if (glm::length(camera.up) < limits::kMinDirectionLength) {
        problems.push_back({"up", "must be at least 0.001 long (it is normalized)"});
    } else if (glm::length(forward) < limits::kMinDirectionLength) {
        problems.push_back({"target", "must be at least 0.001 from eye"});
    } else {
        glm::vec3 side = glm::cross(forward, camera.up);
        if (glm::dot(side, side) <= 1e-12f * glm::dot(forward, forward) * glm::dot(camera.up, camera.up)) {
            problems.push_back({"up", "must not be parallel to the viewing direction (or zero)"});
        }
    }
}

void attenuationRule(const Preset&, const LightDesc* l, std::vector<FieldProblem>& problems) {
    if (l->attenuation == glm::vec3(0.0f)) {
        problems.push_back({"attenuation", "c0, c1 and c2 must not all be 0"});
    }
}

//----------------------------------------------------------------------------------------
// The rows
//----------------------------------------------------------------------------------------

using K = FieldKind;
using G = FieldGroup;
namespace L = limits;

const FieldRow kRows[] = {
    {.path = "name", .kind = K::Text, .group = G::File, .style = kStyleHidden, .label = "name",
     .help = "The scene's title, shown on the page and in reports.", .at = top<&Preset::name>},
    {.path = "description", .kind = K::Text, .group = G::File, .style = kStyleHidden, .label = "description",
     .help = "What the scene shows, in a sentence or two.", .at = top<&Preset::description>},
    // The model: a built-in shape or a glTF file (preset_read.cpp reads the three together).
    {.path = "model.builtin", .kind = K::Choice, .group = G::Model, .choices = kBuiltins, .label = "built-in",
     .help = "The built-in shape drawn.", .at = in<&Preset::model, &Model::builtin>, .applies = builtinModel,
     .written = builtinModel, .custom = true},
    {.path = "model.gltf", .kind = K::Text, .group = G::Model, .style = kStyleHidden, .label = "glTF",
     .help = "A .gltf or .glb model, relative to the preset's folder.", .at = in<&Preset::model, &Model::gltf>,
     .applies = gltfModel, .written = gltfModel, .custom = true},
    {.path = "model.subdivisions", .kind = K::Int2, .group = G::Model, .intRange = &L::kSubdivisions,
     .label = "subdivisions", .help = "How finely the built-in shape is divided into triangles.",
     .at = in<&Preset::model, &Model::subdivisions>, .applies = builtinModel, .written = builtinModel, .custom = true},
    {.path = "model.scale", .kind = K::Vec3, .group = G::Model, .range = &L::kCoordinate, .step = 0.01f,
     .label = "scale", .help = "The model's size along x, y and z.", .at = in<&Preset::model, &Model::scale>,
     .rule = scaleRule},
    {.path = "model.rotate_deg", .kind = K::Vec3, .group = G::Model, .range = &L::kRotationDeg, .step = 0.5f,
     .unit = "deg", .label = "rotate", .help = "The model's rotation about x, y and z.",
     .at = in<&Preset::model, &Model::rotateDeg>},
    {.path = "model.translate", .kind = K::Vec3, .group = G::Model, .range = &L::kCoordinate, .step = 0.01f,
     .label = "translate", .help = "Where the model's centre is moved to.",
     .at = in<&Preset::model, &Model::translate>},
    // The camera.
    {.path = "camera.eye", .kind = K::Vec3, .group = G::Camera, .range = &L::kCoordinate, .step = 0.02f,
     .label = "eye", .help = "Where the camera is.", .at = in<&Preset::camera, &Camera::eye>},
    {.path = "camera.target", .kind = K::Vec3, .group = G::Camera, .range = &L::kCoordinate, .step = 0.02f,
     .label = "target", .help = "The point the camera looks at.", .at = in<&Preset::camera, &Camera::target>},
    {.path = "camera.up", .kind = K::Vec3, .group = G::Camera, .range = &L::kCoordinate, .step = 0.01f,
     .style = kStyleHidden, .label = "up", .help = "Which way is up on the screen.",
     .at = in<&Preset::camera, &Camera::up>},
    {.path = "camera.fovy_deg", .kind = K::Number, .group = G::Camera, .range = &L::kFovyDeg, .format = "%.1f",
     .unit = "deg", .label = "fovy", .help = "The camera's vertical field of view.", .sweep = "20,45,70",
     .at = in<&Preset::camera, &Camera::fovyDeg>},
    {.path = "camera.near", .kind = K::Number, .group = G::Camera, .range = &L::kNear, .style = kStyleHidden,
     .label = "near", .help = "The nearest distance drawn.", .at = in<&Preset::camera, &Camera::near>},
    {.path = "camera.far", .kind = K::Number, .group = G::Camera, .range = &L::kFar, .style = kStyleHidden,
     .label = "far", .help = "The farthest distance drawn.", .at = in<&Preset::camera, &Camera::far>,
     .rule = cameraRule},
    // How the model is shaded and lit.
    {.path = "shading", .kind = K::Choice, .group = G::Shading, .choices = kShadings, .style = kStyleRadios,
     .label = "shading", .help = "Where the lighting is evaluated: once a face, at the vertices, or at every pixel.",
     .sweep = "flat,gouraud,phong", .at = top<&Preset::shading>},
    {.path = "normal_matrix", .kind = K::Choice, .group = G::Shading, .choices = kNormalMatrices,
     .label = "normal matrix",
     .help = "How normals are transformed: the inverse transpose is correct under non-uniform scale.",
     .at = top<&Preset::normalMatrix>},
    {.path = "brdf", .kind = K::Choice, .group = G::Brdf, .choices = kBrdfs, .style = kStyleRadios, .label = "BRDF",
     .help = "The specular reflection model.", .sweep = "phong,blinn-phong,cook-torrance", .at = top<&Preset::brdf>},
    {.path = "cook_torrance.distribution", .kind = K::Choice, .group = G::Brdf, .choices = kDistributions,
     .label = "D: distribution", .help = "The microfacet distribution D.",
     .at = in<&Preset::cookTorrance, &CookTorrance::distribution>, .applies = cookTorrance},
    {.path = "cook_torrance.roughness", .kind = K::Number, .group = G::Brdf, .range = &L::kRoughness,
     .style = kStyleLogarithmic | kStyleLobe, .label = "roughness m", .help = "The microfacets' RMS slope m: larger is rougher.",
     .sweep = "0.1,0.2,0.4,0.8", .at = in<&Preset::cookTorrance, &CookTorrance::roughness>, .applies = cookTorrance},
    {.path = "cook_torrance.fresnel", .kind = K::Choice, .group = G::Brdf, .choices = kFresnels,
     .label = "F: Fresnel", .help = "The Fresnel term F: Schlick's approximation or the full unpolarized equation.",
     .at = in<&Preset::cookTorrance, &CookTorrance::fresnel>, .applies = cookTorrance},
    {.path = "cook_torrance.ior", .kind = K::Number, .group = G::Brdf, .range = &L::kIor, .label = "ior",
     .help = "The index of refraction, which sets the reflectance at normal incidence F0.", .sweep = "1.2,1.5,2,3",
     .at = in<&Preset::cookTorrance, &CookTorrance::ior>, .applies = cookTorrance},
    {.path = "cook_torrance.geometry", .kind = K::Switch, .group = G::Brdf, .label = "G: geometry term",
     .help = "Whether the geometric attenuation G (shadowing and masking) is applied.",
     .at = in<&Preset::cookTorrance, &CookTorrance::geometry>, .applies = cookTorrance},
    // The material.
    {.path = "material.emissive", .kind = K::Color, .group = G::Material, .range = &L::kMaterialColor,
     .label = "emissive", .help = "Light the surface gives off itself.",
     .at = in<&Preset::material, &MaterialDesc::emissive>},
    {.path = "material.ambient", .kind = K::Color, .group = G::Material, .range = &L::kMaterialColor,
     .label = "ambient", .help = "The reflectance k_a of the ambient light.", .sweep = "0,0.2,0.5",
     .at = in<&Preset::material, &MaterialDesc::ambient>},
    {.path = "material.diffuse", .kind = K::Color, .group = G::Material, .range = &L::kMaterialColor,
     .label = "diffuse", .help = "The diffuse reflectance k_d (Lambert).", .sweep = "0.2,0.5,0.8",
     .at = in<&Preset::material, &MaterialDesc::diffuse>},
    {.path = "material.specular", .kind = K::Color, .group = G::Material, .range = &L::kMaterialColor,
     .label = "specular", .help = "The specular reflectance k_s.", .sweep = "0.2,0.5,1",
     .at = in<&Preset::material, &MaterialDesc::specular>},
    {.path = "material.shininess", .kind = K::Number, .group = G::Material, .range = &L::kShininess, .format = "%.1f",
     .style = kStyleLogarithmic | kStyleHelpMarker | kStyleLobe, .label = "shininess",
     .help = "The specular exponent n (logarithmic slider). Ctrl+click to type any value > 0.",
     .sweep = "10,20,30,50", .at = in<&Preset::material, &MaterialDesc::shininess>, .applies = phongLobe},
    {.path = "ambient_light", .kind = K::Color, .group = G::Shading, .range = &L::kAmbientLight,
     .label = "global ambient", .help = "The scene's ambient light, reflected by k_a.", .sweep = "0,0.1,0.3",
     .at = top<&Preset::ambientLight>},
    // Each light.
    {.path = "lights[].type", .kind = K::Choice, .group = G::Lights, .choices = kLightTypes, .label = "type",
     .help = "A point light, a directional light (the sun), or a spot light.", .at = light<&LightDesc::type>},
    {.path = "lights[].position", .kind = K::Vec3, .group = G::Lights, .range = &L::kCoordinate, .step = 0.02f,
     .label = "position", .help = "Where the light is.", .at = light<&LightDesc::position>, .applies = notDirectional},
    {.path = "lights[].direction", .kind = K::Direction, .group = G::Lights, .range = &L::kCoordinate, .step = 0.01f,
     .label = "direction", .help = "Which way the light shines.", .at = light<&LightDesc::direction>,
     .applies = notPoint},
    {.path = "lights[].ambient", .kind = K::Color, .group = G::Lights, .range = &L::kLightColor, .label = "ambient",
     .help = "The light's ambient intensity.", .at = light<&LightDesc::ambient>},
    {.path = "lights[].diffuse", .kind = K::Color, .group = G::Lights, .range = &L::kLightColor, .label = "diffuse",
     .help = "The light's diffuse intensity.", .sweep = "0.25,0.5,1", .at = light<&LightDesc::diffuse>},
    {.path = "lights[].specular", .kind = K::Color, .group = G::Lights, .range = &L::kLightColor, .label = "specular",
     .help = "The light's specular intensity.", .at = light<&LightDesc::specular>},
    {.path = "lights[].attenuation", .kind = K::Vec3, .group = G::Lights, .range = &L::kAttenuation, .step = 0.005f,
     .style = kStyleHelpMarker, .label = "c0, c1, c2", .help = "Att = min(1, 1 / (c0 + c1 d + c2 d^2))",
     .sweep = "[1]=0,0.2,0.5,1;[2]=0,0.1,0.3", .at = light<&LightDesc::attenuation>, .applies = notDirectional,
     .rule = attenuationRule},
    {.path = "lights[].cutoff_deg", .kind = K::Number, .group = G::Lights, .range = &L::kCutoffDeg, .format = "%.1f",
     .unit = "deg", .label = "cut-off", .help = "The spot's half angle: no light outside it.", .sweep = "10,20,30,45",
     .at = light<&LightDesc::cutoffDeg>, .applies = spot},
    {.path = "lights[].exponent", .kind = K::Number, .group = G::Lights, .range = &L::kSpotExponent, .format = "%.1f",
     .label = "exponent", .help = "How fast the spot fades from its axis to its edge.", .sweep = "1,8,32,128",
     .at = light<&LightDesc::exponent>, .applies = spot},
    {.path = "lights[].enabled", .kind = K::Switch, .group = G::Lights, .label = "enabled",
     .help = "Whether the light shines.", .at = light<&LightDesc::enabled>},
    {.path = "lights[].orbit.on", .kind = K::Switch, .group = G::Lights, .style = kStyleHelpMarker,
     .label = "orbit the model",
     .help = "The light circles the axis through the model's centre, starting from the position above, and pauses "
             "while you drag anything. Saved with the preset. Screenshots and lab render show the light at the "
             "position above (no motion).",
     .at = orbit<&LightOrbit::on>, .written = orbitGiven},
    {.path = "lights[].orbit.axis", .kind = K::Direction, .group = G::Lights, .range = &L::kCoordinate, .step = 0.01f,
     .label = "axis", .help = "The axis the light circles.", .at = orbit<&LightOrbit::axis>, .applies = orbiting,
     .written = orbitGiven},
    {.path = "lights[].orbit.degrees_per_second", .kind = K::Number, .group = G::Lights, .range = &L::kOrbitSpeed,
     .format = "%.0f", .unit = "deg/s", .label = "speed",
     .help = "How fast the light circles; negative turns the other way.", .at = orbit<&LightOrbit::degreesPerSecond>,
     .applies = orbiting, .written = orbitGiven},
    // The terms of the equation, each on or off.
    {.path = "terms.emissive", .kind = K::Switch, .group = G::Shading, .label = "emissive",
     .help = "Whether the emissive term is added.", .at = in<&Preset::terms, &TermSwitches::emissive>},
    {.path = "terms.ambient", .kind = K::Switch, .group = G::Shading, .label = "ambient",
     .help = "Whether the ambient term is added.", .at = in<&Preset::terms, &TermSwitches::ambient>},
    {.path = "terms.diffuse", .kind = K::Switch, .group = G::Shading, .label = "diffuse",
     .help = "Whether the diffuse term is added.", .at = in<&Preset::terms, &TermSwitches::diffuse>},
    {.path = "terms.specular", .kind = K::Switch, .group = G::Shading, .label = "specular",
     .help = "Whether the specular term is added.", .at = in<&Preset::terms, &TermSwitches::specular>},
    {.path = "background", .kind = K::Color, .group = G::Shading, .range = &L::kBackground, .label = "background",
     .help = "The colour behind the model.", .at = top<&Preset::background>},
    {.path = "plot.incident_deg", .kind = K::Number, .group = G::Plot, .range = &L::kPlotIncidentDeg,
     .format = "%.1f", .unit = "deg", .label = "incident angle",
     .help = "The plots' angle of incidence from the normal.", .at = top<&Preset::plotIncidentDeg>},
};

} // namespace

std::span<const FieldRow> fieldRows() { return kRows; }

//----------------------------------------------------------------------------------------
// Questions
//----------------------------------------------------------------------------------------

std::string_view fieldKey(const FieldRow& row) {
    std::size_t dot = row.path.rfind('.');
    return dot == std::string_view::npos ? row.path : row.path.substr(dot + 1);
}

std::string_view fieldObject(const FieldRow& row) {
    std::size_t dot = row.path.rfind('.');
    return dot == std::string_view::npos ? std::string_view() : row.path.substr(0, dot);
}

void objectRules(const FieldRow& row, const Preset& preset, const LightDesc* light, std::vector<FieldProblem>& problems) {
    for (const FieldRow& r : kRows) {
        if (r.rule && fieldObject(r) == fieldObject(row)) {
            r.rule(preset, light, problems);
        }
    }
}

// A light's rows start so ("lights[].exponent"), standing for every light's.
constexpr std::string_view kLightRows = "lights[]";

bool isLightRow(const FieldRow& row) { return row.path.starts_with("lights[]."); }

std::string fieldPath(const FieldRow& row, int light) {
    if (!isLightRow(row)) {
        return std::string(row.path);
    }
    return "lights[" + std::to_string(light) + "]" + std::string(row.path.substr(kLightRows.size()));
}

FieldPlace fieldPlace(const FieldRow& row, std::string_view object) {
    std::string_view below = fieldObject(row);
    if (below == object) {
        return {FieldPlace::Member, fieldKey(row), {}, false};
    }
    if (!object.empty() && !covers(object, below)) {
        return {};
    }
    std::string_view rest = object.empty() ? row.path : row.path.substr(object.size() + 1);
    std::string_view child = rest.substr(0, rest.find('.'));
    bool array = child.ends_with("[]");
    return {FieldPlace::Below, array ? child.substr(0, child.size() - 2) : child,
            row.path.substr(0, row.path.size() - rest.size() + child.size()), array};
}

std::string fieldLabel(const FieldRow& row) {
    return std::string(row.label) + (row.unit.empty() ? "" : " (" + std::string(row.unit) + ")");
}

namespace {

// `path` with a light's index written "[]" and an element of a triplet dropped, canonical;
// nullopt when it breaks the grammar or names a light beyond limits::kMaxLights.
std::optional<std::string> rowPattern(std::string_view path, bool& element) {
    std::optional<std::vector<PathStep>> steps = parseFieldPath(path);
    element = false;
    if (!steps) {
        return std::nullopt;
    }
    std::string out;
    for (std::size_t i = 0; i < steps->size(); ++i) {
        const PathStep& s = (*steps)[i];
        if (!s.isIndex()) {
            out += (out.empty() ? "" : ".") + s.name;
        } else if (i == 1 && out == "lights") {
            if (s.index >= static_cast<std::size_t>(limits::kMaxLights)) {
                return std::nullopt;
            }
            out += "[]";
        } else if (i + 1 == steps->size() && !element) {
            element = true; // "material.diffuse[1]": checked against its row's kind below
        } else {
            return std::nullopt;
        }
    }
    return out;
}

} // namespace

const FieldRow* fieldRow(std::string_view path) {
    for (const FieldRow& row : kRows) { // a row's own path: "lights[].exponent"
        if (row.path == path) {
            return &row;
        }
    }
    bool element = false;
    std::optional<std::string> pattern = rowPattern(path, element);
    if (!pattern) {
        return nullptr;
    }
    for (const FieldRow& row : kRows) {
        if (row.path == *pattern) {
            bool triplet = row.kind == K::Vec3 || row.kind == K::Color || row.kind == K::Direction;
            if (element && !(triplet || row.kind == K::Int2)) {
                return nullptr;
            }
            return &row;
        }
    }
    return nullptr;
}

bool isFieldPath(std::string_view path) {
    bool element = false;
    std::optional<std::string> pattern = rowPattern(path, element);
    if (!pattern) {
        return false;
    }
    if (const FieldRow* row = fieldRow(path)) {
        std::optional<std::vector<PathStep>> steps = parseFieldPath(path);
        if (element) { // an element within the triplet's or pair's size
            std::size_t size = row->kind == K::Int2 ? 2 : 3;
            return steps->back().index < size;
        }
        return true;
    }
    return !element && std::any_of(std::begin(kRows), std::end(kRows),
                                    [&](const FieldRow& r) { return covers(*pattern, r.path); });
}

int choiceValue(const FieldRow& row, const Preset& preset, const LightDesc* light) {
    int value = 0;
    static_assert(sizeof(Builtin) == sizeof(int) && sizeof(Shading) == sizeof(int) && sizeof(NormalMatrixMode) == sizeof(int) &&
                  sizeof(BrdfModel) == sizeof(int) && sizeof(Distribution) == sizeof(int) &&
                  sizeof(FresnelMode) == sizeof(int) && sizeof(LightType) == sizeof(int));
    std::memcpy(&value, row.at(const_cast<Preset&>(preset), const_cast<LightDesc*>(light)), sizeof value);
    return value;
}

void setChoice(const FieldRow& row, Preset& preset, LightDesc* light, int value) {
    std::memcpy(row.at(preset, light), &value, sizeof value);
}

bool applies(const FieldRow& row, const Preset& preset, const LightDesc* light) {
    return !row.applies || row.applies(preset, light);
}

} // namespace lab
