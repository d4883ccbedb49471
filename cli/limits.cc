#include "limits.h"

#include "vantage/io/layout_file.h"

namespace vantage::cli {

void add_allow_large_flag(CLI::App* sub, bool& flag) {
  sub->add_flag("--allow-large", flag,
                "lift the size limits (README \"Limits\"): more data vectors, larger --add, input "
                "files up to 1 GiB; may take long and much memory");
}

void check_limit(const std::string& what, long count, long limit, const std::string& command,
                 bool allow_large) {
  if (allow_large || count <= limit) return;
  throw InvalidArgument(what + ": " + std::to_string(count) + " exceeds the limit of " +
                        std::to_string(limit) + " for `vantage " + command +
                        "` (--allow-large lifts it)");
}

long data_vector_count(const Layout& layout) {
  const Eigen::Index n = layout.entries.cols();
  return static_cast<long>(layout.mode == LayoutMode::kPoints ? free_vector_count(n) : n);
}

}  // namespace vantage::cli
