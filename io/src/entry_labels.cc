#include "entry_labels.h"

#include <optional>

#include "vantage/analysis/common.h"
#include "vantage/io/printable.h"

namespace vantage::io::internal {

void validate_labelled(const Layout& layout, const std::string& source,
                       const std::vector<std::string>& labels) {
  try {
    layout.validate();
  } catch (const InvalidArgument& e) {
    const auto label = [&](const std::string& field, long k) -> std::optional<std::string> {
      if (k < 0 || k >= static_cast<long>(labels.size())) return std::nullopt;
      if (field == "points") return printable(labels[static_cast<std::size_t>(k)]);
      if (field == "weights") return printable(labels[static_cast<std::size_t>(k)]) + ", weight";
      return std::nullopt;
    };
    throw e.labelled(label).against(printable(source));
  }
}

}  // namespace vantage::io::internal
