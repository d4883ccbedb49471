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
  if (outcome.complete) io::save_layout(args.out, outcome.placed.layout, args.overwrite);
  if (args.json) {
    print_json(place_json::report(args, sites, outcome, outcome.complete));
  } else {
    print_place_report(args, sites.n_candidates, sites.drawn, outcome.result, outcome.placed,
                       outcome.complete);
  }
  if (!outcome.complete) {
    std::cerr << "vantage: place: " << place_json::failure_message(outcome.result, outcome.placed)
              << "; nothing written" << std::endl;
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
