#pragma once
// Fixed-function state the renderer sets per frame or per pass.
#include <glm/vec4.hpp>

namespace isotrack::gl {

void setViewport(int x, int y, int width, int height);
void clear(const glm::vec4& colour);  // colour and depth (to 1)

void setDepthTest(bool enabled);
// Depth test passes when the fragment is nearer or at the same depth, so a
// second pass over the same triangles (wireframe lines) is not rejected.
void setDepthLessEqual(bool lessEqual);
void setDepthWrite(bool enabled);

// Pushes filled polygons back by factor * slope + units * resolution, so lines
// drawn over them win the depth test. Zero turns it off.
void setPolygonOffsetFill(float factor, float units);
// Rasterise triangles as their edges instead of filled.
void setPolygonLines(bool lines);

void setMultisample(bool enabled);
void setFaceCulling(bool enabled);

// Blocks until the GL has finished every queued command (for timing).
void finish();

}  // namespace isotrack::gl
