// The experiment figures read the CSV files `vantage experiment` writes (fixtures with known
// numbers here), draw decodable PNGs of the requested size and write CSVs whose numbers follow
// from the input: the Eq. 30 curve is arccos p̄, the CDF of a sample is its sorted values with
// fractions k/n, a knee plot draws every sweep row. Bad input names the file.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#include <stb/stb_image.h>  // implementation compiled in figures_test.cc
#pragma GCC diagnostic pop

#include "plot_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/plot/experiment_figures.h"

namespace vantage::plot {
namespace {

using testing::read_csv;
using testing::TempDir;

// The figures write doubles that read back exactly (std::to_chars); what is left is the rounding
// of one acos or one division.
constexpr double kCsvTolerance = 1e-12;
// wu_sweep_csv writes its values with std::to_string: six decimals.
constexpr double kInputDecimals = 1e-6;

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// Decodes the PNG and checks its size and that it is not one colour.
void expect_good_png(const std::filesystem::path& path, int width, int height) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  ASSERT_NE(data, nullptr) << path;
  EXPECT_EQ(w, width);
  EXPECT_EQ(h, height);
  std::set<int> colours;
  for (int i = 0; i < w * h * 3; i += 3)
    colours.insert(data[i] << 16 | data[i + 1] << 8 | data[i + 2]);
  stbi_image_free(data);
  EXPECT_GT(colours.size(), 20u) << path;
}

TEST(ExperimentFigures, BoundDrawsTheTrialsUnderTheEq30Curve) {
  TempDir dir("expbound");
  write_text(dir.path() / "bound_trials.csv",
             "layout,trial,viewpoint,pbar_a,max_vector_err_deg,eq30_curve_deg,bound_deg,"
             "affine_rot_err_deg,spanning_rot_err_deg\n"
             "a,0,random,0.9,20.0,25.8,30,5.0,\n"
             "a,1,random,0.99,8.0,8.1,30,50.0,\n"
             "a,2,worst,0.5,60.0,60.0,30,,\n");
  write_text(dir.path() / "bound_vectors.csv",
             "layout,trial,vector,p,pbar,measured_deg,eq26_deg\n"
             "a,0,0,0.8,0.9,3.0,3.0\n"
             "a,0,1,0.7,0.9,20.0,20.0\n");
  FigureOptions options;
  options.width = 800;
  options.height = 600;
  const std::vector<FigureFiles> files = write_experiment_figures("bound", dir.path(), options);
  ASSERT_EQ(files.size(), 1u);
  expect_good_png(files[0].image, 800, 600);
  const testing::Csv csv = read_csv(files[0].csv);
  std::map<std::string, int> count;
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const std::string& series = csv.text(r, "series");
    ++count[series];
    if (series == "eq30") {
      EXPECT_NEAR(csv.number(r, "error_deg"),
                  std::acos(csv.number(r, "pbar_a")) * kDegreesPerRadian, kCsvTolerance);
    }
  }
  EXPECT_EQ(count["max_vector"], 3);
  EXPECT_EQ(count["affine"], 2);  // the empty field is not drawn
  EXPECT_EQ(count["vector"], 2);
  EXPECT_GT(count["eq30"], 100);
}

TEST(ExperimentFigures, McinroyOrientationDrawsTheEmpiricalCdf) {
  TempDir dir("expmcinroy");
  write_text(dir.path() / "mcinroy_orientation_trials.csv",
             "n,trial,pbar,estimator,rot_err_deg,status\n"
             "3,0,0.9,standard,40,ok\n3,0,0.9,affine,4,ok\n"
             "3,1,0.9,standard,10,ok\n3,1,0.9,affine,0.5,ok\n"
             "3,2,0.9,standard,20,ok\n3,2,0.9,affine,,failed\n"
             "5,0,0.9,standard,30,ok\n5,0,0.9,affine,2,ok\n");
  const std::vector<FigureFiles> files =
      write_experiment_figures("mcinroy-orientation", dir.path());
  ASSERT_EQ(files.size(), 1u);
  expect_good_png(files[0].image, 1000, 800);
  const testing::Csv csv = read_csv(files[0].csv);
  std::vector<double> standard3;
  std::vector<double> fractions3;
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    if (csv.text(r, "n") == "3" && csv.text(r, "estimator") == "standard") {
      standard3.push_back(csv.number(r, "rot_err_deg"));
      fractions3.push_back(csv.number(r, "fraction"));
    }
  }
  EXPECT_EQ(standard3, (std::vector<double>{10, 20, 40}));
  ASSERT_EQ(fractions3.size(), 3u);
  EXPECT_NEAR(fractions3[0], 1.0 / 3.0, kCsvTolerance);
  EXPECT_NEAR(fractions3[2], 1.0, kCsvTolerance);
  EXPECT_EQ(csv.rows.size(), 7u);  // the failed trial without an error is left out
}

TEST(ExperimentFigures, HaralickKneePlotDrawsEverySweepRow) {
  TempDir dir("expharalick");
  std::string text =
      "n,noise,snr_db,estimator,trials,rot_err_deg_mean,rot_err_deg_median,rot_err_deg_p95,"
      "trans_err_mean,trans_err_rel_mean,trans_err_deg_mean,time_us_median,failures,"
      "wrong_but_ok\n";
  int rows = 0;
  for (int n : {8, 100}) {
    for (const char* noise : {"gaussian", "uniform"}) {
      for (int snr = 0; snr <= 40; snr += 10, ++rows) {
        text += std::to_string(n) + "," + noise + "," + std::to_string(snr) + ",haralick-2d,10," +
                std::to_string(50.0 * std::pow(10.0, -snr / 20.0) * 8.0 / n) + ",0,0,0,0,0,0,0,0\n";
      }
    }
  }
  write_text(dir.path() / "haralick_2d2d.csv", text);
  const std::vector<FigureFiles> files = write_experiment_figures("haralick-2d2d", dir.path());
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].image.filename(), "haralick_2d2d_knee.png");
  expect_good_png(files[0].image, 1000, 800);
  EXPECT_EQ(read_csv(files[0].csv).rows.size(), static_cast<std::size_t>(rows));
}

