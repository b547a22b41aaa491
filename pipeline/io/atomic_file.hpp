// io/atomic_file.hpp: the one way every output file is written (images, CSV, Markdown, plots,
// screenshots). A file appears under its final name whole or not at all:
//   - the bytes go to a temporary name unique to the process in the destination folder
//     (NAME.asvgf-<pid>-<n>.partial), so two runs into one folder never share a temporary file and
//     the last complete file wins;
//   - every write, the flush, the sync and the close are checked; the file is synced before the
//     rename so that a crash cannot publish it empty;
//   - on any failure the temporary file is removed and FileWriteError names the file and the
//     system's reason ("No space left on device").
// ASVGF_FILE_FAULT (a test hook, like ASVGF_FAULT for the HAL) fails the n-th write, flush, sync,
// close or rename of the process: "<op>:<n>"; "count" makes the process print
// "file fault counts: write N, flush N, sync N, close N, rename N" to stderr at exit.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace asvgf::render {

class FileWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void write_file_atomic(const std::filesystem::path& path, std::span<const std::byte> bytes);
void write_file_atomic(const std::filesystem::path& path, std::string_view text);

// Removes the temporary files of this writer that dead processes left in `folder` (a killed run);
// returns their names. Files of live processes and every other file are left alone.
std::vector<std::filesystem::path> remove_stale_partials(const std::filesystem::path& folder);

// Throws std::invalid_argument naming ASVGF_FILE_FAULT when it is malformed (the commands check it
// at start-up, so a typo is a usage error rather than a fault in the middle of a run).
void check_file_fault_environment();

}  // namespace asvgf::render
