#pragma once
// Shared by the GL tests: one headless context per test process, and the
// golden-image comparison.
//
// Backend: OSMesa, the reference the baselines are drawn with, unless the
// environment variable ISOTRACK_TEST_GL is "egl" or "auto" (docs/headless.md);
// ctest runs the GL tests both ways (gl/... and gl-egl/...). Under egl a test
// process exits with 77 (skipped) when EGL offers nothing to try.
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

// Makes the shared headless context current (created on first use, backend as
// above) and turns GL error checks on. Call at the top of every test that touches GL.
void useHeadlessGl();

struct GoldenTolerance {
    int channelTolerance = 8;
    double maxDifferentFraction = 0.005;
};

// Under EGL on llvmpipe (Mesa's surfaceless platform) the golden images match
// OSMesa's exactly, so each test keeps its own tolerance. On a GPU the
// baselines are still OSMesa's and the GPU rasterises edges and lines by its
// own rules: every test's tolerance is raised to at least these. On an NVIDIA
// H100 (driver 580) at most 0.008% of a golden image's pixels differed by more
// than 8/255 (docs/headless.md); 0.5% leaves sixty times that.
constexpr int kGpuChannelTolerance = 8;
constexpr double kGpuDifferentFraction = 0.005;

// `tolerance` as used with the current context's backend (above).
GoldenTolerance forCurrentBackend(GoldenTolerance tolerance);

// Checks `actual` against tests/golden/<name>.png as described above (Catch2 assertions).
void checkGolden(const std::string& name, const render::Image& actual, const GoldenTolerance& tolerance = {});

// 320x240 pictures of surfaces inside `volume`'s box, as the golden tests take them.
render::Image renderForGolden(const std::vector<const Mesh*>& surfaces, const Volume& volume,
                              render::SnapshotOptions options = {});

}  // namespace isotrack::test
