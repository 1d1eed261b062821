#include "gl/timer_query.h"

#include <glad/gl.h>

#include "gl/check.h"
#include "gl/make_handle.h"

namespace isotrack::gl {

void detail::destroyQuery(unsigned id) { glDeleteQueries(1, &id); }

TimerQuery::TimerQuery() : handle_(makeHandle(glGenQueries, "glGenQueries", "query")) {}

void TimerQuery::begin() const { ISOTRACK_GL_CALL(glBeginQuery(GL_TIME_ELAPSED, handle_.id())); }

void TimerQuery::end() const { ISOTRACK_GL_CALL(glEndQuery(GL_TIME_ELAPSED)); }

bool TimerQuery::resultReady() const {
    GLuint available = GL_FALSE;
    ISOTRACK_GL_CALL(glGetQueryObjectuiv(handle_.id(), GL_QUERY_RESULT_AVAILABLE, &available));
    return available == GL_TRUE;
}

std::uint64_t TimerQuery::nanoseconds() const {
    GLuint64 result = 0;
    ISOTRACK_GL_CALL(glGetQueryObjectui64v(handle_.id(), GL_QUERY_RESULT, &result));
    return result;
}

bool timerQueriesAvailable() {
    GLint bits = 0;
    glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
    return glGetError() == GL_NO_ERROR && bits > 0;
}

}  // namespace isotrack::gl
