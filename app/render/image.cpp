#include "render/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>
#include <memory>
#include <string>

#include "isotrack/safe_write.h"

namespace isotrack::render {

Image imageFromBottomUp(int width, int height, const std::vector<std::uint8_t>& rgba) {
    Image image(width, height);
    const std::size_t rowBytes = std::size_t(width) * 4;
    if (rgba.size() != rowBytes * std::size_t(height)) throw ImageError("pixel buffer does not match the image size");
    for (int y = 0; y < height; ++y) {
        std::memcpy(image.pixel(0, y), rgba.data() + std::size_t(height - 1 - y) * rowBytes, rowBytes);
    }
    return image;
}

void writePng(const Image& image, const std::string& path) {
    std::vector<std::uint8_t> rgb(std::size_t(image.width) * std::size_t(image.height) * 3);
    for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i) std::memcpy(&rgb[i * 3], &image.rgba[i * 4], 3);
    // Encoded in memory, then written through the safe writer (an existing file survives a failure).
    std::string png;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
    };
    if (stbi_write_png_to_func(append, &png, image.width, image.height, 3, rgb.data(), image.width * 3) == 0) {
        throw ImageError(path + ": cannot encode PNG");
    }
    writeFileSafely(path, png);
}

Image readPng(const std::string& path) {
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(path.c_str(), &width, &height, &channels, 4),
                                                     stbi_image_free);
    if (!pixels) throw ImageError(path + ": cannot read PNG (" + stbi_failure_reason() + ")");
    Image image(width, height);
    std::memcpy(image.rgba.data(), pixels.get(), image.rgba.size());
    return image;
}

}  // namespace isotrack::render
