#pragma once

// Private helper of sdp: a report's message is its parts joined by "; ".

#include <string>

namespace vantage::sdp::internal {

/// Appends `part` to `message` ("a; b"); an empty part adds nothing.
inline void append_message(std::string* message, const std::string& part) {
  if (part.empty()) return;
  if (!message->empty()) *message += "; ";
  *message += part;
}

}  // namespace vantage::sdp::internal
