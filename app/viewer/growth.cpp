#include "viewer/growth.h"

#include <algorithm>
#include <chrono>
#include <cstdint>

namespace isotrack::viewer {

void Growth::step() {
    playing_ = false;
    stepOnce_ = true;
}

void Growth::setBudgetMs(float ms) { budgetMs_ = std::clamp(ms, 0.25f, 1000.0f); }

void Growth::grow(Scene& scene, Profiler& profiler) {
    if (!playing_ && !stepOnce_) return;
    std::size_t growing = 0;
    for (const auto& surface : scene.surfaces()) growing += surface->growing() ? 1 : 0;
    if (growing == 0) return;
    GrowthBudget budget;
    if (cellsPerFrame_ > 0) {
        budget.cells = std::max<std::size_t>(std::size_t(cellsPerFrame_) / growing, 1);
    } else {
        const double ms = double(budgetMs_) / double(growing);
        budget.time = std::chrono::nanoseconds(static_cast<std::int64_t>(ms * 1e6));
    }
    for (auto& surface : scene.surfaces()) {
        if (!surface->growing()) continue;
        const auto start = Profiler::Clock::now();
        const GrowthStep step = surface->grow(budget);
        profiler.add(Stage::Extract, start, step.extract);
        profiler.add(Stage::Upload, start + step.extract, step.upload);
        grownCells_ += step.cells;
    }
    if (scene.explode() != 0.0f) scene.refreshOffsets();  // growing surfaces move their centres
    stepOnce_ = false;
}

}  // namespace isotrack::viewer
