#include <cstdio>
#include <iostream>
#include <sstream>

#include "command.h"

namespace vantage::cli {

void rethrow_against(const std::string& source, const std::exception& error) {
  std::string message = error.what();
  const std::string library_name = "model_object";
  for (auto at = message.find(library_name); at != std::string::npos;
       at = message.find(library_name, at)) {
    message.replace(at, library_name.size(), "model");
  }
  throw InvalidArgument(source + ": " + message);
}

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

void print_json(const Json& object) { std::cout << object.dump(2) << std::endl; }

std::string format_number(double x, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << x;
  return out.str();
}

std::string format_vector(const Eigen::VectorXd& v, int digits) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), " %*.*f", digits + 4, digits, v(i));
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
