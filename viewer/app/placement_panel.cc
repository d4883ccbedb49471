// The design panel's "Place K markers on this body" (docs/math.md §21): the controls, the
// progress of the running search, and the greedy steps, random baseline and final value of the
// last placement.

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "draw_style.h"
#include "panels.h"

namespace vantage::viewer::app {
namespace {

constexpr int kMaxMarkers = 200;
constexpr int kMaxCandidates = 20000;  // as `vantage place --candidates`

void steps_table(const design::PlacementResult& r) {
  if (r.steps.empty()) {
    ImGui::TextDisabled("exhaustive search: no greedy steps (%ld subsets)", r.subsets);
    return;
  }
  std::vector<float> pbar;
  for (const design::PlacementStep& s : r.steps)
    pbar.push_back(static_cast<float>(s.value.pbar_min));
  ImGui::TextDisabled("greedy steps: p\u0304_min (0..1) against k = %d..%d", r.steps.front().k,
                      r.steps.back().k);
  ImGui::PlotLines("##greedy", pbar.data(), static_cast<int>(pbar.size()), 0, nullptr, 0.0f, 1.0f,
                   ImVec2(ImGui::GetContentRegionAvail().x, 56.0f));
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
  ImGui::TableSetupColumn("p\u0304_min");
  ImGui::TableHeadersRow();
  for (const design::PlacementStep& s : r.steps) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::Text("%d", s.k);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f %%", 100.0 * s.value.coverage);
    ImGui::TableNextColumn();
    ImGui::Text("%.4f", s.value.pbar_min);
  }
  ImGui::EndTable();
}

void outcome_summary(const PlaceOutcome& out) {
  const design::PlacementResult& r = out.result;
  if (!out.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    ImGui::TextWrapped("placement failed: %s", out.error.c_str());
    ImGui::PopStyleColor();
    return;
  }
  const bool complete = r.status == design::PlacementResult::Status::kComplete;
  ImGui::TextWrapped("last: %d of %d sites, %s, %s, %.1f s", static_cast<int>(r.chosen.size()),
                     out.n_candidates, r.search.c_str(), design::to_string(r.status), out.seconds);
  if (!complete) {
    ImGui::PushStyleColor(ImGuiCol_Text, kWarningText);
    ImGui::TextWrapped("%s (coverage %.2f %%; layout kept)", r.message.c_str(),
                       100.0 * r.value.coverage);
    ImGui::PopStyleColor();
    return;
  }
  ImGui::Text("certified p\u0304_min %.6f, coverage %.2f %%", r.value.pbar_min,
              100.0 * r.value.coverage);
  if (r.robust) {
    ImGui::TextWrapped("after losing any one marker: p\u0304_min %.6f, coverage %.2f %%",
                       r.robust->pbar_min, 100.0 * r.robust->coverage);
  }
  const design::RandomBaseline& b = r.random_baseline;
  ImGui::TextWrapped("random baseline (%d trials, %d complete): best %.4f, median %.4f", b.trials,
                     b.complete, b.best_pbar_min, b.median_pbar_min);
  steps_table(r);
}

}  // namespace

void Panels::placement_panel(ViewerSession& session) {
  const LayoutDocument& doc = session.document();
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
  ImGui::PopItemWidth();
  place_settings_.markers = std::clamp(place_settings_.markers, 3, kMaxMarkers);
  place_settings_.candidates = std::clamp(place_settings_.candidates, 1, kMaxCandidates);
  place_settings_.min_separation = std::max(place_settings_.min_separation, 0.0);
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
