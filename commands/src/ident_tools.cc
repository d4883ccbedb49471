// Tool files and each tool's own minimum markers (ident_tools.h).

#include "vantage/commands/ident_tools.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "vantage/analysis/common.h"
#include "vantage/io/ndi_rom.h"
#include "vantage/io/text_file.h"

namespace vantage::commands {

namespace {

bool is_tool_file(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".json" || extension == ".csv" || extension == ".ini" || extension == ".rom";
}

}  // namespace

std::vector<std::string> tool_files(const std::vector<std::string>& paths) {
  std::vector<std::string> out;
  for (const std::string& path : paths) {
    std::error_code error;
    if (!std::filesystem::is_directory(path, error)) {
      out.push_back(path);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(path, error)) {
      if (entry.is_regular_file(error) && is_tool_file(entry.path())) {
        found.push_back(entry.path().string());
      }
    }
    if (found.empty()) {
      throw InvalidArgument(path + ": holds no tool files (.json, .csv, .ini, .rom)");
    }
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
  }
  return out;
}

int own_min_visible(const Layout& tool) {
  return tool.visibility ? tool.visibility->min_visible : 3;
}

IdentTool read_ident_tool(const std::string& path, const io::LayoutReadOptions& options) {
  const std::string bytes = io::read_text_file(path, options.max_bytes);
  IdentTool tool;
  tool.layout = io::parse_layout_as(bytes, path, options);
  io::load_body(path, &tool.layout);
  const io::LayoutFormat format =
      options.format == io::LayoutFormat::kAuto ? io::layout_format_of(path) : options.format;
  tool.min_visible = format == io::LayoutFormat::kNdiRom
                         ? io::ndi_rom_min_markers(bytes, path, tool.layout.entries.cols())
                         : own_min_visible(tool.layout);
  return tool;
}

}  // namespace vantage::commands
