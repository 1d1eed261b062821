#include "isotrack/source.h"

#include <cmath>
#include <utility>

#include "isotrack/fields.h"

namespace isotrack {

LoadedSource loadSource(const VolumeSource& source) {
    LoadedSource loaded;
    if (source.kind == VolumeSource::Kind::Field) {
        const FieldSpec spec = parseFieldSpec(source.text);
        loaded.volume = makeField(spec);
        loaded.name = spec.name + ":" + std::to_string(spec.size);
        loaded.defaultIso = fieldDefaultIso(spec.name);
        return loaded;
    }
    loaded.volume = source.raw ? loadRaw(source.text, *source.raw) : loadVolume(source.text);
    loaded.name = source.text;
    const auto range = loaded.volume.range();
    if (std::isfinite(range[0])) loaded.defaultIso = (range[0] + range[1]) / 2.0;
    return loaded;
}

}  // namespace isotrack
