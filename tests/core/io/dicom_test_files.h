#pragma once
// DICOM files written by the tests themselves: explicit VR little endian, one
// element at a time, so that a test can state exactly what a slice holds or lies about.
#include <cstdint>
#include <map>
#include <string>
#include <utility>

#include "io_test_files.h"

namespace isotrack::testing {

class DicomSlice {
public:
    // A 16-bit unsigned slice of columns x rows at z, identity orientation, samples v + z.
    DicomSlice(int columns, int rows, double z, const std::string& seriesUid = "1.2.3.4") {
        text(0x0008, 0x0016, "UI", "1.2.840.10008.5.1.4.1.1.2");
        text(0x0008, 0x0018, "UI", "1.2.3.4.5." + std::to_string(int(z * 1000) + 1000000));
        text(0x0008, 0x0060, "CS", "CT");
        text(0x0020, 0x000e, "UI", seriesUid);
        text(0x0020, 0x0032, "DS", "0\\0\\" + number(z));
        text(0x0020, 0x0037, "DS", "1\\0\\0\\0\\1\\0");
        text(0x0028, 0x0030, "DS", "0.5\\0.75");
        us(0x0028, 0x0002, 1);
        text(0x0028, 0x0004, "CS", "MONOCHROME2");
        us(0x0028, 0x0010, std::uint16_t(rows));
        us(0x0028, 0x0011, std::uint16_t(columns));
        us(0x0028, 0x0100, 16);
        us(0x0028, 0x0101, 12);
        us(0x0028, 0x0102, 11);
        us(0x0028, 0x0103, 0);
        std::string pixels;
        for (int y = 0; y < rows; ++y)
            for (int x = 0; x < columns; ++x) pixels += encode(std::uint16_t(x + 10 * y + int(z)), false);
        pixelData(pixels);
    }

    static std::string number(double v) {
        std::string s = std::to_string(v);
        s.erase(s.find_last_not_of('0') + 1);
        if (!s.empty() && s.back() == '.') s.pop_back();
        return s;
    }

    // A string element, padded to even length.
    void text(std::uint16_t group, std::uint16_t element, const char* vr, std::string value) {
        if (value.size() % 2) value += vr == std::string("UI") ? '\0' : ' ';
        raw(group, element, vr, value);
    }
    void us(std::uint16_t group, std::uint16_t element, std::uint16_t value) {
        raw(group, element, "US", encode(value, false));
    }
    void pixelData(const std::string& bytes) { raw(0x7fe0, 0x0010, "OW", bytes); }
    // Any element, with the length it declares (which may lie about the bytes that follow).
    void raw(std::uint16_t group, std::uint16_t element, const char* vr, const std::string& value,
             std::uint64_t declared = ~std::uint64_t(0)) {
        elements_[{group, element}] = {vr, {value, declared == ~std::uint64_t(0) ? value.size() : declared}};
    }
    void erase(std::uint16_t group, std::uint16_t element) { elements_.erase({group, element}); }
    std::string transferSyntax = "1.2.840.10008.1.2.1";  // explicit VR little endian; the dataset is always written so

    std::string bytes() const {
        std::string out(128, '\0');
        out += "DICM";
        const auto uid = [](std::string u) { return u.size() % 2 ? u + '\0' : u; };
        const auto ui = [&](std::uint16_t e, const std::string& u) {
            return element(0x0002, e, "UI", uid(u), uid(u).size());
        };
        std::string meta = element(0x0002, 0x0001, "OB", std::string("\0\1", 2), 2) +
                           ui(0x0002, "1.2.840.10008.5.1.4.1.1.2") + ui(0x0003, "1.2.3.4.5.6") +
                           ui(0x0010, transferSyntax);
        meta.insert(0, element(0x0002, 0x0000, "UL", encode(std::uint32_t(meta.size()), false), 4));
        out += meta;
        for (const auto& [tag, entry] : elements_)
            out += element(tag.first, tag.second, entry.first.c_str(), entry.second.first, entry.second.second);
        return out;
    }

private:
    static std::string element(std::uint16_t group, std::uint16_t element, const char* vr, const std::string& value,
                               std::uint64_t declared) {
        std::string out = encode(group, false) + encode(element, false) + vr;
        const std::string v = vr;
        if (v == "OB" || v == "OW" || v == "SQ" || v == "UN" || v == "UT")
            out += std::string(2, '\0') + encode(std::uint32_t(declared), false);
        else
            out += encode(std::uint16_t(declared), false);
        return out + value;
    }

    std::map<std::pair<std::uint16_t, std::uint16_t>, std::pair<std::string, std::pair<std::string, std::uint64_t>>>
        elements_;
};

}  // namespace isotrack::testing