TEST(ExperimentFigures, McInroyPoseCdfHasOneCurvePerEstimatorWithoutAnNColumn) {
  TempDir dir("exppose");
  write_text(dir.path() / "mcinroy_pose_trials.csv",
             "trial,estimator,rot_err_deg,trans_err_rel,status\n"
             "0,full3d,1e-9,1e-12,ok\n0,affine,30,1.1,ok\n"
             "1,full3d,2e-9,1e-12,ok\n1,affine,10,0.4,ok\n"
             "2,full3d,,,failed\n2,affine,20,0.5,ok\n");
  const std::vector<FigureFiles> files = write_experiment_figures("mcinroy-pose", dir.path());
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].image.filename(), "mcinroy_pose.png");
  expect_good_png(files[0].image, 1000, 800);
  const testing::Csv csv = read_csv(files[0].csv);
  std::vector<double> affine;
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    if (csv.text(r, "estimator") == "affine") affine.push_back(csv.number(r, "rot_err_deg"));
  }
  EXPECT_EQ(affine, (std::vector<double>{10, 20, 30}));
  EXPECT_EQ(csv.rows.size(), 5u);  // full3d's failed trial has no error
}

// A Wu & Wu sweep: the rows of each estimator, with n across (wu-points) or SNR across (wu-snr).
std::string wu_sweep_csv(const std::vector<int>& ns, const std::vector<int>& snrs) {
  std::string text =
      "n,noise,snr_db,estimator,trials,rot_err_deg_mean,rot_err_deg_median,rot_err_deg_p95,"
      "trans_err_mean,trans_err_rel_mean,trans_err_deg_mean,time_us_median,failures,"
      "wrong_but_ok\n";
  for (int n : ns) {
    for (int snr : snrs) {
      for (const char* estimator : {"oi-foam", "perspective", "affine"}) {
        text += std::to_string(n) + ",gaussian," + std::to_string(snr) + "," + estimator + ",10," +
                std::to_string(100.0 / n / (1 + snr)) + ",0,0,0,0,0," + std::to_string(5.0 * n) +
                ",0,0\n";
      }
    }
  }
  return text;
}

TEST(ExperimentFigures, WuSweepsDrawAccuracyAndTimeForEveryRow) {
  TempDir dir("expwu");
  write_text(dir.path() / "wu_points.csv", wu_sweep_csv({4, 9, 14}, {60}));
  const std::vector<FigureFiles> points = write_experiment_figures("wu-points", dir.path());
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].image.filename(), "wu_points_accuracy.png");
  EXPECT_EQ(points[1].image.filename(), "wu_points_time.png");
  for (const FigureFiles& f : points) expect_good_png(f.image, 1000, 800);
  const testing::Csv accuracy = read_csv(points[0].csv);
  ASSERT_EQ(accuracy.rows.size(), 9u);
  for (std::size_t r = 0; r < accuracy.rows.size(); ++r) {
    const double n = accuracy.number(r, "n");
    EXPECT_NEAR(accuracy.number(r, "rot_err_deg_mean"), 100.0 / n / 61.0, kInputDecimals);
  }
  const testing::Csv time = read_csv(points[1].csv);
  ASSERT_EQ(time.rows.size(), 9u);
  for (std::size_t r = 0; r < time.rows.size(); ++r) {
    EXPECT_NEAR(time.number(r, "time_us_median"), 5.0 * time.number(r, "n"), kInputDecimals);
  }

  write_text(dir.path() / "wu_snr.csv", wu_sweep_csv({10}, {30, 40, 50}));
  const std::vector<FigureFiles> snr = write_experiment_figures("wu-snr", dir.path());
  ASSERT_EQ(snr.size(), 1u);
  expect_good_png(snr[0].image, 1000, 800);
  EXPECT_EQ(read_csv(dir.path() / "wu_snr.csv").rows.size(), 9u) << "the input is untouched";
  const testing::Csv by_snr = read_csv(snr[0].csv);
  ASSERT_EQ(by_snr.rows.size(), 9u);
  for (std::size_t r = 0; r < by_snr.rows.size(); ++r) {
    EXPECT_NEAR(by_snr.number(r, "rot_err_deg_mean"),
                100.0 / 10.0 / (1.0 + by_snr.number(r, "snr_db")), kInputDecimals);
  }
}

TEST(ExperimentFigures, BadInputNamesTheProblemAndWritesNothing) {
  TempDir dir("expbad");
  EXPECT_THROW(write_experiment_figures("no-such-experiment", dir.path()), InvalidArgument);
  try {
    write_experiment_figures("bound", dir.path());
    ADD_FAILURE() << "no throw without bound_trials.csv";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("bound_trials.csv"), std::string::npos) << e.what();
  }
  write_text(dir.path() / "mcinroy_orientation_trials.csv",
             "n,trial,pbar,estimator,status\n3,0,1,a,ok\n");
  try {
    write_experiment_figures("mcinroy-orientation", dir.path());
    ADD_FAILURE() << "no throw without the rot_err_deg column";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("rot_err_deg"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "bound.png"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "mcinroy_orientation.png"));
}

}  // namespace
}  // namespace vantage::plot
