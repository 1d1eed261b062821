// libFuzzer target: ParaView collections (.pvd) through the time series reader.
// The input's directory also holds step.vti, a valid 2 x 2 x 2 volume, so that
// DataSets naming it reach the step loader.
#include "fuzz_harness.h"
#include "isotrack/time_series.h"

namespace {

const char kStep[] =
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
    "<ImageData WholeExtent=\"0 1 0 1 0 1\" Origin=\"0 0 0\" Spacing=\"1 1 1\"><Piece Extent=\"0 1 0 1 0 1\">"
    "<PointData><DataArray type=\"UInt8\" Name=\"s\" format=\"ascii\">0 1 2 3 4 5 6 7</DataArray></PointData>"
    "</Piece></ImageData>\n</VTKFile>\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string step =
        isotrack::fuzz::writeInput(reinterpret_cast<const std::uint8_t*>(kStep), sizeof kStep - 1, "step.vti");
    (void)step;
    const std::string path = isotrack::fuzz::writeInput(data, size, "input.pvd");
    isotrack::fuzz::tryLoad(
        [](const std::string& p) {
            const isotrack::TimeSeries series = isotrack::readTimeSeries(p);
            return isotrack::loadTimeStep(series, series.steps.size() - 1);
        },
        path);
    return 0;
}
