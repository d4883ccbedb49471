#pragma once

/// Bounded reads and all-or-nothing writes of the text files vantage reads and writes.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include "vantage/analysis/common.h"

namespace vantage::io {

/// Default bound of read_text_file(): 64 MiB (a layout of about a million vectors).
constexpr std::size_t kMaxFileBytes = std::size_t{64} << 20;
/// The bound when the user lifts the size limits (the CLI's --allow-large, Python's
/// allow_large=True): 1 GiB.
constexpr std::size_t kMaxFileBytesAllowLarge = std::size_t{1} << 30;

/// Thrown by read_text_file() when the input exceeds its bound (bad input, like any
/// InvalidArgument; a separate type so that a command can say how to lift the bound).
class FileTooLarge : public InvalidArgument {
 public:
  using InvalidArgument::InvalidArgument;
};

/// Thrown when a write fails because of the environment, not of the target the user chose: no
/// space (ENOSPC), quota (EDQUOT), file size limit (EFBIG), I/O error (EIO), no memory, or any
/// failure of write(2), fsync(2) or close(2) on the temporary. The rule holds wherever the
/// failure happens (the lock file, the temporary, the write, the rename), so every command
/// exits 1 on a full disk. The target is untouched.
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
/// system lacks it). Only a regular file is ever replaced: the target is checked before the
/// write and again just before the rename, and a device node, FIFO, socket, directory or
/// symbolic link there is refused, untouched. On any error the temporary is removed and the
/// target is untouched. Throws InvalidArgument for a bad target (empty name, not a regular file,
/// an existing file without `overwrite`, a missing or unwritable directory, a name too long) and
/// WriteError when the environment fails (see WriteError).
void write_text_file(const std::string& path, const std::string& text, bool overwrite);

/// A text file written in pieces, all or nothing, as write_text_file() writes it whole: the
/// constructor checks the target (check_write_target()) and creates the temporary beside it,
/// write() appends (buffered), commit() flushes, fsyncs and renames it into place with the same
/// rule for replacing. Destroyed without commit(), the temporary is removed and the target is
/// untouched, so a run that fails half-way leaves nothing. Errors as write_text_file().
class AtomicTextFile {
 public:
  AtomicTextFile(const std::string& path, bool overwrite);
  ~AtomicTextFile();
  AtomicTextFile(const AtomicTextFile&) = delete;
  AtomicTextFile& operator=(const AtomicTextFile&) = delete;

  void write(std::string_view text);
  void commit();

 private:
  static constexpr std::size_t kBufferBytes = std::size_t{1} << 16;
  void flush();
  void write_bytes(std::string_view bytes);

  std::string path_;
  bool overwrite_;
  std::string temp_;
  int fd_ = -1;
  std::string buffer_;
  int removal_slot_ = -1;  ///< the temporary's slot in the signal handler's list
};

/// Checks everything write_text_file() can check before any work: the name is non-empty; when
/// something exists there it is a regular file (not a directory, symbolic link, dangling or
/// not, character or block device, FIFO or socket) and `overwrite` is set; its directory exists
/// and is writable. Throws InvalidArgument "<path>: <problem>".
void check_write_target(const std::string& path, bool overwrite);

/// True when `a` and `b` name the same existing file (the same device and inode, through any
/// link or spelling of the path); false when either does not exist. A command checks it before
/// it writes, so that its output never replaces one of its own inputs unasked.
bool same_file(const std::string& a, const std::string& b);

/// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove the temporaries of the
/// AtomicTextFile writes and the WriteLock lock files in progress, then end the process by the
/// same signal (its default action, so the exit status still names the signal); a signal the
/// parent ignores (SIGINT in a background job, SIGHUP under nohup) stays ignored. For a program
/// that owns its signals: the vantage command calls it first thing; the libraries and the Python
/// module never do (Python keeps its own SIGINT, KeyboardInterrupt, whose unwinding removes them
/// through the destructors). A SIGKILL cannot be caught: its temporary stays (hidden,
/// ".vantage-write-*"), and its lock file is taken over by the next run, since the kernel
/// releases the lock (flock) with the process.
void remove_partial_files_on_signal();

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
  int removal_slot_ = -1;  ///< the lock file's slot in the signal handler's list
};

}  // namespace vantage::io
