#include "vantage/io/layout_formats.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "json_fields.h"
#include "vantage/analysis/common.h"
#include "vantage/io/atracsys_geometry.h"
#include "vantage/io/csv_layout.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/mesh_file.h"
#include "vantage/io/ndi_rom.h"
#include "vantage/io/printable.h"

namespace vantage::io {

LayoutFormat layout_format_from_string(const std::string& name, const std::string& option) {
  if (name == "auto") return LayoutFormat::kAuto;
  if (name == "json") return LayoutFormat::kJson;
  if (name == "csv") return LayoutFormat::kCsv;
  if (name == "apriltag") return LayoutFormat::kAprilTag;
  if (name == "atracsys") return LayoutFormat::kAtracsys;
  if (name == "ndi") return LayoutFormat::kNdiRom;
  throw InvalidArgument(option + ": expected auto, json, csv, apriltag, atracsys or ndi, got \"" +
                        printable(name) + "\"");
}

const char* to_string(LayoutFormat format) {
  switch (format) {
    case LayoutFormat::kAuto:
      return "auto";
    case LayoutFormat::kJson:
      return "json";
    case LayoutFormat::kCsv:
      return "csv";
    case LayoutFormat::kAprilTag:
      return "apriltag";
    case LayoutFormat::kAtracsys:
      return "atracsys";
    case LayoutFormat::kNdiRom:
      return "ndi";
  }
  return "unknown";
}

namespace {

std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace

LayoutFormat layout_format_of(const std::string& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".json") return LayoutFormat::kJson;
  if (extension == ".csv") return LayoutFormat::kCsv;
  if (extension == ".yaml" || extension == ".yml") return LayoutFormat::kAprilTag;
  if (extension == ".ini") return LayoutFormat::kAtracsys;
  if (extension == ".rom") return LayoutFormat::kNdiRom;
  internal::fail(path, "cannot tell the layout format from the extension \"" + extension +
                           "\" (.json, .csv, .yaml, .yml, .ini or .rom); give --format "
                           "json|csv|apriltag|atracsys|ndi");
}

Layout parse_layout_as(std::string_view text, const std::string& source,
                       const LayoutReadOptions& options) {
  const LayoutFormat format =
      options.format == LayoutFormat::kAuto ? layout_format_of(source) : options.format;
  switch (format) {
    case LayoutFormat::kCsv:
      return parse_csv_layout(text, source);
    case LayoutFormat::kAprilTag:
      return parse_apriltag_layout(text, source, options.apriltag);
    case LayoutFormat::kAtracsys:
      return parse_atracsys_layout(text, source);
    case LayoutFormat::kNdiRom:
      return parse_ndi_rom_layout(text, source);
    case LayoutFormat::kJson:
    case LayoutFormat::kAuto:
      break;
  }
  return parse_layout(text, source);
}

Layout load_layout(const std::string& path, const LayoutReadOptions& options) {
  Layout layout = parse_layout_as(read_text_file(path, options.max_bytes), path, options);
  load_body(path, &layout);
  return layout;
}

void load_body(const std::string& layout_path, Layout* layout) {
  if (!layout->visibility || layout->visibility->body_path.empty()) return;
  const std::filesystem::path body(layout->visibility->body_path);
  const std::filesystem::path resolved =
      body.is_absolute() ? body : std::filesystem::path(layout_path).parent_path() / body;
  try {
    layout->visibility->body = read_mesh(resolved.string());
  } catch (const InvalidArgument& e) {
    internal::fail(layout_path, "visibility.body: " + std::string(e.what()));
  }
  // From here on the path names the mesh wherever the layout goes (save_layout() writes it
  // relative to the file it writes).
  layout->visibility->body_path = std::filesystem::absolute(resolved).lexically_normal().string();
}

LayoutFormat layout_write_format(const std::string& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".json") return LayoutFormat::kJson;
  if (extension == ".csv") return LayoutFormat::kCsv;
  if (extension == ".ini") {
    atracsys_geometry_id_of(path);
    return LayoutFormat::kAtracsys;
  }
  if (extension == ".yaml" || extension == ".yml") {
    internal::fail(path,
                   "cannot write an AprilTag bundle (it describes printed tags, which a layout "
                   "does not hold); name the file .json, .csv, .ini or .rom");
  }
  if (extension == ".rom") return LayoutFormat::kNdiRom;
  internal::fail(path, "cannot tell the layout format from the extension \"" + extension +
                           "\"; name the file .json, .csv, .ini or .rom");
}

std::string layout_to_text(const Layout& layout, LayoutFormat format, std::uint32_t geometry_id) {
  if (format == LayoutFormat::kCsv) return layout_to_csv(layout);
  if (format == LayoutFormat::kAtracsys) return layout_to_atracsys_geometry(layout, geometry_id);
  if (format == LayoutFormat::kNdiRom) return ndi_rom_bytes(ndi_rom_of_layout(layout));
  if (format == LayoutFormat::kAprilTag) {
    throw InvalidArgument(
        "format: AprilTag bundles are read only; write json, csv, atracsys or rom");
  }
  layout.validate();
  return layout_to_json(layout);
}

void save_layout(const std::string& path, const Layout& layout, bool overwrite) {
  const LayoutFormat format = layout_write_format(path);
  const std::uint32_t id = format == LayoutFormat::kAtracsys ? atracsys_geometry_id_of(path) : 0;
  std::string text;
  try {
    if (layout.visibility && !layout.visibility->body_path.empty()) {
      // The body's path as the written file will read it: relative to the file's directory.
      Layout moved = layout;
      const std::filesystem::path body =
          std::filesystem::absolute(layout.visibility->body_path).lexically_normal();
      const std::filesystem::path directory = std::filesystem::path(path).parent_path();
      const std::filesystem::path from =
          std::filesystem::absolute(directory.empty() ? "." : directory).lexically_normal();
      const std::filesystem::path relative = body.lexically_relative(from);
      moved.visibility->body_path = relative.empty() ? body.string() : relative.string();
      text = layout_to_text(moved, format, id);
    } else {
      text = layout_to_text(layout, format, id);
    }
  } catch (const InvalidArgument& e) {
    internal::fail(path, e.what());
  }
  write_text_file(path, text, overwrite);
}

}  // namespace vantage::io
