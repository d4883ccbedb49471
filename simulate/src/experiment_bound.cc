// The bound check over the example layouts and 100 random ones (bound_check.h).

#include <algorithm>
#include <cmath>

#include "experiment_support.h"
#include "vantage/analysis/common.h"
#include "vantage/simulate/bound_check.h"
#include "vantage/simulate/progress.h"
#include "vantage/simulate/report_json.h"
#include "vantage/simulate/scene.h"

namespace vantage::simulate::internal {
namespace {

constexpr int kRandomLayouts = 100;
constexpr int kQuickRandomLayouts = 4;
/// Trials per layout at the worst viewpoint (random roll), besides the random viewpoints.
constexpr long kWorstTrials = 20;
/// Trials per example layout whose every data vector is written to bound_vectors.csv (the
/// first kVectorLayouts layouts when no example is given).
constexpr long kVectorTrials = 5;
constexpr std::size_t kVectorLayouts = 2;

/// Random layouts: half point layouts (4-6 points uniform in [-1, 1]^3), half direction layouts
/// (3-8 random unit vectors).
NamedLayout random_layout(int index, std::uint64_t seed) {
  TrialRandom random = TrialRandom::for_trial(seed ^ 0x5eedb0u, static_cast<std::uint64_t>(index));
  NamedLayout layout;
  layout.vectors = index % 2 == 1;
  const int n = layout.vectors ? 3 + static_cast<int>(random.uniform() * 6.0)
                               : 4 + static_cast<int>(random.uniform() * 3.0);
  layout.entries.resize(3, n);
  for (int i = 0; i < n; ++i) {
    if (layout.vectors) {
      layout.entries.col(i) = random.unit_vector();
    } else {
      for (int r = 0; r < 3; ++r) layout.entries(r, i) = random.uniform(-1.0, 1.0);
    }
  }
  layout.name = "random-" + std::to_string(index) + (layout.vectors ? "-vectors" : "-points");
  return layout;
}

/// The markdown table of the example layouts (rows of to_json(BoundCheck) plus "layout").
std::string examples_table(const Json& layout_rows) {
  std::string table;
  table +=
      "| layout | m | p̄_min | bound (deg) | max error (deg) | max_ratio | affine free vectors "
      "| affine rot max (deg) | p95 | > bound | > own bound |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Json& row : layout_rows) {
    const Json& a = row["affine_relation"][0];
    table +=
        "| " + row["layout"].get<std::string>() + " | " +
        std::to_string(row["vectors"].get<long>()) + " | " +
        cell(row["pbar_min"].get<double>(), 6) + " | " + cell(row["bound_deg"].get<double>(), 6) +
        " | " + cell(row["max_error_deg"].get<double>(), 6) + " | " +
        cell(row["max_ratio"].get<double>(), 12) + " | " + a["free_vectors"].get<std::string>() +
        " | " + cell(a["rot_err_deg"]["max"].get<double>()) + " | " +
        cell(a["rot_err_deg"]["p95"].get<double>()) + " | " +
        std::to_string(a["exceeds_bound"].get<long>()) + " | " +
        std::to_string(a["exceeds_own_bound"].get<long>()) + " |\n";
  }
  return table;
}

/// Runs the trials of one layout (random viewpoints, then kWorstTrials at the worst one), streams
/// them to bound_trials.csv and, with write_vectors, the first kVectorTrials trials' data vectors
/// to bound_vectors.csv.
BoundCheck check_layout(const NamedLayout& named, std::uint64_t seed, long trials, int threads,
                        bool write_vectors, CsvWriter& per_trial, CsvWriter& per_vector) {
  const BoundLayout layout = prepare_bound_layout(named.entries, named.vectors);
  const long count = trials + kWorstTrials;
  const auto scene_of = [&](long t) {
    TrialRandom random = TrialRandom::for_trial(seed, t);
    LayoutSceneOptions scene;
    if (t >= trials) scene.viewpoint = layout.data.worst_viewpoint;
    return make_layout_scene(named.entries, named.vectors, scene, random);
  };
  // Streamed: one block of trials at a time, whatever the trial count.
  BoundCheckAccumulator accumulator(layout);
  parallel_for_in_order<BoundTrial>(
      count, threads, false, [&](long t) { return check_bound_trial(layout, scene_of(t)); },
      [&](long t, const BoundTrial& r) {
        accumulator.add(t, r);
        per_trial << named.name << t << (t >= trials ? "worst" : "random") << r.pbar
                  << r.max_error_rad * kDegreesPerRadian
                  << std::acos(std::min(1.0, r.pbar)) * kDegreesPerRadian
                  << layout.data.bound_rad * kDegreesPerRadian
                  << r.affine_rot_err_rad * kDegreesPerRadian
                  << r.spanning_rot_err_rad * kDegreesPerRadian;
        per_trial.end_row();
      });
  if (write_vectors) {
    for (long t = 0; t < std::min(kVectorTrials, count); ++t) {
      const VectorErrors v = vector_errors(layout, scene_of(t));
      for (Eigen::Index k = 0; k < v.p.size(); ++k) {
        per_vector << named.name << t << static_cast<long>(k) << v.p(k) << v.pbar
                   << v.angle_rad(k) * kDegreesPerRadian << v.eq26_rad(k) * kDegreesPerRadian;
        per_vector.end_row();
      }
    }
  }
  return accumulator.result();
}

/// One row of bound_layouts.csv.
void write_layout_row(const NamedLayout& named, const BoundCheck& check, CsvWriter& per_layout) {
  const PoseRelation& affine = check.relations.front();
  const bool points = check.relations.size() > 1;
  per_layout << named.name << (named.vectors ? "vectors" : "points") << check.vectors
             << check.trials << check.pbar_min << check.bound_deg << check.max_error_deg
             << check.max_ratio << check.max_abs_eq26_mismatch_deg << affine.free_vectors
             << affine.own_bound_deg << affine.rot_err_deg.max << affine.rot_err_deg.p95
             << affine.exceeds_bound << affine.exceeds_own_bound
             << (points ? check.relations[1].own_bound_deg : std::nan(""))
             << (points ? check.relations[1].rot_err_deg.max : std::nan(""))
             << (points ? check.relations[1].exceeds_bound : 0L);
  per_layout.end_row();
}

/// The worst values and counts over all layouts.
struct BoundTotals {
  double worst_ratio = 0.0;
  double worst_mismatch = 0.0;
  double worst_mismatch_ratio = 0.0;
  std::string failure;  ///< the first failing layout's name and message
  long total_trials = 0;
  long affine_exceed = 0;
  long affine_exceed_own = 0;
  double worst_pose_ratio = 0.0;

