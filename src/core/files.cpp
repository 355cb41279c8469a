// SPDX-License-Identifier: MIT
#include "core/files.hpp"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <random>
#include <string>

#include "litkit/error.hpp"

namespace litkit {

namespace {

std::string errno_text(int error) { return std::strerror(error); }

// Reserves the blocks for `size` bytes before they are written; an error
// text when the file system refuses for want of room, else empty. Two
// reasons (docs/design.md, "Output files"): a full disk fails here, before
// a byte is written; and ext4, renaming over an existing file, first
// allocates the new file's delayed-allocation blocks and starts writing
// them out (its auto_da_alloc), which took 1.5 ms for a 60 KB PNG here,
// against 0.05 ms with the blocks reserved first. File systems without
// fallocate (or a size of 0) go on without it.
std::string reserve_space(int fd, std::size_t size) {
#if defined(__linux__)
    if (size == 0) return {};
    if (::fallocate(fd, 0, 0, static_cast<off_t>(size)) == 0) return {};
    const int error = errno;
    if (error == ENOSPC || error == EDQUOT || error == EFBIG) return errno_text(error);
#else
    (void)fd;
    (void)size;
#endif
    return {};
}

// The registry of temporary paths (files.hpp). A slot is free (0), being
// filled (1) or holds a path (2); the handler reads only slots in state 2.
constexpr int registry_slots = 64;
struct TemporarySlot {
    std::atomic<int> state{0};
    char path[PATH_MAX]{};
};
// constinit: zeros in .bss, no code at start-up. Initialised at run time,
// the 64 slots of 4 KiB each were 64 fresh pages touched by every run.
constinit std::array<TemporarySlot, registry_slots> registry;

// Follows a chain of symbolic links to the path it ends at (which may not
// exist yet: a dangling link is written through to its target). Sets
// `through_proc` when the chain passes /proc (/dev/stdout → /proc/self/fd/1):
// such a "link" names an open file of this process, which is written through.
std::filesystem::path follow_links(const std::filesystem::path& path, bool& through_proc) {
    std::filesystem::path current = path;
    for (int hop = 0; hop < 40; ++hop) {
        if (current.string().rfind("/proc/", 0) == 0) {
            through_proc = true;
            return current;
        }
        struct stat link_status;
        if (::lstat(current.c_str(), &link_status) != 0 || !S_ISLNK(link_status.st_mode))
            return current;
        std::array<char, PATH_MAX> target{};
        const ssize_t n = ::readlink(current.c_str(), target.data(), target.size() - 1);
        if (n <= 0) return current;
        std::filesystem::path next(std::string(target.data(), static_cast<std::size_t>(n)));
        current = next.is_absolute() ? next : current.parent_path() / next;
    }
    return current;  // a loop: open() reports ELOOP below
}

// ".litkit-" and six letters or digits: 14 bytes, whatever the target's name.
std::string temporary_name() {
    static constexpr char letters[] =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    std::random_device entropy;
    std::string name = ".litkit-";
    for (int i = 0; i < 6; ++i) name += letters[entropy() % (sizeof letters - 1)];
    return name;
}

}  // namespace

std::string read_file_limited(const std::filesystem::path& path, std::uint64_t limit) {
    const bool standard_input = path == "-";
    const std::string name = standard_input ? std::string("-") : path.string();
    auto fail = [&](const std::string& reason) { throw IoError(name, reason); };
    const std::string too_large = "larger than the limit of " + std::to_string(limit >> 20) +
                                  " MiB for scene and mesh files (docs/reliability.md)";
    const int fd = standard_input ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) fail(errno_text(errno));
    struct Closer {
        int fd;
        bool owned;
        ~Closer() {
            if (owned) ::close(fd);
        }
    } closer{fd, !standard_input};
    struct stat status;
    if (::fstat(fd, &status) != 0) fail(errno_text(errno));
    if (S_ISDIR(status.st_mode)) fail(errno_text(EISDIR));
    // A regular file says its size: refuse at once, read nothing.
    if (S_ISREG(status.st_mode) && static_cast<std::uint64_t>(status.st_size) > limit)
        fail(too_large);
    std::string bytes;
    if (S_ISREG(status.st_mode)) bytes.reserve(static_cast<std::size_t>(status.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(errno_text(errno));
        }
        if (n == 0) break;
        if (bytes.size() + static_cast<std::size_t>(n) > limit) fail(too_large);
        bytes.append(buffer, static_cast<std::size_t>(n));
    }
    return bytes;
}

