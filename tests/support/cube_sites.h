#pragma once

/// Sixteen candidate sites on a unit cube as a layout file's text, for the `vantage place` tests:
/// the centres and the quarter points of the faces (normals the faces'), less the bottom face's
/// last two; 150 degree cones, min_visible 3.

#include <nlohmann/json.hpp>
#include <string>

namespace vantage::testing {

inline std::string cube_sites() {
  nlohmann::json points = nlohmann::json::array(), normals = nlohmann::json::array();
  const double offsets[3][2] = {{0.0, 0.0}, {0.25, 0.1}, {-0.2, -0.25}};
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign : {1, -1}) {
      for (const auto& o : offsets) {
        if (points.size() == 16) break;
        double p[3], n[3] = {0, 0, 0};
        p[axis] = 0.5 * sign;
        p[(axis + 1) % 3] = o[0];
        p[(axis + 2) % 3] = o[1];
        n[axis] = sign;
        points.push_back({p[0], p[1], p[2]});
        normals.push_back({n[0], n[1], n[2]});
      }
    }
  }
  nlohmann::json layout = {{"name", "cube sites"},
                           {"points", points},
                           {"normals", normals},
                           {"visibility", {{"cone_half_angle_deg", 150.0}, {"min_visible", 3}}}};
  return layout.dump();
}

}  // namespace vantage::testing
