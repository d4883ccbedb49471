#include "vantage/io/csv_layout.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "entry_labels.h"
#include "json_fields.h"
#include "vantage/analysis/common.h"

namespace vantage::io {

namespace {

using internal::fail;

constexpr const char* kColumns[] = {"name", "x", "y", "z", "weight"};

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return "";
  const auto last = s.find_last_not_of(" \t\r");
  std::string out(s.substr(first, last - first + 1));
  if (out.size() >= 2 && out.front() == '"' && out.back() == '"')
    out = out.substr(1, out.size() - 2);
  return out;
}

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(
        trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

/// The whole field as a finite double, or false.
bool parse_number(const std::string& field, double* value) {
  if (field.empty()) return false;
  errno = 0;
  char* end = nullptr;
  *value = std::strtod(field.c_str(), &end);
  return end == field.c_str() + field.size() && errno != ERANGE && std::isfinite(*value);
}

/// A data row of the file: its line number and fields.
struct Row {
  int line = 0;
  std::vector<std::string> fields;
};

/// The non-blank, non-comment rows of the text.
std::vector<Row> read_rows(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<Row> rows;
  int line_number = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t newline = text.find('\n', start);
    const std::string_view line = text.substr(
        start, newline == std::string_view::npos ? std::string_view::npos : newline - start);
    ++line_number;
    const std::string content = trim(line);
    if (!content.empty() && content.front() != '#')
      rows.push_back({line_number, split_fields(line)});
    if (newline == std::string_view::npos) break;
    start = newline + 1;
  }
  return rows;
}

/// Whether a cell holds a value, however bad: anything that starts as a number does (finite or
/// not: "nan", "inf", "1e999", "2.5mm"), so does an empty cell or one of the usual markers of a
/// missing value ("n/a", "NA", "null", "-", ...). A header cell is none of these.
bool holds_value(const std::string& cell) {
  if (cell.empty()) return true;
  char* end = nullptr;
  std::strtod(cell.c_str(), &end);
  if (end != cell.c_str()) return true;
  std::string lower;
  for (const char c : cell) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* missing : {"n/a", "#n/a", "na", "n.a.", "nan", "null", "none", "nil", "-", "--",
                              "?", "inf", "+inf", "-inf", "infinity"}) {
    if (lower == missing) return true;
  }
  return false;
}

/// A header names the columns: no cell after the name holds a value (holds_value()). A row with
/// a number, a NaN, an empty cell or "n/a" in any coordinate or weight is a data row, and its bad
/// cells are reported.
bool is_header(const Row& row) {
  for (std::size_t c = 1; c < row.fields.size(); ++c) {
    if (holds_value(row.fields[c])) return false;
  }
  return true;
}

std::string where(const Row& row, const std::string& name) {
  return "line " + std::to_string(row.line) + (name.empty() ? "" : " (" + name + ")");
}

}  // namespace

CsvMarkers parse_csv_markers(std::string_view text, const std::string& source) {
  std::vector<Row> rows = read_rows(text);
  if (rows.empty()) fail(source, "no marker rows (expected name,x,y,z[,weight])");
  const std::size_t columns = rows.front().fields.size();
  if (columns < 4 || columns > 5) {
    fail(source, where(rows.front(), "") + ": expected 4 or 5 fields (name,x,y,z[,weight]), got " +
                     std::to_string(columns));
  }
  if (is_header(rows.front())) rows.erase(rows.begin());
  if (rows.empty()) fail(source, "no marker rows after the header");

  CsvMarkers out;
  Layout& layout = out.layout;
  layout.name = std::filesystem::path(source).stem().string();
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, static_cast<Eigen::Index>(rows.size()));
  layout.weights = Eigen::VectorXd::Ones(layout.entries.cols());
  layout.candidates.resize(3, 0);
  std::map<std::string, int> seen;
  std::vector<std::string> labels;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Row& row = rows[k];
    const std::string& name = row.fields[0];
    if (row.fields.size() != columns) {
      fail(source, where(row, name) + ": expected " + std::to_string(columns) +
                       " fields like the first row, got " + std::to_string(row.fields.size()));
    }
    if (name.empty()) fail(source, where(row, "") + ", name: empty marker name");
    const auto [previous, inserted] = seen.emplace(name, row.line);
    if (!inserted) {
      fail(source, where(row, name) + ", name: repeats the marker of line " +
                       std::to_string(previous->second));
    }
    for (std::size_t c = 1; c < columns; ++c) {
      double value = 0;
      if (!parse_number(row.fields[c], &value)) {
        fail(source, where(row, name) + ", " + kColumns[c] + ": expected a finite number, got \"" +
                         row.fields[c] + "\"");
      }
      if (c < 4) {
        layout.entries(static_cast<Eigen::Index>(c - 1), static_cast<Eigen::Index>(k)) = value;
      } else {
        layout.weights(static_cast<Eigen::Index>(k)) = value;
      }
    }
    out.names.push_back(name);
    labels.push_back(where(row, name));
  }
  layout.names = out.names;
  internal::validate_labelled(layout, source, labels);
  return out;
}

Layout parse_csv_layout(std::string_view text, const std::string& source) {
  return parse_csv_markers(text, source).layout;
}

}  // namespace vantage::io
