// 8-bit RGB images and PNG output.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace litkit {

// Row-major 8-bit RGB, row 0 at the top (docs/spec.md §1).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;  // width · height · 3

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0) {}
    std::uint8_t* pixel(int x, int y) { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
    const std::uint8_t* pixel(int x, int y) const {
        return &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
    }
};

// The PNG file bytes of `image` (8-bit RGB). zlib `compression_level` 0–9;
// the default, 1, is the measured best trade of time for size on rendered
// pictures (docs/performance.md).
inline constexpr int default_png_compression = 1;
std::string encode_png(const Image& image, int compression_level = default_png_compression);

// Writes `image` as a PNG, whole or not at all (write_file_atomically).
// Throws IoError (Access::Write) on failure, leaving any old file untouched.
void write_png(const Image& image, const std::filesystem::path& path);

// Reads an 8-bit RGB or RGBA PNG (alpha dropped). Throws IoError.
Image read_png(const std::filesystem::path& path);

}  // namespace litkit
