// SPDX-License-Identifier: MIT
#include "teach/labels.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <array>
#include <cmath>
#include <string>

#include "litkit/error.hpp"

namespace litkit::detail {

namespace {

// Where Debian's fonts-dejavu-core puts the font (and where other
// distributions commonly do).
constexpr std::array font_paths{
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    "/usr/local/share/fonts/DejaVuSans.ttf",
};

}  // namespace

struct Font::Impl {
    FT_Library library = nullptr;
    FT_Face face = nullptr;

    ~Impl() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }

    // Renders one character into the face's glyph slot; false if the font
    // lacks it or FreeType fails (the character is then skipped).
    bool load(char c) const {
        return FT_Load_Char(face, static_cast<unsigned char>(c), FT_LOAD_RENDER) == 0;
    }
};

Font::Font(int pixel_height) : impl_(std::make_unique<Impl>()) {
    if (FT_Init_FreeType(&impl_->library) != 0)
        throw IoError("DejaVuSans.ttf", "FreeType could not start");
    for (const char* path : font_paths) {
        if (FT_New_Face(impl_->library, path, 0, &impl_->face) == 0) break;
        impl_->face = nullptr;
    }
    if (!impl_->face) {
        throw IoError("DejaVuSans.ttf",
                      "no font for the labels (install Debian's fonts-dejavu-core, or leave the "
                      "labels out)");
    }
    FT_Set_Pixel_Sizes(impl_->face, 0, static_cast<FT_UInt>(pixel_height));
}

Font::~Font() = default;

int Font::width(std::string_view text) const {
    long advance = 0;
    for (char c : text)
        if (impl_->load(c)) advance += impl_->face->glyph->advance.x;
    return static_cast<int>((advance + 63) / 64);
}

int Font::ascent() const {
    return static_cast<int>((impl_->face->size->metrics.ascender + 63) / 64);
}

int Font::descent() const {
    return static_cast<int>((-impl_->face->size->metrics.descender + 63) / 64);
}

void Font::draw(Image& image, int x, int baseline, std::string_view text, const Rgb8& color) const {
    long pen = static_cast<long>(x) * 64;
    for (char c : text) {
        if (!impl_->load(c)) continue;
        const FT_GlyphSlot glyph = impl_->face->glyph;
        const FT_Bitmap& bitmap = glyph->bitmap;
        const int left = static_cast<int>(pen / 64) + glyph->bitmap_left;
        const int top = baseline - glyph->bitmap_top;
        for (unsigned row = 0; row < bitmap.rows; ++row) {
            const int y = top + static_cast<int>(row);
            if (y < 0 || y >= image.height) continue;
            for (unsigned column = 0; column < bitmap.width; ++column) {
                const int px = left + static_cast<int>(column);
                if (px < 0 || px >= image.width) continue;
                const unsigned coverage =
                    bitmap.buffer[row * static_cast<unsigned>(bitmap.pitch) + column];
                if (coverage == 0) continue;
                std::uint8_t* out = image.pixel(px, y);
                for (int k = 0; k < 3; ++k) {
                    out[k] = static_cast<std::uint8_t>(
                        (color[k] * coverage + out[k] * (255 - coverage) + 127) / 255);
                }
            }
        }
        pen += glyph->advance.x;
    }
}

}  // namespace litkit::detail
