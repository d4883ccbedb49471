#pragma once

/// Reading the `tag_bundles` of the ROS AprilTag detector's tags.yaml (apriltag_ros):
///
///   tag_bundles:
///     [ { name: 'board',
///         layout: [ {id: 0, size: 0.05, x: 0.0, y: 0.0, z: 0.0, qw: 1, qx: 0, qy: 0, qz: 0},
///                   {id: 1, size: 0.05, x: 0.1, y: 0.0, z: 0.0, qw: 1, qx: 0, qy: 0, qz: 0} ] } ]
///
/// Each tag's pose in the bundle frame is p_bundle = R(q) p_tag + (x, y, z), q = (qw, qx, qy, qz)
/// normalised. The tag frame has its origin at the tag centre and the tag in its z = 0 plane;
/// the corners are (-s, -s), (s, -s), (s, s), (-s, s) with s = size / 2, in this order (the
/// order apriltag_ros uses for its bundle PnP). Each marker's outward normal is its tag's +z
/// axis R(q) e_z, with a 90-degree cone (a printed tag is seen from in front of its face only;
/// docs/math.md §20). standalone_tags is allowed and not read. As in a
/// JSON layout, a key that appears twice in any map of the document, and an unknown field (at
/// the top level, in a bundle or in a tag), is an error. Every error is one line
/// "<source>: tag_bundles[b].layout[k].<field>: <problem>" in a vantage::InvalidArgument.

#include <string>
#include <string_view>
#include <vector>

#include "vantage/analysis/layout.h"

namespace vantage::io {

/// Which points of each tag become markers.
enum class TagPoints {
  kCorners,  ///< the four corners of every tag (what the detector measures)
  kCentres,  ///< one marker per tag, at its centre
};

/// "corners" | "centres" (also "centers"); throws InvalidArgument naming `option` otherwise.
TagPoints tag_points_from_string(const std::string& name, const std::string& option);

/// Options of the AprilTag bundle reader.
struct AprilTagOptions {
  TagPoints tag_points = TagPoints::kCorners;
  /// Name of the bundle to read; empty: the file must hold exactly one bundle.
  std::string bundle;
};

/// The markers of one tag bundle: the point-mode layout (named after the bundle, weights 1, each
/// marker named "tag<id>_c<corner>", or "tag<id>" for a centre) and for each marker the tag id
/// it belongs to and its corner (0-3; -1 for a centre).
struct AprilTagMarkers {
  Layout layout;
  std::vector<int> tag_ids;
  std::vector<int> corners;
};

/// Parses tags.yaml text. Throws InvalidArgument for text that is not YAML, no `tag_bundles`
/// list, no bundle named `options.bundle` (or several bundles and no name), a tag without one of
/// id, size, x, y, z, qw, qx, qy, qz, a field that is not a finite number, an id that is not a
/// non-negative integer or repeats, size <= 0, a zero quaternion, and for the layout the checks
/// of Layout::validate() (at least 3 markers, no coincident ones).
AprilTagMarkers parse_apriltag_markers(std::string_view text, const std::string& source,
                                       const AprilTagOptions& options = {});

/// The layout of parse_apriltag_markers().
Layout parse_apriltag_layout(std::string_view text, const std::string& source,
                             const AprilTagOptions& options = {});

}  // namespace vantage::io
