#pragma once

// The bounds every `vantage` subcommand checks before any work (README "Limits"): one line on
// stderr naming the bound and exit status 2; --allow-large lifts the soft bounds for a user who
// wants to wait (and has the memory), the hard bounds stay. The bounds themselves live once in
// vantage/commands/limits.h (the Python package checks the same ones); this file words them for
// the command line.

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>

#include "vantage/analysis/layout.h"
#include "vantage/commands/limits.h"
#include "vantage/io/text_file.h"

namespace vantage::cli {

/// Input file size: 64 MiB (about a million vectors); with --allow-large 1 GiB.
constexpr std::size_t kMaxFileBytes = io::kMaxFileBytes;
constexpr std::size_t kMaxFileBytesAllowLarge = io::kMaxFileBytesAllowLarge;

using commands::data_vector_count;
using commands::estimated_design_seconds;
using commands::kDesignDirectionSecondsPerVector;
using commands::kDesignPointSecondsPerVector;
using commands::kDesignPointStepSeconds;
using commands::kDesignSecondsPerSolveVector;
using commands::kMaxAnalyzeVectors;
using commands::kMaxCrbSweepDistances;
using commands::kMaxDesignSeconds;
using commands::kMaxDropoutVectors;
using commands::kMaxIdentTools;
using commands::kMaxPerTrialTrials;
using commands::kMaxTagSweepRows;
using commands::kMaxTreTrials;
using commands::kMaxTrials;
using commands::kMaxWeightsEntries;

/// Adds --allow-large to `sub`, storing into `flag`.
void add_allow_large_flag(CLI::App* sub, bool& flag);

/// Throws InvalidArgument "<what>: <count> exceeds the limit of <limit> for `vantage
/// <command>` (--allow-large lifts it)" when count > limit and not allow_large.
void check_limit(const std::string& what, long count, long limit, const std::string& command,
                 bool allow_large);

/// Throws InvalidArgument "<what>: about <seconds> s of CPU exceeds the budget of <limit> s for
/// `vantage <command>` (README "Limits"; --allow-large lifts it)" when seconds > limit and not
/// allow_large.
void check_time_limit(const std::string& what, double seconds, double limit,
                      const std::string& command, bool allow_large);

}  // namespace vantage::cli
