// `vantage ident TOOL|FOLDER ... [--min-visible K] [--same-tolerance D] [--json]`: how close
// the tools of a library come to each other by their inter-marker distances (issues 20 and 37;
// docs/math.md §24, Eq. 24.4): for every two tools, and for each tool against itself
// relabelled, the least largest distance mismatch of a view of k markers (each tool's own
// minimum, the smaller of a pair's two, unless --min-visible sets one k), which markers give it,
// whether it fits as a rotation or only as a reflection (a mirror image), and whether the two
// files hold one tool, mirror images or distinct tools.

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "command.h"
#include "limits.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/layout.h"
#include "vantage/commands/ident_json.h"
#include "vantage/commands/ident_tools.h"
#include "vantage/io/layout_formats.h"
#include "vantage/tracker/tool_match.h"

namespace vantage::cli {

namespace {

// A 3-D registration needs three markers (DESIGN: min_visible >= 3).
constexpr int kMinIdentVisible = 3;

struct IdentArgs {
  std::vector<std::string> files;
  int min_visible = 0;  // 0: each tool's own
  CLI::Option* min_visible_option = nullptr;
  double same_tolerance = tracker::ToolMatchOptions{}.same_tolerance;
  std::string format = "auto";
  bool json = false;
  bool allow_large = false;
};

// The tools of the files and folders, and each one's k (--min-visible, or its own).
std::vector<Layout> read_tools(const IdentArgs& args, const std::vector<std::string>& files,
                               std::vector<int>* min_visible) {
  io::LayoutReadOptions options;
  options.max_bytes = args.allow_large ? kMaxFileBytesAllowLarge : kMaxFileBytes;
  options.format = io::layout_format_from_string(args.format, "--format");
  std::vector<Layout> tools;
  for (const std::string& file : files) {
    commands::IdentTool read;
    try {
      read = commands::read_ident_tool(file, options);
    } catch (const io::FileTooLarge& e) {
      throw io::FileTooLarge(std::string(e.what()) +
                             (args.allow_large ? "" : " (--allow-large raises it to 1 GiB)"));
    }
    tools.push_back(std::move(read.layout));
    const Layout& tool = tools.back();
    if (tool.mode != LayoutMode::kPoints) {
      throw InvalidArgument(file + ": vectors: a tool needs marker positions (\"points\")");
    }
    const bool given = args.min_visible_option->count() > 0;
    min_visible->push_back(given ? args.min_visible : read.min_visible);
    if (given && tool.entries.cols() < args.min_visible) {
      throw InvalidArgument("--min-visible", std::to_string(args.min_visible) + " exceeds the " +
                                                 std::to_string(tool.entries.cols()) +
                                                 " markers of " + file);
    }
  }
  return tools;
}

std::string marker_list(const Layout& tool, const std::vector<int>& markers) {
  std::string out;
  for (int i : markers) out += (out.empty() ? "" : " ") + tool.entry_name(i);
  return out;
}

std::string tool_label(const std::vector<Layout>& tools, const std::vector<std::string>& files,
                       int t) {
  const Layout& tool = tools[static_cast<std::size_t>(t)];
  return tool.name.empty() ? files[static_cast<std::size_t>(t)] : tool.name;
}

void print_pair(const tracker::ToolPairMatch& p, const std::vector<Layout>& tools) {
  const tracker::ToolMatch& m = p.match;
  const Layout& a = tools[static_cast<std::size_t>(p.a)];
  const Layout& b = tools[static_cast<std::size_t>(p.b)];
  std::cout << "  " << p.a << " vs " << p.b << "  " << to_string(p.verdict) << "  k "
            << p.min_visible << "  " << format_number(m.mismatch, 5)
            << (m.certified ? "" : " (budget spent; >= " + format_number(m.mismatch_lower, 5) + ")")
            << "  " << marker_list(a, m.subset) << " -> " << marker_list(b, m.assignment) << "  "
            << to_string(m.transform) << " (RMS rotation " << format_number(m.proper_rms, 4)
            << ", reflection " << format_number(m.improper_rms, 4) << ")\n";
}

// The n x n mismatches, for a library small enough to read as a table.
void print_matrix(const tracker::ToolLibraryMatches& r) {
  constexpr long kLargestTable = 20;
  const Eigen::MatrixXd m = r.mismatch_matrix();
  if (m.rows() > kLargestTable) {
    std::cout << "\nmatrix: " << m.rows() << " x " << m.rows() << " (in --json)\n";
    return;
  }
  auto line = [](std::string text) {
    text.erase(text.find_last_not_of(' ') + 1);
    std::cout << text << "\n";
  };
  std::cout << "\nmatrix of mismatches (row a, column b; the diagonal: each tool relabelled)\n";
  std::string header = "   ";
  for (Eigen::Index b = 0; b < m.cols(); ++b) header += pad(std::to_string(b), 11);
  line(header);
  for (Eigen::Index a = 0; a < m.rows(); ++a) {
    std::string row = pad(std::to_string(a), 3);
    for (Eigen::Index b = 0; b < m.cols(); ++b) row += pad(format_number(m(a, b), 4), 11);
    line(row);
  }
}

void print_closest(const char* title, const tracker::ToolLibraryMatches& r, int index,
                   const std::vector<Layout>& tools, const std::vector<std::string>& files) {
  if (index < 0) return;
  const tracker::ToolPairMatch& p = r.pairs[static_cast<std::size_t>(index)];
  std::cout << title << p.a << " vs " << p.b << ": mismatch " << format_number(p.match.mismatch, 5)
            << " (" << tool_label(tools, files, p.a)
            << (p.a == p.b ? ", relabelled" : " vs " + tool_label(tools, files, p.b)) << ")\n";
}

void print_report(const tracker::ToolLibraryMatches& r, const std::vector<Layout>& tools,
                  const std::vector<std::string>& files, bool given) {
  std::cout << "vantage ident: " << tools.size() << " tool" << (tools.size() == 1 ? "" : "s")
            << ", views of k markers (" << (given ? "--min-visible" : "each tool's own minimum")
            << "; a pair: the smaller of its two)\n  mismatch: the least, over views of k markers "
               "of one tool and labellings by the other, of the largest inter-marker distance "
               "error (docs/math.md §24);\n  a tracker whose distance tolerance reaches it can "
               "take one for the other; same_tool / mirror: every marker matches within the "
               "tolerance, by a rotation / only by a reflection\n\ntools\n";
  for (std::size_t t = 0; t < tools.size(); ++t) {
    std::cout << "  " << t << "  " << tool_label(tools, files, static_cast<int>(t)) << "  ("
              << tools[t].entries.cols() << " markers, k " << r.min_visible[t] << ", " << files[t]
              << ")\n";
  }
  std::cout << "\npairs: verdict, k, mismatch, markers of the first -> markers of the second, best "
               "fit\n";
  for (const tracker::ToolPairMatch& p : r.pairs) print_pair(p, tools);
  print_matrix(r);
  std::cout << "\n";
  print_closest("closest           ", r, r.closest, tools, files);
  print_closest("closest distinct  ", r, r.closest_distinct, tools, files);
}

int run_ident(const IdentArgs& args) {
  const bool given = args.min_visible_option->count() > 0;
  if (given && args.min_visible < kMinIdentVisible) {
    throw InvalidArgument("--min-visible",
                          "must be >= 3 (a 3-D registration needs three "
                          "markers)");
  }
  if (!(args.same_tolerance >= 0.0 && std::isfinite(args.same_tolerance))) {
    throw InvalidArgument("--same-tolerance", "must be finite and >= 0");
  }
  const std::vector<std::string> files = commands::tool_files(args.files);
  check_limit("TOOL files", static_cast<long>(files.size()), kMaxIdentTools, "ident",
              args.allow_large);
  std::vector<int> min_visible;
  const std::vector<Layout> tools = read_tools(args, files, &min_visible);
  std::vector<Eigen::Matrix3Xd> points;
  for (const Layout& tool : tools) points.push_back(tool.entries);
  tracker::ToolMatchOptions options;
  options.same_tolerance = args.same_tolerance;
  const tracker::ToolLibraryMatches matches =
      tracker::match_tool_library(points, options, min_visible);
  if (args.json) {
    print_json(ident_json::report_without_pairs(matches, tools, files), "pairs",
               matches.pairs.size(),
               [&](std::size_t i) { return ident_json::pair(matches.pairs[i], tools); });
  } else {
    print_report(matches, tools, files, given);
  }
  return kExitOk;
}

}  // namespace

Command add_ident_command(CLI::App& root) {
  auto args = std::make_shared<IdentArgs>();
  CLI::App* sub = root.add_subcommand(
      "ident",
      "how close the tools of a library come by their inter-marker distances (docs/math.md "
      "§24): every pair and each tool relabelled, mirror images included");
  sub->add_option("TOOL", args->files,
                  "tool files (points: .json, .csv, .ini, .rom) or folders of them; at most " +
                      std::to_string(kMaxIdentTools) + " tools without --allow-large")
      ->required();
  args->min_visible_option = sub->add_option(
      "--min-visible", args->min_visible,
      "K: the markers a view holds, for every tool (>= 3, at most every tool's markers); "
      "default: each tool's own (a .rom's minimum markers, a layout's visibility.min_visible, "
      "else 3), a pair the smaller of its two");
  sub->add_option("--same-tolerance", args->same_tolerance,
                  "D: two tools with as many markers whose every marker matches within this "
                  "distance error (the tools' units, mm) are one tool (or mirror images)")
      ->capture_default_str();
  sub->add_option("--format", args->format, "tool file format; auto: by extension")
      ->check(CLI::IsMember({"auto", "json", "csv", "atracsys", "ndi"}))
      ->capture_default_str();
  add_allow_large_flag(sub, args->allow_large);
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_ident(*args); }};
}

}  // namespace vantage::cli
