#pragma once

/// The size limits every front end (the `vantage` command, the Python package) checks before any
/// work (README "Limits"), kept here once. A limit refused is bad input (InvalidArgument, exit
/// status 2 in the CLI, ValueError in Python); the user lifts the soft limits (the CLI's
/// --allow-large, Python's allow_large=True) when they want to wait and have the memory. The
/// input file bound is io::kMaxFileBytes (io::kMaxFileBytesAllowLarge when lifted).

#include <string>

#include "vantage/analysis/layout.h"

namespace vantage::commands {

// Every bound below is set from a time budget, measured on this 2-core machine (RelWithDebInfo,
// `/usr/bin/time`, user CPU; the machine is shared, load average 9-12 during the runs, so wall
// times were about twice these). Layouts: n seeded random markers in [-1, 1]^3 or m seeded random
// unit directions (README "Limits" has the commands).

/// `analyze`: data vectors (vectors, or the n (n - 1) / 2 free vectors of n points: 200 points).
/// Budget: what the global search certifies, about 10 s. 20 000 random directions: 1.4 s CPU,
/// 19 MB; 50 000: not certified (the patch budget, 5e7 patches, runs out after 5.2 s CPU), so the
/// bound stays at 20 000.
constexpr long kMaxAnalyzeVectors = 20000;
/// `analyze --dropout`: one global search per entry (marker or vector). Budget about 10 s:
/// 1000 random directions 5.8 s CPU, 2000 directions 45.8 s.
constexpr long kMaxDropoutVectors = 1000;
/// `design`: refused when its estimated CPU time (estimated_design_seconds) exceeds this budget:
/// about half a minute, for a command that searches.
constexpr double kMaxDesignSeconds = 30.0;
/// The estimate, per greedy step: point mode's free search (the 11^3 grid, its polish, the
/// branch and bound at its default budget) costs about kDesignPointStepSeconds whatever the
/// layout, plus kDesignSecondsPerSolveVector for each unit of --search-budget beyond the default
/// (the drone's 24 607 solves of 20 vectors: 0.55 s); and every mode about
/// kDesign*SecondsPerVector per data vector after the additions (the solves and the direct
/// optimiser). Constants fitted to these runs (default options, direct optimiser on): points: the
/// 5-marker drone --add 20: 38.8 s (estimate 41 s); 30 markers --add 3: 4.6 s (7.5 s; refused
/// before issue 17 at 528 > 200 data vectors); 50 markers --add 3: 10.4 s (13.6 s), --add 5: 21.0 s
/// (21.6 s). Directions: 1000 --add 3: 1.1 s (1.5 s); 5000 --add 3: 7.5 s (7.5 s); the triad --add
/// 50: 1.3 s (1.3 s).
constexpr double kDesignPointStepSeconds = 1.5;
constexpr double kDesignSecondsPerSolveVector = 1.1e-6;
constexpr double kDesignPointSecondsPerVector = 1.9e-3;
constexpr double kDesignDirectionSecondsPerVector = 0.5e-3;
/// `weights`: entries (vectors or points); the LP is O(n), the file size bound comes first.
constexpr long kMaxWeightsEntries = 2'000'000;

/// `simulate` and `experiment` (per cell): --trials. Trials are streamed (13-25 MB whatever their
/// number), so the bound is one of time: measured on this machine (one thread, user time, issue
/// 22), a trial costs 12 us on the triad and 220 us on the 12-marker satellite (every estimator
/// plus the bound check), so 10^7 trials are 2 and 37 CPU minutes. A mistyped 10^15 would run
/// for years.
constexpr long kMaxTrials = 10'000'000;
/// `simulate --per-trial` and `--shard K/N`: the per-trial values of the trials held (one
/// shard's) are kept for the JSON, about 2.1 KB of memory per trial, and the JSON takes up to
/// 1.44 KB per trial (7 estimators on a pinhole camera): 40 000 trials keep a shard file under
/// the 64 MiB that --merge reads (and the memory under 100 MB).
constexpr long kMaxPerTrialTrials = 40'000;

/// `crb --sweep-distance D1:D2:N` (and `plot --crb`): N, the distances, one CRB map each. A map of
/// the 12-corner AprilTag cube at the default 10 000 samples costs 28 ms of CPU (it grows with
/// --samples and the markers): 1000 distances 28 s, where the 1:2:1000000 ran for hours.
constexpr long kMaxCrbSweepDistances = 1000;
/// `crb --sweep-tags`: the tilings, the --tags-per-side values times the --tag-fill values, one
/// CRB map each. The costliest tiling (the cube's 3 faces at 12 x 12 tags, 1728 corners) takes
/// 0.6 s of CPU and 58 MB: 50 tilings about 30 s (the design budget); the default 8 take 1 s.
/// The largest --tags-per-side is camera::TagSweepOptions::kMaxPerSide (a library rule).
constexpr long kMaxTagSweepRows = 50;
/// `tre --monte-carlo`: trials per target. Streamed (flat memory, 16 MB); a trial of the 4-marker
/// NDI-like tool costs 0.67 us of CPU (one registration; more with more markers): 10^7 trials are
/// 6.7 s and measure the RMS to about 0.02 %, where 10^9 ran for 11 minutes.
constexpr long kMaxTreTrials = 10'000'000;
/// `ident`: tools. Every pair is matched and reported: n (n + 1) / 2 pairs, about 180 bytes of
/// memory and 580 bytes of JSON each in the CLI, 4 us of CPU for 4-marker tools (more with more
/// markers, up to the search budget), and about 3.5 KB each as Python objects. Random 4-marker
/// tools: 500 tools (125 250 pairs) take 1.1 s, 38 MB and write 73 MB of JSON, Python 4 s and
/// 470 MB; 1000 tools 5 s and 100 MB, Python 18 s and 1.75 GB; 2000 tools 25 s, 360 MB, 1.2 GB
/// of JSON.
constexpr long kMaxIdentTools = 500;

/// How a front end names its commands and the switch that lifts the limits in its messages:
/// {"`vantage ", "`", "--allow-large"} for the CLI, {"vantage.", "()", "allow_large=True"} for
/// Python.
struct LimitWords {
  std::string command_prefix;
  std::string command_suffix;
  std::string lift;
};

/// Throws InvalidArgument "<what>: <count> exceeds the limit of <limit> for <command> (<lift>
/// lifts it)" when count > limit and not allow_large.
void check_limit(const std::string& what, long count, long limit, const std::string& command,
                 bool allow_large, const LimitWords& words);

/// The number of data vectors a layout gives: its vectors, or n (n - 1) / 2 for n points.
long data_vector_count(const Layout& layout);

/// The CPU seconds design (augment_layout) is expected to take for `add` additions to `layout`
/// (the model and its measurements: kMaxDesignSeconds above): add * (step + per_vector * m) with
/// m the data vectors after the additions; no fixed step cost with candidates_only; a search
/// budget above the default (AugmentOptions::search_budget) adds its solve-vectors' time.
double estimated_design_seconds(const Layout& layout, int add, bool candidates_only,
                                long search_budget);

/// Throws InvalidArgument "<what>: about <seconds> s of CPU exceeds the budget of <limit> s for
/// <command> (README "Limits"; <lift> lifts it)" when seconds > limit and not allow_large.
void check_time_limit(const std::string& what, double seconds, double limit,
                      const std::string& command, bool allow_large, const LimitWords& words);

}  // namespace vantage::commands
