// Time series: ParaView collections (.pvd), 4D NIfTI, numbered files, and single volumes as one step.
#include "isotrack/time_series.h"

#include <expat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <system_error>
#include <type_traits>

#include "io_common.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"

namespace isotrack {

namespace {

using namespace detail;

constexpr std::uint64_t kMaxCollectionBytes = std::uint64_t(64) << 20;
constexpr std::size_t kMaxSteps = 1000000;
constexpr int kMaxDepth = 8;

struct Collection {
    std::string path;
    std::vector<std::string> element;  // the open elements
    std::string fileType;
    std::vector<TimeStep> steps;
    std::string error;
    XML_Parser parser = nullptr;
};

void stop(Collection& c, const std::string& error) {
    if (c.error.empty()) c.error = error;
    XML_StopParser(c.parser, XML_FALSE);
}

const char* attribute(const XML_Char** attrs, const char* name) {
    for (int i = 0; attrs[i]; i += 2)
        if (std::strcmp(attrs[i], name) == 0) return attrs[i + 1];
    return nullptr;
}

void addDataSet(Collection& c, const XML_Char** attrs) {
    const std::string at = "DataSet " + std::to_string(c.steps.size()) + ": ";
    if (c.steps.size() == kMaxSteps) return stop(c, "more than " + std::to_string(kMaxSteps) + " DataSets");
    const char* part = attribute(attrs, "part");
    if (part && std::string(part) != "0")
        return stop(c, at + "part \"" + printable(part) + "\": only one part per time step can be read");
    const char* file = attribute(attrs, "file");
    if (!file || !*file) return stop(c, at + "missing required field \"file\"");
    const char* timestep = attribute(attrs, "timestep");
    const auto time = parseFinite(timestep ? timestep : std::to_string(c.steps.size()));
    if (!time) return stop(c, at + "field \"timestep\": \"" + printable(timestep) + "\" is not a finite number");
    std::filesystem::path step(file);
    if (step.is_relative()) step = std::filesystem::path(c.path).parent_path() / step;
    if (lowerExtension(step.string()) == ".pvd")
        return stop(c, at + "\"" + printable(file) + "\" is another .pvd; a DataSet must be a volume file");
    c.steps.push_back(TimeStep{*time, step.string()});
}

void XMLCALL startElement(void* user, const XML_Char* name, const XML_Char** attrs) {
    Collection& c = *static_cast<Collection*>(user);
    const std::string parent = c.element.empty() ? "" : c.element.back();
    c.element.emplace_back(name);
    if (c.element.size() > std::size_t(kMaxDepth))
        return stop(c, "elements are nested deeper than " + std::to_string(kMaxDepth));
    const std::string element = name;
    if (parent.empty()) {
        if (element != "VTKFile")
            return stop(c, "not a VTK XML file: the root element is <" + printable(element) + ">");
        const char* type = attribute(attrs, "type");
        c.fileType = type ? type : "";
        if (c.fileType != "Collection")
            return stop(c, "field \"VTKFile\": type \"" + printable(c.fileType) + "\" is not Collection");
    } else if (parent == "Collection" && element == "DataSet") {
        addDataSet(c, attrs);
    }
}

void XMLCALL endElement(void* user, const XML_Char*) { static_cast<Collection*>(user)->element.pop_back(); }

void XMLCALL doctype(void* user, const XML_Char*, const XML_Char*, const XML_Char*, int) {
    stop(*static_cast<Collection*>(user), "a DOCTYPE is not allowed in a VTK XML file");
}

TimeSeries readCollection(const std::string& path) {
    const std::uint64_t size = fileSizeOf(path, path);
    if (size > kMaxCollectionBytes) throw FormatError(path + ": a .pvd collection of more than 64 MiB");
    FilePtr f = openForReading(path);
    std::string text(std::size_t(size), '\0');
    if (std::fread(text.data(), 1, text.size(), f.get()) != text.size())
        throw FormatError(path + ": cannot read: " + std::strerror(errno));
    std::unique_ptr<std::remove_pointer_t<XML_Parser>, void (*)(XML_Parser)> parser(XML_ParserCreate(nullptr),
                                                                                    XML_ParserFree);
    if (!parser) throw FormatError(path + ": cannot create an XML parser");
    Collection c;
    c.path = path;
    c.parser = parser.get();
    XML_SetUserData(parser.get(), &c);
    XML_SetElementHandler(parser.get(), startElement, endElement);
    XML_SetStartDoctypeDeclHandler(parser.get(), doctype);
    if (XML_Parse(parser.get(), text.data(), int(text.size()), XML_TRUE) != XML_STATUS_OK) {
        if (!c.error.empty()) throw FormatError(path + ": " + c.error);
        throw FormatError(path + ": XML error at line " + std::to_string(XML_GetCurrentLineNumber(parser.get())) +
                          ": " + XML_ErrorString(XML_GetErrorCode(parser.get())));
    }
    if (c.steps.empty()) throw FormatError(path + ": no DataSet in the Collection");
    std::stable_sort(c.steps.begin(), c.steps.end(),
                     [](const TimeStep& a, const TimeStep& b) { return a.time < b.time; });
    return TimeSeries{path, std::move(c.steps)};
}

// A printf pattern of one integer ("step_%04d.nrrd": prefix, zero padding, width,
// suffix); "%%" is a literal '%'. nullopt for a path without exactly one.
struct NumberPattern {
    std::string prefix, suffix;
    bool zeros = false;
    int width = 0;
    std::string name(std::size_t i) const {
        std::string digits = std::to_string(i);
        if (int(digits.size()) < width) digits.insert(0, std::size_t(width) - digits.size(), zeros ? '0' : ' ');
        return prefix + digits + suffix;
    }
};

std::optional<NumberPattern> numberPattern(const std::string& path) {
    NumberPattern pattern;
    bool found = false;
    for (std::size_t i = 0; i < path.size(); ++i) {
        std::string& out = found ? pattern.suffix : pattern.prefix;
        if (path[i] != '%') {
            out += path[i];
            continue;
        }
        if (i + 1 < path.size() && path[i + 1] == '%') {
            out += '%', ++i;
            continue;
        }
        if (found) return std::nullopt;
        std::size_t j = i + 1;
        if (j < path.size() && path[j] == '0') pattern.zeros = true, ++j;
        while (j < path.size() && std::isdigit(static_cast<unsigned char>(path[j])) && pattern.width < 100)
            pattern.width = pattern.width * 10 + (path[j++] - '0');
        if (j >= path.size() || path[j] != 'd') return std::nullopt;
        found = true;
        i = j;
    }
    if (!found) return std::nullopt;
    return pattern;
}

bool isFile(const std::string& path) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error);
}

