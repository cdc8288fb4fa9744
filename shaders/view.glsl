// view.glsl - how the value views (view_mode.h: the factor views and gouraud-error) colour a
// number: the palettes. One source, two faces, like lighting.glsl: the shaders colour the model
// with it, and the C++ build (lab/core/lighting/lighting.h, paletteColor) draws the legends with it.
// Keep to lighting.glsl's shared subset of GLSL and C++.

// What lit.frag writes (u_view): the lighting (the term views: the preset's own switches), the
// normal as a colour, one factor of the equation (u_factor, for light u_factorLight), or the
// Gouraud error; a value is coloured by u_palette over u_range, or written as the four bytes of
// its float (u_valueBits: the automatic range's pass reads them back).
const int VIEW_SHADE = 0, VIEW_NORMALS = 1, VIEW_FACTOR = 2, VIEW_GOURAUD_ERROR = 3;
const int PALETTE_VIRIDIS = 0, PALETTE_GREY = 1;

// The nine colours of viridis (van der Walt and Smith, matplotlib's default colour map, 2015) at
// t = 0, 1/8, ..., 1: perceptually uniform, readable in grey and by most colour-blind viewers.
vec3 viridisStop(int i) {
    if (i <= 0) return vec3(68.0f, 1.0f, 84.0f) / 255.0f;
    if (i == 1) return vec3(71.0f, 45.0f, 123.0f) / 255.0f;
    if (i == 2) return vec3(59.0f, 82.0f, 139.0f) / 255.0f;
    if (i == 3) return vec3(44.0f, 114.0f, 142.0f) / 255.0f;
    if (i == 4) return vec3(33.0f, 144.0f, 140.0f) / 255.0f;
    if (i == 5) return vec3(39.0f, 173.0f, 129.0f) / 255.0f;
    if (i == 6) return vec3(93.0f, 200.0f, 99.0f) / 255.0f;
    if (i == 7) return vec3(170.0f, 220.0f, 50.0f) / 255.0f;
    return vec3(253.0f, 231.0f, 37.0f) / 255.0f;
}

// Viridis at t in [0, 1], linear between its nine stops.
vec3 viridis(float t) {
    float s = clamp(t, 0.0f, 1.0f) * 8.0f;
    int i = min(int(s), 7);
    return mix(viridisStop(i), viridisStop(i + 1), s - float(i));
}

// The colour of position t in [0, 1] of a value range (view_mode.h rangePosition): grey writes t
// itself, so a byte of the image is round(255 t).
vec3 paletteColor(int palette, float t) {
    float u = clamp(t, 0.0f, 1.0f);
    return palette == PALETTE_GREY ? vec3(u) : viridis(u);
}
