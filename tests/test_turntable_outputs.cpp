// SPDX-License-Identifier: MIT
// `litkit turntable`'s outputs beyond the GIF: the animated PNG (-o
// spin.png), read here by a reader of its own (chunks, CRCs and sequence
// numbers after the APNG specification, each frame inflated by zlib and
// unfiltered), each frame compared with `litkit render` of its angle; and
// --range A:B, its slices and its errors.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "litkit/image.hpp"
#include "litkit/scene.hpp"
#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;
using litkit_test::CommandRun;

std::uint32_t u32(const std::string& bytes, std::size_t at) {
    return (std::uint32_t{static_cast<unsigned char>(bytes[at])} << 24) |
           (std::uint32_t{static_cast<unsigned char>(bytes[at + 1])} << 16) |
           (std::uint32_t{static_cast<unsigned char>(bytes[at + 2])} << 8) |
           std::uint32_t{static_cast<unsigned char>(bytes[at + 3])};
}

struct Chunk {
    std::string type;
    std::string data;
};

// The file's chunks after its signature; a chunk whose CRC-32 (of type and
// data) is wrong, or one cut short, fails the test.
std::vector<Chunk> chunks_of(const std::string& file) {
    std::vector<Chunk> chunks;
    if (file.compare(0, 8, "\x89PNG\r\n\x1a\n", 8) != 0) {
        ADD_FAILURE() << "no PNG signature";
        return chunks;
    }
    for (std::size_t at = 8; at < file.size();) {
        if (file.size() - at < 12) {
            ADD_FAILURE() << "a chunk cut short at byte " << at;
            break;
        }
        const std::uint32_t length = u32(file, at);
        if (file.size() - at - 12 < length) {
            ADD_FAILURE() << "a chunk's data cut short at byte " << at;
            break;
        }
        Chunk chunk{file.substr(at + 4, 4), file.substr(at + 8, length)};
        const std::string typed = file.substr(at + 4, 4 + length);
        const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(typed.data()),
                                static_cast<uInt>(typed.size()));
        EXPECT_EQ(u32(file, at + 8 + length), crc) << chunk.type << " at byte " << at;
        chunks.push_back(std::move(chunk));
        at += 12 + length;
    }
    return chunks;
}

// A frame's zlib stream inflated and unfiltered (all five PNG filter types).
litkit::Image decode(const std::string& stream, int width, int height) {
    const std::size_t row = static_cast<std::size_t>(width) * 3;
    std::vector<unsigned char> raw((row + 1) * static_cast<std::size_t>(height) + 1);
    uLongf size = static_cast<uLongf>(raw.size());
    EXPECT_EQ(uncompress(raw.data(), &size, reinterpret_cast<const Bytef*>(stream.data()),
                         static_cast<uLong>(stream.size())),
              Z_OK);
    EXPECT_EQ(size, raw.size() - 1);  // exactly the filtered rows, no more
    litkit::Image image(width, height);
    for (int y = 0; y < height; ++y) {
        const unsigned char* in = &raw[(row + 1) * static_cast<std::size_t>(y)];
        std::uint8_t* out = image.pixel(0, y);
        const std::uint8_t* up = y > 0 ? image.pixel(0, y - 1) : nullptr;
        for (std::size_t i = 0; i < row; ++i) {
            const int a = i >= 3 ? out[i - 3] : 0, b = up ? up[i] : 0,
                      c = up && i >= 3 ? up[i - 3] : 0;
            const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b),
                      pc = std::abs(p - c);
            const int paeth = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
            const int predictors[5] = {0, a, b, (a + b) / 2, paeth};
            EXPECT_LT(in[0], 5) << "row " << y;
            out[i] = static_cast<std::uint8_t>(in[1 + i] + predictors[in[0] % 5]);
        }
    }
    return image;
}

struct Apng {
    int width = 0, height = 0;
    std::uint32_t frames_declared = 0, plays = 0;
    std::vector<litkit::Image> frames;
    std::vector<int> delays_ms;
};

