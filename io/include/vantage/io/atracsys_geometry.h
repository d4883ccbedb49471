#pragma once

/// Atracsys fusionTrack / spryTrack marker geometry files (geometryNNN.ini), as the fusionTrack
/// user manual (v4.5.2, section 7.7 "Marker geometry files") describes them:
///
///   ; a comment: ';' as the first character of the line
///   [geometry]
///   count=4          <- the number of fiducials, 3 to 6
///   id=150           <- the geometry's unique id (> 100 for custom markers; smaller ones are
///                       the built-in markers')
///   [fiducial0]      <- one section per fiducial, fiducial0 .. fiducial<count - 1>
///   x=0.0            <- its position in mm, in the marker's frame (any origin)
///   y=0.0
///   z=0.0
///   ...
///   [pivot]          <- optional: the tool's tip (the pivot point), in mm; used by the Atracsys
///   x=0              <- wrappers (sawAtracsysFusionTrack, atracsyswrapper), ignored by the SDK
///   y=0
///   z=-150
///
/// The manual lets a file carry additional sections and keys, which the SDK ignores; so does
/// this reader, except for a [fiducialK] section with K >= count (a fiducial the SDK would not
/// read: almost surely a count that was not updated). Blanks around names, keys and values, a
/// UTF-8 byte-order mark and CR-LF line ends are allowed. A repeated section or key is an error
/// (the SDK's reader keeps the last one silently). Every error is one line
/// "<source>: line <n>, [<section>] <key>: <problem>" (or "<source>: [<section>]: ..." for what
/// is missing) in a vantage::InvalidArgument.
///
/// The format holds no normals, weights, marker names or units other than mm.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vantage/analysis/layout.h"

namespace vantage::io {

/// Fiducials a geometry file holds (the manual's bounds on `count`).
constexpr int kAtracsysMinFiducials = 3;
constexpr int kAtracsysMaxFiducials = 6;

/// One geometry file: the point-mode layout of its fiducials (mm, weights 1, named "fiducial0",
/// "fiducial1", ..., the layout named after the file's stem), the geometry id and the pivot.
/// A Layout has no place for the id or the pivot, so parse_layout_as() and load_layout() drop
/// them; parse_atracsys_geometry() keeps them.
struct AtracsysGeometry {
  Layout layout;
  std::uint32_t id = 0;
  std::optional<Eigen::Vector3d> pivot;
};

/// Parses geometry-file text; `source` names it in errors (its stem becomes the layout's name).
/// Throws InvalidArgument for a line that is neither a [section], a key=value pair, a ';'
/// comment nor blank; a key before the first section; a repeated section or key; no [geometry]
/// section; a count that is not an integer in [3, 6]; an id that is not an integer in
/// [0, 2^32 - 1]; a missing [fiducialK] (K < count) or [fiducialK] with K >= count; a missing
/// x, y or z of a fiducial or of [pivot]; a coordinate that is not a finite number; and the
/// checks of Layout::validate() (coincident fiducials).
AtracsysGeometry parse_atracsys_geometry(std::string_view text, const std::string& source);

/// The layout of parse_atracsys_geometry().
Layout parse_atracsys_layout(std::string_view text, const std::string& source);

/// The fields of `layout` a geometry file cannot hold and layout_to_atracsys_geometry() leaves
/// out, by their layout-file names: "names" (when some name is not "fiducial<k>"), "weights"
/// (when some weight is not 1), "normals" and "visibility" (cones, min_visible, body),
/// "workspace", "description". Empty when the file holds the whole layout.
std::vector<std::string> atracsys_dropped_fields(const Layout& layout);

/// The layout as geometry-file text that parse_atracsys_geometry() reads back to the same
/// positions bit for bit (each coordinate in the fewest of 15 to 17 significant digits that
/// read back exactly), with [geometry] id=`id` and, when given, the [pivot]. The layout's name
/// goes into a leading ';' comment line. The coordinates are written as they are: the layout's
/// unit is taken to be mm. What the format cannot hold (atracsys_dropped_fields()) is left out.
/// Throws InvalidArgument for a direction-mode layout ("vectors"), candidates, fewer than 3 or
/// more than 6 markers ("points"), a non-finite pivot, and for an invalid layout.
std::string layout_to_atracsys_geometry(const Layout& layout, std::uint32_t id,
                                        const std::optional<Eigen::Vector3d>& pivot = {});

/// The geometry id a file written to `path` gets: the decimal number that ends the file's stem,
/// as the manual names geometry files geometry<id>.ini ("geometry150.ini" -> 150,
/// "probe_7.ini" -> 7). Throws InvalidArgument "<path>: ..." when the stem does not end in
/// digits or the number exceeds 2^32 - 1.
std::uint32_t atracsys_geometry_id_of(const std::string& path);

}  // namespace vantage::io
