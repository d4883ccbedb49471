// The design panel's "Place K markers on this body" (docs/math.md §21): the controls, the
// progress of the running search, and the greedy steps, random baseline and final value of the
// last placement.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "draw_style.h"
#include "panels.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/commands/point_text.h"

namespace vantage::viewer::app {
namespace {

constexpr int kMaxMarkers = 200;
constexpr int kMaxCandidates = 20000;  // as `vantage place --candidates`

// D1,D2,... as the settings' approach: `vantage place --distances`'s numbers, or NaN for text
// that is not a list of numbers (so that the placement is refused, naming --distances, rather
// than run at the single distance); empty text: no approach.
std::vector<double> approach_of(const std::string& text) {
  if (text.empty()) return {};
  const std::optional<std::vector<double>> numbers = commands::parse_numbers(text);
  if (!numbers || numbers->empty()) return {std::numeric_limits<double>::quiet_NaN()};
  return *numbers;
}

// The settings' distances as text: `digits` 17 reads back to the same numbers (the field), 4 is
// for the report line.
std::string approach_text(const std::vector<double>& distances, int digits) {
  std::string out;
  for (const double d : distances) {
    char number[32];
    std::snprintf(number, sizeof number, "%.*g", digits, d);
    out += (out.empty() ? "" : ",") + std::string(number);
  }
  return out;
}

// A search value of the camera or tracker objective: degrees or layout units, "incomplete" for
// a choice below the least coverage, and no figure past the camera's first-order limit
// (docs/math.md §22, "Unbounded").
std::string search_value(double value, const std::string& objective) {
  if (!std::isfinite(value)) return "incomplete";
  char text[48];
  if (objective == "camera") {
    if (value > camera::PoseCrbAt::kMaxRotRmsDeg) return "unbounded";
    std::snprintf(text, sizeof text, "%.4g\u00b0", value);
  } else {
    std::snprintf(text, sizeof text, "%.4g", value);
  }
  return text;
}

// The greedy steps: p-bar_min for the affine objective, the objective's search value otherwise.
void steps_table(const design::PlacementResult& r, const std::string& objective) {
  if (r.steps.empty()) {
    ImGui::TextDisabled("exhaustive search: no greedy steps (%ld subsets)", r.subsets);
    return;
  }
  const bool affine = objective == "affine";
  if (affine) {
    std::vector<float> pbar;
    for (const design::PlacementStep& s : r.steps)
      pbar.push_back(static_cast<float>(s.value.pbar_min));
    ImGui::TextDisabled("greedy steps: p\u0304_min (0..1) against k = %d..%d", r.steps.front().k,
                        r.steps.back().k);
    ImGui::PlotLines("##greedy", pbar.data(), static_cast<int>(pbar.size()), 0, nullptr, 0.0f, 1.0f,
                     ImVec2(ImGui::GetContentRegionAvail().x, 56.0f));
  } else {
    ImGui::TextDisabled("greedy steps: the %s objective's search value, k = %d..%d",
                        objective.c_str(), r.steps.front().k, r.steps.back().k);
  }
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchSame;
  const float rows = static_cast<float>(std::min<std::size_t>(r.steps.size(), 5) + 1);
  if (!ImGui::BeginTable("steps", 3, flags,
                         ImVec2(0, rows * ImGui::GetTextLineHeightWithSpacing() + 6))) {
    return;
  }
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("k");
  ImGui::TableSetupColumn("coverage");
  ImGui::TableSetupColumn(affine ? "p\u0304_min" : "objective");
  ImGui::TableHeadersRow();
  for (const design::PlacementStep& s : r.steps) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::Text("%d", s.k);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f %%", 100.0 * s.value.coverage);
    ImGui::TableNextColumn();
    if (affine) {
      ImGui::Text("%.4f", s.value.pbar_min);
    } else {
      // A choice that covers nothing keeps the search's initial value: no figure.
      const double value =
          s.value.coverage > 0.0 ? s.value.objective : std::numeric_limits<double>::infinity();
      ImGui::TextUnformatted(search_value(value, objective).c_str());
    }
  }
  ImGui::EndTable();
}

// The objective's value on the placed layout, as `vantage place` reports it.
void objective_line(const PlaceOutcome& out) {
  const PlaceSettings& s = out.settings;
  const std::string at = s.distances.empty() ? approach_text({s.distance}, 4)
                                             : "the approach " + approach_text(s.distances, 4);
  if (s.objective == "camera" && !std::isfinite(out.objective_value)) {
    // Trackable, but the worst direction is past the first-order limit: no figure (§22).
    ImGui::TextWrapped("objective camera: %s rot_rms unbounded at %s (f %.4g px, %.3g px)",
                       s.statistic.c_str(), at.c_str(), s.focal, s.noise_px);
  } else if (!std::isfinite(out.objective_value)) {
    ImGui::TextWrapped("objective %s: none (nothing tracked)", s.objective.c_str());
  } else if (s.objective == "camera") {
    ImGui::TextWrapped("objective camera: %s rot_rms %.4g\u00b0 at %s (f %.4g px, %.3g px)",
                       s.statistic.c_str(), out.objective_value, at.c_str(), s.focal, s.noise_px);
  } else if (s.objective == "tracker") {
    ImGui::TextWrapped("objective tracker: worst RMS TRE %.4g (layout units) at the target",
                       out.objective_value);
  } else {
    ImGui::TextWrapped("objective affine: worst-case error %.4g\u00b0 (scale-free)",
                       out.objective_value);
  }
}

// The keep-out volumes and the region, as given at start-up (--exclude, --region).
void where_controls(const PlaceSettings& s) {
  if (s.exclude.empty() && s.region.empty()) return;
  std::string text;
  for (const std::string& path : s.exclude) {
    text += (text.empty() ? "keep-out: " : ", ") + std::filesystem::path(path).filename().string();
  }
  if (!s.region.empty()) {
    text += (text.empty() ? "" : "; ") + std::string("region: ") +
            std::filesystem::path(s.region).filename().string();
  }
  ImGui::TextWrapped("%s", text.c_str());
}

void outcome_summary(const PlaceOutcome& out) {
  const design::PlacementResult& r = out.result;
  if (!out.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    ImGui::TextWrapped("placement failed: %s", out.error.c_str());
    ImGui::PopStyleColor();
    return;
  }
  ImGui::TextWrapped("last: %d of %d sites, %s, %s, %.1f s", static_cast<int>(r.chosen.size()),
                     out.n_candidates, r.search.c_str(), design::to_string(r.status), out.seconds);
  if (out.excluded > 0) {
    ImGui::TextWrapped("%d sampled sites dropped by the keep-out volumes", out.excluded);
  }
  if (!out.complete) {
    ImGui::PushStyleColor(ImGuiCol_Text, kWarningText);
    ImGui::TextWrapped("%s (coverage %.2f %%; layout kept)", out.failure.c_str(),
                       100.0 * r.value.coverage);
    ImGui::PopStyleColor();
    return;
  }
  objective_line(out);
  const std::string& objective = out.settings.objective;
  const design::RandomBaseline& b = r.random_baseline;
  if (b.trials == 0) {
    ImGui::TextDisabled("random baseline: none (no feasible random subset drawn)");
  }
  if (objective == "affine") {
    ImGui::Text("certified p\u0304_min %.6f, coverage %.2f %%", r.value.pbar_min,
                100.0 * r.value.coverage);
    if (r.robust) {
      ImGui::TextWrapped("after losing any one marker: p\u0304_min %.6f, coverage %.2f %%",
                         r.robust->pbar_min, 100.0 * r.robust->coverage);
    }
    ImGui::TextWrapped("random baseline (%d trials, %d complete): best %.4f, median %.4f", b.trials,
                       b.complete, b.best_pbar_min, b.median_pbar_min);
  } else {
    ImGui::Text("coverage %.2f %%", 100.0 * r.value.coverage);
    if (r.robust) {
      ImGui::TextWrapped("after losing any one marker: %s, coverage %.2f %%",
                         search_value(r.robust->objective, objective).c_str(),
                         100.0 * r.robust->coverage);
    }
    if (b.trials > 0) {
      ImGui::TextWrapped("random baseline (%d trials, %d complete): best %s, median %s", b.trials,
                         b.complete, search_value(b.best_objective, objective).c_str(),
                         search_value(b.median_objective, objective).c_str());
    }
  }
  steps_table(r, objective);
}

// The objective and its settings (docs/math.md §21, "Objectives"); `approach` is the text of
// the camera's distances.
void objective_controls(PlaceSettings* s, std::string* approach) {
  static const char* const kObjectives[] = {"affine", "camera", "tracker"};
  ImGui::Text("objective");
  for (const char* name : kObjectives) {
    ImGui::SameLine();
    if (ImGui::RadioButton(name, s->objective == name)) s->objective = name;
  }
  if (s->objective == "camera") {
    ImGui::BeginDisabled(!approach->empty());
    ImGui::InputDouble("distance", &s->distance, 0.0, 0.0, "%.4g");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::InputDouble("focal px", &s->focal, 0.0, 0.0, "%.4g");
    ImGui::InputTextWithHint("approach", "D1,D2,... (instead of distance)", approach);
    s->distances = approach_of(*approach);
    ImGui::InputDouble("noise px", &s->noise_px, 0.0, 0.0, "%.3g");
    ImGui::SameLine();
    static const char* const kStatistics[] = {"worst", "p95", "median"};
    if (ImGui::BeginCombo("statistic", s->statistic.c_str())) {
      for (const char* name : kStatistics) {
        if (ImGui::Selectable(name, s->statistic == name)) s->statistic = name;
      }
      ImGui::EndCombo();
    }
  } else if (s->objective == "tracker") {
    ImGui::PushItemWidth(228.0f);
    ImGui::InputScalarN("target", ImGuiDataType_Double, s->target.data(), 3, nullptr, nullptr,
                        "%.4g");
    ImGui::PopItemWidth();
    ImGui::InputDouble("FLE RMS", &s->fle_rms, 0.0, 0.0, "%.4g");
  } else {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("the paper's bound: scale-free, it does not spread markers apart");
    ImGui::PopStyleColor();
  }
}

// The workspace of the placement: the layout's own, or a cone about an axis.
void workspace_controls(const Layout& layout, PlaceSettings* s) {
  bool own = !s->workspace.has_value();
  if (ImGui::Checkbox("the layout's workspace", &own)) {
    if (own) {
      s->workspace.reset();
    } else {
      s->workspace = layout.workspace.value_or(LayoutWorkspace{});
    }
  }
  if (own) {
    ImGui::SameLine();
    if (layout.workspace) {
      const Eigen::Vector3d& a = layout.workspace->axis;
      ImGui::TextDisabled("(%.2f, %.2f, %.2f), %.4g\u00b0", a.x(), a.y(), a.z(),
                          layout.workspace->half_angle_deg);
    } else {
      ImGui::TextDisabled("(every direction)");
    }
    return;
  }
  Eigen::Vector3d axis = s->workspace->axis;
  ImGui::PushItemWidth(228.0f);
  if (ImGui::InputScalarN("axis", ImGuiDataType_Double, axis.data(), 3, nullptr, nullptr, "%.3g") &&
      axis.allFinite() && axis.norm() > 0.0) {
    s->workspace->axis = axis.normalized();
  }
  ImGui::PopItemWidth();
  ImGui::SameLine();
  ImGui::PushItemWidth(80.0f);
  ImGui::InputDouble("half-angle\u00b0", &s->workspace->half_angle_deg, 0.0, 0.0, "%.4g");
  ImGui::PopItemWidth();
  s->workspace->half_angle_deg =
      std::clamp(s->workspace->half_angle_deg, kMinWorkspaceHalfAngleDeg, 180.0);
}

// Least coverage: every lattice direction but one, or a fraction.
void coverage_controls(PlaceSettings* s) {
  bool all = s->min_coverage < 0.0;
  if (ImGui::Checkbox("cover every direction", &all)) s->min_coverage = all ? -1.0 : 0.95;
  if (all) return;
  ImGui::SameLine();
  double percent = 100.0 * s->min_coverage;
  ImGui::PushItemWidth(80.0f);
  if (ImGui::InputDouble("% at least", &percent, 0.0, 0.0, "%.4g")) {
    s->min_coverage = std::clamp(percent, 0.01, 100.0) / 100.0;
  }
  ImGui::PopItemWidth();
}

}  // namespace

