#pragma once

/// Runs the built vantage-viewer (path in VANTAGE_VIEWER, set by CMake) through the shell and
/// captures its exit status, stdout and stderr.

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace vantage::testing {

struct ViewerRun {
  int status = -1;
  std::string out;
  std::string err;
};

/// A scratch directory for one test, removed with the object.
class ViewerScratch {
 public:
  ViewerScratch() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("vantage_viewer_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~ViewerScratch() { std::filesystem::remove_all(path_); }
  ViewerScratch(const ViewerScratch&) = delete;
  ViewerScratch& operator=(const ViewerScratch&) = delete;

  std::string path(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name) << text;
    return path(name);
  }

 private:
  std::filesystem::path path_;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs `prefix 'VANTAGE_VIEWER' args` (prefix e.g. "xvfb-run -a", may be empty).
inline ViewerRun run_viewer(const std::string& prefix, const std::string& args,
                            const ViewerScratch& scratch) {
  const std::string out = scratch.path("stdout.txt");
  const std::string err = scratch.path("stderr.txt");
  const std::string command =
      prefix + " '" VANTAGE_VIEWER "' " + args + " > '" + out + "' 2> '" + err + "' < /dev/null";
  const int raw = std::system(command.c_str());
  ViewerRun run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.out = slurp(out);
  run.err = slurp(err);
  return run;
}

}  // namespace vantage::testing
