#include "vantage/io/text_file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "removal_registry.h"
#include "vantage/io/printable.h"

namespace vantage::io {

namespace {

// Bytes read per read(2) call.
constexpr std::size_t kReadChunk = std::size_t{1} << 16;

[[noreturn]] void bad(const std::string& path, const std::string& problem) {
  throw InvalidArgument(printable(path + ": " + problem));
}

std::string errno_text(int error) { return std::strerror(error); }

// The machine, not the user's choice of target, is at fault: the disk or the quota is full, the
// file size limit is reached, the device fails or memory runs out.
bool is_environment_failure(int error) {
  return error == ENOSPC || error == EDQUOT || error == EFBIG || error == EIO || error == ENOMEM;
}

// Failures to open a file for reading: the name is the user's input.
[[noreturn]] void bad_errno(const std::string& path, const std::string& action, int error) {
  bad(path, action + ": " + errno_text(error));
}

// Failures to create, write or replace a file: the name or its directory is the user's input
// (InvalidArgument, exit 2), unless the environment failed (WriteError, exit 1), wherever that
// happens (the lock file, the temporary, the write, the rename): one rule for every write.
[[noreturn]] void write_failure(const std::string& path, const std::string& action, int error) {
  if (is_environment_failure(error)) {
    throw WriteError(printable(path) + ": " + action + ": " + errno_text(error) +
                     "; nothing written");
  }
  bad(path, action + ": " + errno_text(error));
}

// What a non-regular file is, in words.
const char* kind_of(mode_t mode) {
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Only a regular file may ever be replaced: a symbolic link, a directory, a device node, a FIFO
// or a socket at the target is refused (the rename would replace the node itself).
void check_replaceable(const std::string& path, const struct stat& info) {
  if (S_ISLNK(info.st_mode)) bad(path, "is a symbolic link; give the path of the file itself");
  if (S_ISDIR(info.st_mode)) bad(path, "is a directory");
  if (!S_ISREG(info.st_mode)) {
    bad(path, std::string("is ") + kind_of(info.st_mode) +
                  ", not a regular file; refusing to replace it");
  }
}

std::string directory_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string base_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Moves the finished temporary to `target`; without `overwrite` an existing target is refused
// atomically.
void move_into_place(const std::string& temp, const std::string& target, bool overwrite) {
  if (overwrite) {
    // Checked again at rename time: the target may have changed since check_write_target().
    // (rename(2) has no "only a regular file" flag; what remains is the moment between this
    // lstat and the rename, open only to a process that may replace the node itself.)
    struct stat info {};
    if (::lstat(target.c_str(), &info) == 0) {
      check_replaceable(target, info);
    } else if (errno != ENOENT) {
      write_failure(target, "cannot write", errno);
    }
    if (::rename(temp.c_str(), target.c_str()) != 0) write_failure(target, "cannot replace", errno);
    return;
  }
#ifdef SYS_renameat2
  constexpr unsigned kRenameNoReplace = 1;  // RENAME_NOREPLACE
  if (::syscall(SYS_renameat2, AT_FDCWD, temp.c_str(), AT_FDCWD, target.c_str(),
                kRenameNoReplace) == 0) {
    return;
  }
  if (errno == EEXIST) bad(target, "exists already; refusing to overwrite it");
  if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) {
    write_failure(target, "cannot create", errno);
  }
#endif
  if (::link(temp.c_str(), target.c_str()) != 0) {
    if (errno == EEXIST) bad(target, "exists already; refusing to overwrite it");
    write_failure(target, "cannot create", errno);
  }
  ::unlink(temp.c_str());
}

mode_t current_umask() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return mask;
}

}  // namespace

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) bad_errno(path, "cannot open file", errno);
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) == 0 && S_ISDIR(info.st_mode)) bad(path, "is a directory, not a file");
  std::string text;
  std::vector<char> chunk(kReadChunk);
  for (;;) {
    const ssize_t got = ::read(fd, chunk.data(), chunk.size());
    if (got < 0) {
      if (errno == EINTR) continue;
      bad_errno(path, "cannot read file", errno);
    }
    if (got == 0) break;
    if (text.size() + static_cast<std::size_t>(got) > max_bytes) {
      throw FileTooLarge(printable(path) + ": larger than " + std::to_string(max_bytes) +
                         " bytes, the input size limit");
    }
    text.append(chunk.data(), static_cast<std::size_t>(got));
  }
  return text;
}