// The animated PNG at `path`, its structure checked as it is read: IHDR
// first, acTL before the first IDAT, every frame opened by an fcTL of the
// whole picture, fcTL and fdAT numbered 0, 1, 2... in the file's order,
// the first frame's data in IDAT chunks, the others' in fdAT, IEND last.
Apng read_apng(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string file((std::istreambuf_iterator<char>(in)), {});
    const std::vector<Chunk> chunks = chunks_of(file);
    Apng apng;
    if (chunks.size() < 4) {
        ADD_FAILURE() << "too few chunks";
        return apng;
    }
    EXPECT_EQ(chunks.front().type, "IHDR");
    EXPECT_EQ(chunks.back().type, "IEND");
    apng.width = static_cast<int>(u32(chunks[0].data, 0));
    apng.height = static_cast<int>(u32(chunks[0].data, 4));
    EXPECT_EQ(chunks[0].data.substr(8), std::string("\x08\x02\x00\x00\x00", 5));  // 8-bit RGB
    std::uint32_t sequence = 0;
    bool seen_actl = false, seen_idat = false;
    std::vector<std::string> streams;
    for (std::size_t i = 1; i + 1 < chunks.size(); ++i) {
        const Chunk& chunk = chunks[i];
        if (chunk.type == "acTL") {
            EXPECT_FALSE(seen_idat) << "acTL after IDAT";
            EXPECT_EQ(chunk.data.size(), 8u);
            apng.frames_declared = u32(chunk.data, 0);
            apng.plays = u32(chunk.data, 4);
            seen_actl = true;
        } else if (chunk.type == "fcTL") {
            EXPECT_TRUE(seen_actl) << "fcTL before acTL";
            EXPECT_EQ(chunk.data.size(), 26u);
            EXPECT_EQ(u32(chunk.data, 0), sequence++) << "fcTL's sequence number";
            EXPECT_EQ(u32(chunk.data, 4), static_cast<std::uint32_t>(apng.width));
            EXPECT_EQ(u32(chunk.data, 8), static_cast<std::uint32_t>(apng.height));
            EXPECT_EQ(u32(chunk.data, 12), 0u);  // x offset
            EXPECT_EQ(u32(chunk.data, 16), 0u);  // y offset
            const auto num = static_cast<unsigned char>(chunk.data[20]) * 256 +
                             static_cast<unsigned char>(chunk.data[21]);
            const auto den = static_cast<unsigned char>(chunk.data[22]) * 256 +
                             static_cast<unsigned char>(chunk.data[23]);
            apng.delays_ms.push_back(den == 0 ? num * 10 : num * 1000 / den);
            EXPECT_LE(chunk.data[24], 2);  // dispose_op
            EXPECT_LE(chunk.data[25], 1);  // blend_op
            streams.emplace_back();
        } else if (chunk.type == "IDAT") {
            EXPECT_EQ(streams.size(), 1u) << "IDAT outside the first frame";
            seen_idat = true;
            if (!streams.empty()) streams.back() += chunk.data;
        } else if (chunk.type == "fdAT") {
            EXPECT_GE(streams.size(), 2u) << "fdAT in the first frame";
            EXPECT_EQ(u32(chunk.data, 0), sequence++) << "fdAT's sequence number";
            if (!streams.empty()) streams.back() += chunk.data.substr(4);
        } else {
            ADD_FAILURE() << "an unexpected chunk " << chunk.type;
        }
    }
    EXPECT_TRUE(seen_idat);
    for (const std::string& stream : streams)
        apng.frames.push_back(decode(stream, apng.width, apng.height));
    return apng;
}

