#pragma once

/// The layout being edited in vantage-viewer, with its undo stack and its file.
///
/// Every edit builds the new layout, validates it (Layout::validate) and only then replaces the
/// current one, pushing the old layout on the undo stack: an edit that would give an invalid
/// layout throws InvalidArgument (naming the file field and index) and changes nothing. undo()
/// restores the previous layout exactly (same entries, weights, candidates, names, name); a load
/// is undone too, back to the layout, file and unsaved edits it replaced. Entries keep their
/// names (Layout::entry_name) through every edit: removing one never renumbers the others.
/// A marker on a body (Layout::visibility, docs/math.md §20) keeps its normal and cone through
/// every edit, and its removal removes them.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"

namespace vantage::viewer {

class LayoutDocument {
 public:
  /// Layouts kept for undo; the oldest are dropped beyond this.
  static constexpr std::size_t kMaxUndo = 256;

  /// Starts from `layout` (validated; throws InvalidArgument if bad), read from `path` ("" =
  /// not from a file).
  explicit LayoutDocument(Layout layout, std::string path = "");

  /// The orthogonal triad Z = I (the paper's Fig. 2), the layout shown without a file.
  static Layout default_layout();

  const Layout& layout() const { return layout_; }
  const std::string& path() const { return path_; }
  /// Changed since it was loaded or last saved.
  bool modified() const { return modified_; }
  /// Increases by one on every change (edit, undo, load), never repeats: results computed for an
  /// older revision are stale.
  std::uint64_t revision() const { return revision_; }
  std::size_t undo_depth() const { return undo_.size(); }

  /// Sets entry `index` (a vector in direction mode, a marker position in point mode), keeping
  /// its weight. continue_edit = true (a drag in progress) replaces the layout without pushing
  /// another undo step, so one drag is undone at once.
  void set_entry(int index, const Eigen::Vector3d& value, bool continue_edit = false);
  /// Removes entry `index`, its weight and its name (a marker dropout in point mode). The other
  /// entries keep their names: an unnamed layout is named p0, p1, ... (v0, ...) first.
  void remove_entry(int index);
  /// Gives every marker the cone half-angle `degrees` (the file's
  /// "visibility.cone_half_angle_deg" as one number). Throws InvalidArgument naming that field
  /// for a layout without normals or a value outside [kMinConeHalfAngleDeg, 180].
  void set_cone_half_angle_deg(double degrees);
  /// Sets "visibility.min_visible", the markers a tracked direction must see. Throws
  /// InvalidArgument naming that field for a layout without normals or k outside [3, markers].
  void set_min_visible(int k);
  /// Replaces the whole layout (e.g. by the augmenter's result) as one undoable step.
  void replace(Layout layout);
  /// Restores the layout before the last edit; false when there is nothing to undo.
  bool undo();

  /// Reads `path` in any layout format (io::load_layout: .json, .csv, .yaml/.yml). On error
  /// throws InvalidArgument with the reader's message and keeps everything as it was. On
  /// success the replaced layout, its file and its modified() state are one undo step.
  void load(const std::string& path);
  /// Writes the layout to `path` in the format its extension names (io::save_layout: .json or
  /// .csv): an existing file is replaced only when `overwrite` is set, otherwise
  /// InvalidArgument. On success path() becomes `path`.
  void save(const std::string& path, bool overwrite);

 private:
  /// What undo() restores: the layout; after a load also the file and the modified() state
  /// the load replaced (an edit keeps the file it is saved to).
  struct Snapshot {
    Layout layout;
    bool load = false;
    std::string path;
    bool modified = true;
  };

  void push_undo(bool load);
  void commit(Layout next, bool push_undo);

  Layout layout_;
  std::string path_;
  bool modified_ = false;
  std::uint64_t revision_ = 1;
  std::vector<Snapshot> undo_;
};

}  // namespace vantage::viewer
