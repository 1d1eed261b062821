#pragma once
// Time series for the `isotrack` package: a step's volume as numpy arrays,
// steps read one ahead (core's TimeStepReader) and surfaces followed through
// the steps (core's SurfaceTimeline: the records of extract --all-times'
// track.json).
#include <pybind11/pybind11.h>

namespace isotrack::python {

// Adds load, steps, StepReader and follow_through_time to the module.
void addTimeFunctions(pybind11::module_& m);

}  // namespace isotrack::python
