// The tag sweep of the pose CRB (docs/math.md §22, "How many tags, and how big").

#include "vantage/camera/pose_crb_tags.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <regex>
#include <utility>

#include "vantage/analysis/common.h"

namespace vantage::camera {

namespace {

// Two tags share a face when their normals agree to this (n . n' >= 1 - it) and their planes
// are this fraction of the layout's radius apart at most.
constexpr double kSameNormal = 1e-9;
constexpr double kSamePlane = 1e-9;
// A tag's corners form a square when edges and right angles hold to this, relative to its side.
constexpr double kSquareTolerance = 1e-6;

struct TagCorners {
  Eigen::Matrix<double, 3, 4> corners;
  Eigen::Vector3d centre, x, y, n;
  int first_marker = 0;
};

TagCorners read_tag(const Layout& layout, int first) {
  TagCorners tag;
  tag.first_marker = first;
  tag.corners = layout.entries.middleCols<4>(first);
  tag.centre = tag.corners.rowwise().mean();
  const Eigen::Vector3d e01 = tag.corners.col(1) - tag.corners.col(0);
  const Eigen::Vector3d e03 = tag.corners.col(3) - tag.corners.col(0);
  const Eigen::Vector3d e02 = tag.corners.col(2) - tag.corners.col(0);
  const double side = e01.norm();
  const double tolerance = kSquareTolerance * side;
  if (!(side > 0.0) || std::abs(e03.norm() - side) > tolerance ||
      std::abs(e01.dot(e03)) > tolerance * side || (e02 - e01 - e03).norm() > tolerance) {
    throw InvalidArgument("points", first,
                          "tag corners c0..c3 are not a square (--sweep-tags needs AprilTag "
                          "corners in the reader's order)");
  }
  tag.x = e01 / side;
  tag.y = e03.normalized();
  tag.n = tag.x.cross(tag.y).normalized();
  return tag;
}

// "tag<id>_c<k>" with k the corner's place in its tag.
bool is_corner_name(const std::string& name, int corner, std::string* tag) {
  static const std::regex kCorner("(tag[0-9]+)_c([0-3])");
  std::smatch match;
  if (!std::regex_match(name, match, kCorner) || std::stoi(match[2]) != corner) return false;
  *tag = match[1];
  return true;
}

std::vector<TagCorners> read_tags(const Layout& layout) {
  const long n = layout.entries.cols();
  if (layout.mode != LayoutMode::kPoints || layout.names.size() != static_cast<std::size_t>(n) ||
      n % 4 != 0 || n == 0) {
    throw InvalidArgument("names",
                          "--sweep-tags needs AprilTag corners: markers named tag<id>_c0 .. "
                          "tag<id>_c3, four per tag (an AprilTag bundle read with --tag-points "
                          "corners)");
  }
  std::vector<TagCorners> tags;
  for (int first = 0; first < n; first += 4) {
    std::string id, same;
    for (int c = 0; c < 4; ++c) {
      if (!is_corner_name(layout.names[first + c], c, c == 0 ? &id : &same) ||
          (c > 0 && same != id)) {
        throw InvalidArgument("names", first + c,
                              "\"" + layout.names[first + c] + "\" is not corner " +
                                  std::to_string(c) + " of the tag of \"" + layout.names[first] +
                                  "\" (tag<id>_c0 .. _c3, in order)");
      }
    }
    tags.push_back(read_tag(layout, first));
  }
  return tags;
}

double radius_about_centroid(const Eigen::Matrix3Xd& points) {
  const Eigen::Vector3d g = points.rowwise().mean();
  return (points.colwise() - g).colwise().norm().maxCoeff();
}

// The smallest square aligned with the face's axes holding every corner of its tags.
void bound_face(const std::vector<TagCorners>& tags, const std::vector<int>& members,
                TagFace* face) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = -lo;
  const Eigen::Vector3d origin = tags[members.front()].centre;
  for (int t : members) {
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector3d d = tags[t].corners.col(c) - origin;
      const Eigen::Vector2d uv(d.dot(face->x_axis), d.dot(face->y_axis));
      lo = lo.cwiseMin(uv);
      hi = hi.cwiseMax(uv);
    }
  }
  const Eigen::Vector2d mid = (lo + hi) / 2.0;
  face->extent = (hi - lo).maxCoeff();
  face->centre = origin + mid.x() * face->x_axis + mid.y() * face->y_axis;
}

}  // namespace

std::vector<TagFace> tag_faces(const Layout& layout) {
  const std::vector<TagCorners> tags = read_tags(layout);
  const double plane_tolerance = kSamePlane * radius_about_centroid(layout.entries);
  std::vector<std::vector<int>> members;
  for (int t = 0; t < static_cast<int>(tags.size()); ++t) {
    auto same_face = [&](const std::vector<int>& face) {
      const TagCorners& first = tags[face.front()];
      return first.n.dot(tags[t].n) >= 1.0 - kSameNormal &&
             std::abs(first.n.dot(tags[t].centre - first.centre)) <= plane_tolerance;
    };
    auto found = std::find_if(members.begin(), members.end(), same_face);
    if (found == members.end()) {
      members.push_back({t});
    } else {
      found->push_back(t);
    }
  }
  std::vector<TagFace> faces;
  for (const std::vector<int>& face_tags : members) {
    const TagCorners& first = tags[face_tags.front()];
    TagFace face;
    face.x_axis = first.x;
    face.y_axis = first.n.cross(first.x);
    face.normal = first.n;
    face.first_marker = first.first_marker;
    face.tags = static_cast<int>(face_tags.size());
    bound_face(tags, face_tags, &face);
    faces.push_back(face);
  }
  return faces;
}

