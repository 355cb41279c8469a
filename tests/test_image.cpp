// SPDX-License-Identifier: MIT
// PNG output and whole-or-nothing file writing.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <zlib.h>

#include <csignal>
#include <cstdint>
#include <utility>
#include <vector>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "core/files.hpp"
#include "litkit/error.hpp"
#include "litkit/image.hpp"

namespace fs = std::filesystem;

namespace {

class ScratchDir : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("litkit-image-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string read(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }
    fs::path dir;
};

litkit::Image gradient(int width, int height) {
    litkit::Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = static_cast<std::uint8_t>(x * 7);
            p[1] = static_cast<std::uint8_t>(y * 13);
            p[2] = static_cast<std::uint8_t>(x ^ y);
        }
    return image;
}

}  // namespace

TEST_F(ScratchDir, PngRoundTripKeepsEveryPixel) {
    const litkit::Image original = gradient(37, 21);
    litkit::write_png(original, dir / "a.png");
    const litkit::Image back = litkit::read_png(dir / "a.png");
    EXPECT_EQ(back.width, 37);
    EXPECT_EQ(back.height, 21);
    EXPECT_EQ(back.rgb, original.rgb);
}

TEST_F(ScratchDir, PngStartsWithTheSignature) {
    const std::string bytes = litkit::encode_png(gradient(4, 4));
    ASSERT_GE(bytes.size(), 8u);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

// A picture of every kind of content: runs (the background), gradients and
// noise, large enough (over 512 KiB of rows) that encode_png deflates its two
// halves apart and joins them.
litkit::Image mixed_picture(int width, int height) {
    litkit::Image image = gradient(width, height);
    std::uint32_t state = 7;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            if (y < height / 4) {
                p[0] = 30, p[1] = 30, p[2] = 40;  // flat
            } else if (y > height / 2 && y < height * 3 / 4 && x > width / 3) {
                state = state * 1664525u + 1013904223u;  // noise
                p[0] = static_cast<std::uint8_t>(state >> 24);
                p[1] = static_cast<std::uint8_t>(state >> 16);
                p[2] = static_cast<std::uint8_t>(state >> 8);
            }
        }
    return image;
}

std::uint32_t big_endian(const std::string& bytes, std::size_t at) {
    return (std::uint32_t(std::uint8_t(bytes[at])) << 24) |
           (std::uint32_t(std::uint8_t(bytes[at + 1])) << 16) |
           (std::uint32_t(std::uint8_t(bytes[at + 2])) << 8) | std::uint8_t(bytes[at + 3]);
}

TEST_F(ScratchDir, PngOfEverySizeAndLevelRoundTrips) {
    // 12000 × 30: rows of 36,001 bytes, one a stream (two would pass
    // 64,000). Rows longer than a stream are read back without libpng
    // (which reads at most 16384 pixels a side) in the test below.
    for (const auto& [width, height] :
         {std::pair{3, 1}, std::pair{37, 21}, std::pair{700, 400}, std::pair{1920, 1080},
          std::pair{4000, 2}, std::pair{12000, 30}}) {
        const litkit::Image original = mixed_picture(width, height);
        for (const int level : {0, 1, 6, 9}) {
            if (level > 1 && width * height > 700 * 400) continue;  // time
            const fs::path path = dir / ("p" + std::to_string(level) + ".png");
            litkit::write_file_atomically(path, litkit::encode_png(original, level));
            const litkit::Image back = litkit::read_png(path);
            ASSERT_EQ(back.width, width);
            ASSERT_EQ(back.height, height);
            EXPECT_EQ(back.rgb, original.rgb) << width << "x" << height << " level " << level;
        }
    }
}

// Noise in rows [first, end) of a flat picture.
litkit::Image noise_in_rows(int width, int height, int first, int end) {
    litkit::Image image(width, height);
    std::uint32_t state = 11;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = 25, p[1] = 28, p[2] = 36;
            if (y >= first && y < end) {
                state = state * 1664525u + 1013904223u;
                p[0] = static_cast<std::uint8_t>(state >> 24);
                p[1] = static_cast<std::uint8_t>(state >> 16);
            }
        }
    return image;
}

