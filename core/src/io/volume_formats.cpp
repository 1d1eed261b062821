// Choosing a volume loader by extension, and headerless raw files.
#include <string>

#include "io_common.h"
#include "isotrack/dicom.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/time_series.h"

namespace isotrack {

namespace {

constexpr const char* kHeaderExtensions =
    ".nrrd, .nhdr, .nii, .nii.gz, .mhd, .mha, .vtk, .vti, .pvd, .dcm, a DICOM folder or DICOMDIR";

// Headerless samples: the layout the caller gives is the whole header.
class RawReader : public detail::VolumeReader {
public:
    RawReader(const std::string& path, const RawLayout& layout)
        : VolumeReader(path, "dims"), bigEndian_(layout.bigEndian) {
        geometry_.dims = layout.dims;
        geometry_.type = layout.type;
        geometry_.spacing = layout.spacing;
        geometry_.origin = layout.origin;
    }

    Volume read() const {
        detail::sampleBytes(geometry_);
        detail::checkGeometry(geometry_, "spacing", "origin");
        detail::SampleData data;
        data.path = path();
        data.bigEndian = bigEndian_;
        return readVolume(data);
    }

private:
    bool bigEndian_;
};

}  // namespace

const char* volumeFormatName(VolumeFormat format) {
    switch (format) {
        case VolumeFormat::Nrrd: return "NRRD";
        case VolumeFormat::Nifti: return "NIfTI-1";
        case VolumeFormat::MetaImage: return "MetaImage";
        case VolumeFormat::VtkLegacy: return "VTK legacy";
        case VolumeFormat::VtkImageData: return "VTK XML ImageData";
        case VolumeFormat::VtkCollection: return "ParaView collection";
        case VolumeFormat::Raw: return "raw";
        case VolumeFormat::Dicom: return "DICOM";
    }
    return "unknown";
}

std::optional<VolumeFormat> volumeFormatOf(const std::string& path) {
    const std::string ext = detail::lowerExtension(path);
    if (ext == ".nrrd" || ext == ".nhdr") return VolumeFormat::Nrrd;
    if (ext == ".nii" || ext == ".nii.gz") return VolumeFormat::Nifti;
    if (ext == ".mhd" || ext == ".mha") return VolumeFormat::MetaImage;
    if (ext == ".vtk") return VolumeFormat::VtkLegacy;
    if (ext == ".vti") return VolumeFormat::VtkImageData;
    if (ext == ".pvd") return VolumeFormat::VtkCollection;
    if (ext == ".raw") return VolumeFormat::Raw;
    if (isDicomPath(path)) return VolumeFormat::Dicom;
    return std::nullopt;
}

Volume loadVolume(const std::string& path) {
    const auto format = volumeFormatOf(path);
    if (!format)
        throw FormatError(path + ": unsupported volume file extension \"" +
                          detail::printable(detail::lowerExtension(path)) + "\" (supported: " + kHeaderExtensions +
                          "; a headerless raw file needs its dims and type)");
    switch (*format) {
        case VolumeFormat::Nrrd: return loadNrrd(path);
        case VolumeFormat::Nifti: return loadNifti(path);
        case VolumeFormat::MetaImage: return loadMetaImage(path);
        case VolumeFormat::VtkLegacy: return loadVtkLegacy(path);
        case VolumeFormat::VtkImageData: return loadVti(path);
        case VolumeFormat::VtkCollection: return loadTimeStep(readTimeSeries(path), 0);
        case VolumeFormat::Dicom: return loadDicom(path);
        case VolumeFormat::Raw: break;
    }
    throw FormatError(path + ": a raw file has no header: give its dims and type, or use a format that has one (" +
                      kHeaderExtensions + ")");
}

Volume loadRaw(const std::string& path, const RawLayout& layout) { return RawReader(path, layout).read(); }

}  // namespace isotrack
