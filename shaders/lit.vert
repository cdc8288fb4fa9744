// lit.vert - transforms the model into eye space and, for flat and Gouraud shading,
// evaluates the lighting model per vertex.
//
// Prepended at compile time (lab/render/shader.cpp): the version line, the precision
// statements, one of LAB_PER_VERTEX / LAB_PER_PIXEL / LAB_GOURAUD_ERROR, then lighting.glsl and
// view.glsl.
// Flat shading draws a de-indexed mesh whose a_shadePosition is the triangle's centroid and
// a_normal its face normal, so all three vertices get the same colour. Smooth meshes alias
// a_shadePosition to a_position.
// LAB_GOURAUD_ERROR needs both: the per-vertex colour, and the point and normal the fragment
// shader evaluates the model at again, per pixel.

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_shadePosition;

uniform mat4 u_modelView;
uniform mat4 u_projection;
uniform mat3 u_normalMatrix;

uniform Material u_material;
uniform Brdf u_brdf;
uniform Terms u_terms;
uniform vec3 u_ambientLight;
uniform Light u_lights[MAX_LIGHTS];
uniform int u_lightCount;
uniform int u_view;        // VIEW_* (view.glsl)
uniform int u_factor;      // FACTOR_* (lighting_api.glsl), for VIEW_FACTOR
uniform int u_factorLight; // which of u_lights

#if defined(LAB_PER_VERTEX) || defined(LAB_GOURAUD_ERROR)
out vec3 v_color;
#endif
#ifdef LAB_PER_VERTEX
out float v_value; // the factor, for VIEW_FACTOR
#else
out vec3 v_position;
out vec3 v_normal;
#endif

void main() {
    vec3 p = (u_modelView * vec4(a_shadePosition, 1.0f)).xyz;
    vec3 N = normalize(u_normalMatrix * a_normal);
#if defined(LAB_PER_VERTEX) || defined(LAB_GOURAUD_ERROR)
    v_color = u_view == VIEW_NORMALS ? N * 0.5f + 0.5f
                                     : shade(u_material, u_brdf, u_terms, u_ambientLight, u_lights, u_lightCount, p, N);
#endif
#ifdef LAB_PER_VERTEX
    v_value = u_view == VIEW_FACTOR ? equationFactor(u_factor, u_brdf, u_lights[u_factorLight], p, N, viewVector(p)) : 0.0f;
#else
    v_position = p;
    v_normal = N;
#endif
    gl_Position = u_projection * (u_modelView * vec4(a_position, 1.0f));
    gl_PointSize = 1.0f; // the parity test draws single-pixel probes as points
}
