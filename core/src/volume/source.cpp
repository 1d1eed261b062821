#include "isotrack/source.h"

#include <cmath>
#include <utility>

#include "isotrack/dicom.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/isovalue.h"
#include "isotrack/time_series.h"

namespace isotrack {

LoadedSource loadSource(const VolumeSource& source, DefaultIso defaultIso) {
    LoadedSource loaded;
    if (source.kind == VolumeSource::Kind::Field) {
        const FieldSpec spec = parseFieldSpec(source.text);
        loaded.volume = makeField(spec);
        loaded.name = spec.name + ":" + std::to_string(spec.size);
        loaded.defaultIso = fieldDefaultIso(spec.name);
        return loaded;
    }
    const bool dicom = !source.series.empty() || volumeFormatOf(source.text) == VolumeFormat::Dicom;
    if (!source.array.empty() && (source.raw || dicom))
        throw InputError(source.text + ": an array name (--array) is only for .vti files");
    if (source.time != 0 && (source.raw || dicom))
        throw InputError(source.text + ": a time step (--time) is only for .pvd collections and 4D NIfTI");
    if (source.raw) {
        loaded.volume = loadRaw(source.text, *source.raw);
    } else if (dicom) {
        DicomVolume read = readDicom(source.text, source.series);
        loaded.volume = std::move(read.volume);
        loaded.dicom = std::move(read.contents);
        loaded.dicomSeries = read.series;
    } else {
        loaded.volume = loadTimeStep(readTimeSeries(source.text), source.time, source.array);
    }
    loaded.name = source.text;
    if (defaultIso == DefaultIso::Skip) return loaded;
    const auto range = loaded.volume.range();
    if (std::isfinite(range[0])) loaded.defaultIso = suggestIsovalue(loaded.volume, range);
    return loaded;
}

}  // namespace isotrack
