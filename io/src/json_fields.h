#pragma once

// Private helpers shared by the file readers: typed access to JSON fields with one-line errors
// "<source>: <field>[<index>]: <problem>".

#include <Eigen/Core>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace vantage::io::internal {

/// Throws InvalidArgument "<source>: <what>", made printable().
[[noreturn]] void fail(const std::string& source, const std::string& what);

/// Parses `text` as a JSON object; errors for invalid JSON or a non-object root.
nlohmann::json parse_object(std::string_view text, const std::string& source);

/// Errors on a top-level key not in `allowed`.
void reject_unknown_fields(const nlohmann::json& root, const std::string& source,
                           std::initializer_list<const char*> allowed);

/// A list of `Rows`-vectors, e.g. [[x, y, z], ...], as a Rows x n matrix of finite numbers.
template <int Rows>
Eigen::Matrix<double, Rows, Eigen::Dynamic> read_vectors(const nlohmann::json& value,
                                                         const std::string& source,
                                                         const std::string& field);

/// A list of finite numbers.
Eigen::VectorXd read_numbers(const nlohmann::json& value, const std::string& source,
                             const std::string& field);

/// A string field.
std::string read_string(const nlohmann::json& value, const std::string& source,
                        const std::string& field);

/// The columns of `m` as a list of [x, y, z] rows, as every layout file writes them.
nlohmann::json vector_rows(const Eigen::Matrix3Xd& m);

}  // namespace vantage::io::internal
