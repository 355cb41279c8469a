// SPDX-License-Identifier: MIT
// The corpus of bad scene files in tests/bad (docs/spec.md §6): each case is loaded
// and the diagnostics it produces — errors, warnings, or the IoError of a file
// that cannot be read — must equal its expectation file line for line.
//
// A case is either a single file `tests/bad/<name>.toml` with its expectation
// in `tests/bad/<name>.expected`, or a folder `tests/bad/<name>/` whose
// `*.toml` files are loaded together in sorted name order, with its
// expectation in `tests/bad/<name>/expected`. Expectation lines read
// `file:line:col: error: message` with the file relative to tests/bad; a case
// whose expectation holds only warnings must load.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "litkit/scene.hpp"

namespace litkit {
namespace {

namespace fs = std::filesystem;

const fs::path& corpus_folder() {
    static const fs::path folder = fs::path(LITKIT_SOURCE_DIR) / "tests" / "bad";
    return folder;
}

struct BadScene {
    std::string name;             // test name and file stem
    std::vector<fs::path> files;  // relative to tests/bad, in load order
    fs::path expectation;         // relative to tests/bad
};

// Every case on disk, sorted by name.
std::vector<BadScene> find_cases() {
    std::vector<BadScene> cases;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(corpus_folder(), error)) {
        const fs::path relative = entry.path().lexically_relative(corpus_folder());
        if (entry.is_directory()) {
            BadScene scene{relative.string(), {}, relative / "expected"};
            for (const fs::directory_entry& file : fs::directory_iterator(entry.path()))
                if (file.path().extension() == ".toml")
                    scene.files.push_back(file.path().lexically_relative(corpus_folder()));
            std::sort(scene.files.begin(), scene.files.end());
            cases.push_back(std::move(scene));
        } else if (entry.path().extension() == ".toml") {
            const std::string stem = relative.stem().string();
            cases.push_back(BadScene{stem, {relative}, fs::path(stem + ".expected")});
        }
    }
    std::sort(cases.begin(), cases.end(),
              [](const BadScene& a, const BadScene& b) { return a.name < b.name; });
    return cases;
}

std::vector<std::string> read_lines(const fs::path& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    while (!lines.empty() && lines.back().empty()) lines.pop_back();
    return lines;
}

struct Outcome {
    std::vector<std::string> lines;  // errors, or the IoError, or the warnings
    bool loaded = false;
};

// Loads the case's files from inside tests/bad, so that the file names in
// the diagnostics are relative to it.
Outcome load_case(const BadScene& scene) {
    struct WorkingFolder {
        fs::path previous = fs::current_path();
        explicit WorkingFolder(const fs::path& folder) { fs::current_path(folder); }
        ~WorkingFolder() { fs::current_path(previous); }
    } working_folder(corpus_folder());

    Outcome outcome;
    try {
        Scene loaded = load_scene(scene.files);
        outcome.loaded = true;
        for (const Diagnostic& warning : loaded.warnings)
            outcome.lines.push_back(warning.to_string());
    } catch (const SceneError& error) {
        for (const Diagnostic& diagnostic : error.diagnostics())
            outcome.lines.push_back(diagnostic.to_string());
    } catch (const IoError& error) {
        outcome.lines.push_back(error.what());
    }
    return outcome;
}

// "  = line" for lines both share, "  - line" for expected ones missing,
// "  + line" for unexpected ones (a longest-common-subsequence diff).
std::string diff(const std::vector<std::string>& expected, const std::vector<std::string>& actual) {
    const std::size_t n = expected.size(), m = actual.size();
    std::vector<std::vector<std::size_t>> common(n + 1, std::vector<std::size_t>(m + 1, 0));
    for (std::size_t i = n; i-- > 0;)
        for (std::size_t j = m; j-- > 0;)
            common[i][j] = expected[i] == actual[j] ? common[i + 1][j + 1] + 1
                                                    : std::max(common[i + 1][j], common[i][j + 1]);
    std::ostringstream text;
    std::size_t i = 0, j = 0;
    while (i < n || j < m) {
        if (i < n && j < m && expected[i] == actual[j]) {
            text << "  = " << expected[i++] << '\n';
            ++j;
        } else if (j < m && (i == n || common[i][j + 1] >= common[i + 1][j])) {
            text << "  + " << actual[j++] << '\n';
        } else {
            text << "  - " << expected[i++] << '\n';
        }
    }
    return text.str();
}

// Shown by GoogleTest in place of the object's bytes.
void PrintTo(const BadScene& scene, std::ostream* out) { *out << scene.name; }

class BadSceneTest : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneTest, ReportsExactlyTheExpectedDiagnostics) {
    const BadScene& scene = GetParam();
    const std::vector<std::string> expected = read_lines(corpus_folder() / scene.expectation);
    ASSERT_FALSE(expected.empty()) << "no expectation in " << scene.expectation;
    ASSERT_FALSE(scene.files.empty()) << "no .toml files in case " << scene.name;

    const auto start = std::chrono::steady_clock::now();
    const Outcome outcome = load_case(scene);
    const auto elapsed = std::chrono::steady_clock::now() - start;
    EXPECT_TRUE(outcome.lines == expected) << "case " << scene.name << " (- expected, + actual):\n"
                                           << diff(expected, outcome.lines);
    // Bad input is refused quickly: a huge `segments` must not build a mesh.
    EXPECT_LT(elapsed, std::chrono::seconds(5)) << "case " << scene.name << " took too long";

    // "file:line:col: warning: ..." or, for a scene-wide warning of a scene
    // spread over several files, "warning: ...".
    const bool only_warnings =
        std::all_of(expected.begin(), expected.end(), [](const std::string& line) {
            return line.starts_with("warning: ") || line.find(": warning: ") != std::string::npos;
        });
    EXPECT_EQ(outcome.loaded, only_warnings)
        << (only_warnings ? "a case with only warnings must load"
                          : "a case with errors must not load");
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadSceneTest, ::testing::ValuesIn(find_cases()),
                         [](const ::testing::TestParamInfo<BadScene>& info) {
                             std::string name = info.param.name;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

// Guards against a discovery mistake making the suite above vacuous.
TEST(BadSceneCorpus, HoldsAtLeastSixtyCasesEachWithAnExpectation) {
    const std::vector<BadScene> cases = find_cases();
    EXPECT_GE(cases.size(), 60u);
    for (const BadScene& scene : cases)
        EXPECT_TRUE(fs::is_regular_file(corpus_folder() / scene.expectation))
            << "case " << scene.name << " has no expectation file " << scene.expectation;
}

// Every file in the corpus belongs to a case: a stray expectation (say, for
// a renamed scene) would otherwise go unchecked.
TEST(BadSceneCorpus, EveryExpectationHasItsScene) {
    for (const fs::directory_entry& entry : fs::directory_iterator(corpus_folder())) {
        if (entry.path().extension() != ".expected") continue;
        fs::path scene = entry.path();
        scene.replace_extension(".toml");
        EXPECT_TRUE(fs::is_regular_file(scene)) << entry.path() << " has no scene file";
    }
}

}  // namespace
}  // namespace litkit
