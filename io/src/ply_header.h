#pragma once

// Private to io: the element counts of a PLY header held against the size of the file, before
// assimp reserves memory for them (a header that claimed 10^7 vertices of a 3-vertex file took
// 40 s and 518 MB to fail, 10^9 ended in std::bad_alloc).

#include <string>

namespace vantage::io::internal {

/// When the file at `path` starts with the line "ply", throws InvalidArgument (without a source)
/// if its header declares more elements than the bytes after the header can hold, naming the
/// element: an ASCII element takes at least 2 bytes per property (a digit and a separator; the
/// file's last byte may be the last digit) and 1 without properties, a binary element the sizes
/// of its scalar properties and of the count of each list. Also throws for an element count
/// that is not a whole number. Any other file, and a header without "end_header" in its first
/// MiB, is left to assimp.
void check_ply_header(const std::string& path);

}  // namespace vantage::io::internal
