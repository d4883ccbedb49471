// `vantage layout snap LAYOUT [--body MESH] --out OUT.json [--marker-diameter D] [--overwrite]
// [--json]`: moves each marker of a point layout to the nearest point of its body's surface,
// with the outward normal there (and D / 2 off it for spheres of diameter D), and writes the
// layout on that body (docs/math.md §21, "Snapping a layout to its body").

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "layout_convert.h"
#include "layout_input.h"
#include "vantage/analysis/common.h"
#include "vantage/design/placement_layout.h"
#include "vantage/design/surface_snap.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/mesh_file.h"
#include "vantage/io/text_file.h"

namespace vantage::cli {

namespace {

struct SnapArgs {
  std::string in;
  std::string body;
  std::string out;
  double marker_diameter = 0.0;
  LayoutInput input;
  bool overwrite = false;
  bool allow_large = false;
  bool json = false;
};

// The mesh to snap onto: --body, or the body the layout names.
Mesh snap_body(const SnapArgs& args, const Layout& layout, std::string* path) {
  if (args.body.empty()) {
    if (!layout.visibility || !layout.visibility->body) {
      throw InvalidArgument("--body", "required: " + args.in + " names no body mesh");
    }
    *path = layout.visibility->body_path;
    return *layout.visibility->body;
  }
  *path = std::filesystem::absolute(args.body).lexically_normal().string();
  try {
    return io::read_mesh(args.body);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("--body: ") + e.what());
  }
}

// Markers that moved farther than design::kFarSnap of the body's size: the mesh may not be their
// body, or not in their units and frame.
std::string far_moves(const Layout& layout, const design::SurfaceSnap& snap, double limit) {
  std::string names;
  int count = 0;
  for (Eigen::Index i = 0; i < snap.moved.size(); ++i) {
    if (snap.moved(i) <= limit) continue;
    names += (names.empty() ? "" : ", ") + layout.entry_name(i);
    ++count;
  }
  if (count == 0) return "";
  return "layout snap: " + std::to_string(count) + " marker(s) moved more than " +
         format_number(100 * design::kFarSnap, 2) + " % of the body's size (" + names +
         "; the farthest " + format_number(snap.moved.maxCoeff(), 4) +
         "): is the mesh the markers' body, in their units and frame?";
}

Json snap_json(const SnapArgs& args, const Layout& before, const Layout& after,
               const design::SurfaceSnap& snap) {
  Json out;
  out["input"] = args.in;
  out["body"] = args.body.empty() ? before.visibility->body_path : args.body;
  out["marker_diameter"] = args.marker_diameter;
  Json markers = Json::array();
  for (Eigen::Index i = 0; i < snap.moved.size(); ++i) {
    markers.push_back({{"name", after.entry_name(i)},
                       {"from", json_list(before.entries.col(i))},
                       {"to", json_list(snap.centres.col(i))},
                       {"surface", json_list(snap.surface.col(i))},
                       {"normal", json_list(snap.normals.col(i))},
                       {"moved", snap.moved(i)}});
  }
  out["markers"] = markers;
  out["max_moved"] = snap.moved.maxCoeff();
  out["written"] = args.out;
  return out;
}

void print_snap(const SnapArgs& args, const Layout& after, const Mesh& body,
                const design::SurfaceSnap& snap) {
  std::cout
      << "vantage layout snap: " << args.in << " onto "
      << std::filesystem::path(args.body.empty() ? body.source : args.body).filename().string()
      << " (" << body.triangles.cols() << " triangles)";
  if (args.marker_diameter > 0.0) {
    std::cout << ", spheres of diameter " << format_number(args.marker_diameter);
  }
  std::cout << "\n";
  std::size_t width = 6;
  for (Eigen::Index i = 0; i < snap.moved.size(); ++i) {
    width = std::max(width, after.entry_name(i).size());
  }
  std::cout << "  " << std::string("marker").append(width - 6, ' ') << "  moved         "
            << "normal\n";
  for (Eigen::Index i = 0; i < snap.moved.size(); ++i) {
    const std::string name = after.entry_name(i);
    const std::string moved = format_number(snap.moved(i));
    std::cout << "  " << name << std::string(width - name.size(), ' ') << "  " << moved
              << std::string(moved.size() < 14 ? 14 - moved.size() : 1, ' ')
              << format_vector(snap.normals.col(i), 4) << "\n";
  }
  std::cout << "written: " << args.out << "\n";
}

int run_snap(const SnapArgs& args) {
  if (!(args.marker_diameter >= 0.0) || !std::isfinite(args.marker_diameter)) {
    throw InvalidArgument("--marker-diameter", "must be a finite number >= 0");
  }
  try {
    if (io::layout_write_format(args.out) != io::LayoutFormat::kJson) {
      throw InvalidArgument(args.out + ": a layout on a body is written as JSON; use a .json name");
    }
    io::check_write_target(args.out, args.overwrite);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("--out: ") + e.what());
  }
  const Layout layout = args.input.read(args.in, args.allow_large);
  if (layout.mode != LayoutMode::kPoints) {
    throw InvalidArgument(args.in +
                          ": snapping needs marker positions (\"points\"), not data "
                          "vectors");
  }
  std::string body_path;
  const Mesh body = snap_body(args, layout, &body_path);
  try {
    design::check_marker_diameter(args.marker_diameter, body.size());
  } catch (const InvalidArgument& e) {
    throw InvalidArgument("--marker-diameter", e.problem());
  }
  design::SurfaceSnap snap;
  Layout snapped;
  try {
    snap = design::snap_to_surface(body, layout.entries, args.marker_diameter);
    snapped = design::snapped_layout(layout, snap, body, body_path);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string(args.body.empty() ? args.in : "--body") + ": snapped, " +
                          e.what());
  }
  const std::string warning = far_moves(layout, snap, design::kFarSnap * body.size());
  io::save_layout(args.out, snapped, args.overwrite);
  if (!warning.empty()) std::cerr << "vantage: warning: " << warning << std::endl;
  if (args.json) {
    print_json(snap_json(args, layout, snapped, snap));
  } else {
    print_snap(args, snapped, body, snap);
  }
  return kExitOk;
}

}  // namespace

Command add_layout_snap_subcommand(CLI::App* layout) {
  auto args = std::make_shared<SnapArgs>();
  CLI::App* sub = layout->add_subcommand(
      "snap",
      "Move each marker of a point layout to the nearest point of its body's surface, with the "
      "outward normal there (and half a sphere's diameter off it), and write the layout on that "
      "body");
  sub->add_option("LAYOUT", args->in, "the layout file to read (any format)")->required();
  sub->add_option("--body", args->body,
                  "the body mesh (STL, OBJ, PLY, glTF, ...; default: the layout's "
                  "visibility.body)");
  sub->add_option("--out", args->out, "the layout JSON file to write")->required();
  sub->add_option("--marker-diameter", args->marker_diameter,
                  "spheres of this diameter resting on the surface: each centre half of it off "
                  "the surface along the normal (default 0: points on the surface)");
  // Not the body options: the markers get their normals here, and --body is the mesh to snap to.
  args->input.add_options(sub, "--format", false);
  sub->add_flag("--overwrite", args->overwrite, "replace --out if it exists");
  sub->add_flag("--allow-large", args->allow_large, "read inputs up to 1 GiB");
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_snap(*args); }};
}

}  // namespace vantage::cli
