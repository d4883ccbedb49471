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
#include "vantage/io/printable.h"

namespace vantage::io {

namespace {

using internal::fail;

// The columns of each width: name,x,y,z with an optional weight and optional outward normal.
constexpr const char* kColumns4[] = {"name", "x", "y", "z"};
constexpr const char* kColumns5[] = {"name", "x", "y", "z", "weight"};
constexpr const char* kColumns7[] = {"name", "x", "y", "z", "nx", "ny", "nz"};
constexpr const char* kColumns8[] = {"name", "x", "y", "z", "weight", "nx", "ny", "nz"};

const char* const* columns_of(std::size_t width) {
  switch (width) {
    case 4:
      return kColumns4;
    case 5:
      return kColumns5;
    case 7:
      return kColumns7;
    case 8:
      return kColumns8;
    default:
      return nullptr;
  }
}

std::string lowercase(const std::string& s) {
  std::string out;
  for (const char c : s) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

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
  const std::string lower = lowercase(cell);
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
  return "line " + std::to_string(row.line) + (name.empty() ? "" : " (" + excerpt(name) + ")");
}

/// Drops a header row (is_header()); with normals it must name the columns (names).
void drop_header(std::vector<Row>& rows, const char* const* names, bool with_normals,
                 const std::string& source) {
  if (is_header(rows.front())) {
    // With normals the header says which of 7 or 8 columns is which: it must name them.
    for (std::size_t c = 1; with_normals && c < rows.front().fields.size(); ++c) {
      if (lowercase(rows.front().fields[c]) != names[c]) {
        fail(source, where(rows.front(), "") + ": column " + std::to_string(c + 1) +
                         " of the header is \"" + excerpt(rows.front().fields[c]) +
                         "\", expected \"" + names[c] + "\" (name,x,y,z[,weight],nx,ny,nz)");
      }
    }
    rows.erase(rows.begin());
  }
}

/// The numbers of row `column` (columns 1.. of row): its point into layout->entries, its weight
/// into layout->weights and its normal (not yet unit) into *normals.
void read_values(const Row& row, const std::string& name, Eigen::Index column,
                 const char* const* names, const std::string& source, Layout* layout,
                 Eigen::Matrix3Xd* normals) {
  const std::size_t columns = row.fields.size();
  for (std::size_t c = 1; c < columns; ++c) {
    double value = 0;
    if (!parse_number(row.fields[c], &value)) {
      fail(source, where(row, name) + ", " + names[c] + ": expected a finite number, got \"" +
                       excerpt(row.fields[c]) + "\"");
    }
    if (c < 4) {
      layout->entries(static_cast<Eigen::Index>(c - 1), column) = value;
    } else if (c == 4 && columns != 7) {
      layout->weights(column) = value;
    } else {
      (*normals)(static_cast<Eigen::Index>(c - (columns - 3)), column) = value;
    }
  }
}

}  // namespace

CsvMarkers parse_csv_markers(std::string_view text, const std::string& source) {
  std::vector<Row> rows = read_rows(text);
  if (rows.empty()) fail(source, "no marker rows (expected name,x,y,z[,weight][,nx,ny,nz])");
  const std::size_t columns = rows.front().fields.size();
  const char* const* names = columns_of(columns);
  if (names == nullptr) {
    fail(source, where(rows.front(), "") +
                     ": expected 4, 5, 7 or 8 fields (name,x,y,z[,weight][,nx,ny,nz]), got " +
                     std::to_string(columns));
  }
  const bool with_normals = columns >= 7;
  drop_header(rows, names, with_normals, source);
  if (rows.empty()) fail(source, "no marker rows after the header");

  CsvMarkers out;
  Layout& layout = out.layout;
  layout.name = std::filesystem::path(source).stem().string();
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, static_cast<Eigen::Index>(rows.size()));
  layout.weights = Eigen::VectorXd::Ones(layout.entries.cols());
  layout.candidates.resize(3, 0);
  Eigen::Matrix3Xd normals(3, with_normals ? layout.entries.cols() : 0);
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
    read_values(row, name, static_cast<Eigen::Index>(k), names, source, &layout, &normals);
    if (with_normals) {
      const Eigen::Vector3d normal = unit_normal(normals.col(static_cast<Eigen::Index>(k)));
      if (normal.isZero()) fail(source, where(row, name) + ", nx,ny,nz: zero length");
      normals.col(static_cast<Eigen::Index>(k)) = normal;
    }
    out.names.push_back(name);
    labels.push_back(where(row, name));
  }
  layout.names = out.names;
  if (with_normals) {
    MarkerVisibility visibility;
    visibility.normals = normals;
    visibility.cone_half_angle_deg =
        Eigen::VectorXd::Constant(normals.cols(), MarkerVisibility::kDefaultConeDeg);
    layout.visibility = visibility;
  }
  internal::validate_labelled(layout, source, labels);
  return out;
}

Layout parse_csv_layout(std::string_view text, const std::string& source) {
  return parse_csv_markers(text, source).layout;
}

}  // namespace vantage::io
