#pragma once

// Markers grouped by their cones, shared by the branch and bounds of §20 (visibility) and §23
// (TRE): markers of one normal and one cone are seen together wherever the body does not hide
// them, and two cones whose hidden sides {a : n.a < cos theta} do not meet never hide both
// markers at one direction (docs/math.md §20, "Units").

#include <Eigen/Core>
#include <vector>

namespace vantage::visibility::internal {

/// The markers' cone classes (one normal and one cone, bit for bit) and which classes' hidden
/// sides do not meet.
class ConeClasses {
 public:
  ConeClasses(const Eigen::Matrix3Xd& normals, const Eigen::VectorXd& cos_cone);
  int of(int marker) const { return class_[static_cast<std::size_t>(marker)]; }
  bool hidden_apart(int a, int b) const {
    return apart_[static_cast<std::size_t>(a) * class_.size() + static_cast<std::size_t>(b)] != 0;
  }

 private:
  std::vector<int> class_;
  std::vector<char> apart_;
};

}  // namespace vantage::visibility::internal