class TurntableOutputs : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("litkit-turntable-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        std::ofstream(dir / "scene.toml") << litkit::default_scene_toml();
    }
    void TearDown() override { fs::remove_all(dir); }
    CommandRun cli(const std::string& arguments) const {
        return litkit_test::run_command("cd '" + dir.string() + "' && '" LITKIT_CLI "' " +
                                        arguments);
    }
    litkit::Image png(const std::string& name) const { return litkit::read_png(dir / name); }
    // The default scene in a room large enough for `render` to accept the
    // observer at every quarter turn (the turntable itself draws any).
    static std::string big_room_scene() {
        std::string text(litkit::default_scene_toml());
        for (const std::string key : {"width = 10", "height = 10", "depth = 10"}) {
            const std::size_t at = text.find(key);
            EXPECT_NE(at, std::string::npos) << key;
            if (at != std::string::npos)
                text.replace(at, key.size(), key.substr(0, key.size() - 2) + "30");
        }
        return text;
    }
    // `litkit render` of big_room_scene() with the observer turned by
    // `quarters` quarter turns about +y through look_at: its offset from
    // look_at (x, z) -> (z, -x) each time, counter-clockwise seen from
    // above; exact in floats (halves and whole numbers).
    litkit::Image render_turned(int quarters, const std::string& size) const {
        const std::string base = big_room_scene();
        const litkit::Scene scene = litkit::parse_scene(base, dir / "big.toml");
        EXPECT_EQ(scene.observer.up, glm::vec3(0.0f, 1.0f, 0.0f));
        const glm::dvec3 look_at(scene.observer.look_at);
        double x = scene.observer.position.x - look_at.x;
        double z = scene.observer.position.z - look_at.z;
        for (int q = 0; q < quarters; ++q) {
            const double turned_x = z;
            z = -x;
            x = turned_x;
        }
        char position[96];
        std::snprintf(position, sizeof position, "position = [%.9g, %.9g, %.9g]", look_at.x + x,
                      static_cast<double>(scene.observer.position.y), look_at.z + z);
        std::string text = base;
        const std::string own = "position = [3.5, 1, 4]";
        const std::size_t at = text.find(own);
        EXPECT_NE(at, std::string::npos);
        if (at != std::string::npos) text.replace(at, own.size(), position);
        const std::string name = "turned-" + std::to_string(quarters);
        std::ofstream(dir / (name + ".toml")) << text;
        const CommandRun run = cli("render " + name + ".toml" + size + "-o " + name + ".png");
        EXPECT_EQ(run.status, 0) << run.output;
        return png(name + ".png");
    }

    fs::path dir;
};

const std::string small = " --width 64 --height 48 ";

TEST_F(TurntableOutputs, AnAnimatedPngHoldsEveryFrameAsLitkitRenderDrawsIt) {
    std::ofstream(dir / "big.toml") << big_room_scene();
    const CommandRun made =
        cli("turntable big.toml --frames 4 --delay 120" + small + "-o spin.png");
    ASSERT_EQ(made.status, 0) << made.output;
    EXPECT_NE(made.output.find("wrote 1 animated PNG spin.png (4 frames"), std::string::npos)
        << made.output;
    const Apng apng = read_apng(dir / "spin.png");
    EXPECT_EQ(apng.width, 64);
    EXPECT_EQ(apng.height, 48);
    EXPECT_EQ(apng.frames_declared, 4u);
    EXPECT_EQ(apng.plays, 0u);  // loops forever
    EXPECT_EQ(apng.delays_ms, std::vector<int>(4, 120));
    ASSERT_EQ(apng.frames.size(), 4u);
    for (int k = 0; k < 4; ++k)
        EXPECT_EQ(apng.frames[k].rgb, render_turned(k, small).rgb) << "frame " << k;
    // A reader that knows no APNG (libpng's simplified API) shows frame 0.
    EXPECT_EQ(png("spin.png").rgb, apng.frames[0].rgb);
}

TEST_F(TurntableOutputs, AnAnimatedPngOfABigPictureSpansSeveralChunksAFrame) {
    // 1100 × 700: over 1 MiB of filtered rows, so each frame's stream is
    // deflated in two pieces and spread over IDAT or fdAT chunks of 1 MiB.
    litkit::AnimatedPng animated(40, 0);  // stored blocks: every byte counted
    litkit::Image first(1100, 700), second(1100, 700);
    for (std::size_t i = 0; i < first.rgb.size(); ++i) {
        first.rgb[i] = static_cast<std::uint8_t>(i * 7 % 251);
        second.rgb[i] = static_cast<std::uint8_t>(i * 13 % 241);
    }
    animated.add(first);
    animated.add(second);
    EXPECT_EQ(animated.frames(), 2);
    EXPECT_THROW(animated.add(litkit::Image(4, 4)), litkit::ArgumentError);
    animated.write(dir / "big.png");
    const Apng apng = read_apng(dir / "big.png");
    ASSERT_EQ(apng.frames.size(), 2u);
    EXPECT_EQ(apng.frames[0].rgb, first.rgb);
    EXPECT_EQ(apng.frames[1].rgb, second.rgb);
    EXPECT_THROW(litkit::AnimatedPng().bytes(), litkit::ArgumentError);
    EXPECT_THROW(litkit::AnimatedPng(0), litkit::ArgumentError);
}

