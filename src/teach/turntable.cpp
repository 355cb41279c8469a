// SPDX-License-Identifier: MIT
// litkit turntable: the observer on its circle, and animated GIF output.
#include "litkit/turntable.hpp"

#include <gif_lib.h>

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

#include "core/files.hpp"
#include "core/portable_math.hpp"
#include "litkit/error.hpp"

namespace litkit {

Observer orbit(const Observer& observer, double degrees) {
    // Rodrigues' rotation of the offset from look_at about the unit up axis,
    // in double so that frame k of N lands where k·360°/N says.
    const glm::dvec3 axis = glm::normalize(glm::dvec3(observer.up));
    const glm::dvec3 offset = glm::dvec3(observer.position) - glm::dvec3(observer.look_at);
    const SineCosine angle = sin_cos_degrees(degrees);  // the same bits in every build
    const double c = angle.cosine, s = angle.sine;
    const glm::dvec3 turned =
        offset * c + glm::cross(axis, offset) * s + axis * glm::dot(axis, offset) * (1.0 - c);
    Observer result = observer;
    result.position = glm::vec3(glm::dvec3(observer.look_at) + turned);
    return result;
}

namespace {

struct GifCloser {
    void operator()(GifFileType* gif) const {
        int error = 0;
        EGifCloseFile(gif, &error);
    }
};

int append_bytes(GifFileType* gif, const GifByteType* bytes, int count) {
    static_cast<std::string*>(gif->UserData)
        ->append(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(count));
    return count;
}

}  // namespace

void write_gif(std::span<const Image> frames, const std::filesystem::path& path, int delay_ms) {
    const auto fail = [&](const std::string& why) {
        throw IoError(path.string(), why, {}, IoError::Access::Write);
    };
    if (frames.empty()) fail("no frames to write");
    const int width = frames[0].width, height = frames[0].height;
    if (width < 1 || height < 1 || width > 65535 || height > 65535)
        fail("a GIF frame must be 1-65535 pixels a side");

    std::string bytes;
    int error = 0;
    std::unique_ptr<GifFileType, GifCloser> gif(EGifOpen(&bytes, append_bytes, &error));
    if (!gif) fail(GifErrorString(error));
    EGifSetGifVersion(gif.get(), true);
    const auto check = [&](int status) {
        if (status == GIF_ERROR) fail(GifErrorString(gif->Error));
    };
    check(EGifPutScreenDesc(gif.get(), width, height, 8, 0, nullptr));
    // NETSCAPE2.0: loop for ever.
    const GifByteType netscape[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
    const GifByteType loop[] = {1, 0, 0};
    check(EGifPutExtensionLeader(gif.get(), APPLICATION_EXT_FUNC_CODE));
    check(EGifPutExtensionBlock(gif.get(), sizeof netscape, netscape));
    check(EGifPutExtensionBlock(gif.get(), sizeof loop, loop));
    check(EGifPutExtensionTrailer(gif.get()));

    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    std::vector<GifByteType> red(pixels), green(pixels), blue(pixels), indices(pixels);
    std::vector<GifColorType> palette(256);
    for (const Image& frame : frames) {
        if (frame.width != width || frame.height != height)
            fail("every frame of a GIF must have the size of the first");
        for (std::size_t i = 0; i < pixels; ++i) {
            red[i] = frame.rgb[3 * i];
            green[i] = frame.rgb[3 * i + 1];
            blue[i] = frame.rgb[3 * i + 2];
        }
        int colours = 256;
        if (GifQuantizeBuffer(static_cast<unsigned>(width), static_cast<unsigned>(height), &colours,
                              red.data(), green.data(), blue.data(), indices.data(),
                              palette.data()) == GIF_ERROR)
            fail("could not reduce a frame to 256 colours");
        GraphicsControlBlock control{};
        control.DisposalMode = DISPOSE_DO_NOT;
        control.DelayTime = (delay_ms + 5) / 10;
        control.TransparentColor = NO_TRANSPARENT_COLOR;
        GifByteType extension[4];
        const std::size_t length = EGifGCBToExtension(&control, extension);
        check(EGifPutExtension(gif.get(), GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length),
                               extension));
        // A local palette of a power-of-two size, as GIF requires.
        int size = 2;
        while (size < colours) size *= 2;
        std::unique_ptr<ColorMapObject, void (*)(ColorMapObject*)> map(
            GifMakeMapObject(size, palette.data()), GifFreeMapObject);
        if (!map) fail("out of memory for a palette");
        check(EGifPutImageDesc(gif.get(), 0, 0, width, height, false, map.get()));
        for (int y = 0; y < height; ++y)
            check(EGifPutLine(gif.get(), indices.data() + static_cast<std::size_t>(y) * width,
                              width));
    }
    int close_error = 0;
    if (EGifCloseFile(gif.release(), &close_error) == GIF_ERROR) fail(GifErrorString(close_error));
    write_file_atomically(path, bytes);
}

}  // namespace litkit
