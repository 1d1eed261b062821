#version 330 core
// Surfaces: world-space vertices with per-vertex normals, moved by a per-surface
// offset, lit in view space by surface.frag.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uView;        // world to view; a rigid motion, so it also turns normals
uniform mat4 uProjection;
uniform vec3 uOffset;      // the surface's model translation
// 1 / vertex count to colour by growth order, else 0. A tracked surface's
// vertices are numbered in the order the tracker reached them, breadth-first
// from the seed, so the vertex number is the growth order.
uniform float uGrowthScale;

out vec3 vPositionView;
out vec3 vNormalView;
out float vGrowth;

void main() {
    vec4 positionView = uView * vec4(aPosition + uOffset, 1.0);
    vPositionView = positionView.xyz;
    vNormalView = mat3(uView) * aNormal;
    vGrowth = float(gl_VertexID) * uGrowthScale;
    gl_Position = uProjection * positionView;
}
