#pragma once

// Shared pieces of the `vantage` subcommands. Contract (README.md, "The `vantage` command"): every
// subcommand prints a readable report by default and exactly one JSON object on stdout with --json;
// exit status 0 when done, 2 for bad input or usage (one line on stderr, nothing written), 1 for an
// internal failure such as a solver that did not converge.

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/common.h"
#include "vantage/commands/against_source.h"

namespace vantage::cli {

using Json = nlohmann::ordered_json;

/// Exit statuses of the command.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;

/// A registered subcommand: its CLI11 node and the function that runs it after parsing.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

Command add_analyze_command(CLI::App& root);
Command add_orient_command(CLI::App& root);
Command add_design_command(CLI::App& root);
Command add_weights_command(CLI::App& root);
Command add_pose_command(CLI::App& root);
Command add_layout_command(CLI::App& root);
/// `vantage completion bash` (completion.cc): it reads `root`'s tree when it runs.
Command add_completion_command(CLI::App& root);
Command add_simulate_command(CLI::App& root);
Command add_experiment_command(CLI::App& root);
Command add_plot_command(CLI::App& root);
Command add_place_command(CLI::App& root);
Command add_crb_command(CLI::App& root);
Command add_tre_command(CLI::App& root);
Command add_ident_command(CLI::App& root);

using commands::against_source;

/// A matrix as nested JSON rows ([[..], [..]]), a vector as a flat list.
Json json_rows(const Eigen::MatrixXd& m);
Json json_list(const Eigen::VectorXd& v);

/// Prints one JSON object on stdout (two-space indented; invalid UTF-8 in strings, e.g. a file
/// name, is replaced by U+FFFD instead of failing).
void print_json(const Json& object);

/// print_json() of `object` with the value of its key `key` replaced by the array of `count`
/// elements element(0), ..., element(count - 1), each made only when printed: the same bytes,
/// without the whole array in memory (`vantage ident` on many tools).
void print_json(const Json& object, const std::string& key, std::size_t count,
                const std::function<Json(std::size_t)>& element);

/// Fixed-width text for the readable reports: "[ x y z ]" and a number with `digits`
/// significant digits.
std::string format_vector(const Eigen::VectorXd& v, int digits = 6);
std::string format_number(double x, int digits = 6);

/// `text` with spaces appended up to `width` bytes (a column of a text report).
std::string pad(std::string text, std::size_t width);

/// The readable rows of a 3x3 matrix, each indented by `indent` spaces and ending in '\n'.
std::string format_matrix(const Eigen::MatrixXd& m, int indent = 2, int digits = 6);

}  // namespace vantage::cli
