#include "geometry/mesh_formats.hpp"

#include <array>
#include <cctype>
#include <string>

#include "litkit/shapes.hpp"

namespace litkit::detail {

namespace {

// The first entry is also the format of a file whose extension none names.
constexpr std::array formats = {
    MeshFormat{".obj", load_obj, line_of_face},
};

bool same_extension(std::string_view written, std::string_view lower_case) {
    if (written.size() != lower_case.size()) return false;
    for (std::size_t i = 0; i < written.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(written[i])) != lower_case[i]) return false;
    }
    return true;
}

}  // namespace

const MeshFormat& mesh_format(const std::filesystem::path& path) {
    const std::string extension = path.extension().string();
    for (const MeshFormat& format : formats) {
        if (same_extension(extension, format.extension)) return format;
    }
    return formats.front();
}

}  // namespace litkit::detail
