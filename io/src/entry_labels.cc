#include "entry_labels.h"

#include <regex>

#include "json_fields.h"
#include "vantage/analysis/common.h"

namespace vantage::io::internal {

std::string relabel_entries(const std::string& message, const std::vector<std::string>& labels) {
  static const std::regex kEntry(R"((points|weights)\[([0-9]{1,9})\])");
  std::string out;
  auto begin = message.cbegin();
  for (std::sregex_iterator it(message.begin(), message.end(), kEntry), end; it != end; ++it) {
    const std::smatch& match = *it;
    out.append(begin, match[0].first);
    const std::size_t k = std::stoul(match[2].str());
    if (k >= labels.size()) {
      out += match[0].str();
    } else {
      out += labels[k] + (match[1].str() == "weights" ? ", weight" : "");
    }
    begin = match[0].second;
  }
  out.append(begin, message.cend());
  return out;
}

void validate_labelled(const Layout& layout, const std::string& source,
                       const std::vector<std::string>& labels) {
  try {
    layout.validate();
  } catch (const InvalidArgument& e) {
    fail(source, relabel_entries(e.what(), labels));
  }
}

}  // namespace vantage::io::internal
