#version 330 core
// Surfaces: world-space vertices with per-vertex normals, moved by their
// surface's offset, lit in view space by surface.frag.
//
// Many surfaces draw in one call, so what differs per surface comes from the
// surface table (render/surface_arena.h), three texels per surface slot, found
// through the slot number every vertex carries:
//   [slot * 3 + 0] colour.rgb, highlight (1 for the selection, else 0)
//   [slot * 3 + 1] offset.xyz (the model translation), growth scale
//   [slot * 3 + 2] first vertex of the surface in its page, pick id

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in uint aSlot;

uniform mat4 uView;        // world to view; a rigid motion, so it also turns normals
uniform mat4 uProjection;
uniform samplerBuffer uSurfaces;

out vec3 vPositionView;
out vec3 vNormalView;
out float vGrowth;
flat out vec3 vColour;
flat out float vHighlight;
flat out float vGrowthScale;

void main() {
    int entry = int(aSlot) * 3;
    vec4 look = texelFetch(uSurfaces, entry);
    vec4 place = texelFetch(uSurfaces, entry + 1);
    float firstVertex = texelFetch(uSurfaces, entry + 2).x;
    vColour = look.rgb;
    vHighlight = look.a;
    vGrowthScale = place.w;
    vec4 positionView = uView * vec4(aPosition + place.xyz, 1.0);
    vPositionView = positionView.xyz;
    vNormalView = mat3(uView) * aNormal;
    // Growth scale: 1 / vertex count to colour by growth order, else 0. A tracked
    // surface's vertices are numbered in the order the tracker reached them,
    // breadth-first from the seed, so the vertex number is the growth order.
    // gl_VertexID counts from the page's first vertex (it includes the base vertex).
    vGrowth = float(gl_VertexID - int(firstVertex)) * place.w;
    gl_Position = uProjection * positionView;
}
