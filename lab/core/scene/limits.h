// limits.h — the range of every number a preset holds, written once.
//
// The preset validator (preset_read.cpp) refuses what lies outside these ranges, with `text` as
// its wording ("must be greater than 0, got -3"); the GUI's sliders span [sliderMin, sliderMax]
// and clamp typed values with clamp(), so the panel can never produce a preset the validator
// refuses. Rules that tie several values together (far > near, a direction's or a scale's
// length, c0, c1, c2 not all 0) are the validator's.
//
// Every range is chosen so that every formula in shaders/lighting.glsl stays finite in float for
// every accepted preset (a roughness whose square underflows gives NaN, a light a light-year away
// an unlit sphere): coordinates within 10^4 keep distances squared far
// from overflow, a roughness of at least 10^-3 keeps m^2 and (m^2 - 1) + 1 apart from 0, an ior
// of at least 10^-2 keeps ior^2 a normal float, exponents of at least 10^-3 survive a GPU's
// flush of denormals to zero. tests/finite_test.cpp evaluates the model at the corners of these
// ranges on the CPU and the GPU and finds no NaN or infinity.
//
// This file owns the ranges and the two questions asked of them. It does not read JSON or
// report anything.
#pragma once

#include <cstdint>
#include <limits>

namespace lab::limits {

// A closed interval of floats, or half-open at the bottom when minExclusive.
struct Range {
    float min;
    float max;
    bool minExclusive;
    float sliderMin; // what a slider spans: a useful part of [min, max] (typed values may go further)
    float sliderMax;
    const char* text; // the validator's wording, completing "must be ...": "greater than 0", "in [0, 90]"
};

// A closed interval of integers.
struct IntRange {
    int min;
    int max;
};

// The largest finite float: the top of a range that has none. Every float a preset holds is finite.
inline constexpr float kUnbounded = std::numeric_limits<float>::max();

// The next float above `x` (std::nextafter(x, +inf), which is not constexpr before C++23).
constexpr float nextUp(float x) {
    if (x != x || x == std::numeric_limits<float>::infinity()) {
        return x;
    }
    if (x == 0.0f) {
        return std::numeric_limits<float>::denorm_min();
    }
    // __builtin_bit_cast: the browser build's libc++ 13 has no std::bit_cast.
    auto bits = __builtin_bit_cast(std::uint32_t, x);
    return __builtin_bit_cast(float, x > 0.0f ? bits + 1 : bits - 1);
}

// The smallest value `r` contains.
constexpr float lowest(const Range& r) { return r.minExclusive ? nextUp(r.min) : r.min; }

// Whether the validator accepts `v` (never NaN).
constexpr bool contains(const Range& r, float v) { return (r.minExclusive ? r.min < v : r.min <= v) && v <= r.max; }
constexpr bool contains(const IntRange& r, int v) { return r.min <= v && v <= r.max; }

// `v` moved into `r`: the nearest value the validator accepts (NaN becomes the lowest).
constexpr float clamp(const Range& r, float v) {
    float lo = lowest(r);
    if (!(v >= lo)) {
        return lo;
    }
    return v > r.max ? r.max : v;
}
constexpr int clamp(const IntRange& r, int v) { return v < r.min ? r.min : v > r.max ? r.max : v; }

//----------------------------------------------------------------------------------------
// The ranges, by preset key
//----------------------------------------------------------------------------------------

// Any finite float (numbers read outside presets: `lab plot`'s arguments are ranged themselves).
inline constexpr Range kFinite{-kUnbounded, kUnbounded, false, -10.0f, 10.0f, "a finite number"};

// Positions, directions and the model's transform, each coordinate (the slider span is a guess
// at a useful scene size; typed values go further). A direction (a light's, the camera's up) is
// at least kMinDirectionLength long, each scale factor at least kMinScale in magnitude.
inline constexpr Range kCoordinate{-1.0e4f, 1.0e4f, false, -10.0f, 10.0f, "in [-10000, 10000]"};
inline constexpr float kMinDirectionLength = 1.0e-3f;
inline constexpr float kMinScale = 1.0e-4f;
// model.rotate_deg, each angle.
inline constexpr Range kRotationDeg{-1.0e4f, 1.0e4f, false, -180.0f, 180.0f, "in [-10000, 10000]"};

// material.emissive, ambient, diffuse, specular: reflectances, so at most 1.
inline constexpr Range kMaterialColor{0.0f, 1.0f, false, 0.0f, 1.0f, "in [0, 1]"};
// material.shininess: the Phong and Blinn-Phong exponent.
inline constexpr Range kShininess{1.0e-3f, 1.0e6f, false, 1.0f, 1000.0f, "in [0.001, 1000000]"};

// cook_torrance.roughness (m) and ior.
inline constexpr Range kRoughness{1.0e-3f, 10.0f, false, 0.01f, 1.0f, "in [0.001, 10]"};
inline constexpr Range kIor{1.0e-2f, 100.0f, false, 1.0f, 3.0f, "in [0.01, 100]"};

// lights[].ambient, diffuse, specular and ambient_light: intensities, which may exceed 1.
inline constexpr Range kLightColor{0.0f, 1.0e4f, false, 0.0f, 1.0f, "in [0, 10000]"};
inline constexpr Range kAmbientLight = kLightColor;
// lights[].attenuation, each of c0, c1, c2.
inline constexpr Range kAttenuation{0.0f, 1.0e6f, false, 0.0f, 10.0f, "in [0, 1000000]"};
// lights[].cutoff_deg and exponent: the spot cone.
inline constexpr Range kCutoffDeg{0.0f, 90.0f, false, 0.0f, 90.0f, "in [0, 90]"};
inline constexpr Range kSpotExponent{0.0f, 1.0e6f, false, 0.0f, 128.0f, "in [0, 1000000]"};
// lights[].orbit.degrees_per_second: ten turns a second either way at most (the slider spans
// one turn in two seconds); its axis is a direction (kMinDirectionLength).
inline constexpr Range kOrbitSpeed{-3600.0f, 3600.0f, false, -180.0f, 180.0f, "in [-3600, 3600]"};
// At most this many lights (the shaders' MAX_LIGHTS).
inline constexpr int kMaxLights = 8;

// camera.fovy_deg, near and far (far > near is checked apart).
inline constexpr Range kFovyDeg{0.1f, 179.0f, false, 5.0f, 120.0f, "in [0.1, 179]"};
inline constexpr Range kNear{1.0e-4f, 1.0e5f, false, 0.01f, 10.0f, "in [0.0001, 100000]"};
inline constexpr Range kFar{1.0e-3f, 1.0e6f, false, 1.0f, 1000.0f, "in [0.001, 1000000]"};

// background: a colour written as it is.
inline constexpr Range kBackground{0.0f, 1.0f, false, 0.0f, 1.0f, "in [0, 1]"};
// plot.incident_deg (and `lab plot --incident-deg`): the plane of incidence's angle from N.
inline constexpr Range kPlotIncidentDeg{-90.0f, 90.0f, false, -90.0f, 90.0f, "in [-90, 90]"};

// model.subdivisions, each of the two counts: bounded so that no preset can ask for an absurd
// mesh. A sphere's slices and stacks and a torus's rings need 3 to enclose anything.
inline constexpr IntRange kSubdivisions{1, 1024};       // cube, plane
inline constexpr IntRange kSubdivisionsRound{3, 1024};  // sphere, torus

// `lab check`'s tolerances, in a preset's `check` block and as the command's options of the same
// names: a pixel fails above pixel_tolerance levels in any channel; an image fails above
// max_failing (a share of its pixels) or max_mean (levels); a plot fails where a value differs
// from its golden by more than plot_tolerance.
inline constexpr IntRange kPixelTolerance{0, 255};
// check.views[].light: a light of the preset, counted from 1.
inline constexpr IntRange kLightNumber{1, kMaxLights};
inline constexpr Range kMaxFailing{0.0f, 1.0f, false, 0.0f, 0.01f, "in [0, 1]"};
inline constexpr Range kMaxMean{0.0f, 255.0f, false, 0.0f, 2.0f, "in [0, 255]"};
inline constexpr Range kPlotTolerance{0.0f, 1.0e6f, false, 0.0f, 1.0e-3f, "in [0, 1000000]"};
// An exercise's field tolerance (tolerance.fields): |attempt - target| of a field's numbers. The
// widest range a field has (shininess, attenuation: 10^6) is its top; a float keeps it finite.
inline constexpr Range kFieldTolerance{0.0f, 1.0e6f, false, 0.0f, 1.0f, "in [0, 1000000]"};

} // namespace lab::limits