TEST_F(TurntableOutputs, SlicesWrittenIntoOneFolderAreTheWholeTurn) {
    ASSERT_EQ(cli("turntable scene.toml --frames 4" + small + "-o whole/").status, 0);
    const CommandRun first =
        cli("turntable scene.toml --frames 4 --range 0:1" + small + "-o sliced/");
    ASSERT_EQ(first.status, 0) << first.output;
    EXPECT_NE(first.output.find("wrote 1 frames into sliced/ (1 frames, 0 to 0 of 4"),
              std::string::npos)
        << first.output;
    ASSERT_EQ(cli("turntable scene.toml --frames 4 --range 1:4" + small + "-o sliced/").status, 0);
    for (int k = 0; k < 4; ++k) {
        const std::string name = "frame-00" + std::to_string(k) + ".png";
        EXPECT_EQ(png("sliced/" + name).rgb, png("whole/" + name).rgb) << name;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "sliced"), fs::directory_iterator()), 4);
    // A slice as an animation holds its frames alone: frames 2 and 3 here.
    ASSERT_EQ(cli("turntable scene.toml --frames 4 --range 2:4" + small + "-o half.png").status, 0);
    const Apng half = read_apng(dir / "half.png");
    ASSERT_EQ(half.frames.size(), 2u);
    EXPECT_EQ(half.frames[0].rgb, png("whole/frame-002.png").rgb);
    EXPECT_EQ(half.frames[1].rgb, png("whole/frame-003.png").rgb);
}

TEST_F(TurntableOutputs, ABadRangeIsRefusedNamingItsFault) {
    const std::string tail =
        " (--range A:B renders frames A to B-1 of the --frames 4, counted "
        "from 0)";
    const std::pair<const char*, std::string> cases[] = {
        {"3:2", "--range 3:2: the end 2 is not after the first frame 3"},
        {"2:2", "--range 2:2: the end 2 is not after the first frame 2"},
        {"x:5", "--range x:5: the first frame 'x' is not a frame number"},
        {"1:y", "--range 1:y: the end 'y' is not a frame number"},
        {"1:", "--range 1:: the end '' is not a frame number"},
        {"3", "--range 3: no ':' between the first frame and the end"},
        {"-1:2", "--range -1:2: the first frame -1 is below 0"},
        {"0:5", "--range 0:5: the end 5 is beyond the turn's 4 frames"},
        {"1.5:3", "--range 1.5:3: the first frame '1.5' is not a frame number"},
    };
    for (const auto& [range, message] : cases) {
        const CommandRun run =
            cli("turntable scene.toml --frames 4" + small + "--range '" + range + "' -o bad/");
        EXPECT_EQ(run.status, 2) << range << ": " << run.output;
        EXPECT_NE(run.output.find("error: " + message + tail), std::string::npos)
            << range << ": " << run.output;
    }
    EXPECT_FALSE(fs::exists(dir / "bad"));  // refused before anything was written
}

TEST_F(TurntableOutputs, APngOrGifNameIsTakenAndAnyOtherRefused) {
    const CommandRun run = cli("turntable scene.toml --frames 2" + small + "-o spin.webp");
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find("error: -o spin.webp: litkit turntable writes an animated GIF or "
                              "PNG, or PNG frames into a folder named DIR/; name the output "
                              "with .gif or .png"),
              std::string::npos)
        << run.output;
    EXPECT_FALSE(fs::exists(dir / "spin.webp"));
    EXPECT_EQ(cli("turntable scene.toml --frames 2" + small + "-o Spin.PNG").status, 0);
    EXPECT_EQ(read_apng(dir / "Spin.PNG").frames.size(), 2u);
    // An existing folder named like a picture still takes numbered frames.
    fs::create_directories(dir / "frames.png");
    EXPECT_EQ(cli("turntable scene.toml --frames 2" + small + "-o frames.png").status, 0);
    EXPECT_TRUE(fs::exists(dir / "frames.png" / "frame-001.png"));
}

}  // namespace
