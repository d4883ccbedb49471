#include "vantage/analysis/common.h"

#include <sstream>
#include <utility>

namespace vantage {

InvalidArgument::InvalidArgument(std::string field, std::string problem)
    : InvalidArgument({}, std::move(field), std::nullopt, std::move(problem)) {}

InvalidArgument::InvalidArgument(std::string field, long index, std::string problem)
    : InvalidArgument({}, std::move(field), index, std::move(problem)) {}

InvalidArgument::InvalidArgument(std::string problem)
    : InvalidArgument({}, {}, std::nullopt, std::move(problem)) {}

InvalidArgument::InvalidArgument(std::string field, long index, std::string problem,
                                 std::string related, long related_index)
    : InvalidArgument({}, std::move(field), index, std::move(problem), std::move(related),
                      related_index) {}

InvalidArgument::InvalidArgument(std::string source, std::string field, std::optional<long> index,
                                 std::string problem, std::string related,
                                 std::optional<long> related_index)
    : std::invalid_argument(compose(source, field, index, problem, related, related_index)),
      source_(std::move(source)),
      field_(std::move(field)),
      index_(index),
      problem_(std::move(problem)),
      related_(std::move(related)),
      related_index_(related_index) {}

std::string InvalidArgument::compose(const std::string& source, const std::string& field,
                                     std::optional<long> index, const std::string& problem,
                                     const std::string& related,
                                     std::optional<long> related_index) {
  std::string out;
  if (!source.empty()) out += source + ": ";
  if (!field.empty()) {
    out += field;
    if (index) out += "[" + std::to_string(*index) + "]";
    out += ": ";
  }
  out += problem;
  if (!related.empty()) {
    out += " " + related;
    if (related_index) out += "[" + std::to_string(*related_index) + "]";
  }
  return out;
}

InvalidArgument InvalidArgument::against(const std::string& source) const {
  if (!source_.empty()) return *this;
  return InvalidArgument(source, field_, index_, problem_, related_, related_index_);
}

InvalidArgument InvalidArgument::renamed(std::string field, std::optional<long> index) const {
  return InvalidArgument(source_, std::move(field), index, problem_, related_, related_index_);
}

}  // namespace vantage

namespace vantage::internal {

void throw_check_failure(const char* condition, const char* file, int line,
                         const std::string& message) {
  std::ostringstream out;
  out << "internal check failed: " << condition << " at " << file << ":" << line;
  if (!message.empty()) out << ": " << message;
  throw InternalError(out.str());
}

}  // namespace vantage::internal
