// `vantage plot LAYOUT --out DIR [--format png|svg|pdf] [--only NAME,...] [--size WxH]
// [--threshold-deg X] [--design DESIGN.json] [--title T] [--json]`: the figures of a layout
// (vantage::plot), each image with the CSV of the numbers it draws.
// `vantage plot LAYOUT --tre --target X,Y,Z (--fle-rms F | --fle-sigma SP,SD) [--direction A]
// [--radius R] --out DIR`: the TRE figures tre_tip_axis, tre_polar and tre_map (docs/math.md §23).
// `vantage plot --experiment NAME --out DIR [--format F] [--size WxH] [--title T] [--json]`: the
// figures of an experiment directory written by `vantage experiment NAME --out DIR`.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <regex>

#include "command.h"
#include "crb_input.h"
#include "figure_output.h"
#include "layout_input.h"
#include "limits.h"
#include "progress.h"
#include "tre_input.h"
#include "vantage/analysis/common.h"
#include "vantage/commands/tre_json.h"
#include "vantage/io/printable.h"
#include "vantage/io/text_file.h"
#include "vantage/plot/crb_figures.h"
#include "vantage/plot/experiment_figures.h"
#include "vantage/plot/layout_figures.h"
#include "vantage/plot/tre_figures.h"
#include "vantage/report/json_number.h"

