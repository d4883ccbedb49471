#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "command.h"

namespace vantage::cli {

Json json_rows(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    Json row = Json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

Json json_list(const Eigen::VectorXd& v) {
  Json list = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) list.push_back(v(i));
  return list;
}

namespace {

// File names need not be UTF-8: replace invalid bytes (U+FFFD) rather than fail after the work.
// `indent` spaces begin every line but the first (the value is nested that deep).
std::string dump_nested(const Json& value, int indent) {
  std::string text = value.dump(2, ' ', false, Json::error_handler_t::replace);
  if (indent == 0) return text;
  const std::string newline = "\n" + std::string(static_cast<std::size_t>(indent), ' ');
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '\n') {
      out += newline;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

void print_json(const Json& object) { std::cout << dump_nested(object, 0) << std::endl; }

void print_json(const Json& object, const std::string& key, std::size_t count,
                const std::function<Json(std::size_t)>& element) {
  // nlohmann's two-space dump, one member at a time (an object with members, as every report).
  std::cout << "{";
  const char* separator = "\n";
  for (auto member = object.begin(); member != object.end(); ++member) {
    std::cout << separator << "  " << dump_nested(Json(member.key()), 0) << ": ";
    separator = ",\n";
    if (member.key() != key) {
      std::cout << dump_nested(member.value(), 2);
    } else if (count == 0) {
      std::cout << "[]";
    } else {
      std::cout << "[";
      for (std::size_t i = 0; i < count; ++i) {
        std::cout << (i == 0 ? "\n" : ",\n") << "    " << dump_nested(element(i), 4);
      }
      std::cout << "\n  ]";
    }
  }
  std::cout << "\n}" << std::endl;
}

std::string pad(std::string text, std::size_t width) {
  if (text.size() < width) text.append(width - text.size(), ' ');
  return text;
}

std::string format_number(double x, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << (x == 0.0 ? 0.0 : x);  // never "-0"
  return out.str();
}

std::string format_vector(const Eigen::VectorXd& v, int digits) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    // A value that rounds to zero prints as 0.000000, never -0.000000.
    const double x = std::abs(v(i)) < 0.5 * std::pow(10.0, -digits) ? 0.0 : v(i);
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), " %*.*f", digits + 4, digits, x);
    out += buffer;
  }
  return out + " ]";
}

std::string format_matrix(const Eigen::MatrixXd& m, int indent, int digits) {
  std::string out;
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    out += std::string(indent, ' ') + format_vector(m.row(i).transpose(), digits) + "\n";
  }
  return out;
}

}  // namespace vantage::cli
