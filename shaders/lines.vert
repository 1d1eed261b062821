#version 330 core
// Lines in one colour: the bounding box (uOffset, uColour), and the wireframe
// pass over surfaces, which reuses the surfaces' vertex arrays (positions and
// slot numbers) and reads offset and colour from the surface table (surface.vert).

layout(location = 0) in vec3 aPosition;
layout(location = 2) in uint aSlot;

uniform mat4 uViewProjection;
uniform vec3 uOffset;
uniform vec3 uColour;
uniform bool uFromTable;
uniform float uDarkening;  // wireframes: the surface's colour times this
uniform samplerBuffer uSurfaces;

flat out vec3 vColour;

void main() {
    vec3 offset = uOffset;
    vColour = uColour;
    if (uFromTable) {
        int entry = int(aSlot) * 3;
        vColour = texelFetch(uSurfaces, entry).rgb * uDarkening;
        offset = texelFetch(uSurfaces, entry + 1).xyz;
    }
    gl_Position = uViewProjection * vec4(aPosition + offset, 1.0);
}
