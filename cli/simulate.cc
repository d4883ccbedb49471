// `vantage simulate LAYOUT --trials N [--camera affine|pinhole] [--noise-px S | --snr-db X]
// [--noise gaussian|uniform] [--range R] [--focal F] [--principal-point U V] [--offset X Y]
// [--viewpoint worst|random|AX,AY,AZ] [--methods a,b] [--seed S] [--threads T] [--shard K/N]
// [--per-trial] [--csv FILE [--overwrite]] [--json] [--quiet]` and
// `vantage simulate --merge A.json B.json ...`:
// Monte Carlo runs of every applicable estimator on one layout, the bound check of Eq. (26) and
// Eq. (30) (affine camera), and the exact merge of sharded runs.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "command.h"
#include "crb_input.h"
#include "layout_input.h"
#include "limits.h"
#include "vantage/analysis/layout.h"
#include "vantage/commands/point_text.h"
#include "vantage/io/text_file.h"
#include "vantage/simulate/layout_simulation.h"
#include "vantage/simulate/visibility_json.h"

namespace vantage::cli {
namespace {

using namespace vantage::simulate;

struct SimulateArgs {
  std::string file;
  LayoutInput input;
  long trials = 1000;
  std::string camera = "affine";
  double noise_px = 0.0;
  double snr_db = 0.0;
  std::string noise = "gaussian";
  double range = 10.0;
  double focal = 1000.0;
  std::vector<double> principal_point = {0.0, 0.0};
  std::vector<double> offset = {0.0, 0.0};
  std::string viewpoint = "random";
  std::vector<std::string> methods;
  std::uint64_t seed = 1;
  int threads = 0;
  std::string shard;
  bool per_trial = false;
  std::string csv;
  bool overwrite = false;
  bool json = false;
  bool quiet = false;
  std::vector<std::string> merge;
  bool allow_large = false;
  CLI::Option* noise_option = nullptr;
  CLI::Option* snr_option = nullptr;
};

void check_args(const SimulateArgs& args) {
  if (!args.merge.empty()) {
    if (!args.file.empty()) throw InvalidArgument("--merge: give shard files, not a LAYOUT");
    return;
  }
  if (args.file.empty()) throw InvalidArgument("LAYOUT: required (or --merge FILES)");
  if (args.trials < 1) throw InvalidArgument("--trials: must be >= 1");
  check_limit("--trials", args.trials, kMaxTrials, "simulate", args.allow_large);
  if (args.per_trial || !args.shard.empty()) {
    // The per-trial values of the trials this run holds (one shard's) are kept for the JSON.
    long held = args.trials;
    std::string what = "--trials with --per-trial";
    if (!args.shard.empty()) {
      const Shard shard = parse_shard(args.shard, "--shard");
      if (shard.count <= args.trials) {
        long largest = 0;
        for (int k = 1; k <= shard.count; ++k) {
          const auto [first, last] = shard_range(args.trials, {k, shard.count});
          largest = std::max(largest, last - first);
        }
        held = largest;
      }
      what = "--trials per shard (--trials / N of --shard K/N)";
    }
    check_limit(what, held, kMaxPerTrialTrials, "simulate", args.allow_large);
  }
  if (args.threads < 0) throw InvalidArgument("--threads: must be >= 0");
  if (args.noise_option->count() && args.snr_option->count()) {
    throw InvalidArgument("--snr-db: give either --noise-px or --snr-db, not both");
  }
}

/// The direction a of --viewpoint AX,AY,AZ (body toward the camera), or none for random|worst.
std::optional<Eigen::Vector3d> fixed_viewpoint(const SimulateArgs& args) {
  if (args.viewpoint == "random" || args.viewpoint == "worst") return std::nullopt;
  return commands::parse_direction(args.viewpoint, "--viewpoint");
}

simulate::LayoutSimulationOptions simulation_options(const SimulateArgs& args,
                                                     const Layout& layout) {
  simulate::LayoutSimulationOptions options;
  LayoutSceneOptions& scene = options.scene;
  scene.camera = args.camera == "pinhole" ? CameraModel::kPinhole : CameraModel::kAffine;
  scene.focal_px = args.focal;
  scene.range = args.range;
  scene.principal_point = Eigen::Vector2d(args.principal_point[0], args.principal_point[1]);
  scene.lateral_offset = Eigen::Vector2d(args.offset[0], args.offset[1]);
  scene.noise = parse_noise_kind(args.noise, "--noise");
  scene.noise_px = args.noise_px;
  if (args.snr_option->count()) scene.snr_db = args.snr_db;
  std::string why;
  if (!scene.is_valid(&why)) {
    const std::string field = why.substr(0, why.find(':'));
    const std::map<std::string, std::string> option = {{"focal_px", "--focal"},
                                                       {"range", "--range"},
                                                       {"principal_point", "--principal-point"},
                                                       {"lateral_offset", "--offset"},
                                                       {"noise_px", "--noise-px"},
                                                       {"snr_db", "--snr-db"}};
    throw InvalidArgument(option.at(field) + why.substr(why.find(':')));
  }
  if (layout.mode == LayoutMode::kVectors && scene.camera == CameraModel::kPinhole) {
    throw InvalidArgument("--camera: pinhole needs a point layout; " + args.file +
                          " holds direction vectors");
  }
  options.worst_viewpoint = args.viewpoint == "worst";
  if (const auto a = fixed_viewpoint(args)) {
    // The camera of docs/math.md §22: aimed at the markers' centroid, the pose still the
    // layout frame's (its translation is the layout origin's, as `vantage crb` bounds it).
    options.scene.viewpoint = -*a;
    if (layout.mode == LayoutMode::kPoints) options.scene.aim = layout.entries.rowwise().mean();
  }
  options.monte_carlo.trials = args.trials;
  options.monte_carlo.seed = args.seed;
  options.monte_carlo.threads = args.threads;
  if (!args.shard.empty()) options.monte_carlo.shard = parse_shard(args.shard, "--shard");
  if (options.monte_carlo.shard.count > args.trials) {
    throw InvalidArgument("--shard: N must not exceed --trials");
  }
  options.monte_carlo.progress = !args.json && !args.quiet;
  options.monte_carlo.keep_trials = args.per_trial || !args.shard.empty();
  options.methods = args.methods;
  options.methods_argument = "--methods";
  return options;
}

using Report = simulate::LayoutSimulation;

constexpr const char* kCsvHeader =
    "trial,estimator,rot_err_deg,trans_err,trans_err_rel,trans_err_deg,scale_err,time_us,status,"
    "ok\n";

/// The --csv rows of one trial, one per estimator.
std::string csv_rows(const std::vector<std::string>& names, long trial,
                     const std::vector<TrialError>& errors) {
  const auto number = [](double x) {
    std::ostringstream s;
    s.precision(17);
    if (std::isfinite(x)) s << x;
    return s.str();
  };
  std::string rows;
  for (std::size_t e = 0; e < names.size(); ++e) {
    const TrialError& t = errors[e];
    rows += std::to_string(trial) + ',' + names[e] + ',' + number(t.rot_err_deg) + ',' +
            number(t.trans_err) + ',' + number(t.trans_err_rel) + ',' + number(t.trans_err_deg) +
            ',' + number(t.scale_err) + ',' + number(t.time_us) + ',' + t.status + ',' +
            (t.ok ? "1" : "0") + '\n';
  }
  return rows;
}

/// The --csv file, checked before the run and written all or nothing as the trials stream by.
/// An existing file is replaced only with --overwrite, and never when it is one of the run's own
/// inputs (the layout or a --merge shard): trial rows are no replacement for either.
std::unique_ptr<io::AtomicTextFile> open_csv(const SimulateArgs& args) {
  const std::string& path = args.csv;
  if (path.empty()) return nullptr;
  std::vector<std::string> inputs = args.merge;
  inputs.push_back(args.file);
  for (const std::string& input : inputs) {
    if (!input.empty() && io::same_file(path, input)) {
      throw InvalidArgument("--csv: " + path + " is an input of this run (" + input +
                            "); refusing to replace it with the trial rows");
    }
  }
  try {
    auto file = std::make_unique<io::AtomicTextFile>(path, args.overwrite);
    file->write(kCsvHeader);
    return file;
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("--csv: ") + e.what());
  }
}

std::string summary_row(const std::string& what, const Summary& s) {
  return what + "  median " + format_number(s.median, 4) + "  mean " + format_number(s.mean, 4) +
         "  p95 " + format_number(s.p95, 4) + "  max " + format_number(s.max, 4) + "\n";
}

/// The check under visibility (a layout with normals).
void print_visibility(const VisibilityCheck& v) {
  const VisibilitySetup& s = v.setup;
  std::cout << "\nvisibility (" << s.model() << ", min_visible " << s.min_visible
            << "): views drawn from the trackable directions ("
            << format_number(100.0 * s.trackable_fraction, 4) << " % of the "
            << (s.workspace ? "workspace" : "sphere") << "), " << v.draws
            << " directions drawn for " << v.trials << " views; markers per image "
            << format_number(v.visible_markers.median, 4) << " median, "
            << format_number(v.visible_markers.max, 4) << " max\n";
  if (!v.bound_checked) return;
  std::cout << "bound check under visibility (noise-free affine images of the visible markers): "
            << (v.passed ? "passed" : "FAILED") << "\n"
            << "  p-bar_min " << format_number(s.pbar_min, 9) << ", bound arccos p-bar_min "
            << format_number(v.bound_deg, 9)
            << " deg (certified worst viewpoint under visibility)\n"
            << "  max error " << format_number(v.max_error_deg, 9) << " deg, max_ratio "
            << format_number(v.max_ratio, 12) << "; largest t of a view "
            << format_number(v.max_view_t, 9) << " (t_upper " << format_number(s.t_upper, 9)
            << ")\n"
            << "  per view: max error / arccos p-bar(view) " << format_number(v.max_view_ratio, 12)
            << ", max |measured - Eq. 26| " << format_number(v.max_abs_eq26_mismatch_deg, 3)
            << " deg\n";
}

void print_text(const Report& report) {
  std::cout << "vantage simulate: " << report.config["layout"]["name"].get<std::string>() << " ("
            << report.config["layout"]["mode"].get<std::string>() << "), " << report.run.trials
            << " of " << report.run.total_trials << " trials (shard " << report.shard << "), seed "
            << report.run.seed << ", camera " << report.config["camera"].get<std::string>()
            << "\n\n";
  for (const EstimatorSummary& s : summarize(report.run)) {
    std::cout << s.name << ": " << s.trials << " trials, " << s.failures << " failures, "
              << s.wrong_but_ok << " wrong but ok (rotation error > 90 deg with an ok status)\n"
              << summary_row("  rotation error (deg)   ", s.rot_err_deg);
    if (s.trans_err_rel.count > 0) {
      std::cout << summary_row("  |e_p| / |p|            ", s.trans_err_rel);
    }
    std::cout << summary_row("  time per solve (us)    ", s.time_us) << "  statuses  ";
    for (const auto& [status, count] : s.by_status) std::cout << status << " " << count << "  ";
    std::cout << "\n";
  }
  if (report.has_visibility) print_visibility(report.visibility);
  if (!report.has_bound) return;
  const BoundCheck& b = report.bound;
  std::cout << "\nbound check (noise-free affine images, every data vector, Eq. 26 / Eq. 30): "
            << (b.passed ? "passed" : "FAILED") << "\n"
            << "  " << b.trials << " trials x " << b.vectors << " vectors, p-bar_min "
            << format_number(b.pbar_min, 9) << ", bound arccos p-bar_min "
            << format_number(b.bound_deg, 9) << " deg\n"
            << "  max error " << format_number(b.max_error_deg, 9) << " deg, max_ratio "
            << format_number(b.max_ratio, 12) << ", max |measured - Eq. 26| "
            << format_number(b.max_abs_eq26_mismatch_deg, 3) << " deg\n";
  for (const PoseRelation& r : b.relations) {
    std::cout << "  " << r.estimator << " (" << r.free_vectors << ", own bound "
              << format_number(r.own_bound_deg, 6) << " deg): rotation error max "
              << format_number(r.rot_err_deg.max, 4) << " p95 "
              << format_number(r.rot_err_deg.p95, 4) << " deg; above the bound in "
              << r.exceeds_bound << ", above its own bound in " << r.exceeds_own_bound << " of "
              << b.trials << " trials\n";
  }
}

Report run_layout(const SimulateArgs& args, io::AtomicTextFile* csv) {
  const Layout layout = args.input.read(args.file);
  simulate::LayoutSimulationOptions options = simulation_options(args, layout);
  if (csv != nullptr) {
    options.monte_carlo.on_trial = [csv](const MonteCarloRun& run, long trial,
                                         const std::vector<TrialError>& errors) {
      csv->write(csv_rows(run.names, trial, errors));
    };
  }
  try {
    return simulate::simulate_layout(layout, options);
  } catch (const InvalidArgument& e) {
    // The layout's body: name the file (the options name themselves).
    if (e.field() == "visibility") throw e.against(args.file);
    throw;
  }
}

Json read_json_file(const std::string& path, bool allow_large) {
  const std::string text =
      io::read_text_file(path, allow_large ? kMaxFileBytesAllowLarge : kMaxFileBytes);
  try {
    return Json::parse(text);
  } catch (const Json::parse_error&) {
    throw InvalidArgument(path + ": not a JSON file");
  }
}

/// The setup fields of a shard's "visibility" object (the rest summarises its trials).
Json visibility_setup_part(const Json& shard, const std::string& file) {
  if (!shard.contains("visibility") || !shard["visibility"].is_object()) {
    throw InvalidArgument(file + ": visibility: missing (the layout has normals)");
  }
  Json part = Json::object();
  for (const char* key : {"model", "min_visible", "workspace", "occlusion_resolution_deg",
                          "trackable_fraction", "coverage_samples", "worst_viewpoint",
                          "worst_visible_markers", "t_upper", "t_lower", "pbar_min"}) {
    if (shard["visibility"].contains(key)) part[key] = shard["visibility"][key];
  }
  return part;
}

/// The check under visibility of merged shards, in trial order.
void merge_visibility(const std::vector<std::string>& files, const std::vector<Json>& setups,
                      const std::vector<MonteCarloRun>& runs,
                      const std::vector<std::vector<VisibilityTrial>>& trials, Report& report) {
  for (std::size_t s = 1; s < setups.size(); ++s) {
    if (setups[s] != setups[0]) {
      throw InvalidArgument(files[s] + ": visibility: differs from " + files[0] +
                            " (not a shard of the same run)");
    }
  }
  std::vector<std::pair<long, const VisibilityTrial*>> ordered;
  for (std::size_t s = 0; s < runs.size(); ++s) {
    if (trials[s].size() != runs[s].trial_index.size()) {
      throw InvalidArgument(files[s] + ": per_trial.visibility: one entry per trial expected");
    }
    for (std::size_t k = 0; k < trials[s].size(); ++k) {
      ordered.push_back({runs[s].trial_index[k], &trials[s][k]});
    }
  }
  std::sort(ordered.begin(), ordered.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  VisibilityCheckAccumulator check(visibility_setup_from_json(setups[0], files[0]),
                                   report.config["camera"] == "affine");
  for (const auto& [trial, result] : ordered) {
    check.add(trial, *result);
    report.visibility_trials.push_back(*result);
  }
  report.has_visibility = true;
  report.visibility = check.result();
}

Report merge_files(const std::vector<std::string>& files, bool allow_large) {
  std::vector<MonteCarloRun> runs;
  std::vector<std::vector<BoundTrial>> bounds;
  std::vector<Json> visibility_setups;
  std::vector<std::vector<VisibilityTrial>> visibility_trials;
  Json config;
  for (const std::string& file : files) {
    const Json shard = read_json_file(file, allow_large);
    if (!shard.is_object() || !shard.contains("config") || !shard.contains("per_trial")) {
      throw InvalidArgument(file + ": per_trial: missing (run the shard with --shard K/N --json)");
    }
    const Json& c = shard["config"];
    if (!c.is_object() || !c.contains("trials") || !c["trials"].is_number_integer() ||
        !c.contains("seed") || !c["seed"].is_number_unsigned() || !c.contains("layout") ||
        !c["layout"].contains("entries") || !c["layout"]["entries"].is_array()) {
      throw InvalidArgument(file + ": config: not the config of a vantage simulate run");
    }
    if (runs.empty()) config = c;
    if (shard["config"] != config) {
      throw InvalidArgument(file + ": config: differs from " + files.front() +
                            " (not a shard of the same run)");
    }
    runs.push_back(run_from_json(shard["per_trial"], config["trials"].get<long>(),
                                 config["seed"].get<std::uint64_t>(), file));
    if (shard["per_trial"].contains("bound_check")) {
      bounds.push_back(bound_trials_from_json(shard["per_trial"]["bound_check"], file));
      if (bounds.back().size() != runs.back().trial_index.size()) {
        throw InvalidArgument(file + ": per_trial.bound_check: one entry per trial expected");
      }
    }
    if (config["layout"].contains("normals")) {
      visibility_setups.push_back(visibility_setup_part(shard, file));
      if (!shard["per_trial"].contains("visibility")) {
        throw InvalidArgument(file + ": per_trial.visibility: missing (the layout has normals)");
      }
      visibility_trials.push_back(
          visibility_trials_from_json(shard["per_trial"]["visibility"], file));
    }
  }
  Report report;
  report.config = config;
  report.shard = "merged";
  report.run = merge_runs(runs, files);
  if (bounds.size() == runs.size()) {
    std::vector<std::pair<long, BoundTrial>> ordered;
    for (std::size_t s = 0; s < runs.size(); ++s) {
      for (std::size_t k = 0; k < bounds[s].size(); ++k) {
        ordered.push_back({runs[s].trial_index[k], bounds[s][k]});
      }
    }
    std::sort(ordered.begin(), ordered.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& entry : ordered) report.bound_trials.push_back(entry.second);
    Eigen::Matrix3Xd entries(3, config["layout"]["entries"].size());
    for (Eigen::Index i = 0; i < entries.cols(); ++i) {
      for (int r = 0; r < 3; ++r) entries(r, i) = config["layout"]["entries"][i][r].get<double>();
    }
    const BoundLayout layout =
        prepare_bound_layout(entries, config["layout"]["mode"].get<std::string>() == "vectors");
    report.has_bound = true;
    report.bound = summarize_bound_check(layout, report.bound_trials);
  }
  if (!visibility_setups.empty()) {
    merge_visibility(files, visibility_setups, runs, visibility_trials, report);
  }
  return report;
}

int run_simulate(const SimulateArgs& args) {
  check_args(args);
  const bool merging = !args.merge.empty();
  const std::unique_ptr<io::AtomicTextFile> csv = open_csv(args);
  Report report;
  try {
    report = merging ? merge_files(args.merge, args.allow_large) : run_layout(args, csv.get());
  } catch (const Json::exception& e) {  // a shard file whose fields have the wrong types
    throw InvalidArgument("--merge: malformed shard file: " + std::string(e.what()));
  }
  if (csv) {
    if (merging) {
      std::vector<TrialError> errors(report.run.names.size());
      for (std::size_t k = 0; k < report.run.trial_index.size(); ++k) {
        for (std::size_t e = 0; e < errors.size(); ++e) errors[e] = report.run.errors[e][k];
        csv->write(csv_rows(report.run.names, report.run.trial_index[k], errors));
      }
    }
    csv->commit();
  }
  if (args.json) {
    print_json(report_json(report, args.per_trial || !args.shard.empty()));
  } else {
    print_text(report);
  }
  if (report.has_bound && !report.bound.passed) {
    std::cerr << "vantage: simulate: bound check FAILED: " << report.bound.message << std::endl;
    return kExitFailure;
  }
  if (report.has_visibility && !report.visibility.passed) {
    std::cerr << "vantage: simulate: bound check under visibility FAILED: "
              << report.visibility.message << std::endl;
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

Command add_simulate_command(CLI::App& root) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* sub = root.add_subcommand(
      "simulate",
      "Monte Carlo: every applicable estimator on random views of a layout, with the bound check "
      "of Eq. (26) / Eq. (30); --shard K/N and --merge spread a study over machines");
  sub->add_option("LAYOUT", args->file,
                  "layout file (.json points or vectors, .csv markers, .yaml AprilTag bundle)");
  args->input.add_options(sub);
  sub->add_option("--trials", args->trials, "number of trials, >= 1")->capture_default_str();
  sub->add_option("--camera", args->camera,
                  "affine (scaled orthographic, Eq. 14) or pinhole (points only)")
      ->check(CLI::IsMember({"affine", "pinhole"}))
      ->capture_default_str();
  args->noise_option = sub->add_option("--noise-px", args->noise_px,
                                       "image noise standard deviation, pixels (default 0)");
  args->snr_option = sub->add_option(
      "--snr-db", args->snr_db,
      "noise by SNR instead: sigma = peak-to-peak image extent / 10^(SNR/20) (Haralick et al.)");
  sub->add_option("--noise", args->noise, "noise distribution: gaussian or uniform (same sigma)")
      ->check(CLI::IsMember({"gaussian", "uniform"}))
      ->capture_default_str();
  sub->add_option("--range", args->range,
                  "depth of the object origin in object sizes (max marker distance), > 0; "
                  "> 1 for pinhole")
      ->capture_default_str();
  sub->add_option("--focal", args->focal, "focal length, pixels, > 0")->capture_default_str();
  sub->add_option("--principal-point", args->principal_point, "principal point U V, pixels")
      ->expected(2);
  sub->add_option("--offset", args->offset, "lateral offset X Y of the object, object sizes")
      ->expected(2);
  sub->add_option("--viewpoint", args->viewpoint,
                  "random (uniform rotations), worst (the certified worst viewpoint, random "
                  "roll), or a direction AX,AY,AZ (body toward the camera; the camera then looks "
                  "at the markers' centroid from --range sizes about it, docs/math.md §22)")
      ->capture_default_str();
  sub->add_option(
         "--methods", args->methods,
         "estimators to run (comma-separated; default: every applicable one): " + estimator_names())
      ->delimiter(',');
  sub->add_option("--seed", args->seed, "run seed")->capture_default_str();
  sub->add_option("--threads", args->threads, "worker threads, 0 = all cores")
      ->capture_default_str();
  sub->add_option("--shard", args->shard,
                  "run the K-th of N deterministic slices of the trials (K/N); the JSON carries "
                  "the per-trial values for --merge");
  sub->add_flag("--per-trial", args->per_trial, "include the per-trial values in the JSON");
  sub->add_option("--csv", args->csv,
                  "write one row per trial and estimator to FILE (a new file, or an existing "
                  "one with --overwrite)");
  sub->add_flag("--overwrite", args->overwrite, "replace --csv if it exists");
  sub->add_option("--merge", args->merge, "merge the JSON outputs of --shard runs")
      ->expected(1, -1);
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  sub->add_flag("--quiet", args->quiet, "no progress bar");
  add_allow_large_flag(sub, args->allow_large);
  return {sub, [args] { return run_simulate(*args); }};
}

}  // namespace vantage::cli
