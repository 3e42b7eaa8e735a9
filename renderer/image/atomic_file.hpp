// Replacing a file all at once: the new content goes to a temporary file in the destination's folder, which is
// then renamed over the destination. A rename within one file system is atomic on POSIX, so readers see either
// the old file or the complete new one, never a partial write.
#pragma once

#include <filesystem>
#include <functional>

namespace povtrace::image {

// Calls `write_temp` with the path of a fresh, empty temporary file next to `destination` and then renames that
// file to `destination`. If creating the temporary file, `write_temp` or the rename fails, the temporary file is
// removed, an existing `destination` is left untouched, and ImageError is thrown naming `destination` and the
// cause (the message of any exception `write_temp` threw).
void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(const std::filesystem::path& temp)>& write_temp);

}  // namespace povtrace::image
