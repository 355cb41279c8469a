// SPDX-License-Identifier: MIT
/// \file
/// 8-bit RGB images and PNG output.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace litkit {

/// Row-major 8-bit RGB, row 0 at the top (docs/spec.md §1).
struct Image {
    /// Width in pixels.
    int width = 0;
    /// Height in pixels.
    int height = 0;
    std::vector<std::uint8_t> rgb;  ///< width · height · 3: r, g, b per pixel, rows top down

    /// An empty image, 0 × 0.
    Image() = default;
    /// A black image of `w` × `h` pixels (both ≥ 0).
    Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0) {}
    /// The r, g, b bytes of pixel (x, y), x from the left, y from the top.
    /// Not checked: 0 ≤ x < width and 0 ≤ y < height is the caller's to keep.
    std::uint8_t* pixel(int x, int y) {
        return &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
    }
    /// The r, g, b bytes of pixel (x, y), read only; not checked either.
    const std::uint8_t* pixel(int x, int y) const {
        return &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
    }
};

/// The zlib level encode_png uses unless told: 1, the measured best trade of
/// time for size on rendered pictures (docs/performance.md).
inline constexpr int default_png_compression = 1;
/// The PNG file bytes of `image` (8-bit RGB), zlib `compression_level` 0–9.
/// Level 1 is deflated by ISA-L where litkit was built with it (its bytes
/// may then differ between CPUs, its pixels never), the others by zlib.
std::string encode_png(const Image& image, int compression_level = default_png_compression);

/// Writes `image` as a PNG, whole or not at all (write_file_atomically).
/// Throws IoError (Access::Write) on failure, leaving any old file untouched.
void write_png(const Image& image, const std::filesystem::path& path);

/// An animated PNG (APNG, the PNG specification's acTL, fcTL and fdAT
/// chunks), put together frame by frame: each frame is deflated as
/// encode_png deflates a picture when it is added, and only its compressed
/// bytes are kept. Full colour, every frame whole (no palette, no
/// differences between frames); it loops forever. The first frame is also
/// the file's plain PNG picture, which a reader that knows no APNG shows.
class AnimatedPng {
  public:
    /// Each frame shown `delay_ms` milliseconds (1–65535), deflated at zlib
    /// `compression_level` 0–9 (ArgumentError otherwise).
    explicit AnimatedPng(int delay_ms = 40, int compression_level = default_png_compression);
    /// Adds the next frame. Every frame must have the first one's size, and
    /// pixels (ArgumentError otherwise).
    void add(const Image& frame);
    /// The frames added so far.
    int frames() const { return static_cast<int>(streams_.size()); }
    /// The file's bytes. Throws ArgumentError before the first frame.
    std::string bytes() const;
    /// Writes bytes() to `path`, whole or not at all (write_file_atomically).
    /// Throws IoError (Access::Write) on failure, leaving any old file untouched.
    void write(const std::filesystem::path& path) const;

  private:
    int delay_ms_;
    int compression_level_;
    int width_ = 0;
    int height_ = 0;
    std::vector<std::string> streams_;  // each frame's zlib stream
};

/// Reads an 8-bit RGB or RGBA PNG (alpha dropped). Throws IoError.
Image read_png(const std::filesystem::path& path);

}  // namespace litkit
