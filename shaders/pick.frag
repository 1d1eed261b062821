#version 330 core
// Writes the surface's pick id (0 is the background) to the id buffer.

flat in uint vId;

out uint pickId;

void main() {
    pickId = vId;
}
