#include "StagingFolder.h"

#include <unistd.h>

#include <algorithm>

#include "viewpipe/error.hpp"

namespace viewpipe::gui {
namespace fs = std::filesystem;

StagingFolder::StagingFolder(const fs::path& out) : out_(out), madeOut_(!fs::exists(out))
{
    std::error_code error;
    fs::create_directories(out_, error);
    if (error || !fs::is_directory(out_))
        throw InputError("--out", "cannot create the folder \"" + out_.string() + "\": " + error.message());
    staging_ = out_ / (".viewpipe-staging-" + std::to_string(::getpid()));
    fs::remove_all(staging_, error);
    fs::create_directories(staging_, error);
    if (error)
        throw InputError("--out", "cannot write in the folder \"" + out_.string() + "\": " + error.message());
}

StagingFolder::~StagingFolder()
{
    std::error_code ignored;
    fs::remove_all(staging_, ignored);
    if (madeOut_)
        fs::remove(out_, ignored); // only if still empty
}

std::vector<fs::path> StagingFolder::commit()
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(staging_))
        names.push_back(entry.path().filename().string());
    return commit(names);
}

namespace {

// A folder moves into one already there file by file (a pack written again
// into its own folder); a file replaces one.
void moveInto(const fs::path& from, const fs::path& to)
{
    if (fs::is_directory(from) && fs::is_directory(to)) {
        for (const auto& entry : fs::directory_iterator(from))
            moveInto(entry.path(), to / entry.path().filename());
        return;
    }
    fs::rename(from, to);
}

} // namespace

std::vector<fs::path> StagingFolder::commit(const std::vector<std::string>& names)
{
    std::vector<fs::path> moved;
    for (const std::string& name : names) {
        moveInto(staging_ / name, out_ / name);
        moved.push_back(out_ / name);
    }
    madeOut_ = false; // it holds the export now
    std::sort(moved.begin(), moved.end());
    return moved;
}

} // namespace viewpipe::gui
