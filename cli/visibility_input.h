#pragma once

// The options that put a layout on its body (VisibilityOptions,
// vantage/commands/visibility_options.h) as flags of a subcommand; LayoutInput registers and
// applies them.

#include <CLI/CLI.hpp>

#include "vantage/commands/visibility_options.h"

namespace vantage::cli {

struct VisibilityInput : commands::VisibilityOptions {
  void add_options(CLI::App* sub);
};

}  // namespace vantage::cli
