#include "json_fields.h"

#include <algorithm>
#include <cmath>

#include "vantage/analysis/common.h"

namespace vantage::io::internal {

void fail(const std::string& source, const std::string& what) {
  throw InvalidArgument(source + ": " + what);
}

nlohmann::json parse_object(std::string_view text, const std::string& source) {
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {
    // Syntax errors and numbers beyond double range (1e999) both land here. e.what() is
    // "[json.exception.parse_error.101] parse error at ...": keep the readable part.
    std::string what = e.what();
    const auto bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    fail(source, "not valid JSON: " + what);
  }
  if (!root.is_object()) fail(source, "the top level must be a JSON object {...}");
  return root;
}

void reject_unknown_fields(const nlohmann::json& root, const std::string& source,
                           std::initializer_list<const char*> allowed) {
  for (const auto& item : root.items()) {
    const bool known = std::any_of(allowed.begin(), allowed.end(),
                                   [&](const char* name) { return item.key() == name; });
    if (!known) fail(source, "unknown field \"" + item.key() + "\"");
  }
}

namespace {

double read_number(const nlohmann::json& value, const std::string& source,
                   const std::string& where) {
  if (!value.is_number()) fail(source, where + ": expected a number");
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(source, where + ": not a finite number");
  return x;
}

}  // namespace

template <int Rows>
Eigen::Matrix<double, Rows, Eigen::Dynamic> read_vectors(const nlohmann::json& value,
                                                         const std::string& source,
                                                         const std::string& field) {
  if (!value.is_array())
    fail(source, field + ": expected a list of " + std::to_string(Rows) + "-element lists");
  Eigen::Matrix<double, Rows, Eigen::Dynamic> out(Rows, value.size());
  for (std::size_t j = 0; j < value.size(); ++j) {
    const std::string where = field + "[" + std::to_string(j) + "]";
    const nlohmann::json& item = value[j];
    if (!item.is_array() || item.size() != Rows) {
      fail(source, where + ": expected " + std::to_string(Rows) + " numbers, got " +
                       (item.is_array() ? std::to_string(item.size())
                                        : std::string("a ") + item.type_name()));
    }
    for (int i = 0; i < Rows; ++i) {
      out(i, j) = read_number(item[i], source, where + "[" + std::to_string(i) + "]");
    }
  }
  return out;
}

template Eigen::Matrix<double, 2, Eigen::Dynamic> read_vectors<2>(const nlohmann::json&,
                                                                  const std::string&,
                                                                  const std::string&);
template Eigen::Matrix<double, 3, Eigen::Dynamic> read_vectors<3>(const nlohmann::json&,
                                                                  const std::string&,
                                                                  const std::string&);

Eigen::VectorXd read_numbers(const nlohmann::json& value, const std::string& source,
                             const std::string& field) {
  if (!value.is_array()) fail(source, field + ": expected a list of numbers");
  Eigen::VectorXd out(value.size());
  for (std::size_t i = 0; i < value.size(); ++i) {
    out(i) = read_number(value[i], source, field + "[" + std::to_string(i) + "]");
  }
  return out;
}

std::string read_string(const nlohmann::json& value, const std::string& source,
                        const std::string& field) {
  if (!value.is_string()) fail(source, field + ": expected a string");
  return value.get<std::string>();
}

}  // namespace vantage::io::internal
