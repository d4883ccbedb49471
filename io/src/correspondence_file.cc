#include "vantage/io/correspondence_file.h"

#include <cmath>

#include "json_fields.h"
#include "vantage/io/layout_file.h"

namespace vantage::io {

using internal::fail;

void CorrespondenceFile::require(std::initializer_list<const char*> fields,
                                 const std::string& purpose) const {
  for (const std::string field : fields) {
    const bool present = (field == "model" && has_model) || (field == "measured" && has_measured) ||
                         (field == "image" && has_image) || (field == "image1" && has_image1) ||
                         (field == "image2" && has_image2);
    if (!present) fail(source, field + ": missing, required by " + purpose);
  }
}

namespace {

void check_count(const std::string& source, const std::string& field, Eigen::Index got,
                 const std::string& reference, Eigen::Index expected) {
  if (got != expected) {
    fail(source, field + ": has " + std::to_string(got) + " entries but " + reference + " has " +
                     std::to_string(expected));
  }
}

/// "camera": {"focal": F > 0, "principal_point": [cx, cy]}, pixels, both keys optional.
void read_camera(const nlohmann::json& camera, const std::string& source,
                 CorrespondenceFile* file) {
  if (!camera.is_object())
    fail(source, "camera: must be an object {\"focal\", \"principal_point\"}");
  internal::reject_unknown_fields(camera, source + ": camera", {"focal", "principal_point"});
  if (camera.contains("focal")) {
    const nlohmann::json& focal = camera["focal"];
    if (!focal.is_number() || !(focal.get<double>() > 0.0) || !std::isfinite(focal.get<double>())) {
      fail(source, "camera.focal: must be a finite number > 0 (pixels)");
    }
    file->camera.focal_length = focal.get<double>();
    file->has_focal = true;
  }
  if (camera.contains("principal_point")) {
    const Eigen::VectorXd c =
        internal::read_numbers(camera["principal_point"], source, "camera.principal_point");
    if (c.size() != 2) fail(source, "camera.principal_point: must be [cx, cy]");
    file->camera.principal_point = c;
    file->has_principal_point = true;
  }
}

}  // namespace

CorrespondenceFile parse_correspondences(std::string_view text, const std::string& source) {
  const nlohmann::json root = internal::parse_object(text, source);
  internal::reject_unknown_fields(root, source,
                                  {"name", "description", "model", "measured", "image", "image1",
                                   "image2", "weights", "camera"});
  for (const char* text_field : {"name", "description"}) {
    if (root.contains(text_field)) internal::read_string(root[text_field], source, text_field);
  }
  CorrespondenceFile file;
  file.source = source;
  auto read3 = [&](const char* field, Eigen::Matrix3Xd* out, bool* has) {
    *has = root.contains(field);
    if (*has) *out = internal::read_vectors<3>(root[field], source, field);
  };
  auto read2 = [&](const char* field, Eigen::Matrix2Xd* out, bool* has) {
    *has = root.contains(field);
    if (*has) *out = internal::read_vectors<2>(root[field], source, field);
  };
  read3("model", &file.model, &file.has_model);
  read3("measured", &file.measured, &file.has_measured);
  read2("image", &file.image, &file.has_image);
  read2("image1", &file.image1, &file.has_image1);
  read2("image2", &file.image2, &file.has_image2);

  if (file.has_model) {
    if (file.has_measured) {
      check_count(source, "measured", file.measured.cols(), "model", file.model.cols());
    }
    if (file.has_image) check_count(source, "image", file.image.cols(), "model", file.model.cols());
  } else if (file.has_measured || file.has_image) {
    fail(source, std::string(file.has_measured ? "measured" : "image") +
                     ": given without \"model\" to correspond to");
  }
  if (file.has_image1 != file.has_image2) {
    fail(source, std::string(file.has_image1 ? "image2" : "image1") +
                     ": missing; two-view data need both \"image1\" and \"image2\"");
  }
  if (file.has_image1) {
    check_count(source, "image2", file.image2.cols(), "image1", file.image1.cols());
  }
  if (root.contains("weights")) {
    file.weights = internal::read_numbers(root["weights"], source, "weights");
    const bool by_model = file.has_model;
    const Eigen::Index expected = by_model ? file.model.cols() : file.image1.cols();
    if (!by_model && !file.has_image1) fail(source, "weights: given without correspondences");
    check_count(source, "weights", file.weights.size(), by_model ? "model" : "image1", expected);
    for (Eigen::Index i = 0; i < file.weights.size(); ++i) {
      if (!(file.weights(i) > 0.0)) {
        fail(source, "weights[" + std::to_string(i) + "]: must be > 0");
      }
    }
  }
  if (root.contains("camera")) read_camera(root["camera"], source, &file);
  return file;
}

CorrespondenceFile read_correspondences(const std::string& path) {
  return parse_correspondences(read_text_file(path), path);
}

}  // namespace vantage::io
