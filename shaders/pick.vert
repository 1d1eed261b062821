#version 330 core
// Picking: surfaces drawn with the scene's camera into an R32UI id buffer; the
// offset and the id come from the surface table (surface.vert).

layout(location = 0) in vec3 aPosition;
layout(location = 2) in uint aSlot;

uniform mat4 uViewProjection;
uniform samplerBuffer uSurfaces;

flat out uint vId;

void main() {
    int entry = int(aSlot) * 3;
    vec3 offset = texelFetch(uSurfaces, entry + 1).xyz;
    vId = uint(texelFetch(uSurfaces, entry + 2).y);
    gl_Position = uViewProjection * vec4(aPosition + offset, 1.0);
}
