// SPDX-License-Identifier: MIT
#include "litkit/image.hpp"

#include <png.h>
#include <zlib.h>
#if defined(LITKIT_HAVE_LIBDEFLATE)
#include <libdeflate.h>
#endif
#if defined(LITKIT_HAVE_ISAL)
#include <isa-l/igzip_lib.h>
#endif

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "core/files.hpp"
#include "core/thread_pool.hpp"
#include "litkit/error.hpp"
#include "litkit/limits.hpp"

namespace litkit {

namespace {

// PNG output (docs/design.md, "PNG"): each row filtered with PNG's "up"
// filter, deflated at the default level 1 by ISA-L where the build has it
// (deflate_rows_isal) and otherwise, or at any other level, by zlib with
// its run-length strategy; the container written here. libpng compresses a
// picture as one stream on one thread; from `split_from_bytes` of filtered
// rows on, the lower half of the rows is deflated on a second thread apart
// from the upper, which ends on a byte boundary (a sync flush), and the two
// are joined: one zlib stream, its Adler-32 combined. The split depends
// only on the picture's size, and zlib's bytes are the same on every
// machine; ISA-L picks its code for the CPU at run time, so its bytes may
// differ between machines, never the pixels they decode to.
constexpr std::size_t split_from_bytes = std::size_t{512} << 10;
// With zlib, each half is deflated as a run of raw deflate streams of
// whole rows, at most this many filtered bytes each (or one row, if
// longer), each ended on a byte boundary (a sync flush) and the next begun
// afresh (deflateReset). zlib slides its window once a stream has taken 65,274
// bytes, and every 32 KiB after: it moves the window and rewrites its two
// 64 KiB hash tables, which its run-length strategy never reads. That was a
// third of the time (docs/performance.md, "zlib: streams that never slide":
// the default scene 5.7 -> 3.6 ms, 1920×1080 20.5 -> 11.9 ms, the files as
// small). Only runs within a stream are found, so a restart costs at most a run cut in two,
// the block it ends (a new one starts, with its own codes) and an empty
// stored block (5 bytes). A row longer than 65,274 bytes (21,758 pixels)
// still slides within itself, as before.
constexpr std::size_t stream_bytes = 64000;
// IDAT chunks of at most this many bytes (a chunk may hold 2^31 − 1).
constexpr std::size_t idat_chunk_bytes = std::size_t{1} << 20;

// Adler-32 (RFC 1950) of the filtered rows: libdeflate's, in vector
// instructions, where the build has it; zlib's otherwise. The same number.
uLong adler32_of(uLong adler, const unsigned char* data, std::size_t size) {
#if defined(LITKIT_HAVE_LIBDEFLATE)
    return libdeflate_adler32(static_cast<std::uint32_t>(adler), data, size);
#else
    return adler32(adler, data, static_cast<uInt>(size));
#endif
}

// One stretch of rows, deflated without the zlib header and trailer.
struct Piece {
    std::unique_ptr<unsigned char[]> bytes;  // not zero-filled: written once
    std::size_t capacity = 0;
    std::size_t size = 0;
    uLong adler = adler32(0L, Z_NULL, 0);
    uLong length = 0;  // filtered bytes in
};

void grow(Piece& piece, std::size_t capacity) {
    auto bigger = std::make_unique_for_overwrite<unsigned char[]>(capacity);
    if (piece.size) std::memcpy(bigger.get(), piece.bytes.get(), piece.size);
    piece.bytes = std::move(bigger);
    piece.capacity = capacity;
}

// Rows [first, end) of `image` with PNG's "up" filter (each byte minus the
// one above it, 0 above the first row), each after its filter-type byte,
// into `filtered`; and counted into the piece's Adler-32 and length.
void filter_rows(const Image& image, int first, int end, std::vector<unsigned char>& filtered,
                 Piece& piece) {
    const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
    filtered.resize((row_bytes + 1) * static_cast<std::size_t>(end - first));
    unsigned char* out = filtered.data();
    for (int y = first; y < end; ++y, out += row_bytes + 1) {
        out[0] = 2;  // "up"
        const std::uint8_t* row = image.pixel(0, y);
        if (y == 0) {
            std::memcpy(out + 1, row, row_bytes);
        } else {
            const std::uint8_t* above = image.pixel(0, y - 1);
            for (std::size_t i = 0; i < row_bytes; ++i)
                out[i + 1] = static_cast<unsigned char>(row[i] - above[i]);
        }
    }
    piece.adler = adler32_of(piece.adler, filtered.data(), filtered.size());
    piece.length += static_cast<uLong>(filtered.size());
}

// Room for a well-compressed picture (a quarter); grown when needed.
void reserve_quarter(Piece& piece, const Image& image, int rows) {
    grow(piece,
         (static_cast<std::size_t>(image.width) * 3 + 1) * static_cast<std::size_t>(rows) / 4 +
             1024);
}

#if defined(LITKIT_HAVE_ISAL)
// Level 1, the default: Intel's ISA-L (igzip, Debian's libisal-dev), whose
// deflate at its level 1 makes files about as small as zlib's level 1 with
// its run-length strategy, five times as fast (docs/performance.md,
// "The PNG: ISA-L": 0.7 against 3.8 ms for the default 800×600 picture on one
// thread). Rows go in batches of about this many filtered bytes.
constexpr std::size_t isal_batch_bytes = std::size_t{64} << 10;

void deflate_rows_isal(const Image& image, int first, int end, bool last, Piece& piece) {
    isal_zstream stream;
    isal_deflate_init(&stream);
    stream.level = 1;
    const auto level_buffer = std::make_unique_for_overwrite<std::uint8_t[]>(ISAL_DEF_LVL1_DEFAULT);
    stream.level_buf = level_buffer.get();
    stream.level_buf_size = ISAL_DEF_LVL1_DEFAULT;
    reserve_quarter(piece, image, end - first);
    const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3 + 1;
    const int batch = static_cast<int>(std::max<std::size_t>(1, isal_batch_bytes / row_bytes));
    std::vector<unsigned char> filtered;
    for (int y = first; y < end; y += batch) {
        const int batch_end = std::min(end, y + batch);
        filter_rows(image, y, batch_end, filtered, piece);
        stream.next_in = filtered.data();
        stream.avail_in = static_cast<std::uint32_t>(filtered.size());
        const bool final_batch = batch_end == end;
        // The last batch of a piece ends on a byte boundary (a sync flush:
        // an empty stored block) or, the picture's last, with the final block.
        stream.end_of_stream = final_batch && last;
        stream.flush = final_batch && !last ? SYNC_FLUSH : NO_FLUSH;
        for (;;) {
            if (piece.capacity - piece.size < 64) grow(piece, piece.capacity * 2);
            stream.next_out = piece.bytes.get() + piece.size;
            stream.avail_out = static_cast<std::uint32_t>(
                std::min<std::size_t>(piece.capacity - piece.size, std::size_t{1} << 30));
            if (isal_deflate(&stream) != COMP_OK)
                throw Error("PNG encoding failed: ISA-L stream error");
            piece.size = static_cast<std::size_t>(stream.next_out - piece.bytes.get());
            // Done with the batch when ISA-L has taken it all and, at a
            // piece's end, written everything it held back (igzip_lib.h).
            if (stream.avail_in != 0 || stream.avail_out == 0) continue;
            if (!final_batch) break;
            if (last ? stream.internal_state.state == ZSTATE_END
                     : stream.internal_state.state == ZSTATE_NEW_HDR)
                break;
        }
    }
}
#endif

// Rows [first, end): filtered, deflated raw by zlib in streams of whole
// rows (stream_bytes); the last piece ends with the final block, the others
// byte-aligned after a sync flush.
void deflate_rows_zlib(const Image& image, int first, int end, bool last, int level, Piece& piece) {
    z_stream stream{};
    if (deflateInit2(&stream, level, Z_DEFLATED, -15, 8, Z_RLE) != Z_OK)
        throw Error("PNG encoding failed: zlib could not start (out of memory)");
    struct End {
        z_stream& stream;
        ~End() { deflateEnd(&stream); }
    } end_stream{stream};
    reserve_quarter(piece, image, end - first);
    std::vector<unsigned char> filtered;
    std::size_t stream_taken = 0;  // filtered bytes since the stream began
    for (int y = first; y < end; ++y) {
        filter_rows(image, y, y + 1, filtered, piece);
        stream.next_in = filtered.data();
        stream.avail_in = static_cast<uInt>(filtered.size());
        stream_taken += filtered.size();
        // The row that leaves no room for another ends its stream.
        const bool stream_ends = stream_taken + filtered.size() > stream_bytes;
        const int flush = y + 1 == end  ? (last ? Z_FINISH : Z_SYNC_FLUSH)
                          : stream_ends ? Z_SYNC_FLUSH
                                        : Z_NO_FLUSH;
        for (;;) {
            if (piece.capacity - piece.size < 64) grow(piece, piece.capacity * 2);
            stream.next_out = piece.bytes.get() + piece.size;
            stream.avail_out = static_cast<uInt>(
                std::min<std::size_t>(piece.capacity - piece.size, std::size_t{1} << 30));
            const int status = deflate(&stream, flush);
            piece.size = static_cast<std::size_t>(stream.next_out - piece.bytes.get());
            if (status == Z_STREAM_ERROR) throw Error("PNG encoding failed: zlib stream error");
            // Done with this row when zlib has taken it all and, for a flush,
            // had room to spare (else it may hold more output back).
            if (flush == Z_FINISH ? status == Z_STREAM_END
                                  : stream.avail_in == 0 && stream.avail_out > 0)
                break;
        }
        if (stream_ends && y + 1 < end) {
            if (deflateReset(&stream) != Z_OK)
                throw Error("PNG encoding failed: zlib stream error");
            stream_taken = 0;
        }
    }
}

void deflate_rows(const Image& image, int first, int end, bool last, int level, Piece& piece) {
#if defined(LITKIT_HAVE_ISAL)
    if (level == 1) return deflate_rows_isal(image, first, end, last, piece);
#endif
    deflate_rows_zlib(image, first, end, last, level, piece);
}

void append_u32(std::string& out, std::uint32_t value) {
    const char bytes[4] = {static_cast<char>(value >> 24), static_cast<char>(value >> 16),
                           static_cast<char>(value >> 8), static_cast<char>(value)};
    out.append(bytes, 4);
}

// A chunk: length, type, data, CRC-32 of type and data.
void append_chunk(std::string& out, const char (&type)[5], const unsigned char* data,
                  std::size_t size) {
    append_u32(out, static_cast<std::uint32_t>(size));
    out.append(type, 4);
    if (size) out.append(reinterpret_cast<const char*>(data), size);
    uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(type), 4);
    if (size) crc = crc32(crc, data, static_cast<uInt>(size));
    append_u32(out, static_cast<std::uint32_t>(crc));
}

}  // namespace