Layout tag_grid_layout(const Layout& layout, const std::vector<TagFace>& faces, int per_side,
                       double fill) {
  const long n = static_cast<long>(faces.size()) * per_side * per_side * 4;
  Layout out;
  out.name = layout.name;
  out.mode = LayoutMode::kPoints;
  out.entries.resize(3, n);
  out.weights = Eigen::VectorXd::Ones(n);
  out.workspace = layout.workspace;
  if (layout.visibility) {
    out.visibility = layout.visibility;
    out.visibility->normals.resize(3, n);
    out.visibility->cone_half_angle_deg.resize(n);
  }
  static const double kCornerSigns[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  long k = 0;
  int tag = 0;
  for (const TagFace& face : faces) {
    const double pitch = face.extent / per_side;
    const double half = fill * pitch / 2.0;
    for (int row = 0; row < per_side; ++row) {
      for (int col = 0; col < per_side; ++col, ++tag) {
        const Eigen::Vector3d centre = face.centre +
                                       ((col + 0.5) * pitch - face.extent / 2.0) * face.x_axis +
                                       ((row + 0.5) * pitch - face.extent / 2.0) * face.y_axis;
        for (int c = 0; c < 4; ++c, ++k) {
          out.entries.col(k) = centre + half * kCornerSigns[c][0] * face.x_axis +
                               half * kCornerSigns[c][1] * face.y_axis;
          out.names.push_back("tag" + std::to_string(tag) + "_c" + std::to_string(c));
          if (out.visibility) {
            out.visibility->normals.col(k) = face.normal;
            out.visibility->cone_half_angle_deg(k) =
                layout.visibility->cone_half_angle_deg(face.first_marker);
          }
        }
      }
    }
  }
  if (out.visibility) {
    out.visibility->min_visible = std::min<int>(layout.visibility->min_visible, n);
  }
  return out;
}

bool TagSweepOptions::is_valid(std::string* why) const {
  auto fail = [why](const std::string& message) {
    if (why != nullptr) *why = message;
    return false;
  };
  if (per_side.empty()) return fail("per_side: needs at least one count");
  for (int k : per_side) {
    if (k < 1 || k > kMaxPerSide) {
      return fail("per_side: each count must be in [1, " + std::to_string(kMaxPerSide) + "]");
    }
  }
  if (fill.empty()) return fail("fill: needs at least one fill");
  for (double f : fill) {
    if (!(f > 0.0 && f <= 1.0)) return fail("fill: each fill must be in (0, 1]");
  }
  const bool several = std::any_of(per_side.begin(), per_side.end(), [](int k) { return k > 1; });
  if (several && std::find(fill.begin(), fill.end(), 1.0) != fill.end()) {
    return fail("fill: 1 with more than one tag per side puts neighbouring tags' corners together");
  }
  return true;
}

std::vector<TagSweepRow> pose_crb_tag_sweep(const Layout& layout, const PoseCrbOptions& camera,
                                            const TagSweepOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) {
    throw InvalidArgument("sweep_tags." + why.substr(0, why.find(':')),
                          why.substr(why.find(':') + 2));
  }
  const std::vector<TagFace> faces = tag_faces(layout);
  double largest = 0.0;
  for (const TagFace& face : faces) largest = std::max(largest, face.extent);
  std::vector<TagSweepRow> rows;
  const std::size_t tilings = options.per_side.size() * options.fill.size();
  for (int k : options.per_side) {
    for (double fill : options.fill) {
      if (options.progress) {
        options.progress("tiling " + std::to_string(rows.size() + 1) + "/" +
                         std::to_string(tilings));
      }
      TagSweepRow row;
      row.per_side = k;
      row.tags = static_cast<int>(faces.size()) * k * k;
      row.fill = fill;
      row.tag_size = fill * largest / k;
      row.tag_pixels = row.tag_size * camera.focal_length / camera.distance;
      const PoseCrbModel model(tag_grid_layout(layout, faces, k, fill), camera);
      const PoseCrbMap map = pose_crb_map(model);
      row.status = map.status;
      row.trackable_fraction = map.trackable_fraction;
      row.unbounded_fraction = map.unbounded_fraction;
      if (map.status == PoseCrbMap::Status::kOk) {
        row.worst = map.worst;
        row.percentiles = map.percentiles;
        std::vector<const PoseCrbAt*> trackable;
        for (const PoseCrbAt& at : map.samples) {
          if (at.trackable) trackable.push_back(&at);
        }
        std::sort(trackable.begin(), trackable.end(), [](const PoseCrbAt* a, const PoseCrbAt* b) {
          return a->rot_rms_deg < b->rot_rms_deg;
        });
        row.median = *trackable[(trackable.size() - 1) / 2];
      }
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace vantage::camera
