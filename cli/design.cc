// `vantage design LAYOUT --add K [--candidates-only] [--margin M] [--min-distance-difference D]
// [--direct|--no-direct] [--write OUT.json|OUT.csv] [--overwrite] [--json]`: the inductive
// augmenter of McInroy et al. (Sec. III.E, text around Fig. 3) done on the global worst viewpoint
// (docs/math.md §13, §15).

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "command.h"
#include "design_args.h"
#include "layout_input.h"
#include "limits.h"
#include "progress.h"
#include "vantage/analysis/common.h"
#include "vantage/commands/design_json.h"
#include "vantage/design/augment.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/printable.h"
#include "vantage/io/text_file.h"
#include "vantage/tracker/identification.h"

#if VANTAGE_WITH_PLOT
#include "figure_output.h"
#include "vantage/plot/design_curve.h"
#else
#include "without_plot.h"
#endif

namespace vantage::cli {

namespace {

[[noreturn]] void bad(const std::string& message) { throw InvalidArgument(message); }

// The format of --write can hold the augmented layout (CSV: markers only, no candidates left,
// names it can write): checked on the input before the search. The additions are markers with
// writable names, and candidates are left over unless --candidates-only uses them all.
void check_write_format(const DesignArgs& args, const Layout& layout) {
  if (!args.write_given) return;
  Layout probe = layout;
  if (args.candidates_only && args.add >= probe.candidates.cols()) probe.candidates.resize(3, 0);
  if (probe.mode == LayoutMode::kPoints && args.add > 0) {
    // The additions count against a tool format's markers (.ini 6, .rom 20): K distinct
    // stand-ins, placed apart from the markers, without visibility (the additions have none).
    const Eigen::Index n = probe.entries.cols();
    const double far = 1.0 + probe.entries.cwiseAbs().maxCoeff();
    probe.entries.conservativeResize(3, n + args.add);
    probe.weights.conservativeResize(n + args.add);
    for (int k = 0; k < args.add; ++k) {
      probe.entries.col(n + k) = Eigen::Vector3d(far * (k + 2), far * (k + 3), far);
      probe.weights(n + k) = 1.0;
      if (!probe.names.empty()) {
        std::string name = "added" + std::to_string(k + 1);
        while (std::find(probe.names.begin(), probe.names.end(), name) != probe.names.end()) {
          name += "_";
        }
        probe.names.push_back(name);
      }
    }
    probe.visibility.reset();
  }
  try {
    io::layout_to_text(probe, io::layout_write_format(args.write));
  } catch (const InvalidArgument& e) {
    bad("--write: " + args.write + ": " + e.what());
  }
}

// Which global solves did not certify, in words ("initial, step 2, direct").
std::string uncertified_parts(const design::AugmentResult& r) {
  std::string parts;
  auto add = [&parts](const std::string& part) { parts += (parts.empty() ? "" : ", ") + part; };
  if (!r.initial.certified) add("initial");
  for (size_t s = 0; s < r.steps.size(); ++s) {
    if (!r.steps[s].worst.certified) add("step " + std::to_string(s + 1));
  }
  if (r.direct.status == design::DirectResult::Status::kOk && !r.direct.worst.certified) {
    add("direct");
  }
  return parts;
}

std::string format_point(const Eigen::Vector3d& p) {
  // Four decimals; values that round to zero print as 0.0000, never -0.0000.
  auto coordinate = [](double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.4f", std::abs(x) < 5e-5 ? 0.0 : x);
    return std::string(buffer);
  };
  return "(" + coordinate(p.x()) + ", " + coordinate(p.y()) + ", " + coordinate(p.z()) + ")";
}

std::string format_points(const std::vector<Eigen::Vector3d>& points) {
  std::string out;
  for (const Eigen::Vector3d& p : points) out += (out.empty() ? "" : " ") + format_point(p);
  return out;
}

std::string fixed(double x, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, x);
  return buffer;
}

void print_report(const DesignArgs& args, const Layout& layout, const design::AugmentResult& r) {
  const char* unit = layout.mode == LayoutMode::kPoints ? "marker" : "direction";
  std::cout << "vantage design: " << args.file
            << (layout.name.empty() ? "" : " (" + layout.name + ")") << ", "
            << to_string(layout.mode) << " mode, " << layout.entries.cols() << " entries, "
            << r.initial_vector_count << " data vectors; adding " << args.add << " " << unit
            << (args.add == 1 ? "" : "s") << (args.candidates_only ? " from the candidates" : "")
            << "\n"
            << "status  " << design::to_string(r.status)
            << (r.message.empty() ? "" : " (" + r.message + ")") << "\n"
            << "p-bar_min: global worst case (Theorem 6 over all sign cells); max error: Eq. (30) "
               "at the worst viewpoints; ceiling: cos(pi/(2m)) for m data vectors\n\n";
  std::cout << pad("step", 6) << pad("added", 34) << pad("m", 6) << pad("pbar_min", 11)
            << pad("max err deg", 13) << pad("ceiling", 10) << "note\n";
  std::cout << pad("0", 6) << pad("(initial layout)", 34)
            << pad(std::to_string(r.initial_vector_count), 6)
            << pad(fixed(r.initial.pbar_min, 6), 11)
            << pad(fixed(r.initial.max_worst_case_error_deg, 3), 13)
            << pad(fixed(r.initial_ceiling, 6), 10) << r.initial.viewpoints.size()
            << " worst viewpoint(s)\n";
  for (size_t s = 0; s < r.steps.size(); ++s) {
    const design::AugmentStep& st = r.steps[s];
    std::cout << pad(std::to_string(s + 1), 6)
              << pad(format_point(st.added) +
                         (st.candidate_index >= 0 ? " c" + std::to_string(st.candidate_index) : ""),
                     34)
              << pad(std::to_string(st.vector_count), 6) << pad(fixed(st.worst.pbar_min, 6), 11)
              << pad(fixed(st.worst.max_worst_case_error_deg, 3), 13)
              << pad(fixed(st.ceiling, 6), 10) << st.note << "\n";
  }
  std::cout << "\ninitial worst viewpoints: " << format_points(r.initial.viewpoints) << "\n";
  if (!r.steps.empty()) {
    std::cout << "final worst viewpoints:   " << format_points(r.steps.back().worst.viewpoints)
              << "\n";
  }
  std::cout << "final p-bar_min " << fixed(r.final_pbar_min, 6) << "\n";
  if (r.min_distance_difference > 0.0) {
    std::cout << "min distance difference (Eq. 24.1): "
              << format_number(tracker::min_distance_difference(r.augmented.entries).value)
              << " (required >= " << format_number(r.min_distance_difference) << ")\n";
  }
  if (r.direct.status == design::DirectResult::Status::kOk) {
    std::cout << "direct optimiser (" << r.direct.method << ", all " << args.add
              << " at once): p-bar_min " << fixed(r.direct.worst.pbar_min, 6) << " vs greedy "
              << fixed(r.final_pbar_min, 6) << "; added " << format_points(r.direct.added) << "\n";
  } else if (args.direct) {
    std::cout << "direct optimiser: " << r.direct.message << "\n";
  }
  std::cout << "coplanarity (smallest singular value of the unit data vectors / sqrt(m); 0 = "
               "coplanar, two-fold ambiguity): "
            << fixed(r.initial_coplanarity.smallest_singular_value, 4)
            << (r.initial_coplanarity.nearly_coplanar ? " (nearly coplanar)" : "") << " -> "
            << fixed(r.final_coplanarity.smallest_singular_value, 4)
            << (r.final_coplanarity.nearly_coplanar ? " (NEARLY COPLANAR)" : "") << "\n";
}

/// An error of augment_layout() as the command names it: an option by its flag; the layout's
/// own (coincident candidates, distances that break the minimum distance difference) against
/// the file.
InvalidArgument design_error(const InvalidArgument& e, const std::string& file) {
  static const std::pair<std::string, std::string> kFlags[] = {
      {"candidates_only", "--candidates-only"},
      {"margin", "--margin"},
      {"search_budget", "--search-budget"},
      {"min_distance_difference", "--min-distance-difference"}};
  for (const auto& [field, flag] : kFlags) {
    if (e.field() == "options." + field) return e.renamed(flag, std::nullopt);
    if (e.field() == field) return e.renamed(flag, std::nullopt).against(file);
  }
  return e.against(file);
}

/// The augmenter's options from the flags (the library checks them with the layout);
/// --add >= 1 is the command's own rule (the library takes 0 to analyse only).
design::AugmentOptions augment_options(const DesignArgs& args) {
  if (args.add < 1) bad("--add: must be >= 1, got " + std::to_string(args.add));
  design::AugmentOptions options;
  options.add = args.add;
  options.candidates_only = args.candidates_only;
  options.margin = args.margin;
  options.search_budget = args.search_budget;
  options.min_distance_difference = args.min_distance_difference;
  options.run_direct = args.direct;
  return options;
}

/// What needs the layout: the library's checks (options, candidates, the distance difference),
/// the time limit, --candidates-only and the --write format.
void check_design_layout(const DesignArgs& args, const design::AugmentOptions& options,
                         const Layout& layout) {
  // The command's own rule: the library would run out of candidates (status no_candidates).
  const Eigen::Index n_candidates = layout.candidates.cols();
  if (args.candidates_only && n_candidates > 0 && args.add > n_candidates) {
    bad("--add: " + std::to_string(args.add) + " exceeds the " + std::to_string(n_candidates) +
        " candidates of " + args.file + " (--candidates-only uses each at most once)");
  }
  try {
    design::check_augmentation(layout, options);
  } catch (const InvalidArgument& e) {
    throw design_error(e, args.file);
  }
  const long final_count =
      layout.mode == LayoutMode::kPoints
          ? static_cast<long>(free_vector_count(layout.entries.cols() + args.add))
          : static_cast<long>(layout.entries.cols()) + args.add;
  check_time_limit(
      args.file + ": --add " + std::to_string(args.add) + " on " + std::to_string(final_count) +
          " data vectors",
      estimated_design_seconds(layout, args.add, args.candidates_only, args.search_budget),
      kMaxDesignSeconds, "design", args.allow_large);
  check_write_format(args, layout);
}

/// The augmentation (checked already), with a progress line cleared before the report.
design::AugmentResult augment(const DesignArgs& args, design::AugmentOptions options,
                              const Layout& layout) {
  design::AugmentResult r;
  {
    Progress progress("design", !args.json && !args.quiet);  // cleared before the report
    options.progress = progress.callback();
    r = against_source(args.file, [&] { return design::augment_layout(layout, options); });
  }
  return r;
}

/// The one-line error of a result that is not kOk.
void print_failure(const DesignArgs& args, const design::AugmentResult& r) {
  std::cerr << "vantage: design: " << design::to_string(r.status) << ": " << r.message;
  const std::string parts = uncertified_parts(r);
  if (!parts.empty()) std::cerr << " (" << parts << ")";
  if (parts == "direct") {
    std::cerr << "; the greedy steps are certified (--no-direct skips the comparison)";
  }
  std::cerr << (args.write_given ? "; nothing written" : "") << std::endl;
}

// With the paper's bound (--objective affine): none of the camera's or the tracker's settings
// (place's rule, "goes with --objective camera").
void check_affine_objective(const DesignArgs& args) {
  place_json::Request request = args.sensor;
  request.sites = args.file;
  request.markers = 1;
  place_json::check_request(request);
}

int run_design(const DesignArgs& args) {
  if (args.sensor.objective == "camera" || args.sensor.objective == "tracker") {
    return run_sensor_design(args);
  }
  check_affine_objective(args);
  const design::AugmentOptions options = augment_options(args);
  check_write_target(args);
  const Layout layout = args.input.read(args.file, args.allow_large);
  check_design_layout(args, options, layout);
  if (const std::optional<std::string> warning = design_json::unused_visibility_warning(layout)) {
    std::cerr << "vantage: warning: design: " << io::printable(args.file) << ": " << *warning
              << " (--seen-whole drops the model, from --write's file too, and this line)"
              << std::endl;
  }
  std::optional<io::WriteLock> lock;
  if (args.write_given) lock.emplace(args.write);
#if VANTAGE_WITH_PLOT
  if (!args.plot.empty()) check_figure_directory("--plot", args.plot);
#else
  if (!args.plot.empty()) throw InvalidArgument(std::string("--plot: ") + kWithoutPlot);
#endif

  const design::AugmentResult r = augment(args, options, layout);

  const bool ok = r.status == design::AugmentResult::Status::kOk;
  if (ok && args.write_given)
    io::save_layout(args.write, design_json::layout_to_write(r), args.overwrite);
#if VANTAGE_WITH_PLOT
  std::vector<plot::FigureFiles> figures;
  if (ok && !args.plot.empty()) {
    create_figure_directory("--plot", args.plot);
    try {
      figures.push_back(plot::write_design_curve(plot::design_curve(r, layout.name), args.plot));
    } catch (const plot::RenderError& e) {
      std::cerr << "vantage: design: " << e.what() << std::endl;
      return kExitFailure;
    }
  }
#endif

  if (args.json) {
    Json out = design_json::design(args.file, layout, args.direct, r);
    if (ok && args.write_given) out["written"] = args.write;
#if VANTAGE_WITH_PLOT
    if (!figures.empty()) out["figures"] = figure_files_json(figures);
#endif
    print_json(out);
  } else {
    print_report(args, layout, r);
    if (ok && args.write_given) std::cout << "written: " << args.write << "\n";
#if VANTAGE_WITH_PLOT
    for (const plot::FigureFiles& f : figures) {
      std::cout << "figure: " << f.image.string() << " (numbers: " << f.csv.string() << ")\n";
    }
#endif
  }
  if (!ok) {
    print_failure(args, r);
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

// Every check that can fail before the (possibly long) search, so that a bad call costs
// nothing and writes nothing.
void check_write_target(const DesignArgs& args) {
  if (!args.write_given) return;
  if (args.write.empty()) throw InvalidArgument("--write: empty file name");
  if (!io::is_valid_utf8(args.write)) {
    throw InvalidArgument(
        "--write: the file name is not valid UTF-8 (the report could not name it)");
  }
  if (!args.overwrite && io::same_file(args.write, args.file)) {
    throw InvalidArgument("--write: " + args.write +
                          " is the input layout; refusing to overwrite it without " +
                          "--overwrite");
  }
  try {
    io::layout_write_format(args.write);
    io::check_write_target(args.write, args.overwrite);
  } catch (const InvalidArgument& e) {
    // The way out for an existing regular file: the option, not a parse of the message.
    std::error_code ec;
    const bool existing_file = std::filesystem::is_regular_file(args.write, ec) && !args.overwrite;
    throw InvalidArgument(std::string("--write: ") + e.what() +
                          (existing_file ? " (--overwrite)" : ""));
  }
}

Command add_design_command(CLI::App& root) {
  auto args = std::make_shared<DesignArgs>();
  CLI::App* sub = root.add_subcommand(
      "design",
      "Add K directions or markers greedily where the global worst viewpoint is weakest "
      "(the paper's a-perp rule, Sec. III.E), with the ceiling cos(pi/(2m)) and a direct "
      "optimiser for comparison; or, with --objective camera or tracker, the K candidates that "
      "make the camera's pose CRB or the tracker's TRE best");
  sub->add_option("LAYOUT", args->file, "layout JSON file (vectors or points, optional candidates)")
      ->required();
  args->input.add_options(sub);
  sub->add_option("--add", args->add,
                  "K: directions (vector layouts) or markers (point layouts) "
                  "to add, >= 1")
      ->required();
  sub->add_flag("--candidates-only", args->candidates_only,
                "choose only among the layout's candidates (each at most once)");
  args->margin_option =
      sub->add_option("--margin", args->margin,
                      "point mode: search the markers' bounding box grown by M times its largest "
                      "side on every side, >= 0")
          ->capture_default_str();
  args->search_budget_option =
      sub->add_option("--search-budget", args->search_budget,
                      "point mode: the branch and bound's budget per step, in global solves times "
                      "data vectors (about 1 us of CPU each); raise it until the step's search is "
                      "closed; 0: grid and polish only")
          ->capture_default_str();
  sub->add_option("--min-distance-difference", args->min_distance_difference,
                  "point mode: every addition keeps any two inter-marker distances at least D "
                  "apart (tracker identification, the check of `place`); the layout must keep "
                  "it itself; 0: no constraint")
      ->capture_default_str();
  args->direct_option =
      sub->add_flag("--direct,!--no-direct", args->direct,
                    "also run (default) or skip the direct optimiser over all K additions at once");
  args->objective_args
      .add_options(sub, &args->sensor, "the layout's",
                   "the centre of the bounding box of the markers and candidates")
      ->description(
          "affine: the paper's bound, seen whole (the a-perp augmenter above); camera: the "
          "pinhole pose CRB, tracker: the RMS TRE at --target, each choosing --add of the "
          "layout's candidates by place's search (docs/math.md §21, \"In design\")");
  CLI::Option* write =
      sub->add_option("--write", args->write,
                      "write the augmented layout (greedy additions, weight 1; used candidates "
                      "removed) to OUT.json, OUT.csv (markers only) or a tracker's OUT.rom or "
                      "geometryID.ini (markers only), in the format the extension names; "
                      "nothing is written on any error");
  sub->add_flag("--overwrite", args->overwrite,
                "let --write replace an existing file (even the input layout)")
      ->needs(write);
  add_allow_large_flag(sub, args->allow_large);
  sub->add_flag("--quiet", args->quiet, "no progress line on stderr (shown only on a terminal)");
  sub->add_option("--plot", args->plot,
                  "write the design figure (design.png + design.csv: p-bar_min per step, the "
                  "direct optimum, the ceiling) into DIR");
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args, write] {
            args->write_given = write->count() > 0;
            args->objective_args.parse(&args->sensor);
            return run_design(*args);
          }};
}

}  // namespace vantage::cli
