#pragma once

/// Bounded reads and all-or-nothing writes of the text files vantage reads and writes.

#include <cstddef>
#include <stdexcept>
#include <string>

#include "vantage/analysis/common.h"

namespace vantage::io {

/// Default bound of read_text_file(): 64 MiB (a layout of about a million vectors).
constexpr std::size_t kMaxFileBytes = std::size_t{64} << 20;

/// Thrown by read_text_file() when the input exceeds its bound (bad input, like any
/// InvalidArgument; a separate type so that a command can say how to lift the bound).
class FileTooLarge : public InvalidArgument {
 public:
  using InvalidArgument::InvalidArgument;
};

/// Thrown when writing fails after the target was accepted (no space, I/O error, file size
/// limit): an environment failure, not bad input. The target is untouched.
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The whole content of the file at `path`, read in bounded chunks, so that /dev/zero or an
/// endless pipe stops at `max_bytes` instead of exhausting memory. Throws InvalidArgument
/// "<path>: <problem>" when it cannot be opened (missing, a directory, name too long, ...) and
/// FileTooLarge when it holds more than `max_bytes` bytes.
std::string read_text_file(const std::string& path, std::size_t max_bytes = kMaxFileBytes);

/// Writes `text` to `path` all or nothing: into a temporary file in the target's directory,
/// flushed and fsync'ed, then renamed into place; without `overwrite` the rename atomically
/// refuses an existing target (renameat2 RENAME_NOREPLACE, or link + unlink where the file
/// system lacks it). On any error the temporary is removed and the
/// target is untouched. Throws InvalidArgument for a bad target (empty name, a directory, a
/// symbolic link, an existing file without `overwrite`, a missing or unwritable directory, a
/// name too long) and WriteError when the write itself fails (ENOSPC, EIO, EFBIG).
void write_text_file(const std::string& path, const std::string& text, bool overwrite);

/// Checks everything write_text_file() can check before any work: the name is non-empty, not a
/// directory or symbolic link (dangling or not), not an existing file unless `overwrite`, and
/// its directory exists. Throws InvalidArgument "<path>: <problem>".
void check_write_target(const std::string& path, bool overwrite);

/// An exclusive advisory lock (flock) on `path`'s lock file (".<name>.lock" beside it), held
/// for the object's lifetime, so that a second run writing the same target fails at once
/// instead of after its whole computation. The lock file is removed on release.
class WriteLock {
 public:
  /// Throws InvalidArgument "<path>: another process is writing it" when the lock is taken.
  explicit WriteLock(const std::string& path);
  ~WriteLock();
  WriteLock(const WriteLock&) = delete;
  WriteLock& operator=(const WriteLock&) = delete;

 private:
  std::string lock_path_;
  int fd_ = -1;
};

}  // namespace vantage::io
