// `vantage ident TOOL [TOOL ...] [--min-visible K] [--json]`: how close the tools of a library
// come to each other by their inter-marker distances (issue 20; docs/math.md §24, Eq. 24.4):
// for every two tools, and for each tool against itself relabelled, the least largest distance
// mismatch of a view of K markers, which markers give it, and whether it fits as a rotation or
// only as a reflection (a mirror image).

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "command.h"
#include "limits.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/layout.h"
#include "vantage/commands/ident_json.h"
#include "vantage/io/layout_formats.h"
#include "vantage/tracker/tool_match.h"

namespace vantage::cli {

namespace {

// A 3-D registration needs three markers (DESIGN: min_visible >= 3).
constexpr int kMinIdentVisible = 3;

struct IdentArgs {
  std::vector<std::string> files;
  int min_visible = kMinIdentVisible;
  std::string format = "auto";
  bool json = false;
  bool allow_large = false;
};

std::vector<Layout> read_tools(const IdentArgs& args) {
  io::LayoutReadOptions options;
  options.max_bytes = args.allow_large ? kMaxFileBytesAllowLarge : kMaxFileBytes;
  options.format = io::layout_format_from_string(args.format, "--format");
  std::vector<Layout> tools;
  for (const std::string& file : args.files) {
    try {
      tools.push_back(io::load_layout(file, options));
    } catch (const io::FileTooLarge& e) {
      throw io::FileTooLarge(std::string(e.what()) +
                             (args.allow_large ? "" : " (--allow-large raises it to 1 GiB)"));
    }
    const Layout& tool = tools.back();
    if (tool.mode != LayoutMode::kPoints) {
      throw InvalidArgument(file + ": vectors: a tool needs marker positions (\"points\")");
    }
    if (tool.entries.cols() < args.min_visible) {
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
  std::cout << "  " << p.a << " vs " << p.b << (p.a == p.b ? " (self)" : "       ") << "  "
            << format_number(m.mismatch, 5)
            << (m.certified ? "" : " (budget spent; >= " + format_number(m.mismatch_lower, 5) + ")")
            << "  " << marker_list(a, m.subset) << " -> " << marker_list(b, m.assignment) << "  "
            << to_string(m.transform) << " (RMS rotation " << format_number(m.proper_rms, 4)
            << ", reflection " << format_number(m.improper_rms, 4) << ")\n";
}

void print_report(const tracker::ToolLibraryMatches& r, const std::vector<Layout>& tools,
                  const std::vector<std::string>& files) {
  std::cout << "vantage ident: " << tools.size() << " tool" << (tools.size() == 1 ? "" : "s")
            << ", views of " << r.min_visible
            << " markers (--min-visible)\n  mismatch: the least, over views of K markers of one "
               "tool and labellings by the other, of the largest inter-marker distance error "
               "(docs/math.md §24);\n  a tracker whose distance tolerance reaches it can take "
               "one for the other; (self): the tool against itself relabelled\n\ntools\n";
  for (std::size_t t = 0; t < tools.size(); ++t) {
    std::cout << "  " << t << "  " << tool_label(tools, files, static_cast<int>(t)) << "  ("
              << tools[t].entries.cols() << " markers, " << files[t] << ")\n";
  }
  std::cout << "\npairs: mismatch, markers of the first -> markers of the second, best fit\n";
  for (const tracker::ToolPairMatch& p : r.pairs) print_pair(p, tools);
  const tracker::ToolPairMatch& closest = r.pairs[static_cast<std::size_t>(r.closest)];
  std::cout << "\nclosest  " << closest.a << " vs " << closest.b << ": mismatch "
            << format_number(closest.match.mismatch, 5) << " ("
            << tool_label(tools, files, closest.a)
            << (closest.a == closest.b ? ", relabelled"
                                       : " vs " + tool_label(tools, files, closest.b))
            << ")\n";
}

int run_ident(const IdentArgs& args) {
  if (args.min_visible < kMinIdentVisible) {
    throw InvalidArgument("--min-visible",
                          "must be >= 3 (a 3-D registration needs three "
                          "markers)");
  }
  check_limit("TOOL files", static_cast<long>(args.files.size()), kMaxIdentTools, "ident",
              args.allow_large);
  const std::vector<Layout> tools = read_tools(args);
  std::vector<Eigen::Matrix3Xd> points;
  for (const Layout& tool : tools) points.push_back(tool.entries);
  tracker::ToolMatchOptions options;
  options.min_visible = args.min_visible;
  const tracker::ToolLibraryMatches matches = tracker::match_tool_library(points, options);
  if (args.json) {
    print_json(ident_json::report_without_pairs(matches, tools, args.files), "pairs",
               matches.pairs.size(),
               [&](std::size_t i) { return ident_json::pair(matches.pairs[i], tools); });
  } else {
    print_report(matches, tools, args.files);
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
                  "tool files (points: .json, .csv, .ini, .rom); at most " +
                      std::to_string(kMaxIdentTools) + " without --allow-large")
      ->required();
  sub->add_option("--min-visible", args->min_visible,
                  "K: the markers a view holds (>= 3, at most every tool's markers)")
      ->capture_default_str();
  sub->add_option("--format", args->format, "tool file format; auto: by extension")
      ->check(CLI::IsMember({"auto", "json", "csv", "atracsys", "ndi"}))
      ->capture_default_str();
  add_allow_large_flag(sub, args->allow_large);
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_ident(*args); }};
}

}  // namespace vantage::cli
