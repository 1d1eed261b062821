#version 330 core
// Writes the surface's id (index + 1; 0 is the background) to the id buffer.

uniform uint uId;

out uint pickId;

void main() {
    pickId = uId;
}
