#pragma once
// GPU timer queries (GL_TIME_ELAPSED, core since GL 3.3 / ARB_timer_query):
// the time the GL spends executing the commands between begin() and end().
// Results arrive a few frames late; poll resultReady() instead of waiting.
#include <cstdint>

#include "gl/handle.h"

namespace isotrack::gl {

namespace detail {
void destroyQuery(unsigned id);
}

class TimerQuery {
public:
    TimerQuery();  // needs a current context
    TimerQuery(TimerQuery&&) noexcept = default;
    TimerQuery& operator=(TimerQuery&&) noexcept = default;
    TimerQuery(const TimerQuery&) = delete;
    TimerQuery& operator=(const TimerQuery&) = delete;
    ~TimerQuery() = default;

    // Only one time-elapsed query may be active at a time.
    void begin() const;
    void end() const;
    // Never blocks.
    bool resultReady() const;
    // Blocks until the result is known when it is not ready yet.
    std::uint64_t nanoseconds() const;

    unsigned id() const { return handle_.id(); }

private:
    UniqueHandle<detail::destroyQuery> handle_;
};

// True when the context counts timer queries with a non-zero precision.
bool timerQueriesAvailable();

}  // namespace isotrack::gl
