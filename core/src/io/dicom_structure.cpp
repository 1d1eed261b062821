// The element walk: see dicom_structure.h. Part 5 of the DICOM standard (data
// structures and encoding), sections 7.1 (data elements), 7.5 (sequences and
// items) and A.4 (encapsulated pixel data).
#include "dicom_structure.h"

#include <cstdio>
#include <cstring>
#include <set>
#include <string>

#include "io_common.h"
#include "isotrack/errors.h"

namespace isotrack::detail {

namespace {

constexpr std::uint32_t kUndefined = 0xffffffffu;
constexpr int kMaxDepth = 32;
constexpr std::uint32_t kItem = 0xfffee000u, kItemEnd = 0xfffee00du, kSequenceEnd = 0xfffee0ddu;
constexpr std::uint32_t kPixelData = 0x7fe00010u;

// VRs whose length is 4 bytes after 2 reserved ones in explicit VR.
const std::set<std::string> kLongVrs = {"OB", "OD", "OF", "OL", "OV", "OW", "SQ", "SV", "UC", "UN", "UR", "UT", "UV"};
const std::set<std::string> kShortVrs = {"AE", "AS", "AT", "CS", "DA", "DS", "DT", "FD", "FL", "IS", "LO",
                                         "LT", "PN", "SH", "SL", "SS", "ST", "TM", "UI", "UL", "US"};

std::string tagText(std::uint32_t tag) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "(%04X,%04X)", unsigned(tag >> 16), unsigned(tag & 0xffff));
    return buf;
}

class Walker {
public:
    Walker(std::string path, std::FILE* file, std::uint64_t size) : path_(std::move(path)), file_(file), size_(size) {}

    DicomStructure walk();

private:
    [[noreturn]] void fail(const std::string& problem) const { throw FormatError(path_ + ": " + problem); }

    void readAt(std::uint64_t at, unsigned char* out, std::size_t n, std::uint64_t end, const char* what) {
        if (at + n > end)
            fail(std::string("truncated: ") + what + " at byte " + std::to_string(at) + " runs past " +
                 (end == size_ ? "the end of the file" : "its sequence or item"));
        if (std::fseek(file_, long(at), SEEK_SET) != 0 || std::fread(out, 1, n, file_) != n)
            fail("cannot read at byte " + std::to_string(at));
    }
    std::uint16_t u16(const unsigned char* b) const {
        return bigEndian_ ? std::uint16_t(b[0] << 8 | b[1]) : std::uint16_t(b[1] << 8 | b[0]);
    }
    std::uint32_t u32(const unsigned char* b) const {
        return bigEndian_ ? std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 | b[3]
                          : std::uint32_t(b[3]) << 24 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[1]) << 8 | b[0];
    }
    std::uint32_t tagAt(const unsigned char* b) const { return std::uint32_t(u16(b)) << 16 | u16(b + 2); }

    // A delimitation item's length must be 0 (GDCM would size a buffer by it).
    std::uint64_t delimiterEnd(std::uint64_t at, std::uint32_t length) const {
        if (length != 0) fail("a delimitation item declares " + std::to_string(length) + " bytes, not 0");
        return at;
    }
    std::uint64_t metaGroup(std::uint64_t at);
    // Walks elements from `at` to `end` (or, when `delimited`, up to the item's end tag); returns where it stopped.
    std::uint64_t dataset(std::uint64_t at, std::uint64_t end, bool delimited, int depth);
    std::uint64_t sequence(std::uint64_t at, std::uint64_t length, std::uint64_t end, int depth);
    std::uint64_t fragments(std::uint64_t at, std::uint64_t end);
    void rleHeader(std::uint64_t at, std::uint32_t length);

    std::string path_;
    std::FILE* file_;
    std::uint64_t size_;
    bool explicitVr_ = true;
    bool bigEndian_ = false;
    DicomStructure out_;
};

