// SPDX-License-Identifier: MIT
// The command-line tool's heap set-up (apps/litkit/heap.cpp): the heap gets
// transparent huge pages, and allocation still behaves. Each test runs in a
// process of its own (gtest_discover_tests), since the set-up is
// process-wide.
#include <gtest/gtest.h>
#include <sys/utsname.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "heap.hpp"

namespace {

// The mode in /sys/kernel/mm/transparent_hugepage/enabled ("[madvise]" ->
// "madvise"), or "" where the file is missing.
std::string huge_page_mode() {
    std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string text;
    std::getline(file, text);
    const auto open = text.find('[');
    const auto close = text.find(']');
    if (open == std::string::npos || close == std::string::npos) return "";
    return text.substr(open + 1, close - open - 1);
}

// AnonHugePages (kB) of the mapping that holds `address`, from /proc/self/smaps.
long huge_kilobytes_at(const void* address) {
    const auto where = reinterpret_cast<std::uintptr_t>(address);
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t begin = 0;
        std::uintptr_t end = 0;
        if (std::sscanf(line.c_str(), "%lx-%lx ", &begin, &end) == 2 &&
            line.find(" kB") == std::string::npos) {
            inside = begin <= where && where < end;
        } else if (inside && line.rfind("AnonHugePages:", 0) == 0) {
            return std::stol(line.substr(std::strlen("AnonHugePages:")));
        }
    }
    return -1;
}

#if defined(LITKIT_SANITIZED)  // tests/CMakeLists.txt
constexpr bool sanitized = true;
#else
constexpr bool sanitized = false;
#endif

TEST(Heap, LargeBlocksLieInHugePages) {
    if (sanitized) GTEST_SKIP() << "AddressSanitizer's allocator replaces glibc's heap";
    const std::string mode = huge_page_mode();
    if (mode != "madvise" && mode != "always") {
        GTEST_SKIP() << "transparent huge pages are '" << mode << "' on this machine";
    }
    litkit_cli::use_large_pages_for_the_heap();
    // The first block after the set-up lies where the heap's growth starts,
    // the one range touched before the advice: collapsed into a huge page
    // (MADV_COLLAPSE, Linux 6.1 and later).
    std::vector<unsigned char> first(std::size_t{1} << 20, 1);
    // Larger than glibc's largest mmap threshold (32 MiB): without the
    // set-up, a block of its own mapping, and in "madvise" mode no huge page.
    std::vector<unsigned char> block(std::size_t{40} << 20, 1);
    EXPECT_GE(huge_kilobytes_at(block.data() + block.size() / 2), 2048) << "THP mode " << mode;
    utsname system{};
    uname(&system);
    int major = 0;
    int minor = 0;
    std::sscanf(system.release, "%d.%d", &major, &minor);
    if (major > 6 || (major == 6 && minor >= 1)) {
        EXPECT_GE(huge_kilobytes_at(first.data()), 2048) << "kernel " << system.release;
    } else {
        std::printf("kernel %s has no MADV_COLLAPSE: the first block is not checked\n",
                    system.release);
    }
}

TEST(Heap, BlocksOfEverySizeAndThreadStayIntact) {
    litkit_cli::use_large_pages_for_the_heap();
    auto fill_and_check = [](unsigned seed) {
        std::vector<std::unique_ptr<unsigned char[]>> blocks;
        std::vector<std::size_t> sizes;
        for (std::size_t size = 1; size <= (std::size_t{64} << 20); size *= 3) {
            blocks.emplace_back(new unsigned char[size]);
            std::memset(blocks.back().get(), static_cast<int>((seed + size) & 0xff), size);
            sizes.push_back(size);
        }
        bool intact = true;
        for (std::size_t i = 0; i < blocks.size(); ++i) {
            const unsigned char want = static_cast<unsigned char>((seed + sizes[i]) & 0xff);
            intact = intact && blocks[i][0] == want && blocks[i][sizes[i] - 1] == want &&
                     blocks[i][sizes[i] / 2] == want;
        }
        return intact;
    };
    bool in_thread = false;
    std::thread worker([&] { in_thread = fill_and_check(7); });
    const bool in_main = fill_and_check(3);
    worker.join();
    EXPECT_TRUE(in_main);
    EXPECT_TRUE(in_thread);
}

}  // namespace