// Wherever the detail lies (a piece of noise and many of zeros, or the
// other way round), the file holds the picture exactly.
TEST_F(ScratchDir, PngRoundTripsWhereverTheDetailLies) {
    const int width = 800, height = 600;
    for (const auto& [first, end] : {std::pair{0, 1}, std::pair{0, 150}, std::pair{200, 400},
                                     std::pair{450, 600}, std::pair{599, 600}}) {
        const litkit::Image original = noise_in_rows(width, height, first, end);
        litkit::write_png(original, dir / "s.png");
        EXPECT_EQ(litkit::read_png(dir / "s.png").rgb, original.rgb)
            << "noise in rows " << first << "-" << end;
    }
}

// encode_png keeps no state between calls: threads encoding at once get
// the bytes each gets alone, pictures in two halves and in one piece, and
// the bytes decode to the picture.
TEST_F(ScratchDir, PngEncodingFromSeveralThreadsAtOnce) {
    const std::vector<litkit::Image> pictures = {
        gradient(37, 21), mixed_picture(700, 400), noise_in_rows(800, 600, 0, 150),
        noise_in_rows(800, 600, 599, 600), mixed_picture(1920, 1080)};
    std::vector<std::string> expected;
    for (const litkit::Image& picture : pictures) expected.push_back(litkit::encode_png(picture));
    std::vector<std::thread> threads;
    std::vector<int> wrong(4, 0);
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            for (int round = 0; round < 3; ++round)
                for (std::size_t p = 0; p < pictures.size(); ++p)
                    wrong[t] += litkit::encode_png(pictures[p]) != expected[p];
        });
    }
    for (std::thread& thread : threads) thread.join();
    EXPECT_EQ(wrong, std::vector<int>(4, 0));
    for (std::size_t p = 0; p < pictures.size(); ++p) {
        litkit::write_file_atomically(dir / "e.png", expected[p]);
        EXPECT_EQ(litkit::read_png(dir / "e.png").rgb, pictures[p].rgb) << p;
    }
}

// The file read without libpng: every chunk's CRC, the IHDR fields, and the
// IDAT data as one zlib stream (zlib checks its Adler-32) holding exactly
// the rows with PNG's "up" filter, across the places where the halves and
// the streams within them meet.
TEST_F(ScratchDir, PngChunksAndZlibStreamAreWhatTheFormatSays) {
    // Halves of many streams each; and rows longer than a stream may be.
    for (const auto& [width, height] : {std::pair{700, 400}, std::pair{22000, 30}}) {
        SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
        const litkit::Image image = mixed_picture(width, height);
        const std::string png = litkit::encode_png(image);
        ASSERT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
        std::string idat;
        std::vector<std::string> types;
        std::size_t at = 8;
        while (at + 12 <= png.size()) {
            const std::uint32_t length = big_endian(png, at);
            ASSERT_LE(at + 12 + length, png.size());
            const std::string type = png.substr(at + 4, 4);
            const std::string data = png.substr(at + 8, length);
            uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(png.data() + at + 4), 4 + length);
            EXPECT_EQ(big_endian(png, at + 8 + length), static_cast<std::uint32_t>(crc)) << type;
            if (type == "IHDR") {
                ASSERT_EQ(length, 13u);
                EXPECT_EQ(big_endian(data, 0), static_cast<std::uint32_t>(width));
                EXPECT_EQ(big_endian(data, 4), static_cast<std::uint32_t>(height));
                EXPECT_EQ(data.substr(8), std::string("\x08\x02\x00\x00\x00", 5));
            }
            if (type == "IDAT") idat += data;
            types.push_back(type);
            at += 12 + length;
        }
        EXPECT_EQ(at, png.size());
        ASSERT_GE(types.size(), 3u);
        EXPECT_EQ(types.front(), "IHDR");
        EXPECT_EQ(types.back(), "IEND");

        const std::size_t row_bytes = static_cast<std::size_t>(width) * 3;
        const std::size_t row = row_bytes + 1;
        std::vector<unsigned char> expected(row * static_cast<std::size_t>(height));
        for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
            expected[row * y] = 2;
            for (std::size_t i = 0; i < row_bytes; ++i) {
                const std::uint8_t above = y ? image.rgb[(y - 1) * row_bytes + i] : 0;
                expected[row * y + 1 + i] =
                    static_cast<unsigned char>(image.rgb[y * row_bytes + i] - above);
            }
        }
        std::vector<unsigned char> inflated(expected.size() + 1);
        uLongf size = static_cast<uLongf>(inflated.size());
        ASSERT_EQ(uncompress(inflated.data(), &size, reinterpret_cast<const Bytef*>(idat.data()),
                             static_cast<uLong>(idat.size())),
                  Z_OK);
        inflated.resize(size);
        EXPECT_TRUE(inflated == expected);
    }
}

