// SPDX-License-Identifier: MIT
#include "viewer/watch.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <system_error>

#ifdef __linux__
#include <sys/inotify.h>
#include <unistd.h>
#endif

namespace litkit_cli {

namespace fs = std::filesystem;

namespace {

// What polling compares: size and modification time, or nothing if missing.
struct Stamp {
    std::uintmax_t size = 0;
    fs::file_time_type time{};
    bool exists = false;
    bool operator==(const Stamp&) const = default;
};

Stamp stamp_of(const fs::path& file) {
    std::error_code error;
    Stamp stamp;
    stamp.time = fs::last_write_time(file, error);
    if (error) return {};
    stamp.size = fs::file_size(file, error);
    stamp.exists = !error;
    return stamp;
}

}  // namespace

struct FileWatcher::Impl {
    std::vector<fs::path> files;
    std::map<fs::path, Stamp> stamps;  // polling
    int inotify = -1;
    std::map<int, fs::path> folders;  // watch descriptor → folder
    std::set<std::string> names;      // file names watched, per any folder

    void start() {
        stamps.clear();
        for (const fs::path& file : files) stamps[file] = stamp_of(file);
#ifdef __linux__
        if (inotify >= 0) {
            for (const auto& [descriptor, folder] : folders) inotify_rm_watch(inotify, descriptor);
            folders.clear();
        } else {
            inotify = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
        }
        names.clear();
        if (inotify < 0) return;
        std::set<fs::path> wanted;
        for (const fs::path& file : files) {
            const fs::path absolute = fs::absolute(file);
            wanted.insert(absolute.parent_path());
            names.insert(absolute.filename().string());
        }
        for (const fs::path& folder : wanted) {
            const int descriptor =
                inotify_add_watch(inotify, folder.c_str(),
                                  IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE | IN_MODIFY);
            if (descriptor >= 0) folders[descriptor] = folder;
        }
        if (folders.empty()) {
            close(inotify);
            inotify = -1;
        }
#endif
    }

    bool poll_stamps() {
        bool changed = false;
        for (auto& [file, stamp] : stamps) {
            const Stamp now = stamp_of(file);
            if (!(now == stamp)) {
                stamp = now;
                changed = true;
            }
        }
        return changed;
    }

    bool read_inotify() {
#ifdef __linux__
        bool changed = false;
        alignas(inotify_event) char buffer[8192];
        for (;;) {
            const ssize_t length = read(inotify, buffer, sizeof buffer);
            if (length <= 0) break;
            for (ssize_t at = 0; at < length;) {
                const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
                if (event->len > 0 && names.count(event->name)) changed = true;
                at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            }
        }
        return changed;
#else
        return false;
#endif
    }
};

FileWatcher::FileWatcher(std::vector<fs::path> files) : impl_(std::make_unique<Impl>()) {
    impl_->files = std::move(files);
    impl_->start();
}

FileWatcher::~FileWatcher() {
#ifdef __linux__
    if (impl_->inotify >= 0) close(impl_->inotify);
#endif
}

void FileWatcher::watch(std::vector<fs::path> files) {
    impl_->files = std::move(files);
    impl_->start();
}

bool FileWatcher::uses_inotify() const { return impl_->inotify >= 0; }

bool FileWatcher::changed() {
    // inotify says when to look; the stamps say whether a watched file really
    // changed (and cover systems and folders inotify cannot watch).
    if (impl_->inotify >= 0) {
        if (!impl_->read_inotify()) return false;
    }
    return impl_->poll_stamps();
}

}  // namespace litkit_cli
