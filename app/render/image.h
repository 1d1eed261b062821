#pragma once
// RGBA8 images in memory and as PNG files.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace isotrack::render {

class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // top row first, 4 bytes per pixel

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(std::size_t(w) * std::size_t(h) * 4, 0) {}

    std::uint8_t* pixel(int x, int y) {
        return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
    const std::uint8_t* pixel(int x, int y) const {
        return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
};

// Builds an image from GL's bottom-row-first pixels.
Image imageFromBottomUp(int width, int height, const std::vector<std::uint8_t>& rgba);

// Writes an 8-bit RGB PNG (alpha dropped: isotrack's pictures are opaque). The
// same pixels always give the same bytes. Throws ImageError naming the file.
void writePng(const Image& image, const std::string& path);

// Reads any PNG stb_image understands, as RGBA. Throws ImageError naming the file.
Image readPng(const std::string& path);

}  // namespace isotrack::render
