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
  /// Two tools with as many markers are one tool (or mirror images) when their whole marker
  /// sets match within this largest distance error, in the tools' units (mm for a tracker's
  /// tools: 0.01 mm is far above the float32 rounding of a .rom and below any machining step),
  /// >= 0. Used by match_tool_library()'s verdicts.
  double same_tolerance = 0.01;

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
  /// What the two files are (docs/math.md §24, "Verdicts").
  enum class Verdict {
    kSelf,      ///< a == b: the tool against itself relabelled
    kSameTool,  ///< as many markers, and a labelling of all of them (distances within
                ///< same_tolerance) fits by a rotation with an RMS residual within it
    kMirror,    ///< as many markers, and such a labelling fits only by a reflection
    kDistinct,  ///< anything else (a tracker may still confuse them: see the mismatch)
  };
  int a = 0;
  int b = 0;
  int min_visible = 3;  ///< k of this match: the smaller of the two tools' own
  ToolMatch match;
  Verdict verdict = Verdict::kDistinct;
};

/// "self", "same_tool", "mirror" or "distinct".
const char* to_string(ToolPairMatch::Verdict verdict);

/// Every pair of a tool library (`vantage ident`).
struct ToolLibraryMatches {
  std::vector<int> min_visible;  ///< k of each tool (a pair's k is the smaller of its two)
  /// (0,0), (0,1), ..., (0,n-1), (1,1), ...: each unordered pair once (m(A, B) = m(B, A)).
  std::vector<ToolPairMatch> pairs;
  int closest = -1;  ///< index into pairs of the smallest mismatch (the first such)
  /// The same, over pairs of two different files whose verdict is kDistinct (-1: none); the
  /// pair a designer must keep apart.
  int closest_distinct = -1;
  /// Every pair's search, and every verdict's enumeration of labellings, ended within its
  /// budget (options.max_comparisons).
  bool certified = false;

  /// The n x n matrix of mismatches: (a, b) and (b, a) the pair's, (a, a) the self-ambiguity.
  Eigen::MatrixXd mismatch_matrix() const;
};

/// match_tools() for every two tools and self_ambiguity() for each (docs/math.md §24), with the
/// verdict of each pair. Tool t is seen in views of `min_visible[t]` markers (its own minimum,
/// e.g. a .rom's "minimum markers"; every one options.min_visible when empty), and a pair in
/// views of the smaller of its two: a tracker that needs k_B markers of B can take k_B markers
/// of A for B, and m_k only falls as k does. Throws InvalidArgument ("tools[i]": fewer markers
/// than its min_visible or non-finite; "tools": empty; "min_visible": not one per tool or an
/// entry below 2; "options.*").
ToolLibraryMatches match_tool_library(const std::vector<Eigen::Matrix3Xd>& tools,
                                      const ToolMatchOptions& options = {},
                                      const std::vector<int>& min_visible = {});

}  // namespace vantage::tracker
