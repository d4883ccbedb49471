#pragma once

// `vantage layout convert IN --out OUT`: one layout file in another format.

#include <CLI/CLI.hpp>

#include "command.h"

namespace vantage::cli {

/// Registers `convert` under the `layout` command; its run() converts.
Command add_layout_convert_subcommand(CLI::App* layout);

}  // namespace vantage::cli
