// analyze_layout(): the one assembly of a layout's report (the analysis seen whole, the
// ceiling, coplanarity and, when asked, dropout), and its verdict in words.

#include "vantage/report/layout_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/sdp/internal/message_parts.h"

namespace vantage::report {
namespace {

std::string number(double x, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << (x == 0.0 ? 0.0 : x);
  return out.str();
}

std::string vector_text(const Eigen::Vector3d& v);

/// The head of the report for a layout on its body: what the user will meet.
std::string visibility_brief(const visibility::VisibilityReport& v) {
  std::ostringstream out;
  out << "on its body (" << (v.with_body ? "cones and the body's shadow" : "marker cones")
      << ", at least " << v.min_visible << " markers seen):\n";
  const std::string trackable = "  trackable            " +
                                number(100.0 * v.coverage.trackable_fraction, 4) + " % of " +
                                (v.workspace ? "the workspace" : "the sphere of directions") + "\n";
  if (v.worst.status == visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
    out << "  UNTRACKABLE          no direction sees " << v.min_visible
        << " markers that are not collinear\n"
        << trackable;
    return out.str();
  }
  out << "  pbar_min             " << number(v.worst.pbar_min, 9) << "\n"
      << "  max worst-case error " << number(v.max_worst_case_error_deg, 6) << " deg (Eq. 30)\n"
      << "  worst viewpoint a    " << vector_text(v.worst.viewpoint) << " ("
      << v.worst.visible_markers.size() << " markers visible)\n"
      << trackable << "  certificate          t in [" << number(v.worst.t_lower, 12) << ", "
      << number(v.worst.t_upper, 12) << "], ";
  if (v.worst.certified() && v.occlusion_resolution_deg) {
    out << "certified on the occlusion grid at " << number(*v.occlusion_resolution_deg, 3)
        << " deg, not under exact rays";
  } else {
    out << to_string(v.worst.status);
    if (v.occlusion_resolution_deg) {
      out << ", occlusion at " << number(*v.occlusion_resolution_deg, 3) << " deg";
    }
  }
  out << "\n";
  if (v.exact_viewpoint_disagrees()) {
    out << "  exact rays           the worst viewpoint sees " << v.exact_viewpoint->visible.size()
        << " markers, not " << v.worst.visible_markers.size() << ": "
        << (v.exact_viewpoint->trackable ? "t " + number(v.exact_viewpoint->t, 9)
                                         : std::string("not trackable"))
        << " (the occlusion grid's cells decide its neighbourhood wrongly)\n";
  }
  return out.str();
}

std::string vector_text(const Eigen::Vector3d& v) {
  std::string out = "[";
  for (int i = 0; i < 3; ++i) {
    const double x = std::abs(v(i)) < 5e-7 ? 0.0 : v(i);
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), " %10.6f", x);
    out += buffer;
  }
  return out + " ]";
}

/// The analysis of the data vectors; a library error about data vector k is named as the file
/// names it: vectors[k], or the two points of free vector k.
sdp::LayoutAnalysis analyze_data(const Layout& layout, const DataVectors& data,
                                 const sdp::LayoutAnalysisOptions& options) {
  try {
    return sdp::analyze_vectors(data.vectors, data.weights, options);
  } catch (const InvalidArgument& e) {
    if (layout.mode != LayoutMode::kPoints || e.field() != "vectors" || !e.index()) throw;
    const auto& [i, j] = data.pairs[static_cast<std::size_t>(*e.index())];
    throw InvalidArgument(
        "points", j, "minus points[" + std::to_string(i) + "] (a free vector): " + e.problem());
  }
}

}  // namespace

bool LayoutReportOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!analysis.is_valid(&inner)) return vantage::internal::invalid_option(why, "analysis", inner);
  if (!dropout_options.is_valid(&inner)) {
    return vantage::internal::invalid_option(why, "dropout_options", inner);
  }
  if (!(coplanarity_threshold >= 0.0)) {
    return vantage::internal::invalid_option(why, "coplanarity_threshold", "must be >= 0");
  }
  if (!visibility.is_valid(&inner)) {
    return vantage::internal::invalid_option(why, "visibility", inner);
  }
  if (!identification.is_valid(&inner)) {
    return vantage::internal::invalid_option(why, "identification", inner);
  }
  return true;
}

