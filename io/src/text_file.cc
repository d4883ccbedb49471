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

#include "vantage/io/printable.h"

namespace vantage::io {

namespace {

// Bytes read per read(2) call.
constexpr std::size_t kReadChunk = std::size_t{1} << 16;

[[noreturn]] void bad(const std::string& path, const std::string& problem) {
  throw InvalidArgument(printable(path + ": " + problem));
}

std::string errno_text(int error) { return std::strerror(error); }

// Failures to open or create a file: the name or its directory is the user's input.
[[noreturn]] void bad_errno(const std::string& path, const std::string& action, int error) {
  bad(path, action + ": " + errno_text(error));
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

// Closes a descriptor and removes a temporary file unless released.
class Temporary {
 public:
  Temporary(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
  ~Temporary() {
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
  }
  Temporary(const Temporary&) = delete;
  Temporary& operator=(const Temporary&) = delete;
  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  int close() {
    const int result = ::close(fd_);
    fd_ = -1;
    return result;
  }
  void release() { path_.clear(); }

 private:
  int fd_;
  std::string path_;
};

void write_all(const Temporary& temp, const std::string& target, const std::string& text) {
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t written = ::write(temp.fd(), data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      throw WriteError(printable(target) + ": write failed: " + errno_text(errno) +
                       "; nothing written");
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

// Moves the finished temporary to `target`; without `overwrite` an existing target is refused
// atomically.
void move_into_place(const std::string& temp, const std::string& target, bool overwrite) {
  if (overwrite) {
    if (::rename(temp.c_str(), target.c_str()) != 0) bad_errno(target, "cannot replace", errno);
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
    bad_errno(target, "cannot create", errno);
  }
#endif
  if (::link(temp.c_str(), target.c_str()) != 0) {
    if (errno == EEXIST) bad(target, "exists already; refusing to overwrite it");
    bad_errno(target, "cannot create", errno);
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
    if (S_ISLNK(info.st_mode)) {
      bad(path, "is a symbolic link; give the path of the file itself");
    }
    if (S_ISDIR(info.st_mode)) bad(path, "is a directory");
    if (!overwrite) bad(path, "exists already; refusing to overwrite it");
  } else if (errno != ENOENT) {
    bad_errno(path, "cannot write", errno);
  }
  const std::string directory = directory_of(path);
  if (::stat(directory.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) {
    bad(path, "directory " + directory + " does not exist");
  }
  if (::access(directory.c_str(), W_OK) != 0) {
    bad_errno(path, "cannot write in " + directory, errno);
  }
}

void write_text_file(const std::string& path, const std::string& text, bool overwrite) {
  check_write_target(path, overwrite);
  const std::string directory = directory_of(path);
  std::string pattern = directory + "/.vantage-write-XXXXXX";
  const int fd = ::mkostemp(pattern.data(), O_CLOEXEC);
  if (fd < 0) bad_errno(path, "cannot create a temporary file in " + directory, errno);
  Temporary temp(fd, pattern);
  write_all(temp, path, text);
  if (::fchmod(temp.fd(), 0666 & ~current_umask()) != 0 || ::fsync(temp.fd()) != 0) {
    throw WriteError(printable(path) + ": write failed: " + errno_text(errno) +
                     "; nothing written");
  }
  if (temp.close() != 0) {
    throw WriteError(printable(path) + ": write failed: " + errno_text(errno) +
                     "; nothing written");
  }
  move_into_place(temp.path(), path, overwrite);
  temp.release();
  const int dir_fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

WriteLock::WriteLock(const std::string& path)
    : lock_path_(directory_of(path) + "/." + base_name(path) + ".lock") {
  for (;;) {
    fd_ = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) bad_errno(path, "cannot create the lock file " + lock_path_, errno);
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK) bad(path, "another process is writing it (" + lock_path_ + ")");
      bad_errno(path, "cannot lock " + lock_path_, error);
    }
    // The holder before us may have removed the file after we opened it: lock the file that
    // is at the path now.
    struct stat held {
    }, now{};
    if (::fstat(fd_, &held) == 0 && ::stat(lock_path_.c_str(), &now) == 0 &&
        held.st_ino == now.st_ino && held.st_dev == now.st_dev) {
      return;
    }
    ::close(fd_);
    fd_ = -1;
  }
}

WriteLock::~WriteLock() {
  if (fd_ < 0) return;
  ::unlink(lock_path_.c_str());
  ::close(fd_);
}

}  // namespace vantage::io