TEST_F(ScratchDir, AtomicWriteReplacesTheWholeFile) {
    litkit::write_file_atomically(dir / "f.txt", "a long first version of the file");
    litkit::write_file_atomically(dir / "f.txt", "short");
    EXPECT_EQ(read(dir / "f.txt"), "short");
}

TEST_F(ScratchDir, FailedWriteIntoMissingFolderThrowsAndLeavesNothing) {
    EXPECT_THROW(litkit::write_png(gradient(2, 2), dir / "missing" / "x.png"), litkit::IoError);
    EXPECT_FALSE(fs::exists(dir / "missing"));
}

TEST_F(ScratchDir, FailedWriteOverADirectoryLeavesItAndNoTemporaryFile) {
    fs::create_directories(dir / "out.png");
    try {
        litkit::write_png(gradient(2, 2), dir / "out.png");
        FAIL() << "writing over a directory must fail";
    } catch (const litkit::IoError& error) {
        EXPECT_NE(std::string(error.what()).find("cannot write"), std::string::npos)
            << error.what();
    }
    EXPECT_TRUE(fs::is_directory(dir / "out.png"));
    int entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1) << "a temporary file was left behind";
}

TEST_F(ScratchDir, AFileSizeLimitLeavesThePreviousFileUntouched) {
    litkit::write_file_atomically(dir / "keep.txt", "old");
    // A file-size limit refuses the file's space (EFBIG), even for root:
    // where the file system reserves space first (ext4: fallocate), before
    // a byte is written, elsewhere when write() gets part-way.
    struct rlimit saved;
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    struct rlimit tiny = saved;
    tiny.rlim_cur = 16;
    auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &tiny), 0);
    bool threw = false;
    try {
        litkit::write_file_atomically(dir / "keep.txt", std::string(4096, 'n'));
    } catch (const litkit::IoError&) {
        threw = true;
    }
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previous_handler);
    EXPECT_TRUE(threw);
    EXPECT_EQ(read(dir / "keep.txt"), "old");
    int entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1) << "a temporary file was left behind";
}

TEST_F(ScratchDir, SameFileSeesThroughLinksAndDotDot) {
    litkit::write_file_atomically(dir / "a", "x");
    fs::create_symlink(dir / "a", dir / "link");
    fs::create_directories(dir / "sub");
    EXPECT_TRUE(litkit::same_file(dir / "a", dir / "link"));
    EXPECT_TRUE(litkit::same_file(dir / "a", dir / "sub" / ".." / "a"));
    EXPECT_FALSE(litkit::same_file(dir / "a", dir / "sub"));
    EXPECT_FALSE(litkit::same_file(dir / "a", dir / "does-not-exist"));
}

TEST_F(ScratchDir, ReadingANonPngFileThrowsIoError) {
    litkit::write_file_atomically(dir / "fake.png", "not a png at all");
    EXPECT_THROW(litkit::read_png(dir / "fake.png"), litkit::IoError);
}
