#pragma once
// What the commands say about a DICOM folder, DICOMDIR or file: the files
// skipped (a warning line each on stderr, and in --json), and info's list of
// the series with whether each forms a volume.
#include <cstddef>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "isotrack/dicom.h"

namespace isotrack::cli {

// "isotrack: FILE: skipped: WHY" on stderr, one line per skipped file.
void warnSkipped(const DicomContents& contents);

// "dicom_skipped": N and "dicom_skipped_files": [{"file", "why"}], added to `report`.
void addSkippedJson(nlohmann::json& report, const DicomContents& contents);

// Every series: number (for --series N), uid, description, modality, images,
// dims, volume (whether it forms one), problem and detail (null when it does),
// read (the one loaded, `read`).
nlohmann::json seriesJson(const DicomContents& contents, std::optional<std::size_t> read);

// info's listing: per series a line with its number, modality, description,
// size and whether it forms a volume (and why not), and a line with its UID;
// then the count of skipped files.
void printSeries(const DicomContents& contents, std::optional<std::size_t> read);

// info's error when no series forms a volume: the message, then the series on
// following lines, on stderr.
void printNoVolume(const std::string& path, const DicomContents& contents);

}  // namespace isotrack::cli