// Files numbered from 0 (or 1) on, to the first number missing; the time is the number.
TimeSeries readNumbered(const std::string& path, const NumberPattern& pattern) {
    std::size_t first = isFile(pattern.name(0)) ? 0 : 1;
    if (!isFile(pattern.name(first)))
        throw FormatError(path + ": no file matches the pattern: neither \"" + printable(pattern.name(0)) +
                          "\" nor \"" + printable(pattern.name(1)) + "\" is a file");
    TimeSeries series{path, {}};
    for (std::size_t i = first; isFile(pattern.name(i)); ++i) {
        if (series.steps.size() == kMaxSteps)
            throw FormatError(path + ": more than " + std::to_string(kMaxSteps) + " numbered files");
        series.steps.push_back(TimeStep{double(i), pattern.name(i)});
    }
    return series;
}

}  // namespace

TimeSeries readTimeSeries(const std::string& path) {
    if (!isFile(path))
        if (const auto pattern = numberPattern(path)) return readNumbered(path, *pattern);
    const auto format = volumeFormatOf(path);
    if (format == VolumeFormat::VtkCollection) return readCollection(path);
    TimeSeries series{path, {}};
    if (format == VolumeFormat::Nifti) {
        for (const double time : niftiStepTimes(path)) series.steps.push_back(TimeStep{time, path});
    } else if (format == VolumeFormat::Nrrd) {
        const std::size_t steps = nrrdSteps(path);
        for (std::size_t t = 0; t < steps; ++t) series.steps.push_back(TimeStep{double(t), path});
    } else {
        series.steps.push_back(TimeStep{0.0, path});
    }
    return series;
}

Volume loadTimeStep(const TimeSeries& series, std::size_t step, const std::string& array) {
    const std::size_t count = series.steps.size();
    if (step >= count)
        throw InputError(series.path + ": no time step " + std::to_string(step) + ": it has " + std::to_string(count) +
                         (count == 1 ? " step (0)" : " steps (0.." + std::to_string(count - 1) + ")"));
    const std::string& file = series.steps[step].file;
    const auto format = volumeFormatOf(file);
    if (!array.empty() && format != VolumeFormat::VtkImageData)
        throw InputError(file + ": an array name (--array) is only for .vti files");
    if (format == VolumeFormat::Nifti && file == series.path) return loadNifti(file, step);
    if (format == VolumeFormat::Nrrd && file == series.path) return loadNrrd(file, step);
    if (file == series.path) return format == VolumeFormat::VtkImageData ? loadVti(file, array) : loadVolume(file);
    // A collection's step: its message names the collection too.
    const std::string where = series.path + ": step " + std::to_string(step) + ": ";
    try {
        return format == VolumeFormat::VtkImageData ? loadVti(file, array) : loadVolume(file);
    } catch (const FormatError& e) {
        throw FormatError(where + e.what());
    } catch (const InputError& e) {
        throw InputError(where + e.what());
    }
}

}  // namespace isotrack
