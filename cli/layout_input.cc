#include "layout_input.h"

#include "limits.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/text_file.h"

namespace vantage::cli {

void LayoutInput::add_options(CLI::App* sub, const std::string& format_flag, bool body_options) {
  format_option = format_flag;
  sub->add_option(format_flag, format,
                  "layout file format; auto: by extension (.json, .csv name,x,y,z[,weight], "
                  ".yaml/.yml AprilTag tag_bundles, .ini Atracsys geometry, .rom NDI tool "
                  "definition)")
      ->check(CLI::IsMember({"auto", "json", "csv", "apriltag", "atracsys", "ndi"}))
      ->capture_default_str();
  sub->add_option("--tag-points", tag_points,
                  "AprilTag bundles: the markers are each tag's four corners or its centre")
      ->check(CLI::IsMember({"corners", "centres", "centers"}))
      ->capture_default_str();
  sub->add_option("--bundle", bundle,
                  "AprilTag bundles: the name of the bundle to read (needed when the file has "
                  "several)");
  if (body_options) visibility.add_options(sub);
}

Layout LayoutInput::read(const std::string& path, bool allow_large) const {
  io::LayoutReadOptions options;
  options.max_bytes = allow_large ? kMaxFileBytesAllowLarge : kMaxFileBytes;
  options.format = io::layout_format_from_string(format, format_option);
  options.apriltag.tag_points = io::tag_points_from_string(tag_points, "--tag-points");
  options.apriltag.bundle = bundle;
  try {
    Layout layout = io::load_layout(path, options);
    visibility.apply(&layout);
    return layout;
  } catch (const io::FileTooLarge& e) {
    throw io::FileTooLarge(std::string(e.what()) +
                           (allow_large ? "" : " (--allow-large raises it to 1 GiB)"));
  }
}

}  // namespace vantage::cli
