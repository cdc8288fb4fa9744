// limits.h — the range of every number a preset holds, written once.
//
// The preset validator (preset_read.cpp) refuses what lies outside these ranges, with `text` as
// its wording ("must be greater than 0, got -3"); the GUI's sliders span [sliderMin, sliderMax]
// and clamp typed values with clamp(), so the panel can never produce a preset the validator
// refuses. Numbers with no range of their own (positions, directions, the model's transform)
// are any finite float, kFinite. Rules that tie several values together (far > near, a non-zero
// direction or scale, c0, c1, c2 not all 0) are the validator's.
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

// Positions, directions, the model's transform: any finite float (the slider span is a guess
// at a useful scene size; typed values go further).
inline constexpr Range kFinite{-kUnbounded, kUnbounded, false, -10.0f, 10.0f, "a finite number"};

// material.emissive, ambient, diffuse, specular: reflectances, so at most 1.
inline constexpr Range kMaterialColor{0.0f, 1.0f, false, 0.0f, 1.0f, "in [0, 1]"};
// material.shininess: the Phong and Blinn-Phong exponent.
inline constexpr Range kShininess{0.0f, kUnbounded, true, 1.0f, 1000.0f, "greater than 0"};

// cook_torrance.roughness (m) and ior.
inline constexpr Range kRoughness{0.0f, kUnbounded, true, 0.01f, 1.0f, "greater than 0"};
inline constexpr Range kIor{0.0f, kUnbounded, true, 1.0f, 3.0f, "greater than 0"};

// lights[].ambient, diffuse, specular and ambient_light: intensities, which may exceed 1.
inline constexpr Range kLightColor{0.0f, kUnbounded, false, 0.0f, 1.0f, "0 or more"};
inline constexpr Range kAmbientLight = kLightColor;
// lights[].attenuation, each of c0, c1, c2.
inline constexpr Range kAttenuation{0.0f, kUnbounded, false, 0.0f, 10.0f, "0 or more"};
// lights[].cutoff_deg and exponent: the spot cone.
inline constexpr Range kCutoffDeg{0.0f, 90.0f, false, 0.0f, 90.0f, "in [0, 90]"};
inline constexpr Range kSpotExponent{0.0f, kUnbounded, false, 0.0f, 128.0f, "0 or more"};
// At most this many lights (the shaders' MAX_LIGHTS).
inline constexpr int kMaxLights = 8;

// camera.fovy_deg, near and far (far > near is checked apart).
inline constexpr Range kFovyDeg{0.0f, 179.0f, true, 5.0f, 120.0f, "greater than 0 and at most 179"};
inline constexpr Range kNear{0.0f, kUnbounded, true, 0.01f, 10.0f, "greater than 0"};
inline constexpr Range kFar{0.0f, kUnbounded, true, 1.0f, 1000.0f, "greater than 0"};

// background: a colour written as it is.
inline constexpr Range kBackground{0.0f, 1.0f, false, 0.0f, 1.0f, "in [0, 1]"};
// plot.incident_deg (and `lab plot --incident-deg`): the plane of incidence's angle from N.
inline constexpr Range kPlotIncidentDeg{-90.0f, 90.0f, false, -90.0f, 90.0f, "in [-90, 90]"};

// model.subdivisions, each of the two counts: bounded so that no preset can ask for an absurd
// mesh. A sphere's slices and stacks and a torus's rings need 3 to enclose anything.
inline constexpr IntRange kSubdivisions{1, 1024};       // cube, plane
inline constexpr IntRange kSubdivisionsRound{3, 1024};  // sphere, torus

} // namespace lab::limits
