#include "vantage/io/apriltag_bundle.h"

#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "entry_labels.h"
#include "json_fields.h"
#include "vantage/analysis/common.h"
#include "vantage/io/printable.h"

namespace vantage::io {

namespace {

using internal::fail;

// A missing bundle's error lists at most this many of the file's bundle names.
constexpr std::size_t kListedBundles = 10;
// A quaternion shorter than this cannot be normalised into a rotation meaningfully.
constexpr double kMinQuaternionNorm = 1e-12;

YAML::Node parse_yaml(std::string_view text, const std::string& source) {
  try {
    return YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    // yaml-cpp may quote the offending character raw (a newline after a NUL, say): fail() makes
    // the message printable.
    fail(source, "not valid YAML: line " + std::to_string(e.mark.line + 1) + ", column " +
                     std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
}

// The fields each map of tags.yaml may hold (apriltag_ros): anything else is an error, as an
// unknown field of a JSON layout is.
const std::vector<std::string> kRootFields = {"standalone_tags", "tag_bundles"};
const std::vector<std::string> kBundleFields = {"name", "layout"};
const std::vector<std::string> kTagFields = {"id", "size", "x", "y", "z", "qw", "qx", "qy", "qz"};

std::string key_text(const YAML::Node& key) { return key.IsScalar() ? key.Scalar() : ""; }

// Every map of the document, anywhere (standalone_tags too), has each key once: yaml-cpp keeps
// duplicates and operator[] returns the first, so {x: 0.05, x: 9} would be read as x = 0.05.
// Nodes reached again through an alias (the same start position) are checked once, so the walk
// stays linear in the text.
void reject_duplicate_keys(const YAML::Node& node, const std::string& path,
                           const std::string& source, std::set<int>* visited) {
  if (!node.IsMap() && !node.IsSequence()) return;
  if (node.Mark().pos >= 0 && !visited->insert(node.Mark().pos).second) return;
  if (node.IsSequence()) {
    for (std::size_t k = 0; k < node.size(); ++k) {
      reject_duplicate_keys(node[k], path + "[" + std::to_string(k) + "]", source, visited);
    }
    return;
  }
  std::set<std::string> keys;
  for (const auto& entry : node) {
    const std::string name = key_text(entry.first);
    const std::string field = (path.empty() ? "" : path + ".") + name;
    if (!entry.first.IsScalar()) {
      fail(source, (path.empty() ? std::string("top level") : path) +
                       ": a key is not a field name (a scalar)");
    }
    if (!keys.insert(name).second) {
      fail(source, field + ": duplicate key (each field may appear once)");
    }
    reject_duplicate_keys(entry.second, field, source, visited);
  }
}

void reject_unknown_fields(const YAML::Node& map, const std::string& where,
                           const std::string& source, const std::vector<std::string>& allowed) {
  for (const auto& entry : map) {
    const std::string name = key_text(entry.first);
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
      std::string list;
      for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
      fail(source, (where.empty() ? "" : where + ": ") + "unknown field \"" + excerpt(name) +
                       "\" (expected " + list + ")");
    }
  }
}

double read_number(const YAML::Node& tag, const std::string& source, const std::string& where,
                   const char* field) {
  const YAML::Node value = tag[field];
  if (!value) fail(source, where + ": missing field \"" + field + "\"");
  double x = 0;
  if (!value.IsScalar() || !YAML::convert<double>::decode(value, x) || !std::isfinite(x)) {
    fail(source, where + "." + field + ": expected a finite number");
  }
  return x;
}

/// The index of the bundle to read.
std::size_t choose_bundle(const YAML::Node& bundles, const std::string& source,
                          const std::string& wanted) {
  std::string names;
  for (std::size_t b = 0; b < bundles.size(); ++b) {
    const YAML::Node name = bundles[b].IsMap() ? bundles[b]["name"] : YAML::Node();
    const std::string text = name && name.IsScalar() ? name.Scalar() : "";
    if (!wanted.empty() && text == wanted) return b;
    if (b < kListedBundles) {
      names += (b ? ", " : "") +
               (text.empty() ? "tag_bundles[" + std::to_string(b) + "]" : excerpt(text));
    }
  }
  if (bundles.size() > kListedBundles) {
    names += ", and " + std::to_string(bundles.size() - kListedBundles) + " more";
  }
  if (wanted.empty() && bundles.size() == 1) return 0;
  if (wanted.empty()) {
    fail(source, "tag_bundles: " + std::to_string(bundles.size()) +
                     " bundles; choose one with --bundle (" + names + ")");
  }
  fail(source, "tag_bundles: no bundle named \"" + excerpt(wanted) + "\" (" + names + ")");
}

}  // namespace

TagPoints tag_points_from_string(const std::string& name, const std::string& option) {
  if (name == "corners") return TagPoints::kCorners;
  if (name == "centres" || name == "centers") return TagPoints::kCentres;
  throw InvalidArgument(option + ": expected corners or centres, got \"" + excerpt(name) + "\"");
}

namespace {

/// The bundle read (options.bundle, or the only one) of the YAML text, checked down to its
/// "layout" list; *prefix is its path, "tag_bundles[b]".
YAML::Node chosen_bundle(std::string_view text, const std::string& source,
                         const AprilTagOptions& options, std::string* prefix) {
  const YAML::Node root = parse_yaml(text, source);
  if (!root.IsMap()) fail(source, "the top level must be a YAML map with \"tag_bundles\"");
  std::set<int> visited;
  reject_duplicate_keys(root, "", source, &visited);
  reject_unknown_fields(root, "", source, kRootFields);
  const YAML::Node bundles = root["tag_bundles"];
  if (!bundles) fail(source, "tag_bundles: missing (the tags.yaml of apriltag_ros)");
  if (!bundles.IsSequence() || bundles.size() == 0) {
    fail(source, "tag_bundles: expected a non-empty list of bundles");
  }
  const std::size_t b = choose_bundle(bundles, source, options.bundle);
  *prefix = "tag_bundles[" + std::to_string(b) + "]";
  const YAML::Node bundle = bundles[b];
  if (!bundle.IsMap()) fail(source, *prefix + ": expected a map with name and layout");
  reject_unknown_fields(bundle, *prefix, source, kBundleFields);
  const YAML::Node tags = bundle["layout"];
  if (!tags || !tags.IsSequence()) fail(source, *prefix + ".layout: expected a list of tags");
  return bundle;
}

/// One tag of the bundle: its id (unique: seen maps each id to its index), size and pose.
struct TagPose {
  long id = 0;
  double size = 0;
  Eigen::Vector3d p_bundle_tag;
  Eigen::Matrix3d R_bundle_tag;
};

TagPose read_tag(const YAML::Node& tag, std::size_t k, const std::string& source,
                 const std::string& where, std::map<long, std::size_t>* seen) {
  if (!tag.IsMap()) fail(source, where + ": expected a map {id, size, x, y, z, qw, qx, qy, qz}");
  reject_unknown_fields(tag, where, source, kTagFields);
  const double id_value = read_number(tag, source, where, "id");
  if (id_value < 0 || id_value != std::floor(id_value) || id_value > 1e9) {
    fail(source, where + ".id: expected a non-negative integer");
  }
  const long id = static_cast<long>(id_value);
  const auto [previous, inserted] = seen->emplace(id, k);
  if (!inserted) {
    fail(source, where + ".id: tag " + std::to_string(id) + " repeats layout[" +
                     std::to_string(previous->second) + "]");
  }
  const double size = read_number(tag, source, where, "size");
  if (size <= 0) fail(source, where + ".size: must be > 0");
  const Eigen::Vector3d p(read_number(tag, source, where, "x"),
                          read_number(tag, source, where, "y"),
                          read_number(tag, source, where, "z"));
  Eigen::Quaterniond q(read_number(tag, source, where, "qw"), read_number(tag, source, where, "qx"),
                       read_number(tag, source, where, "qy"),
                       read_number(tag, source, where, "qz"));
  if (!(q.norm() >= kMinQuaternionNorm)) fail(source, where + ".qw: zero quaternion");
  return {id, size, p, q.normalized().toRotationMatrix()};
}

AprilTagMarkers read_markers(std::string_view text, const std::string& source,
                             const AprilTagOptions& options) {
  std::string prefix;
  const YAML::Node bundle = chosen_bundle(text, source, options, &prefix);
  const YAML::Node tags = bundle["layout"];

  const bool corners = options.tag_points == TagPoints::kCorners;
  const int per_tag = corners ? 4 : 1;
  AprilTagMarkers out;
  Layout& layout = out.layout;
  const YAML::Node name = bundle["name"];
  layout.name = name && name.IsScalar() ? name.Scalar() : "";
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, static_cast<Eigen::Index>(tags.size() * per_tag));
  layout.candidates.resize(3, 0);
  Eigen::Matrix3Xd normals(3, layout.entries.cols());
  std::vector<std::string> labels;
  std::map<long, std::size_t> seen;
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const std::string where = prefix + ".layout[" + std::to_string(k) + "]";
    const TagPose pose = read_tag(tags[k], k, source, where, &seen);
    const long id = pose.id;
    const Eigen::Vector3d& p = pose.p_bundle_tag;
    const Eigen::Matrix3d& R_bundle_tag = pose.R_bundle_tag;
    const double size = pose.size;
    const double s = size / 2;
    const Eigen::Vector3d corner_tag[4] = {{-s, -s, 0}, {s, -s, 0}, {s, s, 0}, {-s, s, 0}};
    for (int c = 0; c < per_tag; ++c) {
      const Eigen::Index j = static_cast<Eigen::Index>(k) * per_tag + c;
      layout.entries.col(j) = corners ? Eigen::Vector3d(R_bundle_tag * corner_tag[c] + p) : p;
      normals.col(j) = unit_normal(R_bundle_tag.col(2).normalized());
      out.tag_ids.push_back(static_cast<int>(id));
      out.corners.push_back(corners ? c : -1);
      layout.names.push_back("tag" + std::to_string(id) +
                             (corners ? "_c" + std::to_string(c) : std::string()));
      labels.push_back(where + " (tag " + std::to_string(id) +
                       (corners ? ", corner " + std::to_string(c) : std::string()) + ")");
    }
  }
  layout.weights = Eigen::VectorXd::Ones(layout.entries.cols());
  // A printed tag is seen from in front of its face only: its +z axis, the half-space in front.
  MarkerVisibility visibility;
  visibility.normals = normals;
  visibility.cone_half_angle_deg =
      Eigen::VectorXd::Constant(normals.cols(), MarkerVisibility::kDefaultConeDeg);
  layout.visibility = visibility;
  internal::validate_labelled(layout, source, labels);
  return out;
}

}  // namespace

AprilTagMarkers parse_apriltag_markers(std::string_view text, const std::string& source,
                                       const AprilTagOptions& options) {
  try {
    return read_markers(text, source, options);
  } catch (const YAML::Exception& e) {
    fail(source, std::string("unexpected YAML structure: ") + e.what());
  }
}

Layout parse_apriltag_layout(std::string_view text, const std::string& source,
                             const AprilTagOptions& options) {
  return parse_apriltag_markers(text, source, options).layout;
}

}  // namespace vantage::io
