#pragma once

// The bounds every `vantage` subcommand checks before any work (README "Limits"): one line on
// stderr naming the bound and exit status 2; --allow-large lifts the soft bounds for a user who
// wants to wait (and has the memory), the hard bounds stay.

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>

#include "vantage/analysis/layout.h"
#include "vantage/io/text_file.h"

namespace vantage::cli {

/// Input file size: 64 MiB (about a million vectors); with --allow-large 1 GiB.
constexpr std::size_t kMaxFileBytes = io::kMaxFileBytes;
constexpr std::size_t kMaxFileBytesAllowLarge = std::size_t{1} << 30;

/// `analyze`: data vectors (vectors, or the n (n - 1) / 2 free vectors of n points: 200 points).
/// Measured on this machine (docs/benchmarks.md, issue 12 third pass): 5000 random vectors 0.14 s,
/// 20 000 vectors 1.3 s and 20 MB.
constexpr long kMaxAnalyzeVectors = 20000;
/// `analyze --dropout`: one global search per entry (marker or vector), so the bound on data
/// vectors stays where the single search's was: 1000 vectors take about 1000 searches of 15 ms.
constexpr long kMaxDropoutVectors = 1000;
/// `design`: data vectors after the additions (one --add step on 200 random vectors: 4.6 s CPU,
/// about 1700 global solves), and the additions themselves (--add 100 on the triad: 40 s).
constexpr long kMaxDesignVectors = 200;
constexpr int kMaxDesignAdd = 20;
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

/// Adds --allow-large to `sub`, storing into `flag`.
void add_allow_large_flag(CLI::App* sub, bool& flag);

/// Throws InvalidArgument "<what>: <count> exceeds the limit of <limit> for `vantage
/// <command>` (--allow-large lifts it)" when count > limit and not allow_large.
void check_limit(const std::string& what, long count, long limit, const std::string& command,
                 bool allow_large);

/// The number of data vectors a layout gives: its vectors, or n (n - 1) / 2 for n points.
long data_vector_count(const Layout& layout);

}  // namespace vantage::cli
