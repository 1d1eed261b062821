#version 330 core
// Picking: surfaces drawn with the scene's camera into an R32UI id buffer.

layout(location = 0) in vec3 aPosition;

uniform mat4 uViewProjection;
uniform vec3 uOffset;  // the surface's model translation

void main() {
    gl_Position = uViewProjection * vec4(aPosition + uOffset, 1.0);
}
