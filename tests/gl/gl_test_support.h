#pragma once
// Shared by the GL tests: one headless context per test process, and the
// golden-image comparison.
//
// Golden metric: a pixel differs when any of its R, G, B channels differs from
// the baseline by more than `channelTolerance` (default 8 of 255); an image
// fails when more than `maxDifferentFraction` of its pixels differ (default
// 0.5%), or when its size differs. The slack absorbs llvmpipe's rounding
// differences between CPUs and Mesa versions, not changes anyone would see.
//
// On failure the actual image and a diff image (differing pixels in red, the
// rest a dimmed copy of the baseline) go to <build>/tests/golden_out/NAME.actual.png
// and NAME.diff.png, and both paths are printed. A missing baseline fails and
// writes the actual image. ISOTRACK_UPDATE_GOLDEN=1 writes the baselines
// instead of comparing (the CMake target `update-golden` does that for every
// [golden] test): look at the new images before committing them.
#include <string>
#include <vector>

#include "golden_compare.h"
#include "isotrack/mesh.h"
#include "isotrack/volume.h"
#include "render/image.h"
#include "render/snapshot.h"

namespace isotrack::test {

// Makes the shared OSMesa context current (created on first use) and turns GL
// error checks on. Call at the top of every test that touches GL.
void useHeadlessGl();

struct GoldenTolerance {
    int channelTolerance = 8;
    double maxDifferentFraction = 0.005;
};

// Checks `actual` against tests/golden/<name>.png as described above (Catch2 assertions).
void checkGolden(const std::string& name, const render::Image& actual, const GoldenTolerance& tolerance = {});

// 320x240 pictures of surfaces inside `volume`'s box, as the golden tests take them.
render::Image renderForGolden(const std::vector<const Mesh*>& surfaces, const Volume& volume,
                              render::SnapshotOptions options = {});

}  // namespace isotrack::test
