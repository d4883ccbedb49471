#pragma once

/// How close two tools come to each other by their inter-marker distances (docs/math.md §24,
/// Eq. 24.4): the largest distance error under which k visible markers of tool A pass for k
/// markers of tool B (`vantage ident`), and within one tool the self-ambiguity (a view of k
/// markers that could be labelled wrongly).
///
/// Tools are 3 x N point matrices in their own frames; numbers are in their (common) units.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace vantage::tracker {

/// Options of match_tools() and self_ambiguity().
struct ToolMatchOptions {
  int min_visible = 3;  ///< k: the markers a view holds, >= 2
  /// Budget of the branch and bound in distance comparisons (one per pair of a partial
  /// assignment), >= 1. About 0.5 s of CPU at 2 * 10^8.
  long max_comparisons = 200'000'000;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// The best match of k markers of A onto k markers of B.
struct ToolMatch {
  /// How the best match fits as a rigid motion.
  enum class Transform {
    kRotation,    ///< the proper fit's RMS is below the improper one's by more than the tie
    kReflection,  ///< the improper fit (det = -1) is better by more than the tie: a mirror match
    kEither,      ///< within the tie (1e-9 of the subset's RMS radius): the subset is coplanar
  };

  /// m(A, B) = min over k-subsets S of A and injective sigma: S -> B of
  /// max_{i<j in S} |d^A_ij - d^B_sigma(i)sigma(j)| (Eq. 24.4); exact when certified, else an
  /// upper bound (the best found).
  double mismatch = 0.0;
  /// A lower bound: mismatch when certified, else the least partial mismatch left unexplored.
  double mismatch_lower = 0.0;
  bool certified = false;  ///< the search ended within its budget
  /// S (markers of A, increasing) and sigma(S) (the markers of B they match, in S's order): the
  /// first minimiser in the search's lexicographic order.
  std::vector<int> subset;
  std::vector<int> assignment;
  /// RMS residuals of the best rigid fits of A's subset onto B's matched markers, by a rotation
  /// (det = +1) and by a reflection times a rotation (det = -1); translation fitted, no scale.
  double proper_rms = 0.0;
  double improper_rms = 0.0;
  Transform transform = Transform::kEither;
  long comparisons = 0;  ///< distance comparisons spent
};

/// "rotation", "reflection" or "either".
const char* to_string(ToolMatch::Transform transform);

/// Eq. (24.4) between tools A and B (each 3 x N, N >= options.min_visible, finite). m(A, B) =
/// m(B, A). Throws InvalidArgument ("a", "b": fewer markers than min_visible or non-finite;
/// "options.*") on bad input.
ToolMatch match_tools(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b,
                      const ToolMatchOptions& options = {});

/// Eq. (24.4) of A against itself over every sigma other than the inclusion of S (at least one
/// marker of S matched to another marker): the self-ambiguity of docs/math.md §24. Same
/// preconditions as match_tools() with b = a.
ToolMatch self_ambiguity(const Eigen::Matrix3Xd& a, const ToolMatchOptions& options = {});

/// One pair of a tool library: tools a <= b; a == b is the self-ambiguity of tool a.
struct ToolPairMatch {
  int a = 0;
  int b = 0;
  ToolMatch match;
};

/// Every pair of a tool library (`vantage ident`).
struct ToolLibraryMatches {
  int min_visible = 3;  ///< k of every match
  /// (0,0), (0,1), ..., (0,n-1), (1,1), ...: each unordered pair once (m(A, B) = m(B, A)).
  std::vector<ToolPairMatch> pairs;
  int closest = -1;        ///< index into pairs of the smallest mismatch (the first such)
  bool certified = false;  ///< every pair's search ended within its budget
};

/// match_tools() for every two tools and self_ambiguity() for each (docs/math.md §24). Throws
/// InvalidArgument ("tools[i]": fewer markers than min_visible or non-finite; "tools": empty;
/// "options.*").
ToolLibraryMatches match_tool_library(const std::vector<Eigen::Matrix3Xd>& tools,
                                      const ToolMatchOptions& options = {});

}  // namespace vantage::tracker
