// Time series for the `isotrack` package (time_module.h).
#include "time_module.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/follow_time.h"
#include "isotrack/orientation.h"
#include "isotrack/tables.h"
#include "isotrack/threads.h"
#include "isotrack/time_step_reader.h"
#include "mesh_output.h"

namespace isotrack::python {
namespace {

py::dtype dtypeOf(ScalarType type) {
    switch (type) {
        case ScalarType::UInt8: return py::dtype::of<std::uint8_t>();
        case ScalarType::Int8: return py::dtype::of<std::int8_t>();
        case ScalarType::UInt16: return py::dtype::of<std::uint16_t>();
        case ScalarType::Int16: return py::dtype::of<std::int16_t>();
        case ScalarType::UInt32: return py::dtype::of<std::uint32_t>();
        case ScalarType::Int32: return py::dtype::of<std::int32_t>();
        case ScalarType::Float32: return py::dtype::of<float>();
        case ScalarType::Float64: break;
    }
    return py::dtype::of<double>();
}

py::tuple triple(const Vec3d& v) { return py::make_tuple(v[0], v[1], v[2]); }

// (samples, spacing, origin, direction columns), isotrack's (x, y, z) and LPS;
// the samples array keeps the volume (or a share of it) alive.
template <class Owned>
py::tuple volumeArrays(Owned owned, const Volume& volume) {
    const Dims dims = volume.dims();
    py::capsule owner = ownerOf(std::move(owned));
    py::array samples(dtypeOf(volume.type()), {py::ssize_t(dims[2]), py::ssize_t(dims[1]), py::ssize_t(dims[0])},
                      static_cast<const void*>(volume.bytes()), owner);
    // Read-only: mapped samples live in a read-only map of the file (a write would
    // crash), and a loaded volume is the file's, in memory or not.
    samples.attr("setflags")(py::arg("write") = false);
    const Mat3d& d = volume.direction();
    return py::make_tuple(samples, triple(volume.spacing()), triple(volume.origin()),
                          py::make_tuple(triple(d[0]), triple(d[1]), triple(d[2])));
}

// Time step `time` (0 for a single volume) and, for a .vti, PointData `array`.
py::tuple loadPy(const std::string& path, std::size_t time, const std::string& array) {
    std::shared_ptr<const Volume> volume;
    {
        py::gil_scoped_release unlocked;
        volume = std::make_shared<const Volume>(loadTimeStep(readTimeSeries(path), time, array));
    }
    return volumeArrays(volume, *volume);
}

py::object orNone(const std::optional<std::uint32_t>& value) {
    return value ? py::object(py::int_(*value)) : py::object(py::none());
}

// One surface's record: the keys of track.json's (but "file"), and with
// `meshes` its Surface (None unless shown), in the frame.
py::dict surfaceRecord(StepSurface& s, bool meshes) {
    py::dict d;
    d["id"] = s.id;
    d["continues"] = orNone(s.continues);
    d["split"] = s.split;
    d["presence"] = presenceName(s.presence);
    d["merged_into"] = orNone(s.mergedInto);
    d["ended"] = s.ended;
    d["triangles"] = s.surface ? s.surface->mesh.triangleCount() : 0;
    d["area"] = s.surface ? s.surface->stats.area : 0.0;
    d["volume"] = s.surface && s.surface->stats.enclosedVolume
                      ? py::object(py::float_(*s.surface->stats.enclosedVolume))
                      : py::object(py::none());
    d["closed"] = s.surface ? s.surface->stats.closed : false;
    if (s.surface) {
        const SurfaceStats& stats = s.surface->stats;
        d["bounds"] = py::make_tuple(triple(stats.boundsMin), triple(stats.boundsMax));
    } else {
        d["bounds"] = py::none();
    }
    if (meshes) {
        if (s.surface) {
            d["surface"] = py::cast(PySurface{std::move(*s.surface), false});
        } else {
            d["surface"] = py::none();
        }
    }
    return d;
}

// Every step of `path`, its surfaces followed: {"isovalue", "steps": [{"step",
// "time", "seconds", "surfaces": [records]}]}. A seed is a world point in `frame`.
py::dict followThroughTimePy(const std::string& path, const std::string& array, std::optional<double> level,
                             const std::string& method, const std::string& table, int threads,
                             std::optional<Vec3d> seed, const std::string& frame, double minPersistence,
                             std::size_t minSize, bool meshes) {
    TimeFollowOptions options;
    options.iso = level;
    options.method = parseMethod(method);
    options.table = parseTableKind(table);
    options.threads = threads > 0 ? threads : defaultThreadCount();
    options.minPersistence = minPersistence;
    options.minSize = minSize;
    options.frame = parseWorldFrame(frame);
    options.seed = seed;
    SurfaceTimeline timeline(options);  // its argument errors before anything is read
    TimeStepReader reader(path, array);
    py::list steps;
    for (std::size_t k = 0; k < reader.size(); ++k) {
        StepSurfaces step;
        {
            py::gil_scoped_release unlocked;
            const std::shared_ptr<const Volume> volume = reader.load(k);
            step = timeline.next(*volume, reader.time(k));
        }
        py::list surfaces;
        for (StepSurface& s : step.surfaces) surfaces.append(surfaceRecord(s, meshes));
        py::dict record;
        record["step"] = step.step;
        record["time"] = step.time;
        record["seconds"] = step.seconds;
        record["surfaces"] = surfaces;
        steps.append(record);
    }
    py::dict out;
    out["isovalue"] = timeline.iso() ? py::object(py::float_(*timeline.iso())) : py::object(py::none());
    out["steps"] = steps;
    return out;
}

// Steps read one ahead, for isotrack.load_steps.
class StepReaderPy {
public:
    StepReaderPy(const std::string& path, const std::string& array) : reader_(path, array) {}
    std::size_t size() const { return reader_.size(); }
    double time(std::size_t step) const { return reader_.time(step); }
    py::tuple load(std::size_t step) {
        std::shared_ptr<const Volume> volume;
        {
            py::gil_scoped_release unlocked;
            volume = reader_.load(step);
        }
        return volumeArrays(volume, *volume);
    }

private:
    TimeStepReader reader_;
};

}  // namespace

void addTimeFunctions(py::module_& m) {
    m.def("load", &loadPy, py::arg("path"), py::arg("time"), py::arg("array"));
    m.def(
        "steps",
        [](const std::string& path) {
            std::vector<std::pair<double, std::string>> steps;
            for (const TimeStep& step : readTimeSeries(path).steps) steps.emplace_back(step.time, step.file);
            return steps;
        },
        py::arg("path"));
    py::class_<StepReaderPy>(m, "StepReader")
        .def(py::init<const std::string&, const std::string&>(), py::arg("path"), py::arg("array"))
        .def("__len__", &StepReaderPy::size)
        .def("time", &StepReaderPy::time, py::arg("step"))
        .def("load", &StepReaderPy::load, py::arg("step"));
    m.def("follow_through_time", &followThroughTimePy, py::arg("path"), py::arg("array"), py::arg("level"),
          py::arg("method"), py::arg("table"), py::arg("threads"), py::arg("seed"), py::arg("frame"),
          py::arg("min_persistence"), py::arg("min_size"), py::arg("meshes"));
}

}  // namespace isotrack::python
