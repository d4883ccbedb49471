#pragma once

/// Reading and writing layout files (JSON, README.md "File formats"):
///
///   {"name": "orthogonal triad",
///    "vectors": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],      // or "points": [[x, y, z], ...]
///    "names": ["x", "y", "z"],                           // optional, one per entry
///    "weights": [1, 1, 1],                               // optional, default all 1
///    "candidates": [[0.5, 0.5, 0.7]]}                    // optional
///
/// Every error is one line "<source>: <field>[<index>]: <problem>" in a vantage::InvalidArgument.

#include <string>
#include <string_view>

#include "vantage/analysis/layout.h"
#include "vantage/io/text_file.h"

namespace vantage::io {

/// Parses the JSON text of a layout; `source` names it in error messages (usually the path).
/// Accepted top-level fields: name, description, vectors | points, names, weights, candidates.
/// Throws InvalidArgument for text that is not JSON, a root that is not an object, unknown
/// fields, both or neither of vectors/points, wrong arity, non-numbers, NaN/Inf, zero-length
/// vectors, coincident points, weights of the wrong length or <= 0, fewer than 2 entries, names
/// that are not strings, not one per entry, empty or repeated.
Layout parse_layout(std::string_view text, const std::string& source);

/// Reads (at most `max_bytes`, see read_text_file) and parses the layout file at `path` (errors
/// name the path).
Layout read_layout(const std::string& path, std::size_t max_bytes = kMaxFileBytes);

/// The layout as JSON text in the file format (two-space indented, trailing newline); `names`
/// only when the layout has them.
std::string layout_to_json(const Layout& layout);

/// Writes the layout to `path` all or nothing (write_text_file). Refuses (InvalidArgument) to
/// replace an existing file unless `overwrite` is set. Validates the layout first, so nothing is
/// written for a bad layout.
void write_layout(const std::string& path, const Layout& layout, bool overwrite = false);

}  // namespace vantage::io
