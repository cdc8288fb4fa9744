// lit.frag - writes the colour: the interpolated per-vertex colour (flat, Gouraud), or the
// lighting model evaluated per pixel with the renormalized interpolated normal (Phong); for the
// value views (view.glsl), a number through a palette.
//
// Prepended at compile time as for lit.vert, with the same defines.

#if defined(LAB_PER_VERTEX) || defined(LAB_GOURAUD_ERROR)
in vec3 v_color;
#endif
#ifdef LAB_PER_VERTEX
in float v_value;
#else
in vec3 v_position;
in vec3 v_normal;

uniform Material u_material;
uniform Brdf u_brdf;
uniform Terms u_terms;
uniform vec3 u_ambientLight;
uniform Light u_lights[MAX_LIGHTS];
uniform int u_lightCount;
uniform int u_factor;
uniform int u_factorLight;
#endif
uniform int u_view;
uniform int u_palette;    // PALETTE_* (view.glsl)
uniform vec2 u_range;     // the value at the palette's first and last colour
uniform bool u_valueBits; // write the value's float bits instead, one byte per channel

out vec4 o_color;

// A value as its colour, or as its bits for the automatic range's pass.
vec4 valueColor(float v) {
    if (u_valueBits) {
        uint bits = floatBitsToUint(v);
        return vec4(float(bits & 255u), float((bits >> 8u) & 255u), float((bits >> 16u) & 255u), float(bits >> 24u)) / 255.0f;
    }
    return vec4(paletteColor(u_palette, (v - u_range.x) / (u_range.y - u_range.x)), 1.0f);
}

void main() {
#if defined(LAB_PER_VERTEX)
    o_color = u_view == VIEW_FACTOR ? valueColor(v_value) : vec4(v_color, 1.0f);
#else
    vec3 N = normalize(v_normal);
#if defined(LAB_GOURAUD_ERROR)
    vec3 e = abs(shade(u_material, u_brdf, u_terms, u_ambientLight, u_lights, u_lightCount, v_position, N) - v_color);
    o_color = valueColor(max(e.r, max(e.g, e.b)));
#else
    if (u_view == VIEW_NORMALS) {
        o_color = vec4(N * 0.5f + 0.5f, 1.0f);
    } else if (u_view == VIEW_FACTOR) {
        o_color = valueColor(equationFactor(u_factor, u_brdf, u_lights[u_factorLight], v_position, N, viewVector(v_position)));
    } else {
        o_color = vec4(shade(u_material, u_brdf, u_terms, u_ambientLight, u_lights, u_lightCount, v_position, N), 1.0f);
    }
#endif
#endif
}
