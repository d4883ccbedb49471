// `vantage place (BODY | --sites SITES) --markers K --out LAYOUT.json ...`: K markers on a body,
// chosen among candidate sites so that every workspace direction is trackable and the certified
// worst case under visibility is best (docs/math.md §21).

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "command.h"
#include "layout_input.h"
#include "place_report.h"
#include "progress.h"
#include "vantage/analysis/common.h"
#include "vantage/design/placement.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/mesh_file.h"
#include "vantage/io/text_file.h"
#include "vantage/sdp/layout_report.h"
#include "vantage/sdp/visibility_model.h"

namespace vantage::cli {
namespace {

constexpr int kMaxCandidates = 20000;

[[noreturn]] void refuse(const std::string& field, const std::string& message) {
  throw InvalidArgument(field, message);
}

void check_args(const PlaceArgs& args) {
  if (args.body.empty() == args.sites.empty()) {
    refuse("BODY/--sites", "give a body mesh or --sites SITES.json, not both or neither");
  }
  if (!args.sites.empty() && args.candidates_given) {
    refuse("--candidates", "samples the body mesh; --sites gives the candidates itself");
  }
  if (args.candidates < 1 || args.candidates > kMaxCandidates) {
    refuse("--candidates", "must be in [1, " + std::to_string(kMaxCandidates) + "], got " +
                               std::to_string(args.candidates));
  }
  if (args.markers < 1) refuse("--markers", "must be >= 1, got " + std::to_string(args.markers));
  if (!(args.min_separation >= 0.0) || !std::isfinite(args.min_separation)) {
    refuse("--min-separation", "must be a finite number >= 0");
  }
  if (!(args.min_distance_difference >= 0.0) || !std::isfinite(args.min_distance_difference)) {
    refuse("--min-distance-difference", "must be a finite number >= 0");
  }
  if (args.threads < 0) refuse("--threads", "must be >= 0 (0: all cores)");
  if (args.random_trials < 0) refuse("--random-trials", "must be >= 0");
  if (args.exhaustive_limit < 0) refuse("--exhaustive-limit", "must be >= 0");
  if (!(args.certificate_tolerance >= 1e-15 && args.certificate_tolerance <= 1e-3)) {
    refuse("--certificate-tolerance", "must be in [1e-15, 1e-3]");
  }
  if (args.out.empty()) refuse("--out", "empty file name");
  if (!is_valid_utf8(args.out)) refuse("--out", "the file name is not valid UTF-8");
  try {
    if (io::layout_write_format(args.out) != io::LayoutFormat::kJson) {
      refuse("--out", args.out +
                          ": write the placed layout as .json (it keeps normals, body, "
                          "workspace and the placement record)");
    }
    io::check_write_target(args.out, args.overwrite);
  } catch (const InvalidArgument& e) {
    refuse("--out", e.what());
  }
}

// The candidate sites as a point layout on its body: sampled on the mesh, or read.
Layout candidate_sites(const PlaceArgs& args, int* drawn) {
  if (!args.sites.empty()) {
    Layout sites = args.input.read(args.sites);
    if (sites.mode != LayoutMode::kPoints) {
      refuse("--sites", args.sites + ": expected a point layout (\"points\" with \"normals\")");
    }
    if (!sites.visibility) {
      refuse("--sites", args.sites + ": the sites need \"normals\" (or --normals radial)");
    }
    *drawn = static_cast<int>(sites.entries.cols());
    return sites;
  }
  Mesh mesh;
  try {
    mesh = io::read_mesh(args.body);
  } catch (const InvalidArgument& e) {
    refuse("BODY", e.what());
  }
  design::SurfaceSites sampled;
  try {
    sampled = design::sample_surface_sites(mesh, args.candidates, args.min_separation, args.seed);
  } catch (const InvalidArgument& e) {
    refuse("BODY", args.body + ": " + e.what());
  }
  *drawn = sampled.drawn;
  Layout sites = design::surface_sites_layout(
      sampled, mesh, std::filesystem::absolute(args.body).lexically_normal().string());
  sites.name = std::filesystem::path(args.body).stem().string();
  if (!args.input.visibility.body.empty()) {
    refuse("--body", "the positional BODY is the body; --body goes with --sites");
  }
  args.input.visibility.apply(&sites);
  return sites;
}

// The site at exactly the position of kept marker i, or -1.
int site_at(const Layout& sites, const Eigen::Vector3d& p) {
  for (Eigen::Index j = 0; j < sites.entries.cols(); ++j) {
    if (sites.entries.col(j) == p) return static_cast<int>(j);
  }
  return -1;
}

// The kept markers: a kept marker at a site's very position keeps that site; the others are
// appended to the sites (their normals and cones from their file).
std::vector<int> append_kept(const PlaceArgs& args, Layout* sites) {
  if (args.keep.empty()) return {};
  Layout kept = io::load_layout(args.keep);
  if (kept.mode != LayoutMode::kPoints || !kept.visibility) {
    refuse("--keep",
           args.keep + ": expected points with \"normals\" (the markers already on the body)");
  }
  std::vector<int> at_sites;
  std::vector<Eigen::Index> appended;
  for (Eigen::Index i = 0; i < kept.entries.cols(); ++i) {
    const int site = site_at(*sites, kept.entries.col(i));
    if (site >= 0) {
      at_sites.push_back(site);
    } else {
      appended.push_back(i);
    }
  }
  if (appended.size() != static_cast<std::size_t>(kept.entries.cols())) {
    Layout rest = kept;
    rest.entries.resize(3, static_cast<Eigen::Index>(appended.size()));
    rest.visibility->normals.resize(3, rest.entries.cols());
    rest.visibility->cone_half_angle_deg.resize(rest.entries.cols());
    rest.names.clear();
    for (std::size_t k = 0; k < appended.size(); ++k) {
      const Eigen::Index i = appended[k], to = static_cast<Eigen::Index>(k);
      rest.entries.col(to) = kept.entries.col(i);
      rest.visibility->normals.col(to) = kept.visibility->normals.col(i);
      rest.visibility->cone_half_angle_deg(to) = kept.visibility->cone_half_angle_deg(i);
      if (!kept.names.empty()) rest.names.push_back(kept.names[static_cast<std::size_t>(i)]);
    }
    kept = rest;
  }
  std::vector<int> out = at_sites;
  const Eigen::Index n = sites->entries.cols();
  const Eigen::Index f = kept.entries.cols();
  if (f == 0) return out;
  std::vector<std::string> names;
  for (Eigen::Index i = 0; i < n; ++i) names.push_back(sites->entry_name(i));
  for (Eigen::Index i = 0; i < f; ++i) {
    const std::string name = kept.names.empty() ? "kept" + std::to_string(i + 1) : kept.names[i];
    if (std::find(names.begin(), names.end(), name) != names.end()) {
      refuse("--keep", args.keep + ": marker name \"" + name + "\" is also a site's name");
    }
    names.push_back(name);
  }
  MarkerVisibility& v = *sites->visibility;
  sites->entries.conservativeResize(3, n + f);
  sites->entries.rightCols(f) = kept.entries;
  sites->weights = Eigen::VectorXd::Ones(n + f);
  v.normals.conservativeResize(3, n + f);
  v.normals.rightCols(f) = kept.visibility->normals;
  v.cone_half_angle_deg.conservativeResize(n + f);
  v.cone_half_angle_deg.tail(f) = kept.visibility->cone_half_angle_deg;
  sites->names = names;
  against_source(args.keep, [&] { sites->validate(); });
  for (Eigen::Index i = 0; i < f; ++i) out.push_back(static_cast<int>(n + i));
  return out;
}

void check_problem(const PlaceArgs& args, const Layout& sites, std::size_t kept) {
  const long n = static_cast<long>(sites.entries.cols());
  const int min_visible = sites.visibility->min_visible;
  if (args.markers > n) {
    refuse("--markers", std::to_string(args.markers) + " exceeds the " + std::to_string(n) +
                            " sites" + (kept > 0 ? " and kept markers" : ""));
  }
  if (args.markers < min_visible) {
    refuse("--markers", "must be at least min_visible (" + std::to_string(min_visible) + "), got " +
                            std::to_string(args.markers));
  }
  if (static_cast<long>(kept) > args.markers) {
    refuse("--markers",
           "the " + std::to_string(kept) + " kept markers exceed " + std::to_string(args.markers));
  }
  if (args.robust_dropout && args.markers <= min_visible) {
    refuse("--robust-dropout", "needs --markers above min_visible (" + std::to_string(min_visible) +
                                   "): a lost marker leaves too few otherwise");
  }
}

int run_place(const PlaceArgs& args) {
  check_args(args);
  int drawn = 0;
  Layout sites = candidate_sites(args, &drawn);
  const int n_candidates = static_cast<int>(sites.entries.cols());
  const std::vector<int> keep = append_kept(args, &sites);
  check_problem(args, sites, keep.size());
  io::WriteLock lock(args.out);

  design::PlacementResult result;
  PlacedLayout placed;
  {
    Progress progress("place", !args.json && !args.quiet);
    progress.update("occlusion grid");
    const sdp::VisibilityModel model =
        against_source(args.sites.empty() ? args.body : args.sites, [&] {
          return sdp::VisibilityModel::of(sites, sdp::VisibilityModel::kDefaultResolutionDeg,
                                          args.threads);
        });
    design::PlacementProblem problem;
    problem.sites = model.problem();
    problem.keep = keep;
    problem.markers = args.markers;
    problem.min_separation = args.min_separation;
    problem.min_distance_difference = args.min_distance_difference;
    design::PlaceOptions options;
    options.robust_dropout = args.robust_dropout;
    options.random_trials = args.random_trials;
    options.exhaustive_limit = args.exhaustive_limit;
    options.seed = args.seed;
    options.threads = args.threads;
    options.search.certificate_tolerance = args.certificate_tolerance;
    options.progress = progress.callback();
    try {
      result = design::place_markers(problem, options);
    } catch (const InvalidArgument& e) {
      refuse(e.field() == "min_separation" ? "--min-separation" : "--markers", e.what());
    }
    progress.update("final analysis");
    placed = placed_layout(args, sites, n_candidates, result);
  }
  const bool complete = result.status == design::PlacementResult::Status::kComplete &&
                        placed.report.visibility && placed.report.visibility->worst.certified();
  if (complete) io::save_layout(args.out, placed.layout, args.overwrite);
  if (args.json) {
    print_json(place_json(args, n_candidates, drawn, result, placed, complete));
  } else {
    print_place_report(args, n_candidates, drawn, result, placed, complete);
  }
  if (!complete) {
    std::cerr << "vantage: place: " << failure_message(result, placed) << "; nothing written"
              << std::endl;
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

Command add_place_command(CLI::App& root) {
  auto args = std::make_shared<PlaceArgs>();
  CLI::App* sub = root.add_subcommand(
      "place",
      "Choose K marker sites on a body (a mesh's surface, or given sites with normals) so that "
      "every workspace direction is tracked and the certified worst case under visibility is "
      "best (docs/math.md §21)");
  sub->add_option("BODY", args->body, "body mesh (STL, OBJ, PLY, glTF, ...) to sample sites on");
  sub->add_option("--sites", args->sites,
                  "candidate sites: a point layout with normals (its cones, min_visible, body and "
                  "workspace apply)");
  CLI::Option* candidates =
      sub->add_option("--candidates", args->candidates, "sites sampled area-uniformly on BODY")
          ->capture_default_str();
  sub->add_option("--markers", args->markers, "K: markers of the answer (kept ones included)")
      ->required();
  sub->add_option("--out", args->out, "the placed layout (.json)")->required();
  args->input.add_options(sub);
  sub->add_option("--min-separation", args->min_separation,
                  "least distance between chosen markers (also thins the sampled sites)")
      ->capture_default_str();
  sub->add_option("--keep", args->keep,
                  "markers already on the body: a layout of points with normals (3 or more): "
                  "always chosen, counted in K");
  sub->add_flag("--robust-dropout", args->robust_dropout,
                "maximise the worst case over the loss of any one marker");
  sub->add_option("--min-distance-difference", args->min_distance_difference,
                  "least difference between any two inter-marker distances (tracker "
                  "identification)")
      ->capture_default_str();
  sub->add_option("--seed", args->seed, "seed of the site sampling and the random baseline")
      ->capture_default_str();
  sub->add_option("--threads", args->threads, "threads (0: all cores); the answer is the same")
      ->capture_default_str();
  sub->add_option("--random-trials", args->random_trials,
                  "random feasible K-subsets of the baseline")
      ->capture_default_str();
  sub->add_option("--exhaustive-limit", args->exhaustive_limit,
                  "search every subset when there are at most this many (0: never)")
      ->capture_default_str();
  sub->add_option("--certificate-tolerance", args->certificate_tolerance,
                  "t_upper - t_lower of every certified search, in [1e-15, 1e-3]")
      ->capture_default_str();
  sub->add_flag("--overwrite", args->overwrite, "let --out replace an existing regular file");
  sub->add_flag("--quiet", args->quiet, "no progress line on stderr (shown only on a terminal)");
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args, candidates] {
            args->candidates_given = candidates->count() > 0;
            return run_place(*args);
          }};
}

}  // namespace vantage::cli
