#pragma once

/// One entry point for every layout file format vantage reads and writes: layout JSON
/// (layout_file.h), CSV marker sets (csv_layout.h), AprilTag bundles (apriltag_bundle.h),
/// Atracsys geometry files (atracsys_geometry.h) and NDI tool definitions (ndi_rom.h).
/// The format comes from the file's extension unless given: .json -> JSON, .csv -> CSV,
/// .yaml/.yml -> AprilTag, .ini -> Atracsys, .rom -> NDI. Every command, the viewer and the
/// Python module read with load_layout() and write with save_layout(), so each reads every
/// format and writes the one its target's extension names (AprilTag bundles and NDI tool
/// definitions are read only).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "vantage/analysis/layout.h"
#include "vantage/io/apriltag_bundle.h"
#include "vantage/io/text_file.h"

namespace vantage::io {

/// A layout file format.
enum class LayoutFormat {
  kAuto,      ///< from the extension
  kJson,      ///< vantage layout JSON
  kCsv,       ///< name,x,y,z[,weight]
  kAprilTag,  ///< ROS apriltag tags.yaml, tag_bundles
  kAtracsys,  ///< Atracsys fusionTrack / spryTrack geometry .ini
  kNdiRom,    ///< NDI tool definition .rom (binary)
};

/// "auto" | "json" | "csv" | "apriltag" | "atracsys" | "ndi"; throws InvalidArgument naming
/// `option` otherwise.
LayoutFormat layout_format_from_string(const std::string& name, const std::string& option);

/// "auto", "json", "csv", "apriltag", "atracsys" or "ndi".
const char* to_string(LayoutFormat format);

/// The format of `path` by its extension (case-insensitive). Throws InvalidArgument
/// "<path>: cannot tell the layout format from the extension ..." for any other extension.
LayoutFormat layout_format_of(const std::string& path);

/// How to read a layout file.
struct LayoutReadOptions {
  LayoutFormat format = LayoutFormat::kAuto;
  AprilTagOptions apriltag;               ///< used for AprilTag bundles only
  std::size_t max_bytes = kMaxFileBytes;  ///< larger files are refused (io::FileTooLarge)
};

/// Parses `text` in `format` (kAuto: by the extension of `source`).
Layout parse_layout_as(std::string_view text, const std::string& source,
                       const LayoutReadOptions& options = {});

/// Reads the layout file at `path` in any supported format (errors name the path).
Layout load_layout(const std::string& path, const LayoutReadOptions& options = {});

/// Reads the body mesh a layout names ("visibility": {"body": ...}, relative to the layout
/// file's directory) into layout->visibility->body; nothing without one. Throws InvalidArgument
/// "<layout_path>: visibility.body: <why>" when the mesh does not load. load_layout() calls it.
void load_body(const std::string& layout_path, Layout* layout);

/// The format save_layout() writes to `path`: kJson for .json, kCsv for .csv, kAtracsys for .ini
/// (case-insensitive; an .ini name must end its stem in the geometry id,
/// atracsys_geometry_id_of()), kNdiRom for .rom. Throws InvalidArgument "<path>: ..." for
/// .yaml/.yml (AprilTag bundles describe printed tags, which a layout does not hold), for an
/// .ini name without the id, and for any other extension.
LayoutFormat layout_write_format(const std::string& path);

/// The layout as the text of `format` (kJson: layout_to_json, kCsv: layout_to_csv, kAtracsys:
/// layout_to_atracsys_geometry with `geometry_id`, kNdiRom: the 752 bytes of
/// ndi_rom_of_layout()). Throws InvalidArgument for what the format cannot hold (csv_layout.h,
/// atracsys_geometry.h, ndi_rom.h), for AprilTag bundles (read only) and for an invalid layout.
std::string layout_to_text(const Layout& layout, LayoutFormat format,
                           std::uint32_t geometry_id = 0);

/// Writes the layout to `path` in the format of its extension (layout_write_format; an .ini
/// gets the geometry id its name ends in), all or nothing (write_text_file): an existing file is
/// replaced only with `overwrite`. Everything is checked before the file is touched; errors name
/// the path.
void save_layout(const std::string& path, const Layout& layout, bool overwrite = false);

}  // namespace vantage::io