void write_all(int fd, std::string_view bytes, const std::string& name) {
    for (std::size_t written = 0; written < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw IoError(name, errno_text(errno), {}, IoError::Access::Write);
        }
        written += static_cast<std::size_t>(n);
    }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
    auto fail = [&](const std::string& reason) {
        throw IoError(path.string(), reason, {}, IoError::Access::Write);
    };
    const std::string& text = path.native();
    if (text.empty()) fail("no file name given");

    bool through_proc = false;
    const std::filesystem::path target = follow_links(path, through_proc);
    struct stat status;
    const bool exists = ::stat(target.c_str(), &status) == 0;
    const int stat_error = exists ? 0 : errno;
    if (exists && S_ISDIR(status.st_mode)) fail("is a folder; name a file to write");
    if (!exists && stat_error == ENOTDIR) fail("a part of the path is not a folder");
    if (text.back() == '/') fail("names a folder (ends with '/'); name a file to write");

    // Devices, FIFOs, sockets and this process's own open files are written
    // through: replacing /dev/null with a regular file would break the
    // machine, and a pipe has no folder to rename into.
    if (through_proc || (exists && !S_ISREG(status.st_mode))) {
        const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY |
                                                (exists && S_ISREG(status.st_mode) ? O_TRUNC : 0));
        if (fd < 0) fail(errno_text(errno));
        try {
            write_all(fd, bytes, path.string());
        } catch (...) {
            ::close(fd);
            throw;
        }
        if (::close(fd) != 0) fail(errno_text(errno));
        return;
    }
    if (!exists && stat_error != ENOENT) fail(errno_text(stat_error));

    const std::filesystem::path folder =
        target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    std::filesystem::path temporary;
    int fd = -1;
    int slot = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        temporary = folder / temporary_name();
        // Registered before it exists: a signal may arrive on any thread at
        // any moment, and must find the file's name once the file is there.
        slot = register_temporary(temporary);
        // O_EXCL: never follow or reuse something already at the temporary name.
        fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0) {
            const int error = errno;
            unregister_temporary(slot);
            if (error != EEXIST) fail(errno_text(error));
        }
    }
    if (fd < 0) fail("cannot create a temporary file beside it");

    std::string failure;
    if (exists) {
        // Keep the replaced file's owner (root only; others cannot, and
        // keep their own) and mode; chown first, as it clears set-id bits.
        if (::fchown(fd, status.st_uid, status.st_gid) != 0) { /* not root: the file is ours */
        }
        if (::fchmod(fd, status.st_mode & 07777) != 0) failure = errno_text(errno);
    }
    if (failure.empty()) failure = reserve_space(fd, bytes.size());
    if (failure.empty()) {
        try {
            write_all(fd, bytes, path.string());
        } catch (const IoError& error) {
            failure = error.reason();
        }
    }
    // No fsync: the rename makes the file appear whole or not at all to
    // every other process; surviving a power cut is left to the system
    // (it cost 5-15 ms a file here, more than rendering the default scene;
    // docs/design.md, "Output files").
    if (::close(fd) != 0 && failure.empty()) failure = errno_text(errno);
    if (failure.empty() && ::rename(temporary.c_str(), target.c_str()) != 0) {
        failure = errno_text(errno);
    }
    if (!failure.empty()) ::unlink(temporary.c_str());
    unregister_temporary(slot);
    if (!failure.empty()) fail(failure);
}

