#pragma once

// `vantage layout convert IN --out OUT`: one layout file in another format; `vantage layout
// snap LAYOUT --out OUT`: its markers moved onto the surface of their body.

#include <CLI/CLI.hpp>

#include "command.h"

namespace vantage::cli {

/// Registers `convert` under the `layout` command; its run() converts.
Command add_layout_convert_subcommand(CLI::App* layout);

/// Registers `snap` under the `layout` command (layout_snap.cc); its run() snaps.
Command add_layout_snap_subcommand(CLI::App* layout);

}  // namespace vantage::cli
