// parse_atracsys_geometry(): the reader of Atracsys geometry files (atracsys_geometry.h).

#include "vantage/io/atracsys_geometry.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <vector>

#include "entry_labels.h"
#include "json_fields.h"
#include "vantage/analysis/common.h"
#include "vantage/io/printable.h"

namespace vantage::io {

namespace {

using internal::fail;

std::string trim_blanks(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return "";
  const auto last = s.find_last_not_of(" \t\r");
  return std::string(s.substr(first, last - first + 1));
}

/// One key=value line of a section.
struct IniValue {
  int line = 0;
  std::string value;
};

/// One [section]: the line of its header and its keys.
struct IniSection {
  int line = 0;
  std::map<std::string, IniValue> keys;
};

using IniSections = std::map<std::string, IniSection>;

std::string at_line(int line) { return "line " + std::to_string(line); }

/// The sections of the text, with the checks of the INI syntax the manual describes.
IniSections read_sections(std::string_view text, const std::string& source) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  IniSections sections;
  IniSection* current = nullptr;
  std::string current_name;
  int line_number = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t newline = text.find('\n', start);
    const std::string line = trim_blanks(text.substr(
        start, newline == std::string_view::npos ? std::string_view::npos : newline - start));
    ++line_number;
    start = newline == std::string_view::npos ? text.size() + 1 : newline + 1;
    if (line.empty() || line.front() == ';') continue;
    if (line.front() == '[') {
      if (line.back() != ']') fail(source, at_line(line_number) + ": expected ']' at the end");
      current_name = trim_blanks(std::string_view(line).substr(1, line.size() - 2));
      if (current_name.empty()) fail(source, at_line(line_number) + ": empty section name");
      const auto [it, inserted] = sections.emplace(current_name, IniSection{line_number, {}});
      if (!inserted) {
        fail(source, at_line(line_number) + ": [" + excerpt(current_name) +
                         "] repeats the section of " + at_line(it->second.line));
      }
      current = &it->second;
      continue;
    }
    const std::size_t equal = line.find('=');
    if (equal == std::string::npos) {
      fail(source, at_line(line_number) +
                       ": expected a [section], a key=value line or a ';' comment, got \"" +
                       excerpt(line) + "\"");
    }
    const std::string key = trim_blanks(std::string_view(line).substr(0, equal));
    if (current == nullptr) {
      fail(source,
           at_line(line_number) + ", " + excerpt(key) + ": a key before the first [section]");
    }
    if (key.empty()) {
      fail(source, at_line(line_number) + ", [" + excerpt(current_name) + "]: empty key");
    }
    const auto [it, inserted] = current->keys.emplace(
        key, IniValue{line_number, trim_blanks(std::string_view(line).substr(equal + 1))});
    if (!inserted) {
      fail(source, at_line(line_number) + ", [" + excerpt(current_name) + "] " + excerpt(key) +
                       ": repeats the key of " + at_line(it->second.line));
    }
  }
  return sections;
}

/// The key's value; errors naming the section when it is missing.
const IniValue& required_key(const IniSections::value_type& section, const std::string& key,
                             const std::string& source) {
  const auto it = section.second.keys.find(key);
  if (it == section.second.keys.end()) {
    fail(source, "[" + excerpt(section.first) + "] (" + at_line(section.second.line) + "): no " +
                     key + " key");
  }
  return it->second;
}

std::string where(const IniValue& value, const std::string& section, const std::string& key) {
  return at_line(value.line) + ", [" + excerpt(section) + "] " + excerpt(key);
}

/// A decimal integer in [low, high] (digits only).
std::uint64_t read_integer(const IniSections::value_type& section, const std::string& key,
                           std::uint64_t low, std::uint64_t high, const std::string& source) {
  const IniValue& value = required_key(section, key, source);
  const std::string& text = value.value;
  const bool digits = !text.empty() && text.size() <= 19 &&
                      text.find_first_not_of("0123456789") == std::string::npos;
  const std::uint64_t n = digits ? std::strtoull(text.c_str(), nullptr, 10) : 0;
  if (!digits || n < low || n > high) {
    fail(source, where(value, section.first, key) + ": expected an integer from " +
                     std::to_string(low) + " to " + std::to_string(high) + ", got \"" +
                     excerpt(text) + "\"");
  }
  return n;
}

/// The x, y and z keys of a section as a point.
Eigen::Vector3d read_point(const IniSections::value_type& section, const std::string& source) {
  Eigen::Vector3d p;
  const char* const axes[] = {"x", "y", "z"};
  for (int r = 0; r < 3; ++r) {
    const IniValue& value = required_key(section, axes[r], source);
    const std::string& text = value.value;
    errno = 0;
    char* end = nullptr;
    p(r) = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE ||
        !std::isfinite(p(r))) {
      fail(source, where(value, section.first, axes[r]) +
                       ": expected a finite number (mm), got \"" + excerpt(text) + "\"");
    }
  }
  return p;
}

/// K when `name` is "fiducial<K>" (decimal digits, no sign), else -1.
long fiducial_index(const std::string& name) {
  constexpr std::string_view kPrefix = "fiducial";
  if (name.size() <= kPrefix.size() || name.size() > kPrefix.size() + 9 ||
      name.compare(0, kPrefix.size(), kPrefix) != 0) {
    return -1;
  }
  const std::string digits = name.substr(kPrefix.size());
  if (digits.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::strtol(digits.c_str(), nullptr, 10);
}

}  // namespace

AtracsysGeometry parse_atracsys_geometry(std::string_view text, const std::string& source) {
  const IniSections sections = read_sections(text, source);
  const auto geometry = sections.find("geometry");
  if (geometry == sections.end()) fail(source, "no [geometry] section");
  const auto count = static_cast<long>(
      read_integer(*geometry, "count", kAtracsysMinFiducials, kAtracsysMaxFiducials, source));
  AtracsysGeometry out;
  out.id = static_cast<std::uint32_t>(read_integer(*geometry, "id", 0, 0xFFFFFFFFu, source));
  for (const auto& section : sections) {
    if (fiducial_index(section.first) >= count) {
      fail(source, at_line(section.second.line) + ", [" + section.first +
                       "]: beyond count=" + std::to_string(count) + " of [geometry] (" +
                       at_line(required_key(*geometry, "count", source).line) +
                       "), so the SDK would not read it");
    }
  }
  Layout& layout = out.layout;
  layout.name = std::filesystem::path(source).stem().string();
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, count);
  layout.weights = Eigen::VectorXd::Ones(count);
  layout.candidates.resize(3, 0);
  std::vector<std::string> labels;
  for (long k = 0; k < count; ++k) {
    const std::string name = "fiducial" + std::to_string(k);
    const auto section = sections.find(name);
    if (section == sections.end()) {
      fail(source, "no [" + name + "] section (count=" + std::to_string(count) + ")");
    }
    layout.entries.col(k) = read_point(*section, source);
    layout.names.push_back(name);
    labels.push_back(at_line(section->second.line) + ", [" + name + "]");
  }
  const auto pivot = sections.find("pivot");
  if (pivot != sections.end()) out.pivot = read_point(*pivot, source);
  internal::validate_labelled(layout, source, labels);
  return out;
}

Layout parse_atracsys_layout(std::string_view text, const std::string& source) {
  return parse_atracsys_geometry(text, source).layout;
}

}  // namespace vantage::io
