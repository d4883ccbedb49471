#pragma once

/// Shared vocabulary of vantage: the error types, the invariant check and the one constant pi.
///
/// Three kinds of failure (STYLE.md 7):
///  - expected numerical outcomes (degenerate data, no convergence) are a Status in a result;
///  - bad caller input throws InvalidArgument "<arg>: <problem>" (see internal/checks.h);
///  - broken internal invariants throw vantage::InternalError through VANTAGE_CHECK, which stays
///    on in Release builds.

#include <optional>
#include <stdexcept>
#include <string>

namespace vantage {

/// pi, the one definition every module uses (docs/math.md §1).
inline constexpr double kPi = 3.14159265358979323846;
/// Degrees per radian: an angle in radians times this is in degrees.
inline constexpr double kDegreesPerRadian = 180.0 / kPi;

/// Thrown when a caller passes input that violates a documented precondition. The error is
/// data, not text to rewrite: which input (`source`: a file or "" when the caller's own
/// argument), which field of it (`field`: an argument, a file field such as "points" or an
/// option such as "--trials"; "" when none applies), which entry (`index`, or none) and what is
/// wrong (`problem`, a lower-case phrase). what() is "<source>: <field>[<index>]: <problem>",
/// the absent parts left out. A front end adds the source (against()) and prints what(): it
/// never parses or rewrites the text.
class InvalidArgument : public std::invalid_argument {
 public:
  /// "<field>: <problem>".
  InvalidArgument(std::string field, std::string problem);
  /// "<field>[<index>]: <problem>".
  InvalidArgument(std::string field, long index, std::string problem);
  /// A problem that names no field of its own (e.g. a whole-file error).
  explicit InvalidArgument(std::string problem);
  /// "<field>[<index>]: <problem> <related>[<related_index>]", e.g. "points[5]: coincides
  /// with points[2]": the problem relates two entries.
  InvalidArgument(std::string field, long index, std::string problem, std::string related,
                  long related_index);

  const std::string& source() const { return source_; }
  const std::string& field() const { return field_; }
  std::optional<long> index() const { return index_; }
  const std::string& problem() const { return problem_; }

  /// The same error against `source` (a file name): "<source>: ..." unless it has a source
  /// already, in which case it is returned unchanged.
  InvalidArgument against(const std::string& source) const;
  /// The same problem named as another field and index (e.g. the file's "points[3]" for the
  /// library's "vectors[7]").
  InvalidArgument renamed(std::string field, std::optional<long> index) const;
  /// The same error with entries named as a file names them: `label(field, index)` returns the
  /// file's name of an entry ("line 4 (m3)") or nullopt to keep "<field>[<index>]"; applied to
  /// the field and to the related entry.
  template <typename Label>
  InvalidArgument labelled(Label&& label) const {
    InvalidArgument out = *this;
    if (index_) {
      if (std::optional<std::string> name = label(field_, *index_)) {
        out.field_ = *name;
        out.index_.reset();
      }
    }
    if (related_index_) {
      if (std::optional<std::string> name = label(related_, *related_index_)) {
        out.related_ = *name;
        out.related_index_.reset();
      }
    }
    return InvalidArgument(out.source_, out.field_, out.index_, out.problem_, out.related_,
                           out.related_index_);
  }

 private:
  InvalidArgument(std::string source, std::string field, std::optional<long> index,
                  std::string problem, std::string related = {},
                  std::optional<long> related_index = std::nullopt);
  static std::string compose(const std::string& source, const std::string& field,
                             std::optional<long> index, const std::string& problem,
                             const std::string& related, std::optional<long> related_index);

  std::string source_;
  std::string field_;
  std::optional<long> index_;
  std::string problem_;
  std::string related_;  ///< the other entry of a problem that relates two, or empty
  std::optional<long> related_index_;
};

/// Thrown when an internal invariant does not hold (a bug in vantage, not in the input).
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

namespace internal {
[[noreturn]] void throw_check_failure(const char* condition, const char* file, int line,
                                      const std::string& message);
}  // namespace internal

}  // namespace vantage

/// Invariant check that is never compiled out. Throws vantage::InternalError.
#define VANTAGE_CHECK(condition, message)                                                  \
  do {                                                                                     \
    if (!(condition)) {                                                                    \
      ::vantage::internal::throw_check_failure(#condition, __FILE__, __LINE__, (message)); \
    }                                                                                      \
  } while (false)
