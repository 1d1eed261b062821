#include "viewer/volume_cache.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "isotrack/isovalue.h"
#include "isotrack/source.h"

namespace isotrack::viewer {
namespace {

std::vector<float> histogramOf(const Volume& volume, const std::array<double, 2>& range) {
    const std::vector<std::uint64_t> counts = sampleHistogram(volume, range, kHistogramBins);
    return std::vector<float>(counts.begin(), counts.end());
}

std::string gib(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.3g GiB", double(bytes) / double(std::uint64_t(1) << 30));
    return text;
}

}  // namespace

InputError overBudgetWithoutIso(const LoadedVolume& volume, std::uint64_t memoryBudget) {
    return InputError(volume.source.text + ": " + gib(volume.mappedBytes) + " mapped, over the memory budget of " +
                      gib(memoryBudget) + ": give --iso (a default isovalue reads every sample) or a larger " +
                      "--memory-budget");
}

std::string displayName(const VolumeSource& source) {
    if (source.kind == VolumeSource::Kind::Field) return source.text;
    return std::filesystem::path(source.text).filename().string();
}

std::uint64_t defaultMemoryBudget() { return availableMemoryBytes() / 2; }

namespace {

// Range, histogram and default isovalue (`defaultIso` when the source has its
// own, else core's suggestion), unless the volume is mapped and over the
// budget: then nothing is read and the isovalue must be given.
void describe(LoadedVolume& loaded, std::optional<double> defaultIso, bool isoGiven, std::uint64_t memoryBudget) {
    if (loaded.mapped) {
        loaded.mappedBytes = loaded.mapped->size();
        loaded.overBudget = loaded.mappedBytes > memoryBudget;
    }
    if (loaded.overBudget) {
        if (!isoGiven) throw overBudgetWithoutIso(loaded, memoryBudget);
        loaded.valuesRead = false;
        loaded.defaultIso = std::numeric_limits<double>::quiet_NaN();
        return;
    }
    loaded.range = loaded.volume.range();
    if (!std::isfinite(loaded.range[0])) throw InputError(loaded.source.text + ": no finite samples");
    loaded.defaultIso = defaultIso ? *defaultIso : suggestIsovalue(loaded.volume, loaded.range);
    loaded.histogram = histogramOf(loaded.volume, loaded.range);
}

}  // namespace

bool sameSeries(const VolumeSource& a, VolumeSource b) {
    b.time = a.time;
    return a == b;
}

// The samples are read (range, histogram, and for a file core's suggested
// isovalue) unless the volume is mapped and over the budget: then nothing is
// read until an extraction goes there, and the isovalue must be given.
std::shared_ptr<LoadedVolume> loadForView(const VolumeSource& source, bool isoGiven, std::uint64_t memoryBudget) {
    LoadedSource read = isotrack::loadSource(source, DefaultIso::Skip);
    auto loaded = std::make_shared<LoadedVolume>();
    loaded->source = source;
    loaded->volume = std::move(read.volume);
    if (read.dicom) loaded->skipped = read.dicom->skipped;
    loaded->mapped = loaded->volume.mappedFile();
    describe(*loaded, read.defaultIso, isoGiven, memoryBudget);
    return loaded;
}

std::shared_ptr<LoadedVolume> loadStepForView(const VolumeSource& source, TimeStepReader& reader, bool isoGiven,
                                              std::uint64_t memoryBudget) {
    auto loaded = std::make_shared<LoadedVolume>();
    loaded->source = source;
    loaded->step = reader.load(source.time);
    const Volume& step = *loaded->step;
    loaded->volume = Volume::view(step.dims(), step.type(), step.bytes(), step.spacing(), step.origin());
    loaded->volume.setDirection(step.direction());
    loaded->mapped = step.mappedFile();
    describe(*loaded, std::nullopt, isoGiven, memoryBudget);
    return loaded;
}

std::shared_ptr<const LoadedVolume> VolumeCache::find(const VolumeSource& source) const {
    return volume_ && volume_->source == source ? volume_ : nullptr;
}

std::shared_ptr<const LoadedVolume> VolumeCache::load(const VolumeSource& source, bool isoGiven,
                                                      const std::shared_ptr<const TimeSeries>& series) {
    volume_.reset();  // the old volume goes before the new one is read
    tree_.reset();
    simplified_.reset();
    fullLayout_.reset();
    simplifiedLayout_.reset();
    if (!series || series->steps.size() < 2) {
        reader_.reset();
        volume_ = loadForView(source, isoGiven, memoryBudget_);
        return volume_;
    }
    if (!reader_ || !sameSeries(source, readerOf_)) {
        reader_.reset();
        reader_ = std::make_unique<TimeStepReader>(*series, source.array);
        readerOf_ = source;
    }
    volume_ = loadStepForView(source, *reader_, isoGiven, memoryBudget_);
    return volume_;
}

void VolumeCache::buildTree(int threads, ContourTreeProgress* progress) {
    tree_ = std::make_shared<const ContourTree>(computeContourTree(volume_->volume, threads, progress));
    fullLayout_ = std::make_shared<const TreeLayout>(layoutContourTree(*tree_, plotBranches_));
}

VolumeCache::Tree VolumeCache::tree(double minPersistence) {
    if (minPersistence <= 0.0) return {tree_, fullLayout_};
    if (!simplified_ || simplifiedBy_ != minPersistence) {
        simplified_.reset();
        ContourTree simplified = *tree_;
        simplifyContourTree(simplified, minPersistence);
        simplified_ = std::make_shared<const ContourTree>(std::move(simplified));
        simplifiedLayout_ = std::make_shared<const TreeLayout>(layoutContourTree(*simplified_, plotBranches_));
        simplifiedBy_ = minPersistence;
    }
    return {simplified_, simplifiedLayout_};
}

}  // namespace isotrack::viewer
