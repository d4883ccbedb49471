#pragma once

// A CSV table written by `vantage experiment` (header line, comma-separated fields, no quoting),
// read for the experiment figures. Private to vantage::plot.

#include <filesystem>
#include <string>
#include <vector>

namespace vantage::plot::internal {

class ExperimentCsv {
 public:
  /// Reads `path`. Throws InvalidArgument naming the file when it is missing, empty or has a
  /// row whose field count differs from the header's.
  explicit ExperimentCsv(const std::filesystem::path& path);

  std::size_t rows() const { return rows_.size(); }
  bool has_column(const std::string& name) const;
  /// Column index of `name`; throws InvalidArgument naming the file and the column when absent.
  std::size_t column(const std::string& name) const;
  const std::string& text(std::size_t row, std::size_t column) const { return rows_[row][column]; }
  /// The field as a number; an empty field is NaN; throws InvalidArgument naming the file, line
  /// and column when the field is not a number.
  double number(std::size_t row, std::size_t column) const;

 private:
  std::filesystem::path path_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace vantage::plot::internal
