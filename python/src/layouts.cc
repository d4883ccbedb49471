#include "layouts.h"

#include <pybind11/stl.h>

#include "arrays.h"
#include "results.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
#include "vantage/analysis/free_vectors.h"
#include "vantage/io/calibration_board.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/text_file.h"

namespace vantage::python {

namespace {

std::string text_of(const py::handle& value, const char* name) {
  if (!py::isinstance<py::str>(value)) {
    throw InvalidArgument(std::string(name) + ": expected a string");
  }
  return value.cast<std::string>();
}

std::vector<std::string> names_from(const py::object& names) {
  if (names.is_none()) return {};
  if (py::isinstance<py::str>(names)) {
    throw InvalidArgument("names: expected a list of strings (one per entry), got a string");
  }
  std::vector<std::string> out;
  std::size_t i = 0;
  for (const py::handle item : py::iter(names)) {
    if (!py::isinstance<py::str>(item)) {
      throw InvalidArgument("names[" + std::to_string(i) + "]: expected a string");
    }
    out.push_back(item.cast<std::string>());
    ++i;
  }
  return out;
}

/// A dict (or None) as JSON, arrays through their tolist().
Json json_of(const py::object& value) {
  const py::object json = py::module_::import("json");
  const py::object tolist = py::cpp_function([](const py::object& o) -> py::object {
    if (py::hasattr(o, "tolist")) return o.attr("tolist")();
    throw py::type_error("not JSON: " + py::repr(o).cast<std::string>());
  });
  return Json::parse(json.attr("dumps")(value, py::arg("default") = tolist).cast<std::string>());
}

/// The layout on its body: normals=, visibility= and workspace= as the JSON file gives them, read
/// by the file's own reader (the body's path relative to the working directory).
Layout on_body(const Layout& layout, const py::object& normals, const py::object& visibility,
               const py::object& workspace) {
  Json root = Json::parse(io::layout_to_json(layout));
  if (!normals.is_none()) {
    const Eigen::Matrix3Xd n = rows_from_array<3>(normals, "normals");
    Json rows = Json::array();
    for (Eigen::Index i = 0; i < n.cols(); ++i) rows.push_back({n(0, i), n(1, i), n(2, i)});
    root["normals"] = rows;
  }
  if (!visibility.is_none()) root["visibility"] = json_of(visibility);
  if (!workspace.is_none()) root["workspace"] = json_of(workspace);
  const std::string source = "Layout";
  Layout out = io::parse_layout(root.dump(), source);
  io::load_body(source, &out);
  return out;
}

Layout make_layout(const py::object& vectors, const py::object& points, const py::object& weights,
                   const py::object& candidates, const py::object& names, const std::string& name,
                   const std::string& description, const py::object& normals = py::none(),
                   const py::object& visibility = py::none(),
                   const py::object& workspace = py::none()) {
  if (vectors.is_none() == points.is_none()) {
    throw InvalidArgument(
        vectors.is_none() ? "vectors/points: missing; give vectors= (directions) or points= "
                            "(marker positions)"
                          : "vectors/points: give exactly one of vectors= or points=, not both");
  }
  Layout layout;
  layout.name = name;
  layout.description = description;
  layout.mode = points.is_none() ? LayoutMode::kVectors : LayoutMode::kPoints;
  layout.entries = rows_from_array<3>(points.is_none() ? vectors : points, layout.entries_field());
  layout.weights = weights.is_none() ? Eigen::VectorXd::Ones(layout.entries.cols())
                                     : vector_from_array(weights, "weights");
  layout.candidates =
      candidates.is_none() ? Eigen::Matrix3Xd(3, 0) : rows_from_array<3>(candidates, "candidates");
  layout.names = names_from(names);
  layout.validate();
  if (normals.is_none() && visibility.is_none() && workspace.is_none()) return layout;
  return on_body(layout, normals, visibility, workspace);
}

py::object layout_dict(const Layout& layout) {
  return to_python(Json::parse(io::layout_to_json(layout)));
}

}  // namespace

io::LayoutReadOptions read_options_from(const ReadArguments& read) {
  io::LayoutReadOptions options;
  options.max_bytes = read.allow_large ? io::kMaxFileBytesAllowLarge : io::kMaxFileBytes;
  if (!read.format.is_none()) {
    options.format = io::layout_format_from_string(text_of(read.format, "format"), "format");
  }
  if (!read.tag_points.is_none()) {
    options.apriltag.tag_points =
        io::tag_points_from_string(text_of(read.tag_points, "tag_points"), "tag_points");
  }
  if (!read.bundle.is_none()) options.apriltag.bundle = text_of(read.bundle, "bundle");
  return options;
}

Layout layout_from_arguments(const py::object& layout, const py::object& vectors,
                             const py::object& points, const py::object& weights,
                             const py::object& candidates, const ReadArguments& read,
                             std::string* source) {
  source->clear();
  if (layout.is_none()) {
    if (!read.format.is_none() || !read.tag_points.is_none() || !read.bundle.is_none()) {
      throw InvalidArgument(
          "format/tag_points/bundle: read a layout file; give its path as layout");
    }
    return make_layout(vectors, points, weights, candidates, py::none(), "", "");
  }
  if (!vectors.is_none() || !points.is_none() || !weights.is_none() || !candidates.is_none()) {
    throw InvalidArgument(
        "layout: give a layout or vectors=/points= (with weights=, candidates=), not both");
  }
  if (py::isinstance<Layout>(layout)) return layout.cast<Layout>();
  *source = path_from(layout, "layout");
  const io::LayoutReadOptions options = read_options_from(read);
  try {
    return without_gil([&] { return io::load_layout(*source, options); });
  } catch (const io::FileTooLarge& e) {
    throw io::FileTooLarge(std::string(e.what()) +
                           (read.allow_large ? "" : " (allow_large=True raises it to 1 GiB)"));
  }
}

namespace {

/// The Layout class: its constructor, read-only fields and to_dict().
void bind_layout_class(py::module_& module) {
  py::class_<Layout>(module, "Layout",
                     "A fiducial layout: marker positions (points) or data vectors (vectors), "
                     "with weights and optional candidates. Arrays are n x 3.")
      .def(py::init([](const py::object& vectors, const py::object& points,
                       const py::object& weights, const py::object& candidates,
                       const py::object& names, const std::string& name,
                       const std::string& description, const py::object& normals,
                       const py::object& visibility, const py::object& workspace) {
             return make_layout(vectors, points, weights, candidates, names, name, description,
                                normals, visibility, workspace);
           }),
           py::kw_only(), py::arg("vectors") = py::none(), py::arg("points") = py::none(),
           py::arg("weights") = py::none(), py::arg("candidates") = py::none(),
           py::arg("names") = py::none(), py::arg("name") = "", py::arg("description") = "",
           py::arg("normals") = py::none(), py::arg("visibility") = py::none(),
           py::arg("workspace") = py::none())
      .def_readonly("name", &Layout::name)
      .def_property_readonly(
          "names",
          [](const Layout& l) {
            std::vector<std::string> names;
            for (Eigen::Index i = 0; i < l.entries.cols(); ++i) names.push_back(l.entry_name(i));
            return names;
          },
          "One name per entry: the file's (CSV name column, AprilTag tag3_c0, JSON names), or "
          "p0, p1, ... (v0, ... for vectors) when it has none")
      .def_readonly("description", &Layout::description)
      .def_property_readonly("mode", [](const Layout& l) { return to_string(l.mode); })
      .def_property_readonly(
          "entries", [](const Layout& l) { return array_from_columns(l.entries); },
          "n x 3: the points (point mode) or vectors (direction mode)")
      .def_property_readonly("weights",
                             [](const Layout& l) { return array_from_vector(l.weights); })
      .def_property_readonly("candidates",
                             [](const Layout& l) { return array_from_columns(l.candidates); })
      .def_property_readonly(
          "normals",
          [](const Layout& l) -> py::object {
            if (!l.visibility) return py::none();
            return array_from_columns(l.visibility->normals);
          },
          "n x 3 outward unit normals of the markers on their body, or None")
      .def("to_dict", &layout_dict, "The layout as the dict of its JSON file")
      .def("__len__", [](const Layout& l) { return l.entries.cols(); })
      .def("__repr__", [](const Layout& l) {
        return "<vantage.Layout '" + l.name + "': " + std::to_string(l.entries.cols()) + " " +
               to_string(l.mode) + ">";
      });
}

/// load_layout, save_layout and board: layouts from and to files, and calibration targets.
void bind_layout_files(py::module_& module) {
  module.def(
      "load_layout",
      [](const py::object& path, const py::object& format, const py::object& tag_points,
         const py::object& bundle, bool allow_large) {
        std::string source;
        return layout_from_arguments(path, py::none(), py::none(), py::none(), py::none(),
                                     {format, tag_points, bundle, allow_large}, &source);
      },
      py::arg("path"), py::kw_only(), py::arg("format") = py::none(),
      py::arg("tag_points") = py::none(), py::arg("bundle") = py::none(),
      py::arg("allow_large") = false,
      "Reads a layout file: .json (vantage layout), .csv (name,x,y,z[,weight]) or .yaml/.yml "
      "(AprilTag tag_bundles). format='auto'|'json'|'csv'|'apriltag', "
      "tag_points='corners'|'centres', bundle=NAME; allow_large=True reads files up to 1 GiB.");
  module.def(
      "save_layout",
      [](const Layout& layout, const py::object& path, bool overwrite) {
        io::save_layout(path_from(path, "path"), layout, overwrite);
      },
      py::arg("layout"), py::arg("path"), py::kw_only(), py::arg("overwrite") = false,
      "Writes the layout in the format its extension names: .json (everything), .csv "
      "(markers: name,x,y,z,weight; refused for vectors or candidates), an Atracsys .ini (named "
      "for its geometry id, geometry150.ini) or an NDI .rom (markers, normals, one cone, "
      "min_visible); .yaml and other extensions are refused. Refuses to replace an existing "
      "file unless overwrite=True.");
  module.def(
      "board",
      [](const std::string& type, int rows, int cols, double square, double marker,
         double spacing) {
        io::BoardOptions options;
        options.type = io::board_type_from_string(type, "type");
        options.rows = rows;
        options.cols = cols;
        options.square = square;
        options.marker = marker;
        options.spacing = spacing;
        return io::calibration_board(options);
      },
      py::arg("type"), py::kw_only(), py::arg("rows"), py::arg("cols"), py::arg("square"),
      py::arg("marker") = 0.0, py::arg("spacing") = io::BoardOptions{}.spacing,
      "The layout of a calibration target (as `vantage layout board`): 'chessboard' or "
      "'charuco' inner corners (rows x cols squares), 'aprilgrid' tag corners (rows x cols tags, "
      "Kalibr spacing ratio).");
}

/// data_vectors and pbar_at_viewpoints: what the analysis computes from a layout.
void bind_layout_vectors(py::module_& module) {
  module.def(
      "data_vectors",
      [](const Layout& layout, const std::string& pair_weighting) {
        const std::optional<PairWeighting> weighting = parse_pair_weighting(pair_weighting);
        if (!weighting) throw InvalidArgument("pair_weighting: expected geometric or arithmetic");
        const DataVectors data = data_vectors(layout, *weighting);
        return py::make_tuple(array_from_columns(data.vectors), array_from_vector(data.weights));
      },
      py::arg("layout"), py::kw_only(), py::arg("pair_weighting") = "geometric",
      "(vectors, weights): the data vectors the analysis uses, m x 3 (point mode: the free "
      "vectors z_j - z_i, i < j, Prop. 8) and their weights.");
  module.def(
      "pbar_at_viewpoints",
      [](const py::object& vectors, const py::object& viewpoints) {
        const Eigen::Matrix3Xd z = rows_from_array<3>(vectors, "vectors");
        const Eigen::Matrix3Xd a = rows_from_array<3>(viewpoints, "viewpoints");
        return array_from_vector(without_gil([&] { return pbar_at_viewpoints(z, a); }));
      },
      py::arg("vectors"), py::arg("viewpoints"),
      "p-bar(a) = sqrt(1 - min_i (a.n_i)^2), n_i = z_i / |z_i|, at each unit viewpoint a (rows of "
      "viewpoints, k x 3) "
      "for the data vectors (m x 3): the figure of merit whose minimum analyze() reports.");
}

}  // namespace

void bind_layouts(py::module_& module) {
  bind_layout_class(module);
  bind_layout_files(module);
  bind_layout_vectors(module);
}

}  // namespace vantage::python
