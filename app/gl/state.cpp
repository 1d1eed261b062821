#include "gl/state.h"

#include <glad/gl.h>

#include "gl/check.h"

namespace isotrack::gl {
namespace {

void toggle(GLenum capability, bool enabled) {
    if (enabled) {
        ISOTRACK_GL_CALL(glEnable(capability));
    } else {
        ISOTRACK_GL_CALL(glDisable(capability));
    }
}

}  // namespace

void setViewport(int x, int y, int width, int height) { ISOTRACK_GL_CALL(glViewport(x, y, width, height)); }

void clear(const glm::vec4& colour) {
    ISOTRACK_GL_CALL(glClearColor(colour.r, colour.g, colour.b, colour.a));
    ISOTRACK_GL_CALL(glClearDepth(1.0));
    ISOTRACK_GL_CALL(glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
}

void setDepthTest(bool enabled) { toggle(GL_DEPTH_TEST, enabled); }
void setDepthLessEqual(bool lessEqual) { ISOTRACK_GL_CALL(glDepthFunc(lessEqual ? GL_LEQUAL : GL_LESS)); }
void setDepthWrite(bool enabled) { ISOTRACK_GL_CALL(glDepthMask(enabled ? GL_TRUE : GL_FALSE)); }

void setPolygonOffsetFill(float factor, float units) {
    const bool enabled = factor != 0.0f || units != 0.0f;
    toggle(GL_POLYGON_OFFSET_FILL, enabled);
    if (enabled) ISOTRACK_GL_CALL(glPolygonOffset(factor, units));
}

void setPolygonLines(bool lines) { ISOTRACK_GL_CALL(glPolygonMode(GL_FRONT_AND_BACK, lines ? GL_LINE : GL_FILL)); }

void setMultisample(bool enabled) { toggle(GL_MULTISAMPLE, enabled); }
void setFaceCulling(bool enabled) { toggle(GL_CULL_FACE, enabled); }

void finish() { ISOTRACK_GL_CALL(glFinish()); }

}  // namespace isotrack::gl