std::uint64_t Walker::metaGroup(std::uint64_t at) {
    // Always explicit VR little endian.
    while (at + 8 <= size_) {
        unsigned char h[12];
        readAt(at, h, 8, size_, "a file meta element");
        if (u16(h) != 0x0002) break;
        const std::uint32_t tag = tagAt(h);
        const std::string vr(reinterpret_cast<const char*>(h + 4), 2);
        std::uint64_t length = 0, header = 8;
        if (kLongVrs.count(vr)) {
            readAt(at, h, 12, size_, "a file meta element");
            length = u32(h + 8), header = 12;
        } else if (kShortVrs.count(vr)) {
            length = u16(h + 6);
        } else {
            fail("file meta element " + tagText(tag) + " has no valid VR (\"" + printable(vr) + "\")");
        }
        if (length == kUndefined || at + header + length > size_)
            fail("truncated: file meta element " + tagText(tag) + " declares " + std::to_string(length) + " bytes, " +
                 std::to_string(size_ - std::min(size_, at + header)) + " remain");
        if (tag == 0x00020010u) {
            std::string uid(std::size_t(length), '\0');
            if (length)
                readAt(at + header, reinterpret_cast<unsigned char*>(&uid[0]), uid.size(), size_, "TransferSyntaxUID");
            while (!uid.empty() && (uid.back() == '\0' || uid.back() == ' ')) uid.pop_back();
            out_.transferSyntax = uid;
        }
        at += header + length;
    }
    return at;
}

// An RLE Lossless frame opens with 16 little-endian words: the segment count
// (1..15) and each segment's offset into the frame, the first 64, rising, all
// inside the frame. GDCM's RLE decoder seeks to the offsets unchecked.
void Walker::rleHeader(std::uint64_t at, std::uint32_t length) {
    constexpr std::uint32_t kHeaderBytes = 64, kMaxSegments = 15;
    if (length < kHeaderBytes) fail("an RLE frame of " + std::to_string(length) + " bytes has no 64-byte header");
    unsigned char h[kHeaderBytes];
    readAt(at, h, kHeaderBytes, size_, "an RLE frame header");
    const auto word = [&](std::uint32_t i) {
        const unsigned char* b = h + 4 * i;
        return std::uint32_t(b[3]) << 24 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[1]) << 8 | b[0];
    };
    const std::uint32_t segments = word(0);
    if (segments < 1 || segments > kMaxSegments)
        fail("an RLE frame declares " + std::to_string(segments) + " segments");
    std::uint32_t previous = 0;
    for (std::uint32_t s = 1; s <= segments; ++s) {
        const std::uint32_t offset = word(s);
        if ((s == 1 && offset != kHeaderBytes) || (s > 1 && offset <= previous) || offset >= length)
            fail("an RLE frame's segment " + std::to_string(s) + " starts at byte " + std::to_string(offset) + " of " +
                 std::to_string(length));
        previous = offset;
    }
}

std::uint64_t Walker::fragments(std::uint64_t at, std::uint64_t end) {
    out_.encapsulated = true;
    const bool rle = out_.transferSyntax == "1.2.840.10008.1.2.5";
    bool offsetTable = true;  // the first item is the basic offset table, not a frame
    while (true) {
        unsigned char h[8];
        readAt(at, h, 8, end, "an encapsulated pixel data item");
        const std::uint32_t tag = tagAt(h), length = u32(h + 4);
        at += 8;
        if (tag == kSequenceEnd) return delimiterEnd(at, length);
        if (tag != kItem) fail("encapsulated pixel data holds " + tagText(tag) + ", not an item");
        if (length == kUndefined || at + length > end)
            fail("truncated: a pixel data fragment declares " + std::to_string(length) + " bytes, " +
                 std::to_string(end - std::min(end, at)) + " remain");
        if (rle && !offsetTable) rleHeader(at, length);
        offsetTable = false;
        out_.pixelDataBytes += length;
        at += length;
    }
}

std::uint64_t Walker::sequence(std::uint64_t at, std::uint64_t length, std::uint64_t end, int depth) {
    if (depth > kMaxDepth) fail("sequences nested deeper than " + std::to_string(kMaxDepth));
    const bool delimited = length == kUndefined;
    const std::uint64_t stop = delimited ? end : at + length;
    while (delimited || at < stop) {
        unsigned char h[8];
        readAt(at, h, 8, stop, "a sequence item");
        const std::uint32_t tag = tagAt(h), itemLength = u32(h + 4);
        at += 8;
        if (delimited && tag == kSequenceEnd) return delimiterEnd(at, itemLength);
        if (tag != kItem) fail("a sequence holds " + tagText(tag) + ", not an item");
        if (itemLength == kUndefined) {
            at = dataset(at, stop, true, depth + 1);
        } else {
            if (at + itemLength > stop)
                fail("truncated: a sequence item declares " + std::to_string(itemLength) + " bytes, " +
                     std::to_string(stop - at) + " remain");
            dataset(at, at + itemLength, false, depth + 1);
            at += itemLength;
        }
    }
    return at;
}

