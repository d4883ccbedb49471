// `vantage place (BODY | --sites SITES) --markers K --out LAYOUT.json ...`: K markers on a body,
// chosen among candidate sites so that every workspace direction is trackable and the certified
// worst case under visibility is best (docs/math.md §21).

#include <functional>
#include <iostream>
#include <memory>
#include <string>

#include "command.h"
#include "layout_input.h"
#include "place_report.h"
#include "progress.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/text_file.h"

namespace vantage::cli {
namespace {

int run_place(const PlaceArgs& args) {
  place_json::check_request(args);
  if (args.out.empty()) throw InvalidArgument("--out", "empty file name");
  const place_json::Sites sites = place_json::candidate_sites(
      args, [&](const std::string& path) { return args.input.read(path); },
      [&](Layout* layout) {
        if (!args.input.visibility.body.empty()) {
          throw InvalidArgument("--body",
                                "the positional BODY is the body; --body goes with --sites");
        }
        args.input.visibility.apply(layout);
      });
  io::WriteLock lock(args.out);

  place_json::Outcome outcome;
  {
    Progress progress("place", !args.json && !args.quiet);
    const std::function<void(const std::string&)> callback = progress.callback();
    outcome = place_json::place(args, sites, callback);
  }
  const bool write = outcome.complete || args.allow_partial;
  if (write) io::save_layout(args.out, outcome.placed.layout, args.overwrite);
  if (args.json) {
    print_json(place_json::report(args, sites, outcome, write));
  } else {
    print_place_report(args, sites.n_candidates, sites.drawn, sites.excluded, outcome, write);
  }
  if (!outcome.complete) {
    const std::string why = place_json::failure_message(outcome.result, outcome.placed);
    if (args.allow_partial) {
      std::cerr << "vantage: warning: place: " << why << "; written as asked (--allow-partial)"
                << std::endl;
      return kExitOk;
    }
    std::cerr << "vantage: place: " << why
              << "; nothing written (--allow-partial writes the best answer)" << std::endl;
    return kExitFailure;
  }
  return kExitOk;
}

// BODY or --sites, K and --out, the visibility options, and where markers may go. Returns
// --candidates (whether it was given decides a check).
CLI::Option* add_site_options(CLI::App* sub, PlaceArgs* args) {
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
                  "least distance between chosen markers (also thins the sampled sites); at "
                  "least --marker-diameter")
      ->capture_default_str();
  sub->add_option("--marker-diameter", args->marker_diameter,
                  "spherical markers of this diameter: each centre sits half of it off the "
                  "surface along the site normal (0: point markers)")
      ->capture_default_str();
  sub->add_option("--exclude", args->exclude,
                  "keep-out volume: a mesh in the body's frame (propellers, battery, ...); sites "
                  "inside it or within --marker-diameter of it are dropped (repeatable)")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub->add_option("--region", args->region,
                  "sample sites only on this part of BODY (a mesh on its surface); visibility "
                  "and occlusion stay the whole body's");
  sub->add_option("--keep", args->keep,
                  "markers already on the body: a layout of points with normals (3 or more): "
                  "always chosen, counted in K");
  return candidates;
}

// The search: the robust objective, identification, seeds, threads and the search's sizes.
void add_search_options(CLI::App* sub, PlaceArgs* args) {
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
  sub->add_option("--perturbations", args->perturbations,
                  "rounds of iterated local search after the swaps (a third of the markers, at "
                  "least two, replaced at random, then swaps; the better answer kept)")
      ->capture_default_str();
  sub->add_option("--exhaustive-limit", args->exhaustive_limit,
                  "search every subset when there are at most this many (0: never)")
      ->capture_default_str();
  sub->add_option("--certificate-tolerance", args->certificate_tolerance,
                  "t_upper - t_lower of every certified search, in [1e-15, 1e-3]")
      ->capture_default_str();
}

}  // namespace

Command add_place_command(CLI::App& root) {
  auto args = std::make_shared<PlaceArgs>();
  CLI::App* sub = root.add_subcommand(
      "place",
      "Choose K marker sites on a body (a mesh's surface, or given sites with normals) so that "
      "every workspace direction is tracked and the certified worst case under visibility is "
      "best (docs/math.md §21)");
  CLI::Option* candidates = add_site_options(sub, args.get());
  add_search_options(sub, args.get());
  args->objective_args.add_options(sub, args.get(), "the sites'",
                                   "the centre of the sites' bounding box");
  sub->add_option("--min-coverage", args->min_coverage,
                  "least trackable fraction of the workspace's lattice, in (0, 1] (default: "
                  "every direction but one)");
  sub->add_flag("--allow-partial", args->allow_partial,
                "write the best answer even when it covers less than --min-coverage (warning, "
                "exit 0)");
  sub->add_flag("--overwrite", args->overwrite, "let --out replace an existing regular file");
  sub->add_flag("--quiet", args->quiet, "no progress line on stderr (shown only on a terminal)");
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args, candidates] {
            args->candidates_given = candidates->count() > 0;
            args->objective_args.parse(args.get());
            return run_place(*args);
          }};
}

}  // namespace vantage::cli
