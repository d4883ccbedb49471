// `vantage weights LAYOUT [--json]`: max-min non-negative weights with sum_i w_i z_i = 0, the
// null-space condition (Eq. 11) of the decoupled pose solution of Prop. 3 (McInroy et al.).
// Weights that do not exist are an answer (exit 0), with the paper's fixes.

#include <iostream>
#include <memory>

#include "command.h"
#include "layout_input.h"
#include "limits.h"
#include "vantage/commands/design_json.h"
#include "vantage/design/weights.h"
#include "vantage/io/layout_file.h"

namespace vantage::cli {

namespace {

struct WeightsArgs {
  std::string file;
  LayoutInput input;
  bool json = false;
  bool allow_large = false;
};

int run_weights(const WeightsArgs& args) {
  const Layout layout = args.input.read(args.file, args.allow_large);
  check_limit(args.file + ": " + layout.entries_field(), layout.entries.cols(), kMaxWeightsEntries,
              "weights", args.allow_large);
  const design::Weights w =
      against_source(args.file, [&] { return design::layout_weights(layout); });
  const bool solved = w.status != design::Weights::Status::kSolverFailed;

  if (args.json) {
    print_json(design_json::weights(args.file, layout, w));
  } else {
    std::cout << "vantage weights: " << args.file
              << (layout.name.empty() ? "" : " (" + layout.name + ")") << ", "
              << layout.entries.cols() << " " << layout.entries_field() << "\n"
              << "Prop. 3 / Eq. (11): w_i >= 0, sum_i w_i z_i = 0, sum_i w_i = n, smallest weight "
                 "as large as possible\n"
              << "status      " << design::to_string(w.status)
              << (w.feasible ? " (weights exist)" : " (no such weights)") << "\n"
              << "            " << w.message << "\n";
    if (w.feasible) {
      std::cout << "min weight  " << format_number(w.min_weight) << "\n"
                << "residual    " << format_number(w.residual) << "  (||sum_i w_i z_i||)\n"
                << "  i  " << layout.entries_field() << "\n";
      for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) {
        char index[24];
        std::snprintf(index, sizeof(index), "%3ld", static_cast<long>(i));
        std::cout << index << "  " << format_vector(layout.entries.col(i), 4)
                  << "  w = " << format_number(w.weights(i))
                  << (layout.names.empty() ? "" : "  " + layout.names[i]) << "\n";
      }
    } else if (solved) {
      std::cout << "lp optimum  " << format_number(w.lp_optimum)
                << "  (largest smallest weight; < 0: the origin is outside conv{z_i})\n";
    }
    for (size_t s = 0; s < w.suggestions.size(); ++s) {
      std::cout << (s == 0 ? "suggestion: " : "or:         ") << w.suggestions[s].text << "\n";
    }
  }
  if (!solved) {
    std::cerr << "vantage: weights: " << w.message << std::endl;
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

Command add_weights_command(CLI::App& root) {
  auto args = std::make_shared<WeightsArgs>();
  CLI::App* sub = root.add_subcommand(
      "weights",
      "Non-negative weights with sum_i w_i z_i = 0 (Prop. 3, Eq. 11), smallest weight maximised; "
      "when none exist, the fix: a symmetric partner -z_i or a shift of the origin");
  sub->add_option("LAYOUT", args->file,
                  "layout JSON file (points: marker positions; vectors: the z_i themselves)")
      ->required();
  args->input.add_options(sub);
  add_allow_large_flag(sub, args->allow_large);
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_weights(*args); }};
}

}  // namespace vantage::cli
