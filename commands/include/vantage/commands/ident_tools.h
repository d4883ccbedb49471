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

/// The markers a tracker needs in view to report `tool`, read from `file` in `format`
/// (kAuto: by its extension): a .rom's minimum markers (byte 32, io::read_ndi_rom_min_markers,
/// with or without normals), else the layout's visibility.min_visible, else 3 (a 3-D
/// registration's least). Empty `file` (a tool given as a layout): the layout's.
int own_min_visible(const Layout& tool, const std::string& file, io::LayoutFormat format);

}  // namespace vantage::commands
