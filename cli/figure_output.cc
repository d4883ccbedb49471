#include "figure_output.h"

#include <unistd.h>

#include <filesystem>
#include <iostream>

namespace vantage::cli {

namespace fs = std::filesystem;

void check_figure_directory(const std::string& option, const std::string& directory) {
  if (directory.empty()) throw InvalidArgument(option + ": empty directory name");
  std::error_code ec;
  fs::path path(directory);
  if (fs::exists(path, ec)) {
    if (!fs::is_directory(path, ec)) {
      throw InvalidArgument(option + ": " + directory + " exists and is not a directory");
    }
    if (::access(path.c_str(), W_OK | X_OK) != 0) {
      throw InvalidArgument(option + ": directory " + directory + " is not writable");
    }
    return;
  }
  fs::path ancestor = fs::absolute(path, ec).parent_path();
  while (!ancestor.empty() && !fs::exists(ancestor, ec)) {
    if (ancestor == ancestor.parent_path()) break;
    ancestor = ancestor.parent_path();
  }
  if (!fs::is_directory(ancestor, ec)) {
    throw InvalidArgument(option + ": cannot create " + directory + " (" + ancestor.string() +
                          " is not a directory)");
  }
  if (::access(ancestor.c_str(), W_OK | X_OK) != 0) {
    throw InvalidArgument(option + ": cannot create " + directory + " (" + ancestor.string() +
                          " is not writable)");
  }
}

void create_figure_directory(const std::string& option, const std::string& directory) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec || !fs::is_directory(directory)) {
    throw InvalidArgument(option + ": cannot create directory " + directory +
                          (ec ? " (" + ec.message() + ")" : ""));
  }
}

Json figure_files_json(const std::vector<plot::FigureFiles>& files) {
  Json list = Json::array();
  for (const plot::FigureFiles& f : files) {
    list.push_back({{"name", f.name}, {"image", f.image.string()}, {"csv", f.csv.string()}});
  }
  return list;
}

void print_figure_files(const std::vector<plot::FigureFiles>& files, plot::Format format) {
  std::cout << files.size() << " figure" << (files.size() == 1 ? "" : "s") << " written ("
            << plot::to_string(format) << " + csv):\n";
  for (const plot::FigureFiles& f : files) {
    std::cout << "  " << f.image.string() << "\n  " << f.csv.string() << "\n";
  }
}

}  // namespace vantage::cli
