// PNG output and whole-or-nothing file writing.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>

#include <filesystem>
#include <fstream>
#include <string>

#include "litkit/error.hpp"
#include "core/files.hpp"
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
        EXPECT_NE(std::string(error.what()).find("cannot write"), std::string::npos) << error.what();
    }
    EXPECT_TRUE(fs::is_directory(dir / "out.png"));
    int entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1) << "a temporary file was left behind";
}

TEST_F(ScratchDir, WriteFailingHalfwayLeavesThePreviousFileUntouched) {
    litkit::write_file_atomically(dir / "keep.txt", "old");
    // A file-size limit makes write() fail part-way (EFBIG), even for root.
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
