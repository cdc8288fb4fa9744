// lit.frag - writes the colour: the interpolated per-vertex colour (flat, Gouraud), or the
// lighting model evaluated per pixel with the renormalized interpolated normal (Phong).
//
// Prepended at compile time as for lit.vert, with the same defines.

#ifdef LAB_PER_VERTEX
in vec3 v_color;
#else
in vec3 v_position;
in vec3 v_normal;

uniform Material u_material;
uniform Brdf u_brdf;
uniform Terms u_terms;
uniform vec3 u_ambientLight;
uniform Light u_lights[MAX_LIGHTS];
uniform int u_lightCount;
uniform bool u_showNormals; // the per-term view's "normals as colours"
#endif

out vec4 o_color;

void main() {
#ifdef LAB_PER_VERTEX
    o_color = vec4(v_color, 1.0f);
#else
    vec3 N = normalize(v_normal);
    o_color = u_showNormals ? vec4(N * 0.5f + 0.5f, 1.0f)
                            : vec4(shade(u_material, u_brdf, u_terms, u_ambientLight, u_lights, u_lightCount,
                                         v_position, N), 1.0f);
#endif
}
