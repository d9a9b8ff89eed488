#pragma once

// Write, then move into place: an export's files are written into a hidden
// folder inside `out` and moved into `out` (rename is atomic) only once all
// of them are complete. A failed or cancelled export leaves nothing half
// written, and no `out` it had to make.

#include <filesystem>
#include <string>
#include <vector>

namespace viewpipe::gui {

class StagingFolder {
public:
    // Makes `out` where missing; throws InputError naming --out when it cannot.
    explicit StagingFolder(const std::filesystem::path& out);
    // Removes what was not moved, and `out` when it was made here and is still empty.
    ~StagingFolder();
    StagingFolder(const StagingFolder&) = delete;
    StagingFolder& operator=(const StagingFolder&) = delete;

    // Where to write.
    const std::filesystem::path& path() const { return staging_; }
    // Moves every file (and folder) written into `out`, a folder into one already there file by file;
    // their new paths, sorted.
    std::vector<std::filesystem::path> commit();
    // Moves the files `names` only (the rest were the making's: logs, sources).
    std::vector<std::filesystem::path> commit(const std::vector<std::string>& names);

private:
    std::filesystem::path out_, staging_;
    bool madeOut_;
};

} // namespace viewpipe::gui
