// Haralick et al. [H]: error vs SNR and number of point pairs, and the SNR knees.

#include <cmath>

#include "experiment_support.h"
#include "vantage/simulate/report_json.h"
#include "vantage/simulate/seed_scenes.h"

namespace vantage::simulate::internal {
namespace {

/// Nominal signal of every Haralick scene: the side of the square/cube [-2, 2] (noise.h).
constexpr double kSignal = 4.0;
const std::vector<NoiseKind> kNoises = {NoiseKind::kGaussian, NoiseKind::kUniform};

/// The knee of one (n, noise) curve for a metric of the cell.
double knee(const std::vector<SweepCell>& cells, int n, NoiseKind noise, const std::string& name,
            double Summary::*stat, Summary EstimatorSummary::*metric, double threshold) {
  std::vector<double> snr;
  std::vector<double> error;
  for (const SweepCell& c : cells) {
    const EstimatorSummary* s = find_summary(c, name);
    if (c.n != n || c.noise != noise || !s) continue;
    snr.push_back(c.snr_db);
    error.push_back((s->*metric).*stat);
  }
  return snr_knee(snr, error, threshold);
}

/// A knee table in the layout of Haralick's Table 1: rows = noise kinds, columns = n; each
/// entry "ours (paper)".
std::string knee_table(const std::string& title, const std::vector<int>& ns,
                       const std::vector<SweepCell>& cells, const std::string& name,
                       Summary EstimatorSummary::*metric, double threshold,
                       const std::vector<std::vector<double>>& paper, Json* json) {
  std::string table = "| " + title + " |";
  std::string rule = "|---|";
  for (int n : ns) {
    table += " " + std::to_string(n) + " |";
    rule += "---|";
  }
  table += "\n" + rule + "\n";
  Json rows = Json::object();
  for (std::size_t k = 0; k < kNoises.size(); ++k) {
    table += std::string("| ") + to_string(kNoises[k]) + " |";
    Json row = Json::object();
    for (std::size_t j = 0; j < ns.size(); ++j) {
      const double ours = knee(cells, ns[j], kNoises[k], name, &Summary::mean, metric, threshold);
      table += " " + (std::isnan(ours) ? std::string("> grid") : cell(ours, 3));
      if (!paper.empty()) table += " (" + cell(paper[k][j], 3) + ")";
      table += " |";
      row[std::to_string(ns[j])] = json_number(ours);
    }
    table += "\n";
    rows[to_string(kNoises[k])] = row;
  }
  (*json)[title] = rows;
  return table;
}

std::string mean_table(const std::vector<SweepCell>& cells, const std::vector<int>& ns,
                       NoiseKind noise, const std::string& name, Summary EstimatorSummary::*metric,
                       const std::string& what) {
  std::string table = "| SNR (dB) |";
  std::string rule = "|---|";
  for (int n : ns) {
    table += " n = " + std::to_string(n) + " |";
    rule += "---|";
  }
  table += "\n" + rule + "\n";
  std::vector<double> snrs;
  for (const SweepCell& c : cells) {
    if (c.n == ns.front() && c.noise == noise) snrs.push_back(c.snr_db);
  }
  for (double snr : snrs) {
    table += "| " + cell(snr, 4) + " |";
    for (int n : ns) {
      for (const SweepCell& c : cells) {
        const EstimatorSummary* s = find_summary(c, name);
        if (c.n == n && c.noise == noise && c.snr_db == snr && s) {
          table += " " + cell((s->*metric).mean) + " |";
        }
      }
    }
    table += "\n";
  }
  return "Mean " + what + ", " + to_string(noise) + " noise:\n\n" + table + "\n";
}

}  // namespace

ExperimentResult run_haralick_2d2d(const ExperimentOptions& options, long trials) {
  const std::vector<int> ns =
      options.quick ? std::vector<int>{8, 100} : std::vector<int>{8, 20, 50, 100, 200};
  const std::vector<double> snrs = options.quick ? std::vector<double>{20, 40} : grid(0, 52, 4);
  const std::vector<SweepCell> cells = run_sweep(
      ns, kNoises, snrs,
      [](int n, NoiseKind noise, double snr) -> SceneGenerator {
        const double sigma = sigma_from_snr(snr, kSignal);
        return [=](long, TrialRandom& r) { return make_planar_2d_scene(n, noise, sigma, r); };
      },
      {"haralick-2d"}, trials, options);
  ExperimentResult result;
  result.files.push_back(output_path(options, "haralick_2d2d.csv"));
  write_sweep_csv(result.files.back(), cells);
  Json knees = Json::object();
  std::string table = "# haralick-2d2d: points in [-2, 2]^2, rotation in [-15, 15] deg, " +
                      std::to_string(trials) + " trials per cell\n\n";
  table +=
      "SNR knee (dB) for mean |rotation error| < 1 deg (paper: 40 dB at 8 pairs, 25 dB at "
      "100):\n\n" +
      knee_table("rotation < 1 deg", ns, cells, "haralick-2d", &EstimatorSummary::rot_err_deg, 1.0,
                 {}, &knees);
  table +=
      "\nSNR knee (dB) for mean translation error < 0.01 (paper: 100 pairs at 32 dB; 8 pairs "
      "give about 0.03 at 52 dB):\n\n" +
      knee_table("translation < 0.01", ns, cells, "haralick-2d", &EstimatorSummary::trans_err, 0.01,
                 {}, &knees);
  table += "\n" + mean_table(cells, ns, NoiseKind::kGaussian, "haralick-2d",
                             &EstimatorSummary::rot_err_deg, "rotation error (deg)");
  result.summary["knees_db"] = knees;
  result.table = table;
  return result;
}

ExperimentResult run_haralick_3d3d(const ExperimentOptions& options, long trials) {
  const std::vector<int> ns =
      options.quick ? std::vector<int>{10, 25} : std::vector<int>{10, 25, 50, 100, 200};
  const std::vector<double> snrs = options.quick ? std::vector<double>{24, 48} : grid(8, 72, 4);
  const std::vector<SweepCell> cells = run_sweep(
      ns, kNoises, snrs,
      [](int n, NoiseKind noise, double snr) -> SceneGenerator {
        const double sigma = sigma_from_snr(snr, kSignal);
        return [=](long, TrialRandom& r) { return make_points_3d_scene(n, noise, sigma, r); };
      },
      {"haralick-3d"}, trials, options);
  ExperimentResult result;
  result.files.push_back(output_path(options, "haralick_3d3d.csv"));
  write_sweep_csv(result.files.back(), cells);
  Json knees = Json::object();
  std::string table = "# haralick-3d3d: points in [-2, 2]^3, random rotations, " +
                      std::to_string(trials) + " trials per cell\n\n";
  table +=
      "SNR knee (dB) for mean rotation error < 3 deg (paper: 25 points, < 3 deg above 25 "
      "dB):\n\n" +
      knee_table("rotation < 3 deg", ns, cells, "haralick-3d", &EstimatorSummary::rot_err_deg, 3.0,
                 {}, &knees);
  table += "\nSNR knee (dB) for mean rotation error < 1 deg:\n\n" +
           knee_table("rotation < 1 deg", ns, cells, "haralick-3d", &EstimatorSummary::rot_err_deg,
                      1.0, {}, &knees);
  table += "\n" + mean_table(cells, ns, NoiseKind::kGaussian, "haralick-3d",
                             &EstimatorSummary::rot_err_deg, "rotation error (deg)");
  result.summary["knees_db"] = knees;
  result.table = table;
  return result;
}

ExperimentResult run_haralick_two_view(const ExperimentOptions& options, long trials) {
  struct NamedScene {
    const char* name;
    TwoViewScene geometry;
  };
  const std::vector<NamedScene> scenes =
      options.quick ? std::vector<NamedScene>{{"A", {4.0, 6.0, 1.0, 15.0}}}
                    : std::vector<NamedScene>{{"A", {4.0, 6.0, 1.0, 15.0}},
                                              {"B-deep", {8.0, 12.0, 1.0, 15.0}},
                                              {"C-wide", {4.0, 6.0, 2.0, 15.0}}};
  const std::vector<int> ns =
      options.quick ? std::vector<int>{8} : std::vector<int>{8, 20, 50, 110};
  const std::vector<double> snrs = options.quick ? std::vector<double>{50, 90} : grid(26, 122, 6);
  const std::vector<std::vector<double>> paper_rot = {{75, 57, 52, 50}, {74, 56, 52, 49}};
  const std::vector<std::vector<double>> paper_trans = {{105, 78, 73, 68}, {106, 78, 72, 68}};
  ExperimentResult result;
  std::string table = "# haralick-two-view: " + std::to_string(trials) +
                      " trials per cell; view-1 image in [-2, 2]^2, Euler angles in [-15, 15] "
                      "deg; SNR knees in dB for a mean error < 1 deg, ours (paper's Table 1)\n\n";
  Json scenes_json = Json::object();
  for (const NamedScene& s : scenes) {
    const std::vector<SweepCell> cells = run_sweep(
        ns, kNoises, snrs,
        [geometry = s.geometry](int n, NoiseKind noise, double snr) -> SceneGenerator {
          const double sigma = sigma_from_snr(snr, kSignal);
          return [=](long, TrialRandom& r) {
            return make_two_view_scene(n, geometry, noise, sigma, r);
          };
        },
        {"two-view"}, trials, options);
    result.files.push_back(
        output_path(options, std::string("haralick_two_view_") + s.name + ".csv"));
    write_sweep_csv(result.files.back(), cells);
    Json knees = Json::object();
    const bool paper_layout = ns.size() == 4;
    table += std::string("## Scene ") + s.name + ": depth in [" + cell(s.geometry.depth_min) +
             ", " + cell(s.geometry.depth_max) + "], T in [-" + cell(s.geometry.translation) +
             ", " + cell(s.geometry.translation) + "]^3\n\n" +
             knee_table("rotation", ns, cells, "two-view", &EstimatorSummary::rot_err_deg, 1.0,
                        paper_layout ? paper_rot : std::vector<std::vector<double>>{}, &knees) +
             "\n" +
             knee_table("translation", ns, cells, "two-view", &EstimatorSummary::trans_err_deg, 1.0,
                        paper_layout ? paper_trans : std::vector<std::vector<double>>{}, &knees) +
             "\n";
    scenes_json[s.name] = {{"depth", {s.geometry.depth_min, s.geometry.depth_max}},
                           {"translation", s.geometry.translation},
                           {"knees_db", knees}};
  }
  result.summary["scenes"] = scenes_json;
  result.summary["paper_table_1"] = {{"rotation", paper_rot}, {"translation", paper_trans}};
  result.table = table;
  return result;
}

}  // namespace vantage::simulate::internal