void write_folder_atomically(const std::filesystem::path& directory,
                             const std::vector<std::pair<std::string, std::string>>& files) {
    auto fail = [](const std::filesystem::path& path, const std::string& reason) {
        throw IoError(path.string(), reason, {}, IoError::Access::Write);
    };
    struct stat status;
    const bool exists = ::stat(directory.c_str(), &status) == 0;
    if (exists && !S_ISDIR(status.st_mode)) fail(directory, "exists and is not a folder");
    std::filesystem::path parent = directory.lexically_normal().parent_path();
    if (parent.empty()) parent = ".";
    if (!exists) {
        std::error_code error;
        std::filesystem::create_directories(parent, error);
        if (error) fail(parent, "cannot create the folder: " + error.message());
    }
    // The temporary folder: beside a new folder, inside an existing one.
    const std::filesystem::path home = exists ? directory : parent;
    std::filesystem::path temporary;
    std::vector<int> slots;
    for (int attempt = 0; attempt < 100 && slots.empty(); ++attempt) {
        temporary = home / temporary_name();
        const int slot = register_temporary(temporary);
        if (::mkdir(temporary.c_str(), 0777) == 0) {
            slots.push_back(slot);
            break;
        }
        const int error = errno;
        unregister_temporary(slot);
        if (error != EEXIST) fail(directory, errno_text(error));
    }
    if (slots.empty()) fail(directory, "cannot create a temporary folder");
    auto clean = [&] {
        for (const auto& [name, bytes] : files) ::unlink((temporary / name).c_str());
        ::rmdir(temporary.c_str());
        for (int slot : slots) unregister_temporary(slot);
    };
    try {
        for (const auto& [name, bytes] : files) {
            const std::filesystem::path file = temporary / name;
            slots.push_back(register_temporary(file));
            mode_t mode = 0666;
            struct stat old;
            if (exists && ::stat((directory / name).c_str(), &old) == 0) mode = old.st_mode & 07777;
            const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (fd < 0) fail(directory / name, errno_text(errno));
            std::string failure;
            if (mode != 0666 && ::fchmod(fd, mode) != 0) failure = errno_text(errno);
            if (failure.empty()) failure = reserve_space(fd, bytes.size());
            if (failure.empty()) {
                try {
                    write_all(fd, bytes, (directory / name).string());
                } catch (const IoError& error) {
                    failure = error.reason();
                }
            }
            // No fsync, as in write_file_atomically.
            if (::close(fd) != 0 && failure.empty()) failure = errno_text(errno);
            if (!failure.empty()) fail(directory / name, failure);
        }
        if (!exists) {
            if (::rename(temporary.c_str(), directory.c_str()) != 0)
                fail(directory, errno_text(errno));
            for (int slot : slots) unregister_temporary(slot);
            return;
        }
        // Every file is written: only renames remain, which a full disk
        // cannot stop. Signals wait until the folder is whole.
        sigset_t all;
        sigset_t previous;
        sigfillset(&all);
        ::pthread_sigmask(SIG_BLOCK, &all, &previous);
        std::string failure;
        for (const auto& [name, bytes] : files) {
            if (::rename((temporary / name).c_str(), (directory / name).c_str()) != 0 &&
                failure.empty())
                failure = (directory / name).string() + ": " + errno_text(errno);
        }
        clean();
        ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
        if (!failure.empty()) fail(directory, failure);
    } catch (...) {
        clean();
        throw;
    }
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code error;
    bool same = std::filesystem::equivalent(a, b, error);
    return !error && same;
}

int register_temporary(const std::filesystem::path& path) noexcept {
    const std::string& text = path.native();
    if (text.size() >= PATH_MAX) return -1;
    for (int slot = 0; slot < registry_slots; ++slot) {
        int free = 0;
        if (!registry[slot].state.compare_exchange_strong(free, 1)) continue;
        std::memcpy(registry[slot].path, text.c_str(), text.size() + 1);
        registry[slot].state.store(2);
        return slot;
    }
    return -1;
}

void unregister_temporary(int slot) noexcept {
    if (slot >= 0 && slot < registry_slots) registry[slot].state.store(0);
}

void remove_registered_temporaries() noexcept {
    // Files first, then folders (a temporary folder is emptied before it is removed).
    for (TemporarySlot& slot : registry)
        if (slot.state.load() == 2) ::unlink(slot.path);
    for (TemporarySlot& slot : registry)
        if (slot.state.load() == 2) ::rmdir(slot.path);
}

}  // namespace litkit
