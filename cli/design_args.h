#pragma once

// `vantage design`: its arguments, shared by the augmenter's run (design.cc, the paper's bound)
// and the camera and tracker objectives' run (design_objective.cc, place's search on the
// layout's candidates; docs/math.md §21, "In design").

#include <CLI/CLI.hpp>
#include <string>

#include "layout_input.h"
#include "objective_input.h"
#include "vantage/commands/place_json.h"
#include "vantage/design/augment.h"

namespace vantage::cli {

struct DesignArgs {
  std::string file;
  LayoutInput input;
  int add = 0;
  bool candidates_only = false;
  double margin = design::AugmentOptions{}.margin;
  long search_budget = design::AugmentOptions{}.search_budget;
  double min_distance_difference = 0.0;
  bool direct = true;
  std::string write;
  bool write_given = false;  // --write appeared, possibly with an empty name
  bool overwrite = false;
  std::string plot;
  bool json = false;
  bool quiet = false;
  bool allow_large = false;
  /// --objective and the camera's or the tracker's settings ("affine": the augmenter).
  place_json::Request sensor;
  ObjectiveArgs objective_args;
  /// The augmenter's own options, to refuse them with another objective.
  CLI::Option* margin_option = nullptr;
  CLI::Option* search_budget_option = nullptr;
  CLI::Option* direct_option = nullptr;
};

/// --write's name and target, checked before anything is read or searched.
void check_write_target(const DesignArgs& args);

/// `vantage design --objective camera|tracker` (design_objective.cc).
int run_sensor_design(const DesignArgs& args);

}  // namespace vantage::cli
