// Wu & Wu [W] Sec. 3: accuracy and time per solve vs number of points and vs SNR.

#include "experiment_support.h"
#include "vantage/simulate/report_json.h"
#include "vantage/simulate/seed_scenes.h"

namespace vantage::simulate::internal {
namespace {

/// The perspective estimators compared (orthogonal iteration and the maximum-likelihood pinhole
/// pose), and the affine ones for reference.
const std::vector<std::string> kEstimators = {"oi-foam", "oi-svd", "perspective", "affine",
                                              "standard"};

ExperimentResult wu_sweep(const ExperimentOptions& options, long trials, const std::vector<int>& ns,
                          const std::vector<double>& snrs, const std::string& file,
                          const std::string& title) {
  const std::vector<SweepCell> cells = run_sweep(
      ns, {NoiseKind::kGaussian}, snrs,
      [](int n, NoiseKind, double snr) -> SceneGenerator {
        return [=](long, TrialRandom& r) { return make_wu_scene(n, snr, r); };
      },
      kEstimators, trials, options);
  ExperimentResult result;
  result.files.push_back(output_path(options, file));
  write_sweep_csv(result.files.back(), cells);
  std::string table = title + ", " + std::to_string(trials) +
                      " trials per cell (mean rotation error deg / mean ‖e_p‖/‖p‖ / median time "
                      "us; wrong_but_ok = rotation error > 90 deg with an ok status)\n\n"
                      "| n | SNR (dB) | estimator | rot mean (deg) | rot median | ‖e_p‖/‖p‖ mean "
                      "| time median (us) | failures | wrong_but_ok |\n"
                      "|---|---|---|---|---|---|---|---|---|\n";
  Json rows = Json::array();
  for (const SweepCell& c : cells) {
    for (const EstimatorSummary& s : c.summaries) {
      table += "| " + std::to_string(c.n) + " | " + cell(c.snr_db, 3) + " | " + s.name + " | " +
               cell(s.rot_err_deg.mean) + " | " + cell(s.rot_err_deg.median) + " | " +
               cell(s.trans_err_rel.mean) + " | " + cell(s.time_us.median) + " | " +
               std::to_string(s.failures) + " | " + std::to_string(s.wrong_but_ok) + " |\n";
    }
    rows.push_back(
        {{"n", c.n}, {"snr_db", c.snr_db}, {"estimators", estimators_json(c.summaries)}});
  }
  result.summary["cells"] = rows;
  result.table = table;
  return result;
}

}  // namespace

ExperimentResult run_wu_points(const ExperimentOptions& options, long trials) {
  const std::vector<int> ns =
      options.quick ? std::vector<int>{4, 9} : std::vector<int>{4, 9, 14, 19, 24, 29};
  return wu_sweep(options, trials, ns, {60.0}, "wu_points.csv",
                  "# wu-points: pinhole f = 1000 px, points in [-1, 1]^3 at 8-12 units, 60 dB");
}

ExperimentResult run_wu_snr(const ExperimentOptions& options, long trials) {
  const std::vector<double> snrs = options.quick ? std::vector<double>{30, 80} : grid(30, 80, 10);
  return wu_sweep(options, trials, {10}, snrs, "wu_snr.csv",
                  "# wu-snr: pinhole f = 1000 px, 10 points in [-1, 1]^3 at 8-12 units");
}

}  // namespace vantage::simulate::internal