void Panels::placement_panel(ViewerSession& session) {
  const LayoutDocument& doc = session.document();
  if (!place_seeded_ && session.placement()) {
    place_settings_ = session.placement()->settings;  // e.g. the start-up --place
    approach_text_ = approach_text(place_settings_.distances, 17);
    place_seeded_ = true;
  }
  if (place_revision_ != doc.revision() && !session.placing()) {
    const int markers = static_cast<int>(doc.layout().entries.cols());
    place_settings_.markers = markers >= 3 ? markers : 8;
    place_revision_ = doc.revision();
  }
  ImGui::Text("place markers on this body (docs/math.md \u00a721):");
  ImGui::BeginDisabled(session.placing());
  ImGui::PushItemWidth(110.0f);
  ImGui::InputInt("K markers", &place_settings_.markers);
  ImGui::SameLine();
  ImGui::InputInt("N sites", &place_settings_.candidates, 50, 500);
  ImGui::InputDouble("min separation", &place_settings_.min_separation, 0.0, 0.0, "%.4g");
  ImGui::SameLine();
  int seed = static_cast<int>(place_settings_.seed);
  if (ImGui::InputInt("seed", &seed))
    place_settings_.seed = static_cast<std::uint64_t>(std::max(seed, 0));
  ImGui::InputDouble("marker diameter", &place_settings_.marker_diameter, 0.0, 0.0, "%.4g");
  where_controls(place_settings_);
  objective_controls(&place_settings_, &approach_text_);
  ImGui::PopItemWidth();
  workspace_controls(doc.layout(), &place_settings_);
  coverage_controls(&place_settings_);
  place_settings_.markers = std::clamp(place_settings_.markers, 3, kMaxMarkers);
  place_settings_.candidates = std::clamp(place_settings_.candidates, 1, kMaxCandidates);
  place_settings_.min_separation = std::max(place_settings_.min_separation, 0.0);
  place_settings_.marker_diameter = std::max(place_settings_.marker_diameter, 0.0);
  ImGui::Checkbox("robust to one lost marker", &place_settings_.robust_dropout);
  ImGui::SameLine();
  char label[64];
  std::snprintf(label, sizeof label, "Place %d markers on this body", place_settings_.markers);
  if (ImGui::Button(label)) session.place_markers(place_settings_);
  ImGui::EndDisabled();
  if (session.placing()) {
    const std::string stage = session.place_progress();
    ImGui::TextColored(ImVec4(1, 0.75f, 0.25f, 1), "placing: %s",
                       stage.empty() ? "waiting for the worker" : stage.c_str());
  } else if (session.placement()) {
    outcome_summary(*session.placement());
  }
}

}  // namespace vantage::viewer::app