std::uint64_t Walker::dataset(std::uint64_t at, std::uint64_t end, bool delimited, int depth) {
    while (delimited || at < end) {
        unsigned char h[12];
        readAt(at, h, 8, end, "an element");
        const std::uint32_t tag = tagAt(h);
        if (delimited && tag == kItemEnd) return delimiterEnd(at + 8, u32(h + 4));
        std::string vr;
        std::uint64_t length = 0, header = 8;
        if (!explicitVr_ || (tag >> 16) == 0xfffe) {
            length = u32(h + 4);
        } else {
            vr.assign(reinterpret_cast<const char*>(h + 4), 2);
            out_.explicitVrs.emplace_back(tag, vr);
            if (kLongVrs.count(vr)) {
                readAt(at, h, 12, end, "an element");
                length = u32(h + 8), header = 12;
            } else if (kShortVrs.count(vr)) {
                length = u16(h + 6);
            } else {
                fail("element " + tagText(tag) + " has no valid VR (\"" + printable(vr) + "\")");
            }
        }
        at += header;
        const bool isPixels = depth == 0 && tag == kPixelData;
        if (isPixels) out_.hasPixelData = true;
        if (length == kUndefined) {
            if (isPixels)
                at = fragments(at, end);
            else if (vr.empty() || vr == "SQ" || vr == "UN" || (vr == "OB" && tag == kPixelData))
                // GDCM asserts on any other explicit VR of undefined length (an icon's
                // encapsulated pixel data, deeper down, is the one OB it reads so).
                at = sequence(at, kUndefined, end, depth + 1);
            else
                fail("element " + tagText(tag) + " (" + vr + ") has an undefined length");
            continue;
        }
        if (at + length > end)
            fail("truncated: element " + tagText(tag) + " declares " + std::to_string(length) + " bytes, " +
                 std::to_string(end - std::min(end, at)) + " remain");
        if (isPixels) out_.pixelDataBytes = length;
        if (vr == "SQ") sequence(at, length, at + length, depth + 1);
        at += length;
    }
    return at;
}

DicomStructure Walker::walk() {
    unsigned char preamble[132];
    std::uint64_t at = 0;
    if (size_ >= 132) {
        readAt(0, preamble, 132, size_, "the preamble");
        out_.hasMagic = std::memcmp(preamble + 128, "DICM", 4) == 0;
    }
    if (out_.hasMagic) at = metaGroup(132);
    const std::string& ts = out_.transferSyntax;
    if (ts == "1.2.840.10008.1.2" || (!out_.hasMagic && ts.empty())) {
        explicitVr_ = false;  // implicit VR little endian, also what a file without meta group is taken to be
    } else if (ts == "1.2.840.10008.1.2.2") {
        bigEndian_ = true;
    } else if (ts == "1.2.840.10008.1.2.1.99") {
        fail("transfer syntax " + ts + " (deflated dataset) is not supported");
    } else if (ts.empty()) {
        fail("no TransferSyntaxUID in its file meta information");
    }
    if (at >= size_) fail("no dataset after its file meta information");
    const std::uint64_t end = dataset(at, size_, false, 0);
    if (end != size_) fail("the dataset ends at byte " + std::to_string(end) + " of " + std::to_string(size_));
    return out_;
}

}  // namespace

bool hasDicomMagic(const std::string& path) {
    FilePtr f = openForReading(path);
    char buf[132];
    return std::fread(buf, 1, sizeof buf, f.get()) == sizeof buf && std::memcmp(buf + 128, "DICM", 4) == 0;
}

DicomStructure checkDicomStructure(const std::string& path) {
    FilePtr f = openForReading(path);
    const std::uint64_t size = fileSizeOf(path, path);
    if (size == 0) throw FormatError(path + ": not a DICOM file: it is empty");
    return Walker(path, f.get(), size).walk();
}

}  // namespace isotrack::detail
