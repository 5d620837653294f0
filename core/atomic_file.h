// All-or-nothing file output: readers of `path` see either the old file or
// the complete new one, never a partial write.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace unfold {

/// Writes a file through a temporary file in the same directory that is renamed
/// over `path` only once `write` has finished and the stream is flushed; while
/// an OutputTransaction is open, only when that transaction commits.
/// @param path   destination; its directory must exist and be writable.
/// @param write  fills the stream; may throw.
/// @param binary open the stream in binary mode.
/// @throws OutputError naming `path` if the temporary file cannot be created,
///         the stream fails, `write` throws a non-unfold exception, or the
///         rename fails. An unfold::Error thrown by `write` is rethrown as is.
///         In every failure case the temporary file has been removed.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

/// Checks early, before long work, that `path` could be created: its directory
/// exists and is writable.
/// @throws OutputError naming `path` and the reason
void check_writable_destination(const std::string& path);

}  // namespace unfold
