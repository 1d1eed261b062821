#pragma once
// Volumes as the viewer loads them (LoadedVolume: the samples and what the
// panel shows about them; loadForView), and what the extraction worker keeps
// between requests (VolumeCache): the volume loaded last
// (with what the panel shows about it), its contour tree, built on the first
// request that needs it, and a copy simplified by the last persistence asked
// for, each laid out for the panel's plot. Arcs keep their numbers in the copy
// (pruned ones are only marked), so surfaces match across both. Used from the
// worker's thread only.
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "isotrack/contour_tree.h"
#include "isotrack/dicom.h"
#include "isotrack/errors.h"
#include "isotrack/mapped_file.h"
#include "isotrack/source.h"
#include "isotrack/time_series.h"
#include "isotrack/time_step_reader.h"
#include "isotrack/tree_layout.h"

namespace isotrack::viewer {

// What the panel calls a source: the field spec, or the file's name.
std::string displayName(const VolumeSource& source);

// The same data, perhaps at another time step.
bool sameSeries(const VolumeSource& a, VolumeSource b);

// A loaded volume and what the panel shows about it.
struct LoadedVolume {
    VolumeSource source;
    Volume volume;
    std::array<double, 2> range{0.0, 0.0};
    std::vector<float> histogram;       // sample counts in kHistogramBins bins across `range`
    double defaultIso = 0.0;            // a field's own, or suggestIsovalue for a file
    std::vector<DicomSkipped> skipped;  // a DICOM folder or DICOMDIR: the files left out, and why
    // A mapped file's samples (isotrack/mapped_file.h): its bytes, and whether
    // they exceed the memory budget. Over it, the samples were not read:
    // `range`, `histogram` and `defaultIso` are unknown (valuesRead false).
    const MappedFile* mapped = nullptr;
    std::uint64_t mappedBytes = 0;
    bool overBudget = false;
    bool valuesRead = true;
    // A time series' step (source.time): the step's volume, read by a
    // TimeStepReader, whose samples `volume` views; null for a single volume.
    std::shared_ptr<const Volume> step;
};

inline constexpr std::size_t kHistogramBins = 128;

// Loads a source as the viewer shows it (volume, range, histogram, default
// isovalue). A mapped volume over `memoryBudget` bytes is left unread, and
// needs `isoGiven` (InputError naming the file, its size and the budget).
std::shared_ptr<LoadedVolume> loadForView(const VolumeSource& source, bool isoGiven = false,
                                          std::uint64_t memoryBudget = std::numeric_limits<std::uint64_t>::max());
// The same for step `source.time` of a time series already read by `reader`
// (which prefetches the step after it meanwhile).
std::shared_ptr<LoadedVolume> loadStepForView(const VolumeSource& source, TimeStepReader& reader, bool isoGiven,
                                              std::uint64_t memoryBudget);

// A volume over the budget has no default isovalue (it would read every
// sample): the error that says so.
InputError overBudgetWithoutIso(const LoadedVolume& volume, std::uint64_t memoryBudget);

// The viewer's memory budget when none is given: half of the memory the system
// can give without swapping (isotrack::availableMemoryBytes).
std::uint64_t defaultMemoryBudget();

class VolumeCache {
public:
    VolumeCache(std::uint64_t memoryBudget, std::size_t plotBranches)
        : memoryBudget_(memoryBudget), plotBranches_(plotBranches) {}

    // The volume kept, when it is `source`'s; else null.
    std::shared_ptr<const LoadedVolume> find(const VolumeSource& source) const;
    // Loads `source` (loadForView); the volume kept and its trees go first.
    // With `series` (a time series of more than one step, source.text's), the
    // step source.time comes from a TimeStepReader kept for the series, which
    // reads the next step in the background meanwhile.
    std::shared_ptr<const LoadedVolume> load(const VolumeSource& source, bool isoGiven,
                                             const std::shared_ptr<const TimeSeries>& series = nullptr);

    bool hasTree() const { return tree_ != nullptr; }
    // Builds the volume's contour tree (progress: the build's; Cancelled through its cancel flag).
    void buildTree(int threads, ContourTreeProgress* progress);
    struct Tree {
        std::shared_ptr<const ContourTree> tree;
        std::shared_ptr<const TreeLayout> layout;
    };
    // The tree built, simplified by `minPersistence` when > 0 (a copy, kept for the next request).
    Tree tree(double minPersistence);

private:
    const std::uint64_t memoryBudget_;
    const std::size_t plotBranches_;
    std::shared_ptr<const LoadedVolume> volume_;
    std::unique_ptr<TimeStepReader> reader_;         // the time series loaded last (readerOf_'s), one step ahead
    VolumeSource readerOf_;                          // its source, time aside
    std::shared_ptr<const ContourTree> tree_;        // volume_'s
    std::shared_ptr<const ContourTree> simplified_;  // tree_ simplified by simplifiedBy_ (> 0)
    double simplifiedBy_ = 0.0;
    std::shared_ptr<const TreeLayout> fullLayout_;        // tree_'s plot
    std::shared_ptr<const TreeLayout> simplifiedLayout_;  // simplified_'s plot
};

}  // namespace isotrack::viewer
