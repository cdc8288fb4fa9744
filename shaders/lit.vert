// lit.vert - transforms the model into eye space and, for flat and Gouraud shading,
// evaluates the lighting model per vertex.
//
// Prepended at compile time (lab/render/shader.cpp): the version line, the precision
// statements, one of LAB_PER_VERTEX / LAB_PER_PIXEL, then lighting.glsl.
// Flat shading draws a de-indexed mesh whose a_shadePosition is the triangle's centroid and
// a_normal its face normal, so all three vertices get the same colour. Smooth meshes alias
// a_shadePosition to a_position.

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
uniform bool u_showNormals; // the per-term view's "normals as colours"

#ifdef LAB_PER_VERTEX
out vec3 v_color;
#else
out vec3 v_position;
out vec3 v_normal;
#endif

void main() {
    vec3 p = (u_modelView * vec4(a_shadePosition, 1.0f)).xyz;
    vec3 N = normalize(u_normalMatrix * a_normal);
#ifdef LAB_PER_VERTEX
    v_color = u_showNormals ? N * 0.5f + 0.5f
                            : shade(u_material, u_brdf, u_terms, u_ambientLight, u_lights, u_lightCount, p, N);
#else
    v_position = p;
    v_normal = N;
#endif
    gl_Position = u_projection * (u_modelView * vec4(a_position, 1.0f));
    gl_PointSize = 1.0f; // the parity test draws single-pixel probes as points
}
