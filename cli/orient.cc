// `vantage orient CORRESPONDENCES [--method qmethod|svd|foam] [--json]`: absolute orientation
// and pose from 3-D correspondences (Theorem 1 / Haralick SVD / FOAM, centred as in Prop. 3).

#include <iostream>
#include <memory>

#include "command.h"
#include "vantage/analysis/absolute_orientation.h"
#include "vantage/io/correspondence_file.h"

namespace vantage::cli {

namespace {

/// 0 for a unique pose; 1 (with the reason on stderr) when the data do not determine it.
int exit_status(const PoseResult& pose) {
  if (pose.status == OrientationStatus::kOk) return kExitOk;
  std::cerr << "vantage: orient: " << to_string(pose.status) << ": " << pose.message << std::endl;
  return kExitFailure;
}

struct OrientArgs {
  std::string file;
  std::string method = "qmethod";
  bool json = false;
};

int run_orient(const OrientArgs& args) {
  const io::CorrespondenceFile file = io::read_correspondences(args.file);
  file.require({"model", "measured"}, "vantage orient");
  OrientationOptions options;
  // CLI11 has checked the name (IsMember).
  options.method = parse_orientation_method(args.method).value_or(OrientationMethod::kQMethod);
  const PoseResult pose = against_source(file.source, [&] {
    try {
      return absolute_pose(file.model, file.measured, file.weights, options);
    } catch (const InvalidArgument& e) {
      // absolute_pose() names its arguments z_object and measured; the file says model.
      if (e.field() == "z_object") throw e.renamed("model", e.index());
      throw;
    }
  });

  if (args.json) {
    Json out;
    out["method"] = to_string(options.method);
    out["n"] = file.model.cols();
    out["R"] = json_rows(pose.R_camera_object);
    out["p"] = json_list(pose.p_camera_object);
    out["alpha"] = pose.alpha;
    out["residual"] = pose.residual;
    out["eigen_gap"] = pose.eigen_gap;
    out["status"] = to_string(pose.status);
    if (!pose.message.empty()) out["message"] = pose.message;
    print_json(out);
    return exit_status(pose);
  }
  std::cout << "vantage orient: " << file.model.cols() << " correspondences from " << args.file
            << ", method " << to_string(options.method) << "\n"
            << "model:  alpha * measured = R * model + p\n"
            << "status     " << to_string(pose.status)
            << (pose.message.empty() ? "" : " (" + pose.message + ")") << "\n"
            << "R_camera_object\n"
            << format_matrix(pose.R_camera_object, 4) << "p_camera_object  "
            << format_vector(pose.p_camera_object) << "\n"
            << "alpha      " << format_number(pose.alpha, 10) << "\n"
            << "residual   " << format_number(pose.residual) << "  (weighted sum of squares)\n"
            << "eigen gap  " << format_number(pose.eigen_gap)
            << "  (lambda1 - lambda2 of D: conditioning)\n";
  return exit_status(pose);
}

}  // namespace

Command add_orient_command(CLI::App& root) {
  auto args = std::make_shared<OrientArgs>();
  CLI::App* sub = root.add_subcommand(
      "orient",
      "Rotation, translation and scale from 3-D correspondences: alpha*measured = R*model + p");
  sub->add_option("CORRESPONDENCES", args->file,
                  "JSON file {\"model\": [[x,y,z]...], \"measured\": [[x,y,z]...], "
                  "\"weights\": [...]}")
      ->required();
  sub->add_option("--method", args->method,
                  "qmethod (Theorem 1), svd (Haralick et al.) or foam (Markley)")
      ->check(CLI::IsMember({"qmethod", "svd", "foam"}))
      ->capture_default_str();
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_orient(*args); }};
}

}  // namespace vantage::cli
