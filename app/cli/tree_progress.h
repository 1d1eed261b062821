#pragma once
// The contour tree of a command's volume, with its progress on the terminal:
// while the build runs, stderr shows its phase and how far it has got, on one
// line redrawn ten times a second and cleared at the end. Only when stderr is
// a terminal, so that logs, pipes and --json stay as they were.
#include <array>

#include "isotrack/contour_tree.h"
#include "isotrack/volume.h"

namespace isotrack::cli {

// With `phaseSeconds`, each phase's wall time (ContourTreeProgress::seconds) goes there.
ContourTree buildContourTree(const Volume& volume, int threads, std::array<double, 4>* phaseSeconds = nullptr);

}  // namespace isotrack::cli