namespace {

// The zlib stream of `image`'s filtered rows (docs/design.md, "PNG"): what
// a PNG's IDAT chunks, or an animated PNG frame's IDAT or fdAT chunks, hold.
std::string zlib_stream_of(const Image& image, int compression_level, const char* caller) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
        throw ArgumentError(std::string(caller) + ": image has no pixels or an inconsistent size");
    }
    if (compression_level < 0 || compression_level > 9)
        throw ArgumentError(std::string(caller) + ": compression level must be 0-9");

    const std::size_t filtered_bytes =
        (static_cast<std::size_t>(image.width) * 3 + 1) * static_cast<std::size_t>(image.height);
    const int split =
        filtered_bytes >= split_from_bytes && image.height >= 2 ? image.height / 2 : image.height;
    Piece upper;
    Piece lower;
    if (split < image.height) {
        // The second piece on a second thread; with no thread to be had,
        // the same bytes, one piece after the other.
        std::optional<ThreadPool> pool;
        try {
            pool.emplace(2);
        } catch (const std::system_error&) {
        }
        const auto deflate_piece = [&](std::size_t piece, int) {
            if (piece == 0) {
                deflate_rows(image, 0, split, false, compression_level, upper);
            } else {
                deflate_rows(image, split, image.height, true, compression_level, lower);
            }
        };
        if (pool) {
            pool->parallel_for(2, deflate_piece);
        } else {
            deflate_piece(0, 0);
            deflate_piece(1, 0);
        }
    } else {
        deflate_rows(image, 0, image.height, true, compression_level, upper);
    }

    // The zlib stream: header (deflate, 32 KiB window, the level's class,
    // a check making it a multiple of 31), the pieces, the Adler-32.
    const int level_class = compression_level < 2    ? 0
                            : compression_level < 6  ? 1
                            : compression_level == 6 ? 2
                                                     : 3;
    unsigned header[2] = {0x78, static_cast<unsigned>(level_class << 6)};
    header[1] += (31 - (header[0] * 256 + header[1]) % 31) % 31;
    uLong adler = upper.adler;
    if (lower.bytes)
        adler = adler32_combine(adler, lower.adler, static_cast<z_off_t>(lower.length));
    std::string stream;
    stream.reserve(2 + upper.size + lower.size + 4);
    stream.push_back(static_cast<char>(header[0]));
    stream.push_back(static_cast<char>(header[1]));
    stream.append(reinterpret_cast<const char*>(upper.bytes.get()), upper.size);
    if (lower.bytes) stream.append(reinterpret_cast<const char*>(lower.bytes.get()), lower.size);
    append_u32(stream, static_cast<std::uint32_t>(adler));
    return stream;
}