void check_write_target(const std::string& path, bool overwrite) {
  if (path.empty()) throw InvalidArgument("empty file name");
  struct stat info {};
  if (::lstat(path.c_str(), &info) == 0) {
    check_replaceable(path, info);
    if (!overwrite) bad(path, "exists already; refusing to overwrite it");
  } else if (errno != ENOENT) {
    write_failure(path, "cannot write", errno);
  }
  const std::string directory = directory_of(path);
  if (::stat(directory.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) {
    bad(path, "directory " + directory + " does not exist");
  }
  if (::access(directory.c_str(), W_OK) != 0) {
    write_failure(path, "cannot write in " + directory, errno);
  }
}

bool same_file(const std::string& a, const std::string& b) {
  struct stat first {};
  struct stat second {};
  return ::stat(a.c_str(), &first) == 0 && ::stat(b.c_str(), &second) == 0 &&
         first.st_dev == second.st_dev && first.st_ino == second.st_ino;
}

AtomicTextFile::AtomicTextFile(const std::string& path, bool overwrite)
    : path_(path), overwrite_(overwrite) {
  check_write_target(path, overwrite);
  const std::string directory = directory_of(path);
  std::string pattern = directory + "/.vantage-write-XXXXXX";
  fd_ = ::mkostemp(pattern.data(), O_CLOEXEC);
  if (fd_ < 0) write_failure(path, "cannot create a temporary file in " + directory, errno);
  temp_ = pattern;
  removal_slot_ = internal::register_removal(temp_);
}

AtomicTextFile::~AtomicTextFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!temp_.empty()) ::unlink(temp_.c_str());
  internal::unregister_removal(removal_slot_);
}

void AtomicTextFile::write(std::string_view text) {
  if (buffer_.size() + text.size() > kBufferBytes) {
    flush();
    if (text.size() >= kBufferBytes) return write_bytes(text);  // large pieces: no copy
  }
  buffer_.append(text);
}

void AtomicTextFile::flush() {
  write_bytes(buffer_);
  buffer_.clear();
}

void AtomicTextFile::write_bytes(std::string_view bytes) {
  const char* data = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t written = ::write(fd_, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      throw WriteError(printable(path_) + ": write failed: " + errno_text(errno) +
                       "; nothing written");
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

void AtomicTextFile::commit() {
  VANTAGE_CHECK(fd_ >= 0 && !temp_.empty(), "AtomicTextFile committed twice");
  flush();
  if (::fchmod(fd_, 0666 & ~current_umask()) != 0 || ::fsync(fd_) != 0) {
    throw WriteError(printable(path_) + ": write failed: " + errno_text(errno) +
                     "; nothing written");
  }
  const int closed = ::close(fd_);
  fd_ = -1;
  if (closed != 0) {
    throw WriteError(printable(path_) + ": write failed: " + errno_text(errno) +
                     "; nothing written");
  }
  move_into_place(temp_, path_, overwrite_);
  internal::unregister_removal(removal_slot_);
  removal_slot_ = -1;
  temp_.clear();
  const int dir_fd = ::open(directory_of(path_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

void write_text_file(const std::string& path, const std::string& text, bool overwrite) {
  AtomicTextFile file(path, overwrite);
  file.write(text);
  file.commit();
}

WriteLock::WriteLock(const std::string& path)
    : lock_path_(directory_of(path) + "/." + base_name(path) + ".lock") {
  for (;;) {
    fd_ = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) write_failure(path, "cannot create the lock file " + lock_path_, errno);
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK) bad(path, "another process is writing it (" + lock_path_ + ")");
      write_failure(path, "cannot lock " + lock_path_, error);
    }
    // The holder before us may have removed the file after we opened it: lock the file that
    // is at the path now.
    struct stat held {
    }, now{};
    if (::fstat(fd_, &held) == 0 && ::stat(lock_path_.c_str(), &now) == 0 &&
        held.st_ino == now.st_ino && held.st_dev == now.st_dev) {
      removal_slot_ = internal::register_removal(lock_path_);
      return;
    }
    ::close(fd_);
    fd_ = -1;
  }
}

WriteLock::~WriteLock() {
  if (fd_ < 0) return;
  ::unlink(lock_path_.c_str());
  internal::unregister_removal(removal_slot_);
  ::close(fd_);
}

}  // namespace vantage::io
