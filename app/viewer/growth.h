#pragma once
// Growing tracked surfaces a budget at a time: each frame the growing
// surfaces share a time budget (or, in deterministic sessions, a cell count)
// and append what they grew to their GPU buffers. Play, pause and step.
#include <cstddef>

#include "viewer/profiler.h"
#include "viewer/scene.h"

namespace isotrack::viewer {

class Growth {
public:
    // Grows the scene's growing surfaces by this frame's budget.
    void grow(Scene& scene, Profiler& profiler);
    void beginFrame() { grownCells_ = 0; }
    std::size_t grownCells() const { return grownCells_; }  // this frame

    bool playing() const { return playing_; }
    void play() { playing_ = true; }
    void pause() { playing_ = false; }
    void step();  // one frame's growth, then paused

    int cellsPerFrame() const { return cellsPerFrame_; }  // 0: a time budget
    void setCellsPerFrame(int cells) { cellsPerFrame_ = cells; }
    float budgetMs() const { return budgetMs_; }
    void setBudgetMs(float ms);  // clamped to [0.25, 1000]

private:
    bool playing_ = true;
    bool stepOnce_ = false;
    int cellsPerFrame_ = 0;
    float budgetMs_ = 4.0f;
    std::size_t grownCells_ = 0;
};

}  // namespace isotrack::viewer
