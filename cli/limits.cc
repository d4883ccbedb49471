#include "limits.h"

namespace vantage::cli {

namespace {

const commands::LimitWords kCommandLine{"`vantage ", "`", "--allow-large"};

}  // namespace

void add_allow_large_flag(CLI::App* sub, bool& flag) {
  sub->add_flag("--allow-large", flag,
                "lift the size limits (README \"Limits\"): more data vectors, larger --add, input "
                "files up to 1 GiB; may take long and much memory");
}

void check_limit(const std::string& what, long count, long limit, const std::string& command,
                 bool allow_large) {
  commands::check_limit(what, count, limit, command, allow_large, kCommandLine);
}

void check_time_limit(const std::string& what, double seconds, double limit,
                      const std::string& command, bool allow_large) {
  commands::check_time_limit(what, seconds, limit, command, allow_large, kCommandLine);
}

}  // namespace vantage::cli