  void add(const std::string& name, const BoundCheck& check) {
    const PoseRelation& affine = check.relations.front();
    worst_ratio = std::max(worst_ratio, check.max_ratio);
    worst_mismatch = std::max(worst_mismatch, check.max_abs_eq26_mismatch_deg);
    worst_mismatch_ratio = std::max(worst_mismatch_ratio, check.max_eq26_mismatch_over_tolerance);
    if (!check.passed && failure.empty()) failure = name + ": " + check.message;
    worst_pose_ratio = std::max(worst_pose_ratio, affine.rot_err_deg.max / check.bound_deg);
    total_trials += check.trials;
    affine_exceed += affine.exceeds_bound;
    affine_exceed_own += affine.exceeds_own_bound;
  }
};

/// The summary JSON of the experiment.
Json bound_summary(const BoundTotals& totals, std::size_t layouts, std::size_t examples,
                   const Json& layout_rows) {
  Json summary;
  summary["layouts"] = static_cast<long>(layouts);
  summary["example_layouts"] = static_cast<long>(examples);
  summary["trials"] = totals.total_trials;
  summary["max_ratio"] = totals.worst_ratio;
  summary["max_abs_eq26_mismatch_deg"] = totals.worst_mismatch;
  summary["max_eq26_mismatch_over_tolerance"] = totals.worst_mismatch_ratio;
  summary["passed"] = totals.failure.empty();
  if (!totals.failure.empty()) summary["message"] = totals.failure;
  summary["affine_exceeds_bound"] = totals.affine_exceed;
  summary["affine_exceeds_own_bound"] = totals.affine_exceed_own;
  summary["affine_max_rot_err_over_bound"] = totals.worst_pose_ratio;
  summary["examples"] = layout_rows;
  return summary;
}

/// The markdown report: the heading, the examples' table and the line on all layouts.
std::string bound_table(const BoundTotals& totals, std::size_t layouts, std::size_t examples,
                        long trials, const Json& layout_rows) {
  std::string table = "# bound: " + std::to_string(layouts) + " layouts (" +
                      std::to_string(examples) + " examples), " + std::to_string(trials) +
                      " random viewpoints + " + std::to_string(kWorstTrials) +
                      " at the worst viewpoint each, noise-free affine images\n\n";
  table += examples_table(layout_rows);
  table += "\nAll layouts: max_ratio " + cell(totals.worst_ratio, 15) +
           ", max |measured - Eq. 26| " + cell(totals.worst_mismatch, 3) + " deg over " +
           std::to_string(totals.total_trials) +
           " trials; the affine estimator's rotation error exceeded the per-vector bound in " +
           std::to_string(totals.affine_exceed) + " trials (its own free vectors' bound in " +
           std::to_string(totals.affine_exceed_own) + "), max rotation error / bound " +
           cell(totals.worst_pose_ratio) + ".\n";
  return table;
}

}  // namespace

