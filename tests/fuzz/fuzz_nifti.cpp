// libFuzzer target: the NIfTI-1 loader, on the input as .nii and gzip-compressed
// as .nii.gz. Both must agree: the same volume, or both refused.
#include <zlib.h>

#include <cstring>
#include <vector>

#include "fuzz_harness.h"
#include "isotrack/io.h"

namespace {

std::vector<std::uint8_t> gzip(const std::uint8_t* data, std::size_t size) {
    z_stream zs{};
    if (deflateInit2(&zs, Z_BEST_SPEED, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK) std::abort();
    std::vector<std::uint8_t> out(deflateBound(&zs, uLong(size)) + 64);
    zs.next_in = const_cast<Bytef*>(data);
    zs.avail_in = uInt(size);
    zs.next_out = out.data();
    zs.avail_out = uInt(out.size());
    if (deflate(&zs, Z_FINISH) != Z_STREAM_END) std::abort();
    out.resize(zs.total_out);
    deflateEnd(&zs);
    return out;
}

bool same(const isotrack::Volume& a, const isotrack::Volume& b) {
    return a.dims() == b.dims() && a.type() == b.type() && a.spacing() == b.spacing() && a.origin() == b.origin() &&
           a.byteSize() == b.byteSize() && std::memcmp(a.bytes(), b.bytes(), a.byteSize()) == 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using isotrack::fuzz::tryLoad;
    using isotrack::fuzz::writeInput;
    auto load = [](const std::string& p) { return isotrack::loadNifti(p); };
    const auto plain = tryLoad(load, writeInput(data, size, "input.nii"));
    const std::vector<std::uint8_t> packed = gzip(data, size);
    const auto compressed = tryLoad(load, writeInput(packed.data(), packed.size(), "input.nii.gz"));
    if (plain.has_value() != compressed.has_value() || (plain && !same(*plain, *compressed))) std::abort();
    return 0;
}
