// SPDX-License-Identifier: MIT
// Watching the files a scene is made of, for the viewer's live reload.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <vector>

namespace litkit_cli {

// Reports when any of a set of files changes: written in place, replaced by
// a rename (how vim, VS Code and most editors save), created, deleted. On
// Linux it watches the files' folders with inotify (so a replaced file is
// still seen); elsewhere, or if inotify fails, it polls each file's size and
// modification time.
class FileWatcher {
  public:
    explicit FileWatcher(std::vector<std::filesystem::path> files);
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    // True when a watched file changed since the last call. Never blocks.
    bool changed();
    // The files watched, to replace (a reload may add or drop mesh files).
    void watch(std::vector<std::filesystem::path> files);
    bool uses_inotify() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace litkit_cli
