#version 330 core
// Lines in one colour: the bounding box, and the wireframe pass over surfaces
// (which reuses a surface's vertex array; only its positions are read).

layout(location = 0) in vec3 aPosition;

uniform mat4 uViewProjection;
uniform vec3 uOffset;

void main() {
    gl_Position = uViewProjection * vec4(aPosition + uOffset, 1.0);
}