void put_u32(unsigned char* at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) at[i] = static_cast<unsigned char>(value >> (24 - 8 * i));
}

// The signature and the IHDR chunk of an 8-bit RGB picture.
void append_header(std::string& png, int width, int height) {
    png.append("\x89PNG\r\n\x1a\n", 8);
    unsigned char ihdr[13] = {};
    put_u32(ihdr, static_cast<std::uint32_t>(width));
    put_u32(ihdr + 4, static_cast<std::uint32_t>(height));
    ihdr[8] = 8;  // bits per channel
    ihdr[9] = 2;  // RGB; compression, filter method and interlace stay 0
    append_chunk(png, "IHDR", ihdr, sizeof ihdr);
}

}  // namespace

std::string encode_png(const Image& image, int compression_level) {
    const std::string stream = zlib_stream_of(image, compression_level, "encode_png");
    std::string png;
    png.reserve(stream.size() + stream.size() / idat_chunk_bytes * 12 + 64);
    append_header(png, image.width, image.height);
    const auto* data = reinterpret_cast<const unsigned char*>(stream.data());
    for (std::size_t at = 0; at < stream.size(); at += idat_chunk_bytes)
        append_chunk(png, "IDAT", data + at, std::min(idat_chunk_bytes, stream.size() - at));
    append_chunk(png, "IEND", nullptr, 0);
    return png;
}

