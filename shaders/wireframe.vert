// wireframe.vert - the lines drawn over the shaded model: the triangles' edges (the wireframe) and
// each vertex's normal as a short line, in one flat colour (lab/render/wireframe.cpp).
//
// Prepended at compile time (lab/render/shader.cpp): the version line and the precision
// statements; none of the lighting files (the lines are not lit).
// The wireframe draws the mesh's own vertices (u_normalLength 0). A normal's line is the two
// vertices of one instance (one vertex of the mesh): its base at the vertex (a_tip 0) and its
// tip (a_tip 1) u_normalLength eye-space units along the normal, transformed and renormalized
// exactly as lit.vert does, so the line shows the normal the lighting used (a wrong normal
// matrix tilts it).

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_tip; // per vertex of an instance, not per instance (overlay.cpp)

uniform mat4 u_modelView;
uniform mat4 u_projection;
uniform mat3 u_normalMatrix;
uniform float u_normalLength; // 0 for the wireframe
uniform float u_depthBias;    // a share of the distance to the eye (a few pixels' footprints)

void main() {
    vec3 p = (u_modelView * vec4(a_position, 1.0f)).xyz;
    if (u_normalLength > 0.0f) { // a normal's line: 2 vertices an instance, its base and its tip
        p += a_tip * u_normalLength * normalize(u_normalMatrix * a_normal);
    }
    gl_Position = u_projection * vec4(p, 1.0f);
    // Toward the eye by u_depthBias of the distance to it, so a line lying on the surface wins
    // the depth test against the triangles just drawn under it. With a perspective projection
    // the point p * (1 - b) lies on the same pixel, and its depth is what adding
    // b / (1 - b) * projection[3][2] (about b times it; negative: nearer) to clip z gives: a
    // constant offset in clip space that, in eye space, grows with the distance as a pixel's
    // footprint on the surface does (overlay.h, kOverlayDepthBiasPixels). Lines on the far side
    // stay hidden: the model's thickness puts them behind the front surface by far more.
    gl_Position.z += u_depthBias * u_projection[3][2];
}
