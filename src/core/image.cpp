#include "litkit/image.hpp"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstring>
#include <stdexcept>
#include <string>

#include "litkit/error.hpp"
#include "core/files.hpp"

namespace litkit {

namespace {

// libpng reports errors by longjmp; the message is kept for our exception.
struct PngWriteState {
    std::string bytes;
    std::string error;
};

void on_png_error(png_structp png, png_const_charp message) {
    auto* state = static_cast<PngWriteState*>(png_get_error_ptr(png));
    if (state) state->error = message;
    png_longjmp(png, 1);
}
void on_png_warning(png_structp, png_const_charp) {}
void on_png_write(png_structp png, png_bytep data, png_size_t length) {
    auto* state = static_cast<PngWriteState*>(png_get_io_ptr(png));
    state->bytes.append(reinterpret_cast<const char*>(data), length);
}
void on_png_flush(png_structp) {}

// Encodes into state.bytes; returns false (with state.error) on failure.
// Nothing with a destructor lives between setjmp and longjmp.
bool encode_png(const Image& image, int level, PngWriteState& state) {
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, on_png_error, on_png_warning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &state, on_png_write, on_png_flush);
    // The "up" filter turns flat backgrounds and smooth gradients into runs
    // of zeros, which zlib's run-length strategy packs fastest: on the
    // default scene, 5.4 ms and 60 KB against 6.2 ms and 64 KB for level 1
    // with the default strategy (docs/performance.md).
    png_set_compression_level(png, level);
    png_set_compression_strategy(png, Z_RLE);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
                 static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y) {
        png_write_row(png, const_cast<png_bytep>(image.pixel(0, y)));
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

std::string encode_png(const Image& image, int compression_level) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
        throw ArgumentError("encode_png: image has no pixels or an inconsistent size");
    }
    PngWriteState state;
    state.bytes.reserve(image.rgb.size() / 4 + 1024);
    if (compression_level < 0 || compression_level > 9)
        throw ArgumentError("encode_png: compression level must be 0-9");
    if (!encode_png(image, compression_level, state)) {
        throw Error("PNG encoding failed: " +
                                 (state.error.empty() ? std::string("out of memory") : state.error));
    }
    return std::move(state.bytes);
}

void write_png(const Image& image, const std::filesystem::path& path) {
    write_file_atomically(path, encode_png(image));
}

Image read_png(const std::filesystem::path& path) {
    png_image decoded;
    std::memset(&decoded, 0, sizeof decoded);
    decoded.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&decoded, path.c_str())) {
        std::string reason = decoded.message;
        png_image_free(&decoded);
        throw IoError(path.string(), reason);
    }
    decoded.format = PNG_FORMAT_RGB;
    if (decoded.width > 16384 || decoded.height > 16384) {
        png_image_free(&decoded);
        throw IoError(path.string(), "image larger than 16384 pixels on a side");
    }
    Image image(static_cast<int>(decoded.width), static_cast<int>(decoded.height));
    if (!png_image_finish_read(&decoded, nullptr, image.rgb.data(), 0, nullptr)) {
        std::string reason = decoded.message;
        png_image_free(&decoded);
        throw IoError(path.string(), reason);
    }
    return image;
}

}  // namespace litkit
