#include "visibility_input.h"

namespace vantage::cli {

void VisibilityInput::add_options(CLI::App* sub) {
  sub->add_option("--normals", normals,
                  "radial: each marker's normal points away from the markers' centroid (a quick "
                  "start for a convex body without normals)")
      ->check(CLI::IsMember({"radial"}));
  sub->add_option("--cone-deg", cone_deg,
                  "every marker's cone half-angle in degrees, [0.001, 180] (overrides the file's "
                  "visibility.cone_half_angle_deg)");
  sub->add_option("--min-visible", min_visible,
                  "markers a direction must see to track the body, >= 3 (default 3)");
  sub->add_option("--body", body, "the body mesh (STL, OBJ, PLY, glTF, ...) that shadows markers");
  sub->add_option("--workspace", workspace,
                  "AX,AY,AZ,DEG: only directions within DEG of the axis (a docking approach, a "
                  "fixed tracker)");
  sub->add_flag("--seen-whole", seen_whole,
                "ignore the file's normals, cones, body and workspace: every camera sees every "
                "marker (the paper's model)");
}

}  // namespace vantage::cli
