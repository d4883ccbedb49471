#pragma once

// Shared by `vantage plot` and `vantage design --plot`: the checks on a figure directory that
// run before any work (so that bad input writes nothing), its creation, and the figure list as
// JSON and as text.

#include <string>
#include <vector>

#include "command.h"
#include "vantage/plot/figure.h"

namespace vantage::cli {

/// Throws InvalidArgument "<option>: ..." when `directory` exists and is not a writable
/// directory, or does not exist and cannot be created (its nearest existing ancestor is not a
/// writable directory). Writes nothing.
void check_figure_directory(const std::string& option, const std::string& directory);

/// Creates `directory` (and missing parents). Throws InvalidArgument "<option>: ..." on failure.
void create_figure_directory(const std::string& option, const std::string& directory);

/// [{"name", "image", "csv"}, ...]
Json figure_files_json(const std::vector<plot::FigureFiles>& files);

/// "N figures written (png + csv):" and each figure's image and CSV, one per line, on stdout.
void print_figure_files(const std::vector<plot::FigureFiles>& files, plot::Format format);

}  // namespace vantage::cli
