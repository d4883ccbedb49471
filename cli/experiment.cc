// `vantage experiment NAME --out DIR [--trials N] [--seed S] [--threads T] [--quick]
// [--layouts FILE ...] [--json]`: the seed papers' simulation experiments (vantage::simulate
// experiments.h), each writing its CSV files and a summary table into DIR.

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "command.h"
#include "layout_input.h"
#include "limits.h"
#include "vantage/analysis/layout.h"
#include "vantage/simulate/experiments.h"

namespace vantage::cli {
namespace {

using namespace vantage::simulate;

struct ExperimentArgs {
  std::string name;
  std::string out;
  long trials = 0;
  std::uint64_t seed = 1;
  int threads = 0;
  bool quick = false;
  std::vector<std::string> layouts;
  bool json = false;
  bool quiet = false;
  bool allow_large = false;
};

/// The layouts of the bound experiment: those given, else the bundled examples/layouts.
std::vector<NamedLayout> bound_layouts(const ExperimentArgs& args) {
  std::vector<std::string> files = args.layouts;
  if (files.empty()) {
    const std::filesystem::path dir = std::filesystem::path(VANTAGE_EXAMPLES_DIR) / "layouts";
    if (std::filesystem::is_directory(dir)) {
      for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() == ".json") files.push_back(entry.path().string());
      }
    }
    std::sort(files.begin(), files.end());
  }
  std::vector<NamedLayout> layouts;
  for (const std::string& file : files) {
    const Layout layout = LayoutInput().read(file);
    NamedLayout named;
    named.name = std::filesystem::path(file).stem().string();
    named.entries = layout.entries;
    named.vectors = layout.mode == LayoutMode::kVectors;
    layouts.push_back(std::move(named));
  }
  return layouts;
}

int run_experiment_command(const ExperimentArgs& args) {
  if (args.out.empty()) throw InvalidArgument("--out: must not be empty");
  if (args.trials < 0) throw InvalidArgument("--trials: must be >= 1 (or 0 for the default)");
  check_limit("--trials", args.trials, kMaxTrials, "experiment", args.allow_large);
  if (args.threads < 0) throw InvalidArgument("--threads: must be >= 0");
  if (!args.layouts.empty() && args.name != "bound") {
    throw InvalidArgument("--layouts: only the bound experiment takes layouts");
  }
  bool known = false;
  for (const Experiment& e : experiment_registry()) known = known || e.name == args.name;
  if (!known) {
    throw InvalidArgument("NAME: unknown experiment '" + args.name +
                          "' (known: " + experiment_names() + ")");
  }
  ExperimentOptions options;
  options.out_dir = args.out;
  options.trials = args.trials;
  options.seed = args.seed;
  options.threads = args.threads;
  options.quick = args.quick;
  options.progress = !args.json && !args.quiet;
  if (args.name == "bound") options.layouts = bound_layouts(args);
  const ExperimentResult result = run_experiment(args.name, options);
  if (args.json) {
    Json out = result.summary;
    out["files"] = result.files;
    print_json(out);
  } else {
    std::cout << result.table << "\nwrote";
    for (const std::string& file : result.files) std::cout << " " << file;
    std::cout << "\n(" << format_number(result.seconds, 3) << " s)\n";
  }
  const bool failed = result.summary.contains("passed") && !result.summary["passed"].get<bool>();
  if (failed) {
    std::cerr << "vantage: experiment " << args.name << ": FAILED: "
              << (result.summary.contains("message") ? result.summary["message"].get<std::string>()
                                                     : std::string("see the summary"))
              << std::endl;
  }
  return failed ? kExitFailure : kExitOk;
}

}  // namespace

Command add_experiment_command(CLI::App& root) {
  auto args = std::make_shared<ExperimentArgs>();
  CLI::App* sub = root.add_subcommand(
      "experiment",
      "The seed papers' simulation experiments with our numbers: CSV files and a summary table "
      "(summary.md, summary.json) in --out");
  sub->add_option("NAME", args->name, experiment_names())->required();
  sub->add_option("--out", args->out, "output directory (created when missing)")->required();
  sub->add_option("--trials", args->trials, "trials per cell (default: the experiment's own)");
  sub->add_option("--seed", args->seed, "run seed")->capture_default_str();
  sub->add_option("--threads", args->threads, "worker threads, 0 = all cores")
      ->capture_default_str();
  sub->add_flag("--quick", args->quick, "a tiny version (for tests)");
  sub->add_option("--layouts", args->layouts,
                  "bound: layout files to check (default: the bundled examples/layouts)");
  sub->add_flag("--json", args->json, "print the summary as one JSON object");
  sub->add_flag("--quiet", args->quiet, "no progress bar");
  add_allow_large_flag(sub, args->allow_large);
  return {sub, [args] { return run_experiment_command(*args); }};
}

}  // namespace vantage::cli
