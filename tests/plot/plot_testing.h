#pragma once

// Helpers of the vantage::plot tests: reading the CSV written beside each figure, example
// layouts, a design curve with known numbers.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "vantage/io/layout_file.h"
#include "vantage/plot/design_curve.h"
#include "vantage/report/layout_report.h"

namespace vantage::plot::testing {

/// A CSV file: its header names and its rows (as text).
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  /// Index of a header column; fails the test when absent.
  std::size_t column(const std::string& name) const {
    for (std::size_t k = 0; k < header.size(); ++k) {
      if (header[k] == name) return k;
    }
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  double number(std::size_t row, const std::string& name) const {
    return std::strtod(rows[row][column(name)].c_str(), nullptr);
  }
  const std::string& text(std::size_t row, const std::string& name) const {
    return rows[row][column(name)];
  }
};

inline std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();  // an empty last field
  return fields;
}

/// Reads a CSV written by vantage::plot; every row must have as many fields as the header.
inline Csv read_csv(const std::filesystem::path& path) {
  Csv csv;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) {
    ADD_FAILURE() << "empty or missing CSV " << path;
    return csv;
  }
  csv.header = split(line);
  while (std::getline(in, line)) {
    csv.rows.push_back(split(line));
    EXPECT_EQ(csv.rows.back().size(), csv.header.size()) << path << ": " << line;
  }
  return csv;
}

inline Layout example_layout(const std::string& name) {
  return io::read_layout(std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/" + name);
}

/// A scratch directory removed with the object.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("vantage_plot_" + tag + "_" + std::to_string(::getpid()) + "_" +
             std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// A design curve with fixed numbers: Z = I (m = 3, 0.8165) grown by two directions.
/// The report the figures are drawn from, with the dropout analysis the dropout figure needs
/// (what `vantage plot` computes).
inline report::LayoutReport report_of(const Layout& layout) {
  report::LayoutReportOptions options;
  options.dropout = true;
  return report::analyze_layout(layout, options);
}

inline DesignCurve example_design_curve() {
  DesignCurve curve;
  curve.layout_name = "example design";
  curve.n_vectors = {3, 4, 5};
  curve.pbar_min = {0.816496580927726, 0.816496580927726, 0.9};
  curve.has_direct = true;
  curve.direct_n_vectors = 5;
  curve.direct_pbar_min = 0.92;
  return curve;
}

}  // namespace vantage::plot::testing