LayoutReport analyze_layout(const Layout& layout, const LayoutReportOptions& options) {
  vantage::internal::check_options("options", options);
  LayoutReport report;
  report.layout = layout;
  report.data = data_vectors(layout, options.pair_weighting);
  report.analysis = analyze_data(layout, report.data, options.analysis);
  report.ceiling = sdp::pbar_ceiling(report.data.vectors.cols());
  report.coplanarity = sdp::coplanarity(report.data.vectors, options.coplanarity_threshold);
  if (layout.mode == LayoutMode::kPoints) {
    report.identification = tracker::identification_margins(layout.entries, options.identification);
  }
  if (options.dropout) {
    if (options.analysis.progress) options.analysis.progress("dropout");
    report.dropout = dropout_analysis(layout, options.dropout_options);
  }
  if (layout.visibility) {
    if (layout.visibility->body) report.mesh = mesh_report(*layout.visibility->body);
    if (options.analysis.progress) options.analysis.progress("visibility");
    visibility::VisibilityReportOptions visibility = options.visibility;
    visibility.dropout = options.dropout;
    report.visibility = visibility::analyze_visibility(layout, visibility);
  }
  return report;
}

bool LayoutReport::is_usable() const {
  return analysis.trusted() && !analysis.degenerate && !analysis.near_degenerate &&
         (!dropout || dropout->status == DropoutAnalysis::Status::kCertified) &&
         (!visibility || visibility->is_usable());
}

std::string LayoutReport::message() const {
  std::string out = analysis.message;
  if (out.empty() && !analysis.trusted()) out = "result not certified";
  if (dropout && dropout->status != DropoutAnalysis::Status::kCertified) {
    sdp::internal::append_message(
        &out,
        "dropout: " + (dropout->message.empty() ? std::string("not certified") : dropout->message));
  }
  if (visibility && !visibility->is_usable()) {
    sdp::internal::append_message(&out, visibility->message());
  }
  return out;
}

std::string LayoutReport::brief_report() const {
  const sdp::LayoutAnalysis& r = analysis;
  std::ostringstream out;
  if (visibility)
    out << visibility_brief(*visibility) << "seen whole (every marker from everywhere):\n";
  if (r.degenerate && !data.pairs.empty()) {
    // Collinear markers: a tracker tool of them measures five degrees of freedom.
    out << "5-DOF TOOL             every marker is on one line: the rotation about it is not "
           "measured (`vantage tre --target` on the line gives a target's error; "
           "docs/math.md §23)\n";
  } else if (r.degenerate) {
    out << "DEGENERATE             every data vector is parallel to one line: the rotation "
           "about it is not determined\n";
  } else if (r.near_degenerate) {
    out << "NEAR-DEGENERATE        every data vector is within " << number(std::asin(r.pbar_min), 3)
        << " rad of one line: the rotation about it is barely determined\n";
  }
  out << "pbar_min = sqrt(1-t^2) " << number(r.pbar_min, 9) << "   (ceiling for "
      << data.vectors.cols() << " vectors: " << number(ceiling, 6) << ")\n"
      << "max worst-case error   " << number(r.max_worst_case_error_deg, 6) << " deg (Eq. 30)"
      << (r.degenerate        ? ", and the rotation about the line is free"
          : r.near_degenerate ? ", and the rotation about the line is barely determined"
                              : "")
      << "\n"
      << "worst viewpoint a      " << vector_text(r.worst_viewpoint) << "\n";
  for (std::size_t k = 1; k < r.worst_viewpoints.size(); ++k) {
    out << "  also (tie)           " << vector_text(r.worst_viewpoints[k]) << "\n";
  }
  out << "certificate            t in [" << number(r.certificate.t_lower, 12) << ", "
      << number(r.certificate.t_upper, 12) << "], " << to_string(r.solver.status) << ", "
      << r.solver.cells_solved << " cells solved, confirmed on " << to_string(r.solver.backend)
      << " (" << to_string(r.solver.sdp_status) << ")\n";
  return out.str();
}

std::string LayoutReport::entry_label(long k) const { return layout.entry_name(k); }

std::string LayoutReport::vector_label(long k) const {
  if (data.pairs.empty()) return "v" + std::to_string(k);
  const auto& [i, j] = data.pairs[static_cast<std::size_t>(k)];
  return entry_label(i) + "-" + entry_label(j);
}

}  // namespace vantage::report
