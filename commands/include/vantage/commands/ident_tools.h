#pragma once

// The tools of `vantage ident` and Python's vantage.ident: files and folders of tool files, and
// each tool's own minimum markers (docs/math.md §24), one rule for both front ends.

#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/io/layout_formats.h"

namespace vantage::commands {

/// The tool files of `paths`, in order: a file as given; a folder's files whose extension names
/// a tool format (.json, .csv, .ini, .rom; case-insensitive), sorted by name, not recursing.
/// Throws InvalidArgument "<folder>: holds no tool files (.json, .csv, .ini, .rom)" for a
/// folder without one.
std::vector<std::string> tool_files(const std::vector<std::string>& paths);

/// The markers a tracker needs in view to report a tool given as a layout: its
/// visibility.min_visible, else 3 (a 3-D registration's least).
int own_min_visible(const Layout& tool);

/// A tool file as `vantage ident` and vantage.ident read it.
struct IdentTool {
  Layout layout;
  /// Its own minimum markers: a .rom's (byte 32, io::ndi_rom_min_markers, with or without
  /// normals), else own_min_visible(layout).
  int min_visible = 3;
};

/// Reads the tool file at `path` once (io::load_layout's reading, with `options`; kAuto: the
/// format its extension names), and its own minimum. Throws what load_layout throws, and
/// io::ndi_rom_min_markers' error for a .rom.
IdentTool read_ident_tool(const std::string& path, const io::LayoutReadOptions& options);

}  // namespace vantage::commands
