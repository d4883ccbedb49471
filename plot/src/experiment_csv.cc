#include "experiment_csv.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "vantage/analysis/common.h"

namespace vantage::plot::internal {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

}  // namespace

ExperimentCsv::ExperimentCsv(const std::filesystem::path& path) : path_(path) {
  std::ifstream in(path);
  if (!in) throw InvalidArgument(path.string() + ": cannot read (run `vantage experiment` first)");
  std::string line;
  if (!std::getline(in, line)) throw InvalidArgument(path.string() + ": empty file");
  header_ = split(line);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    rows_.push_back(split(line));
    if (rows_.back().size() != header_.size()) {
      throw InvalidArgument(path.string() + ": line " + std::to_string(rows_.size() + 1) + " has " +
                            std::to_string(rows_.back().size()) + " fields, expected " +
                            std::to_string(header_.size()));
    }
  }
}

bool ExperimentCsv::has_column(const std::string& name) const {
  return std::find(header_.begin(), header_.end(), name) != header_.end();
}

std::size_t ExperimentCsv::column(const std::string& name) const {
  for (std::size_t k = 0; k < header_.size(); ++k) {
    if (header_[k] == name) return k;
  }
  throw InvalidArgument(path_.string() + ": no column " + name);
}

double ExperimentCsv::number(std::size_t row, std::size_t column) const {
  const std::string& field = rows_[row][column];
  if (field.empty()) return std::nan("");
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);
  if (end != field.c_str() + field.size()) {
    throw InvalidArgument(path_.string() + ": line " + std::to_string(row + 2) + ", column " +
                          header_[column] + ": not a number: " + field);
  }
  return value;
}

}  // namespace vantage::plot::internal
