#include "ply_header.h"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/io/printable.h"

namespace vantage::io::internal {
namespace {

constexpr std::streamoff kMaxHeaderBytes = 1 << 20;

struct Element {
  std::string name;
  unsigned long long count = 0;
  long line = 0;                  ///< header line of its "element" keyword, from 1
  unsigned long long binary = 0;  ///< least bytes of one element in a binary file
  int properties = 0;
};

/// Bytes of a PLY scalar type; 1 for a name PLY does not define (assimp refuses those).
unsigned long long type_size(const std::string& type) {
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
      type == "float32") {
    return 4;
  }
  if (type == "double" || type == "float64") return 8;
  return 1;
}

std::string what(const Element& e) {
  if (e.name == "vertex") return "vertices";
  if (e.name == "face") return "faces";
  return "\"" + printable(e.name) + "\" elements";
}

/// Reads the header's elements; false when the file is not PLY or its header does not end in
/// the first kMaxHeaderBytes. `header_bytes` is where the body starts.
bool read_elements(std::istream& in, std::vector<Element>* elements, bool* ascii,
                   std::streamoff* header_bytes) {
  std::string line;
  if (!std::getline(in, line) || (line != "ply" && line != "ply\r")) return false;
  for (long number = 2; std::getline(in, line); ++number) {
    if (in.tellg() > kMaxHeaderBytes) return false;
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") {
      *header_bytes = in.tellg();
      return *header_bytes >= 0;
    }
    if (keyword == "format") {
      std::string format;
      words >> format;
      *ascii = format == "ascii";
    } else if (keyword == "element") {
      Element e;
      std::string count;
      words >> e.name >> count;
      e.line = number;
      const auto [end, error] = std::from_chars(count.data(), count.data() + count.size(), e.count);
      if (error != std::errc() || end != count.data() + count.size()) {
        throw InvalidArgument("PLY header line " + std::to_string(number) + ": element \"" +
                              excerpt(e.name) + "\" has count \"" + excerpt(count) +
                              "\", not a whole number");
      }
      elements->push_back(e);
    } else if (keyword == "property" && !elements->empty()) {
      std::string type;
      words >> type;
      if (type == "list") words >> type;  // a list takes at least its count
      elements->back().binary += type_size(type);
      ++elements->back().properties;
    }
  }
  return false;
}

}  // namespace

void check_ply_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<Element> elements;
  bool ascii = true;
  std::streamoff header_bytes = 0;
  if (!read_elements(in, &elements, &ascii, &header_bytes)) return;
  std::error_code ec;
  const auto size = static_cast<long double>(std::filesystem::file_size(path, ec));
  if (ec) return;
  // Counts reach 2^64 and sizes 2^63: long double holds both exactly enough to compare.
  long double available = size - static_cast<long double>(header_bytes);
  const long double last_separator = ascii ? 1 : 0;  // the file may end without one
  for (const Element& e : elements) {
    const unsigned long long each =
        ascii ? (e.properties > 0 ? 2ULL * static_cast<unsigned>(e.properties) : 1ULL) : e.binary;
    const long double needed = static_cast<long double>(e.count) * static_cast<long double>(each);
    if (needed > available + last_separator) {
      std::ostringstream out;
      out << "PLY header declares " << e.count << " " << what(e) << " (header line " << e.line
          << ", element \"" << printable(e.name) << "\": at least " << each << " bytes each in "
          << (ascii ? "ASCII" : "binary") << ") but the file holds at most "
          << static_cast<unsigned long long>(available < 0 ? 0 : available)
          << " bytes for them after its header";
      throw InvalidArgument(out.str());
    }
    available -= needed;
  }
}

}  // namespace vantage::io::internal
