#pragma once
// Volumes that change over time: a list of steps, each a time value and where
// its 3D volume is; a step is read only when asked for, one at a time.
//
// A ParaView collection (.pvd: <Collection><DataSet timestep=".." file=".."/>)
// has one step per DataSet, its file relative to the .pvd, in the order of their
// time values; a 4D NIfTI has dim[4] steps (loadNifti), a 4D NRRD its last
// axis's size (loadNrrd, each at its index as time). A path that is not a file
// and holds one printf integer ("step_%04d.nrrd"; "%%" is a '%') names numbered
// files: from 0 (or 1 when there is no 0) to the first number missing, each at
// its number as time. Any other volume file is one step at time 0, the file itself.
#include <cstddef>
#include <string>
#include <vector>

#include "isotrack/volume.h"

namespace isotrack {

struct TimeStep {
    double time = 0.0;
    std::string file;  // the file that holds the step's volume
};

struct TimeSeries {
    std::string path;  // the .pvd, or the volume file itself
    std::vector<TimeStep> steps;
};

// The steps of `path`; reads a .pvd or a NIfTI header, no samples. FormatError
// for a .pvd that is not a Collection of DataSets with a file and a finite
// timestep each, that names another .pvd, or that holds more than one part per
// step.
TimeSeries readTimeSeries(const std::string& path);

// Step `step`'s volume; `array` picks a .vti's PointData array (loadVti).
// InputError naming the series when there is no such step.
Volume loadTimeStep(const TimeSeries& series, std::size_t step, const std::string& array = "");

}  // namespace isotrack
