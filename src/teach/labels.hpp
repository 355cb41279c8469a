// SPDX-License-Identifier: MIT
// Text for picture labels (litkit compare), drawn with FreeType in DejaVu Sans.
#pragma once

#include <memory>
#include <string_view>

#include "litkit/image.hpp"
#include "litkit/scene.hpp"

namespace litkit::detail {

class Font {
  public:
    // DejaVu Sans at `pixel_height` pixels per em, from the paths Debian's
    // fonts-dejavu-core installs. Throws IoError when no such file can be
    // loaded, naming the package.
    explicit Font(int pixel_height);
    ~Font();
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    int width(std::string_view text) const;  // advance of the whole line, pixels
    int ascent() const;                      // above the baseline, pixels
    int descent() const;                     // below the baseline, pixels (≥ 0)

    // Draws `text` with its baseline at `baseline` and its left edge at `x`,
    // blending the glyphs' coverage over what is there; clipped to the image.
    void draw(Image& image, int x, int baseline, std::string_view text, const Rgb8& color) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace litkit::detail