AnimatedPng::AnimatedPng(int delay_ms, int compression_level)
    : delay_ms_(delay_ms), compression_level_(compression_level) {
    if (delay_ms < 1 || delay_ms > 65535)
        throw ArgumentError("AnimatedPng: a frame's delay must be 1-65535 ms");
    if (compression_level < 0 || compression_level > 9)
        throw ArgumentError("AnimatedPng: compression level must be 0-9");
}

void AnimatedPng::add(const Image& frame) {
    if (!streams_.empty() && (frame.width != width_ || frame.height != height_)) {
        throw ArgumentError("AnimatedPng: frame " + std::to_string(streams_.size()) + " is " +
                            std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                            ", the first " + std::to_string(width_) + "x" +
                            std::to_string(height_) + "; every frame must have one size");
    }
    streams_.push_back(zlib_stream_of(frame, compression_level_, "AnimatedPng"));
    width_ = frame.width;
    height_ = frame.height;
}

std::string AnimatedPng::bytes() const {
    if (streams_.empty()) throw ArgumentError("AnimatedPng: no frames");
    std::size_t total = 64;
    for (const std::string& stream : streams_) total += stream.size() + 64;
    std::string png;
    png.reserve(total);
    append_header(png, width_, height_);
    // acTL: the number of frames, and of plays (0: loop forever).
    unsigned char actl[8] = {};
    put_u32(actl, static_cast<std::uint32_t>(streams_.size()));
    append_chunk(png, "acTL", actl, sizeof actl);
    // fcTL and fdAT chunks share one sequence, from 0; IDAT has none.
    std::uint32_t sequence = 0;
    std::vector<unsigned char> data;
    for (std::size_t k = 0; k < streams_.size(); ++k) {
        // fcTL: sequence, the frame's size and offset (the whole picture),
        // its delay as delay_ms/1000 s, dispose_op NONE, blend_op SOURCE.
        unsigned char fctl[26] = {};
        put_u32(fctl, sequence++);
        put_u32(fctl + 4, static_cast<std::uint32_t>(width_));
        put_u32(fctl + 8, static_cast<std::uint32_t>(height_));
        fctl[20] = static_cast<unsigned char>(delay_ms_ >> 8);
        fctl[21] = static_cast<unsigned char>(delay_ms_);
        fctl[22] = 1000 >> 8;
        fctl[23] = 1000 & 0xff;
        append_chunk(png, "fcTL", fctl, sizeof fctl);
        const std::string& stream = streams_[k];
        const auto* bytes = reinterpret_cast<const unsigned char*>(stream.data());
        for (std::size_t at = 0; at < stream.size(); at += idat_chunk_bytes) {
            const std::size_t size = std::min(idat_chunk_bytes, stream.size() - at);
            if (k == 0) {  // the first frame is the default image, for plain PNG readers
                append_chunk(png, "IDAT", bytes + at, size);
                continue;
            }
            data.resize(4 + size);
            put_u32(data.data(), sequence++);
            std::memcpy(data.data() + 4, bytes + at, size);
            append_chunk(png, "fdAT", data.data(), data.size());
        }
    }
    append_chunk(png, "IEND", nullptr, 0);
    return png;
}

void AnimatedPng::write(const std::filesystem::path& path) const {
    write_file_atomically(path, bytes());
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
    constexpr auto largest = static_cast<png_uint_32>(max_image_side);
    if (decoded.width > largest || decoded.height > largest) {
        png_image_free(&decoded);
        throw IoError(path.string(),
                      "image larger than " + std::to_string(max_image_side) + " pixels on a side");
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
