#include "litkit/files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <string>

#include "litkit/error.hpp"

namespace litkit {

namespace {
std::string errno_text(int error) { return std::strerror(error); }
}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
    auto fail = [&](const std::string& reason) {
        throw IoError(path.string(), reason, {}, IoError::Access::Write);
    };
    std::random_device entropy;
    std::filesystem::path temporary = path;
    temporary += ".tmp-" + std::to_string(entropy() % 1000000000u);

    // O_EXCL: never follow or reuse something already at the temporary name.
    int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) fail(errno_text(errno));
    std::string failure;
    for (std::size_t written = 0; written < bytes.size();) {
        ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            failure = errno_text(errno);
            break;
        }
        written += static_cast<std::size_t>(n);
    }
    if (failure.empty() && ::fsync(fd) != 0) failure = errno_text(errno);
    if (::close(fd) != 0 && failure.empty()) failure = errno_text(errno);
    if (failure.empty() && ::rename(temporary.c_str(), path.c_str()) != 0) {
        failure = errno_text(errno);
    }
    if (!failure.empty()) {
        ::unlink(temporary.c_str());
        fail(failure);
    }
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code error;
    bool same = std::filesystem::equivalent(a, b, error);
    return !error && same;
}

}  // namespace litkit