ExperimentResult run_bound(const ExperimentOptions& options, long trials) {
  std::vector<NamedLayout> layouts = options.layouts;
  const std::size_t examples = layouts.size();
  const int randoms = options.quick ? kQuickRandomLayouts : kRandomLayouts;
  for (int i = 0; i < randoms; ++i) layouts.push_back(random_layout(i, options.seed));

  CsvWriter per_layout(
      output_path(options, "bound_layouts.csv"),
      {"layout", "mode", "vectors", "trials", "pbar_min", "bound_deg", "max_error_deg", "max_ratio",
       "max_abs_eq26_mismatch_deg", "affine_free_vectors", "affine_own_bound_deg",
       "affine_rot_err_max_deg", "affine_rot_err_p95_deg", "affine_exceeds_bound",
       "affine_exceeds_own_bound", "spanning_bound_deg", "spanning_rot_err_max_deg",
       "spanning_exceeds_bound"});
  CsvWriter per_trial(
      output_path(options, "bound_trials.csv"),
      {"layout", "trial", "viewpoint", "pbar_a", "max_vector_err_deg", "eq30_curve_deg",
       "bound_deg", "affine_rot_err_deg", "spanning_rot_err_deg"});
  CsvWriter per_vector(output_path(options, "bound_vectors.csv"),
                       {"layout", "trial", "vector", "p", "pbar", "measured_deg", "eq26_deg"});

  BoundTotals totals;
  Json layout_rows = Json::array();
  ProgressBar bar(static_cast<long>(layouts.size()), options.progress, "layouts");
  for (std::size_t l = 0; l < layouts.size(); ++l) {
    bar.update(static_cast<long>(l));
    const NamedLayout& named = layouts[l];
    const bool write_vectors = l < std::max<std::size_t>(examples, kVectorLayouts);
    const BoundCheck check = check_layout(named, trial_seed(options.seed, 1000000 + l), trials,
                                          options.threads, write_vectors, per_trial, per_vector);
    write_layout_row(named, check, per_layout);
    totals.add(named.name, check);
    if (l < examples) {
      Json row = to_json(check);
      row["layout"] = named.name;
      layout_rows.push_back(row);
    }
  }
  ExperimentResult result;
  result.summary = bound_summary(totals, layouts.size(), examples, layout_rows);
  result.table = bound_table(totals, layouts.size(), examples, trials, layout_rows);
  result.files = {per_layout.path(), per_trial.path(), per_vector.path()};
  return result;
}

}  // namespace vantage::simulate::internal
