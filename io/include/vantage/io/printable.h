#pragma once

/// User text quoted in an error message, kept on one line.

#include <string>

namespace vantage::io {

/// `text` with every control character (bytes below 0x20, and 0x7f) written as \xNN, other bytes
/// (UTF-8 included) unchanged: file names, keys, option values and parser messages quoted in an
/// InvalidArgument stay on one line.
std::string printable(const std::string& text);

}  // namespace vantage::io
