#pragma once

/// User text quoted in an error message, kept on one line.

#include <cstddef>
#include <string>

namespace vantage::io {

/// `text` with every control character (bytes below 0x20, and 0x7f) written as \xNN, other bytes
/// (UTF-8 included) unchanged: file names, keys, option values and parser messages quoted in an
/// InvalidArgument stay on one line.
std::string printable(const std::string& text);

/// True when `text` is well-formed UTF-8 (file names need not be; a JSON report needs it).
bool is_valid_utf8(const std::string& text);

/// Most bytes of file content that excerpt() quotes.
constexpr std::size_t kExcerptBytes = 60;

/// A value read from a file, quoted in an error message: printable(), and past kExcerptBytes its
/// first kExcerptBytes bytes (never half a UTF-8 character) and "... (N bytes)", so that a
/// 50 MB line does not become a 50 MB message.
std::string excerpt(const std::string& text);

}  // namespace vantage::io
