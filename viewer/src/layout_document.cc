#include "vantage/viewer/layout_document.h"

#include <sstream>
#include <utility>

#include "vantage/analysis/common.h"
#include "vantage/io/layout_formats.h"

namespace vantage::viewer {
namespace {

void check_index(const Layout& layout, int index) {
  if (index < 0 || index >= layout.entries.cols()) {
    throw InvalidArgument(std::string(layout.entries_field()) + "[" + std::to_string(index) +
                          "]: no such entry (the layout has " +
                          std::to_string(layout.entries.cols()) + ")");
  }
}

// The layout's visibility, for an edit of `field`; InvalidArgument when it has none.
MarkerVisibility& visibility_of(Layout& layout, const char* field) {
  if (!layout.visibility) {
    throw InvalidArgument(field, "the layout has no marker normals (no visibility to edit)");
  }
  return *layout.visibility;
}

}  // namespace

LayoutDocument::LayoutDocument(Layout layout, std::string path)
    : layout_(std::move(layout)), path_(std::move(path)) {
  layout_.validate();
}

Layout LayoutDocument::default_layout() {
  Layout layout;
  layout.name = "orthogonal triad (Fig. 2)";
  layout.mode = LayoutMode::kVectors;
  layout.entries = Eigen::Matrix3d::Identity();
  layout.weights = Eigen::VectorXd::Ones(3);
  layout.candidates.resize(3, 0);
  return layout;
}

void LayoutDocument::push_undo(bool load) {
  undo_.push_back({std::move(layout_), load, path_, modified_});
  if (undo_.size() > kMaxUndo) undo_.erase(undo_.begin());
}

void LayoutDocument::commit(Layout next, bool push) {
  next.validate();
  if (push) push_undo(false);
  layout_ = std::move(next);
  modified_ = true;
  ++revision_;
}

void LayoutDocument::set_entry(int index, const Eigen::Vector3d& value, bool continue_edit) {
  check_index(layout_, index);
  Layout next = layout_;
  next.entries.col(index) = value;
  commit(std::move(next), !(continue_edit && !undo_.empty()));
}

void LayoutDocument::remove_entry(int index) {
  check_index(layout_, index);
  commit(without_entry(layout_, index), true);
}

void LayoutDocument::set_cone_half_angle_deg(double degrees) {
  constexpr const char* kField = "visibility.cone_half_angle_deg";
  Layout next = layout_;
  MarkerVisibility& visibility = visibility_of(next, kField);
  if (!(degrees >= kMinConeHalfAngleDeg && degrees <= 180.0)) {
    std::ostringstream got;
    got << degrees;
    throw InvalidArgument(kField, "must be in [0.001, 180] degrees, got " + got.str());
  }
  visibility.cone_half_angle_deg.setConstant(degrees);
  commit(std::move(next), true);
}

void LayoutDocument::set_min_visible(int k) {
  Layout next = layout_;
  visibility_of(next, "visibility.min_visible").min_visible = k;
  commit(std::move(next), true);
}

void LayoutDocument::replace(Layout layout) { commit(std::move(layout), true); }

bool LayoutDocument::undo() {
  if (undo_.empty()) return false;
  Snapshot& last = undo_.back();
  layout_ = std::move(last.layout);
  modified_ = true;
  if (last.load) {
    path_ = std::move(last.path);
    modified_ = last.modified;
  }
  undo_.pop_back();
  ++revision_;
  return true;
}

void LayoutDocument::load(const std::string& path) {
  Layout next = io::load_layout(path);
  push_undo(true);
  layout_ = std::move(next);
  path_ = path;
  modified_ = false;
  ++revision_;
}

void LayoutDocument::save(const std::string& path, bool overwrite) {
  if (path.empty()) throw InvalidArgument("save: no file name given");
  io::save_layout(path, layout_, overwrite);
  path_ = path;
  modified_ = false;
}

}  // namespace vantage::viewer