namespace vantage::cli {

namespace {

struct PlotArgs {
  std::string file;
  LayoutInput input;
  std::string out;
  std::string format = "png";
  std::vector<std::string> only;
  std::string size = "1000x800";
  double threshold_deg = 5.0;
  std::string design;
  std::string title;
  std::string experiment;
  bool crb = false;
  CrbCameraArgs camera;
  bool tre = false;
  TreTargetArgs target;
  double radius = 0.0;
  CLI::Option* radius_option = nullptr;
  bool json = false;
  bool quiet = false;
};

[[noreturn]] void bad(const std::string& message) { throw InvalidArgument(message); }

void parse_size(const std::string& text, plot::FigureOptions& options) {
  static const std::regex pattern("([0-9]{1,5})[xX]([0-9]{1,5})");
  std::smatch match;
  if (!std::regex_match(text, match, pattern)) {
    bad("--size: expected WxH in pixels, e.g. 1000x800, got \"" + text + "\"");
  }
  options.width = std::stoi(match[1].str());
  options.height = std::stoi(match[2].str());
  std::string why;
  if (!options.is_valid(&why)) {
    bad("--size: each side must be in [" + std::to_string(plot::kMinFigureSide) + ", " +
        std::to_string(plot::kMaxFigureSide) + "] pixels, got " + text);
  }
}

// A number field of the design JSON, or an error naming the file and the field.
double number_at(const Json& object, const std::string& key, const std::string& where) {
  if (!object.is_object() || !object.contains(key) || !object.at(key).is_number()) {
    bad(where + "." + key + ": missing or not a number");
  }
  return object.at(key).get<double>();
}

int count_at(const Json& object, const std::string& key, const std::string& where) {
  const double value = number_at(object, key, where);
  if (!(value >= 1.0) || value != std::floor(value) || value > 1e9) {
    bad(where + "." + key + ": must be a positive integer");
  }
  return static_cast<int>(value);
}

// The curve of a `vantage design --json` output file.
plot::DesignCurve read_design_curve(const std::string& path) {
  Json root;
  try {
    root = Json::parse(io::read_text_file(path));
  } catch (const Json::exception& e) {
    bad(path + ": not JSON (" + std::string(e.what()) + ")");
  }
  if (!root.is_object()) bad(path + ": not a JSON object (expected `vantage design --json`)");
  plot::DesignCurve curve;
  if (root.contains("name") && root.at("name").is_string()) curve.layout_name = root.at("name");
  if (!root.contains("initial")) bad(path + ": initial: missing");
  curve.n_vectors.push_back(count_at(root.at("initial"), "n_vectors", path + ": initial"));
  curve.pbar_min.push_back(number_at(root.at("initial"), "pbar_min", path + ": initial"));
  if (!root.contains("steps") || !root.at("steps").is_array()) bad(path + ": steps: missing");
  const Json& steps = root.at("steps");
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const std::string where = path + ": steps[" + std::to_string(k) + "]";
    curve.n_vectors.push_back(count_at(steps[k], "n_vectors", where));
    curve.pbar_min.push_back(number_at(steps[k], "pbar_min", where));
  }
  if (root.contains("direct")) {
    curve.has_direct = true;
    curve.direct_n_vectors = curve.n_vectors.back();
    curve.direct_pbar_min = number_at(root.at("direct"), "pbar_min", path + ": direct");
  }
  std::string why;
  if (!curve.is_valid(&why)) bad(path + ": " + why);
  return curve;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

int run_experiment_plot(const PlotArgs& args) {
  if (!args.file.empty()) bad("LAYOUT: not allowed with --experiment");
  if (args.crb) bad("--crb: not allowed with --experiment");
  if (args.tre) bad("--tre: not allowed with --experiment");
  if (!args.only.empty() || !args.design.empty()) {
    bad("--only/--design: not allowed with --experiment");
  }
  const std::vector<std::string> names = plot::experiment_figure_names();
  if (std::find(names.begin(), names.end(), args.experiment) == names.end()) {
    bad("--experiment: no figures for \"" + args.experiment + "\" (" + joined(names) + ")");
  }
  plot::FigureOptions options;
  options.format = plot::parse_format(args.format, "--format");
  options.title = args.title;
  parse_size(args.size, options);
  if (!std::filesystem::is_directory(args.out)) {
    bad("--out: " + args.out + " is not a directory (run `vantage experiment " + args.experiment +
        " --out " + args.out + "` first)");
  }
  std::vector<plot::FigureFiles> files;
  try {
    files = plot::write_experiment_figures(args.experiment, args.out, options);
  } catch (const plot::RenderError& e) {
    std::cerr << "vantage: plot: " << e.what() << std::endl;
    return kExitFailure;
  }
  if (args.json) {
    Json out;
    out["experiment"] = args.experiment;
    out["out"] = args.out;
    out["format"] = plot::to_string(options.format);
    out["size"] = {options.width, options.height};
    out["figures"] = figure_files_json(files);
    print_json(out);
  } else {
    std::cout << "vantage plot: experiment " << args.experiment << "\n";
    print_figure_files(files, options.format);
  }
  return kExitOk;
}

// The camera options without --crb, or --crb without them or with the layout figures' options.
void check_crb_options(const PlotArgs& args) {
  const CrbCameraArgs& c = args.camera;
  const std::pair<const char*, CLI::Option*> camera[] = {{"--distance", c.distance_option},
                                                         {"--focal", c.focal_option},
                                                         {"--noise-px", c.noise_option}};
  for (const auto& [name, option] : camera) {
    if (args.crb && option->count() == 0) bad(std::string(name) + ": required with --crb");
    if (!args.crb && option->count() > 0) bad(std::string(name) + ": only with --crb");
  }
  if (!args.crb && (!c.principal_point.empty() || !c.sweep_distance.empty())) {
    bad("--principal-point/--sweep-distance: only with --crb");
  }
  if (args.crb && (!args.only.empty() || !args.design.empty())) {
    bad("--only/--design: not allowed with --crb (it writes crb_map and crb_sweep)");
  }
}

void print_crb_plot(const PlotArgs& args, const Layout& layout, const plot::CrbFigures& figures,
                    const plot::FigureOptions& options) {
  const camera::PoseCrbMap& map = figures.report.map;
  const bool ok = map.status == camera::PoseCrbMap::Status::kOk;
  if (args.json) {
    Json out;
    out["layout"] = args.file;
    out["name"] = layout.name;
    out["out"] = args.out;
    out["format"] = plot::to_string(options.format);
    out["size"] = {options.width, options.height};
    out["status"] = camera::to_string(map.status);
    if (!ok) out["message"] = camera::untrackable_reason(map, figures.report.camera.distance);
    if (ok) {
      out["worst_rot_rms_deg"] = report::json_number(map.worst.rot_rms_deg);  // null: unbounded
      out["worst_unbounded"] = map.worst.unbounded;
    }
    out["unbounded_fraction"] = map.unbounded_fraction;
    out["figures"] = figure_files_json(figures.files);
    print_json(out);
    return;
  }
  std::cout << "vantage plot --crb: " << (layout.name.empty() ? args.file : layout.name) << "\n";
  if (ok) {
    std::cout << "worst rot_rms "
              << (map.worst.unbounded ? std::string("unbounded (first-order rot_rms past 45 deg)")
                                      : format_number(map.worst.rot_rms_deg, 4) + " deg")
              << ", p50 " << format_number(map.percentiles.p50, 4) << " deg\n";
  } else {
    std::cout << "not trackable: "
              << camera::untrackable_reason(map, figures.report.camera.distance) << "\n";
  }
  print_figure_files(figures.files, options.format);
}

// `vantage plot LAYOUT --crb --distance D --focal F --noise-px S`: crb_map and crb_sweep.
int run_crb_plot(const PlotArgs& args) {
  plot::CrbFiguresOptions options;
  options.figure.format = plot::parse_format(args.format, "--format");
  options.figure.title = args.title;
  parse_size(args.size, options.figure);
  options.sweep = args.camera.sweep();
  // plot has no --allow-large: the bound of `vantage crb --sweep-distance`, not lifted here.
  if (options.sweep && options.sweep->count > kMaxCrbSweepDistances) {
    bad("--sweep-distance: " + std::to_string(options.sweep->count) + " exceeds the limit of " +
        std::to_string(kMaxCrbSweepDistances) + " for `vantage plot --crb` (README \"Limits\")");
  }
  check_figure_directory("--out", args.out);
  const Layout layout = args.input.read(args.file);
  plot::CrbFigures figures;
  {
    Progress progress("plot", !args.json && !args.quiet);  // cleared before the report
    options.progress = progress.callback();
    try {
      figures = plot::crb_figures(layout, args.camera.options(), options);
    } catch (const InvalidArgument& e) {
      throw crb_option_error(e, args.file);
    }
  }
  create_figure_directory("--out", args.out);
  try {
    plot::write_crb_figures(figures, options, args.out);
  } catch (const plot::RenderError& e) {
    std::cerr << "vantage: plot: " << e.what() << std::endl;
    return kExitFailure;
  }
  print_crb_plot(args, layout, figures, options.figure);
  return kExitOk;
}

// The TRE options without --tre, or --tre with the other figures' options.
void check_tre_options(const PlotArgs& args) {
  const TreTargetArgs& t = args.target;
  const std::pair<const char*, CLI::Option*> tre_only[] = {{"--target", t.target_option},
                                                           {"--fle-rms", t.fle_rms_option},
                                                           {"--fle-sigma", t.fle_sigma_option},
                                                           {"--direction", t.direction_option},
                                                           {"--radius", args.radius_option}};
  for (const auto& [name, option] : tre_only) {
    if (!args.tre && option->count() > 0) bad(std::string(name) + ": only with --tre");
  }
  if (!args.tre) return;
  if (args.crb) bad("--tre: not allowed with --crb");
  if (!args.only.empty() || !args.design.empty()) {
    bad("--only/--design: not allowed with --tre (it writes tre_tip_axis, tre_polar and "
        "tre_map)");
  }
}

void print_tre_plot(const PlotArgs& args, const Layout& layout, const plot::TreFigures& figures,
                    const plot::FigureOptions& options) {
  const tracker::TreExtremes& x = figures.sweeps.report.targets.front().extremes;
  const bool tracked = x.worst.status != tracker::TreExtreme::Status::kUntracked;
  if (args.json) {
    Json out;
    out["layout"] = args.file;
    out["name"] = layout.name;
    out["out"] = args.out;
    out["format"] = plot::to_string(options.format);
    out["size"] = {options.width, options.height};
    out["worst"] = tre_json::extreme(x.worst);
    out["best"] = tre_json::extreme(x.best);
    out["radius"] = figures.sweeps.polar.radius;
    out["figures"] = figure_files_json(figures.files);
    print_json(out);
    return;
  }
  std::cout << "vantage plot --tre: " << (layout.name.empty() ? args.file : layout.name) << "\n";
  if (tracked) {
    std::cout << "first target: worst RMS TRE " << format_number(x.worst.rms, 5) << ", best "
              << format_number(x.best.rms, 5) << " (layout units)\n";
  } else {
    std::cout << "no line of sight tracks the tool\n";
  }
  print_figure_files(figures.files, options.format);
}

// `vantage plot LAYOUT --tre --target X,Y,Z (--fle-rms F | --fle-sigma SP,SD)`: tre_tip_axis,
// tre_polar and tre_map.
int run_tre_plot(const PlotArgs& args) {
  plot::TreFiguresOptions options;
  options.figure.format = plot::parse_format(args.format, "--format");
  options.figure.title = args.title;
  parse_size(args.size, options.figure);
  const std::vector<Eigen::Vector3d> targets = args.target.parsed_targets();
  tracker::TreOptions tre;
  tre.fle = args.target.parsed_fle();
  tre.direction = args.target.parsed_direction();
  if (args.radius_option->count() > 0) {
    if (!(std::isfinite(args.radius) && args.radius > 0.0)) {
      bad("--radius: must be a finite number > 0, got " + format_number(args.radius));
    }
    options.sweep.radius = args.radius;
  }
  check_figure_directory("--out", args.out);
  const Layout layout = args.input.read(args.file);
  plot::TreFigures figures;
  try {
    figures = plot::tre_figures(layout, targets, tre, options);
  } catch (const InvalidArgument& e) {
    throw tre_option_error(e, args.file);
  }
  create_figure_directory("--out", args.out);
  try {
    plot::write_tre_figures(figures, options, args.out);
  } catch (const plot::RenderError& e) {
    std::cerr << "vantage: plot: " << e.what() << std::endl;
    return kExitFailure;
  }
  print_tre_plot(args, layout, figures, options.figure);
  return kExitOk;
}

/// The layout figures' options from --format, --title, --size, --threshold-deg and --only.
plot::LayoutFiguresOptions layout_figures_options(const PlotArgs& args) {
  plot::LayoutFiguresOptions options;
  options.figure.format = plot::parse_format(args.format, "--format");
  options.figure.title = args.title;
  parse_size(args.size, options.figure);
  if (!(args.threshold_deg > 0.0 && args.threshold_deg < 90.0)) {
    bad("--threshold-deg: must be in (0, 90) degrees, got " + format_number(args.threshold_deg));
  }
  options.threshold_deg = args.threshold_deg;
  for (const std::string& name : args.only) {
    if (!plot::is_figure_name(name)) {
      bad("--only: unknown figure \"" + io::excerpt(name) +
          "\" (viewpoint_map, visibility, dropout, error_surface, vectors, placement, design)");
    }
    if (name == "design" && args.design.empty()) {
      bad("--only: the design figure needs --design DESIGN.json (`vantage design --json`)");
    }
  }
  options.only = args.only;
  try {
    plot::selected_figures(options, !args.design.empty(), true, true);
  } catch (const InvalidArgument& e) {
    throw e.renamed("--" + e.field(), e.index());
  }
  return options;
}

/// Refuses --only visibility without normals and --only placement without a placement.
void check_layout_figures(const PlotArgs& args, const Layout& layout) {
  const bool on_body = layout.visibility.has_value();
  if (!on_body && std::find(args.only.begin(), args.only.end(), "visibility") != args.only.end()) {
    bad("--only: the visibility figure needs markers with normals (\"normals\" in " + args.file +
        ", or --normals radial)");
  }
  if (!layout.placement &&
      std::find(args.only.begin(), args.only.end(), "placement") != args.only.end()) {
    bad("--only: the placement figure needs a layout written by vantage place (\"placement\" in " +
        args.file + ")");
  }
}

/// The JSON (--json) or text summary of the layout figures written.
void print_layout_plot(const PlotArgs& args, const Layout& layout,
                       const plot::LayoutFigures& figures,
                       const plot::LayoutFiguresOptions& options, bool certified) {
  if (args.json) {
    Json out;
    out["layout"] = args.file;
    out["name"] = layout.name;
    out["out"] = args.out;
    out["format"] = plot::to_string(options.figure.format);
    out["size"] = {options.figure.width, options.figure.height};
    out["threshold_deg"] = options.threshold_deg;
    out["pbar_min"] = figures.pbar_min;
    out["max_worst_case_error_deg"] = figures.max_worst_case_error_deg;
    if (figures.visibility_max_worst_case_error_deg) {
      out["visibility"] = {
          {"max_worst_case_error_deg", *figures.visibility_max_worst_case_error_deg},
          {"trackable_fraction", *figures.trackable_fraction}};
    }
    out["status"] = !certified          ? "not_certified"
                    : figures.with_body ? "certified_at_resolution"
                                        : "certified";
    if (!figures.message.empty()) out["message"] = figures.message;
    out["figures"] = figure_files_json(figures.files);
    print_json(out);
  } else {
    std::cout << "vantage plot: " << (layout.name.empty() ? args.file : layout.name) << "\n"
              << "p-bar_min " << format_number(figures.pbar_min, 6) << ", max worst-case error "
              << format_number(figures.max_worst_case_error_deg, 6) << " deg"
              << (figures.visibility_max_worst_case_error_deg ? " seen whole" : "") << "\n";
    if (figures.visibility_max_worst_case_error_deg) {
      std::cout << "on the body: max worst-case error "
                << format_number(*figures.visibility_max_worst_case_error_deg, 6)
                << " deg, trackable " << format_number(100.0 * *figures.trackable_fraction, 4)
                << " %\n";
    }
    print_figure_files(figures.files, options.figure.format);
  }
}

int run_plot(const PlotArgs& args) {
  if (!args.experiment.empty()) return run_experiment_plot(args);
  if (args.file.empty()) bad("LAYOUT: required (or --experiment NAME)");
  check_crb_options(args);
  check_tre_options(args);
  if (args.crb) return run_crb_plot(args);
  if (args.tre) return run_tre_plot(args);
  const plot::LayoutFiguresOptions options = layout_figures_options(args);
  check_figure_directory("--out", args.out);
  const Layout layout = args.input.read(args.file);
  check_layout_figures(args, layout);
  std::unique_ptr<plot::DesignCurve> design;
  if (!args.design.empty()) {
    design = std::make_unique<plot::DesignCurve>(read_design_curve(args.design));
    if (design->layout_name.empty()) design->layout_name = layout.name;
  }
  create_figure_directory("--out", args.out);

  report::LayoutReportOptions report_options;
  report_options.dropout = plot::needs_dropout(
      options, design != nullptr, layout.visibility.has_value(), layout.placement.has_value());
  report_options.dropout_options.threads = options.figure.threads;
  const report::LayoutReport report =
      against_source(args.file, [&] { return report::analyze_layout(layout, report_options); });
  plot::LayoutFigures figures;
  try {
    figures = plot::write_layout_figures(report, args.out, options, design.get());
  } catch (const plot::RenderError& e) {
    std::cerr << "vantage: plot: " << e.what() << std::endl;
    return kExitFailure;
  }
  const bool certified = figures.status == plot::LayoutFigures::Status::kCertified;
  print_layout_plot(args, layout, figures, options, certified);
  if (!certified) {
    std::cerr << "vantage: warning: " << figures.message << std::endl;
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

Command add_plot_command(CLI::App& root) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* sub = root.add_subcommand(
      "plot",
      "Figures of a layout (PNG, SVG or PDF, each with a CSV of its numbers): viewpoint_map, "
      "visibility (markers with normals), dropout, error_surface, vectors, and design (with "
      "--design); or, with --experiment NAME, the figures of a `vantage experiment NAME --out "
      "DIR` directory");
  sub->add_option("LAYOUT", args->file,
                  "layout file (.json vectors or points, .csv markers, .yaml AprilTag bundle)");
  args->input.add_options(sub, "--layout-format");
  sub->add_option("--experiment", args->experiment,
                  "draw the figures of experiment NAME from the CSVs in --out DIR instead: " +
                      joined(plot::experiment_figure_names()));
  sub->add_option(
         "--out", args->out,
         "directory for the figures (created if missing); with --experiment, the experiment's "
         "directory")
      ->required();
  sub->add_option("--format", args->format, "png, svg or pdf")->capture_default_str();
  sub->add_option("--only", args->only,
                  "comma-separated figures to write: viewpoint_map, visibility, dropout, "
                  "error_surface, vectors, placement, design (default: all; visibility only "
                  "for markers with normals, placement only for a layout written by vantage "
                  "place, design only with --design)")
      ->delimiter(',');
  sub->add_option("--size", args->size, "WxH in pixels (points for SVG/PDF)")
      ->capture_default_str();
  sub->add_option("--threshold-deg", args->threshold_deg,
                  "viewpoint_map: contour of the directions whose worst-case error exceeds X deg "
                  "(layouts without normals)")
      ->capture_default_str();
  sub->add_option("--design", args->design,
                  "DESIGN.json written by `vantage design ... --json`: adds the design figure");
  sub->add_option("--title", args->title, "replaces every figure's title");
  sub->add_flag("--crb", args->crb,
                "write the pose Cramér-Rao bound figures crb_map and crb_sweep instead (needs "
                "--distance, --focal, --noise-px; docs/math.md §22)");
  args->camera.add_options(sub, false);
  args->camera.threads = 0;
  sub->add_flag("--tre", args->tre,
                "write the target registration error figures tre_tip_axis, tre_polar and tre_map "
                "instead (needs --target and --fle-rms or --fle-sigma; docs/math.md §23)");
  args->target.add_options(sub);
  args->radius_option = sub->add_option(
      "--radius", args->radius,
      "tre_polar: radius of the circles about the markers' centroid (default: the first "
      "target's distance from it)");
  sub->add_flag("--json", args->json, "print one JSON object listing the files written");
  sub->add_flag("--quiet", args->quiet,
                "no progress line on stderr (--crb shows one on a terminal during its distance "
                "sweep)");
  return {sub, [args] { return run_plot(*args); }};
}

}  // namespace vantage::cli
