#pragma once

/// Reading marker sets from CSV, the format every motion-capture tool exports:
///
///   # optional comment lines start with '#'
///   name,x,y,z,weight            <- optional header: a first row none of whose cells after the
///                                   name holds a value (a number, NaN, Inf, empty, n/a, ...)
///   LED1,0.10,0.00,0.25,1
///   LED2,-0.10,0.05,0.25         <- weight column optional; all rows have the same columns
///
/// The result is a point-mode layout (markers, Layout::names the name column), weights 1 where
/// the column is absent. Fields are
/// separated by commas, surrounding blanks and double quotes are stripped, blank lines and a
/// UTF-8 byte-order mark are ignored. Every error is one line
/// "<source>: line <n> (<name>), <column>: <problem>" in a vantage::InvalidArgument.

#include <string>
#include <string_view>
#include <vector>

#include "vantage/analysis/layout.h"

namespace vantage::io {

/// A CSV marker set: the layout and the name of each marker (in column order of `entries`;
/// the same as layout.names).
struct CsvMarkers {
  Layout layout;
  std::vector<std::string> names;
};

/// Parses CSV text; `source` names it in errors and (its file stem) becomes the layout name.
/// Throws InvalidArgument for rows with 3 or more than 5 fields, rows whose field count differs
/// from the first row, empty names, repeated names, non-numbers, NaN/Inf, weights <= 0,
/// coincident markers and fewer than 3 markers (the checks of Layout::validate()).
CsvMarkers parse_csv_markers(std::string_view text, const std::string& source);

/// The layout of parse_csv_markers().
Layout parse_csv_layout(std::string_view text, const std::string& source);

/// The layout as CSV text that parse_csv_markers() reads back to the same markers, names and
/// weights: a header "name,x,y,z,weight", then one row per marker, each number in the fewest
/// of 15 to 17 significant digits that read back exactly; the layout's name and description go into
/// leading '#' comment lines (the reader names a CSV layout after its file). An unnamed layout's
/// markers are written as p0, p1, ... (Layout::entry_name). Throws InvalidArgument for what CSV
/// cannot hold: a direction-mode layout ("vectors"), candidates, a name with a comma, a double
/// quote, a line break, surrounding blanks or a leading '#' ("names[i]: ..."); and for an invalid
/// layout.
std::string layout_to_csv(const Layout& layout);

}  // namespace vantage::io
