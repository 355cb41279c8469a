// SPDX-License-Identifier: MIT
#include "outputs.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <variant>

#include "core/files.hpp"
#include "usage_error.hpp"

namespace litkit_cli {

namespace fs = std::filesystem;

namespace {

// Every file the run reads: the scene files and the mesh files they name.
std::vector<fs::path> inputs_of(const litkit::Scene& scene, const std::vector<std::string>& files) {
    std::vector<fs::path> inputs(files.begin(), files.end());
    for (const litkit::SceneObject& object : scene.objects) {
        if (const auto* mesh = std::get_if<litkit::MeshFileShape>(&object.shape))
            inputs.push_back(mesh->file);
    }
    return inputs;
}

}  // namespace

bool is_standard_output(const std::filesystem::path& output) {
    if (output == "-") return true;
    struct stat named {};
    struct stat standard {};
    return ::stat(output.c_str(), &named) == 0 && ::fstat(STDOUT_FILENO, &standard) == 0 &&
           named.st_dev == standard.st_dev && named.st_ino == standard.st_ino;
}

void write_png_output(const litkit::Image& image, const std::filesystem::path& output) {
    if (is_standard_output(output)) {
        litkit::write_all(STDOUT_FILENO, litkit::encode_png(image), "standard output");
    } else {
        litkit::write_png(image, output);
    }
}

void require_picture_name(const fs::path& output,
                          std::initializer_list<std::string_view> extensions,
                          std::string_view command, std::string_view writes) {
    if (is_standard_output(output) || output.string().ends_with('/')) return;
    struct stat existing {};
    if (::stat(output.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode)) return;
    std::string extension = output.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::string wanted;
    for (const std::string_view allowed : extensions) {
        if (extension == allowed) return;
        wanted += (wanted.empty() ? "" : " or ") + std::string(allowed);
    }
    throw UsageError{"-o " + output.string() + ": litkit " + std::string(command) + " writes " +
                     std::string(writes) + "; name the output with " + wanted +
                     " (or - for standard output); nothing was written"};
}

fs::path default_output(const std::vector<std::string>& scenes) {
    if (scenes.empty()) return "default.png";
    if (scenes.front() == "-") return "stdin.png";  // the scene came from standard input
    return fs::path(scenes.front()).filename().replace_extension(".png");
}

fs::path output_beside(const std::vector<std::string>& scenes, const std::string& suffix) {
    const std::string stem = scenes.empty() ? "default" : fs::path(scenes.front()).stem().string();
    return stem + suffix;
}

void refuse_to_overwrite_inputs(const litkit::Scene& scene, const std::vector<std::string>& files,
                                const fs::path& output) {
    for (const fs::path& input : inputs_of(scene, files)) {
        if (litkit::same_file(input, output)) {
            throw UsageError{"refusing to write over input file '" + input.string() +
                             "'; choose another name with -o"};
        }
    }
}

}  // namespace litkit_cli
