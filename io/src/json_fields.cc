#include "json_fields.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/io/printable.h"

namespace vantage::io::internal {

void fail(const std::string& source, const std::string& what) {
  throw InvalidArgument(printable(source + ": " + what));
}

namespace {

// nlohmann's exception id for a number beyond double range (1e999).
constexpr int kNumberOverflow = 406;

// nlohmann's "last read" may start before the value ("1,N"): the value's own characters.
std::string value_text(const std::string& last_read) {
  const auto start = last_read.find_last_of(",[{: \t\r\n");
  return start == std::string::npos ? last_read : last_read.substr(start + 1);
}

// The lexer stops at the first character that cannot continue a literal: "N" for NaN, "I" or
// "-I" for Infinity, "na" for nan, "i" for inf.
bool spells_non_finite(const std::string& token) {
  const std::string t = !token.empty() && token[0] == '-' ? token.substr(1) : token;
  return !t.empty() && (t[0] == 'N' || t[0] == 'I' || t[0] == 'i' || t.rfind("na", 0) == 0);
}

// Builds the DOM like nlohmann's own parser while tracking where it is ("vectors[1][2]"), so
// that duplicate keys and numbers out of range are reported with the field and index.
class TrackingSax {
 public:
  TrackingSax(nlohmann::json& root, const std::string& source) : dom_(root), source_(source) {}

  bool null() { return value(dom_.null()); }
  bool boolean(bool b) { return value(dom_.boolean(b)); }
  bool number_integer(nlohmann::json::number_integer_t x) { return value(dom_.number_integer(x)); }
  bool number_unsigned(nlohmann::json::number_unsigned_t x) {
    return value(dom_.number_unsigned(x));
  }
  bool number_float(nlohmann::json::number_float_t x, const std::string& text) {
    return value(dom_.number_float(x, text));
  }
  bool string(std::string& text) { return value(dom_.string(text)); }
  bool binary(nlohmann::json::binary_t& bytes) { return value(dom_.binary(bytes)); }
  bool start_object(std::size_t size) {
    frames_.push_back({false, 0, {}, {}});
    return dom_.start_object(size);
  }
  bool key(std::string& name) {
    Frame& frame = frames_.back();
    if (!frame.keys.insert(name).second) {
      fail(source_, where(name) + ": duplicate key (each field may appear once)");
    }
    frame.key = name;
    return dom_.key(name);
  }
  bool end_object() {
    frames_.pop_back();
    return value(dom_.end_object());
  }
  bool start_array(std::size_t size) {
    frames_.push_back({true, 0, {}, {}});
    return dom_.start_array(size);
  }
  bool end_array() {
    frames_.pop_back();
    return value(dom_.end_array());
  }
  bool parse_error(std::size_t, const std::string& last_read,
                   const nlohmann::detail::exception& error) {
    const std::string token = value_text(last_read);
    const std::string at = where();
    const std::string prefix = at.empty() ? "" : at + ": ";
    if (error.id == kNumberOverflow) {
      fail(source_, prefix + "number out of range (" + excerpt(token) + ")");
    }
    if (spells_non_finite(token)) {
      fail(source_, prefix + "not a finite number (NaN and Infinity are not JSON numbers)");
    }
    // e.what() is "[json.exception.parse_error.101] parse error at ...": keep the readable part.
    std::string what = error.what();
    const auto bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    // Its "last read: '...'" quotes the token, which may be the rest of a huge line.
    const auto quoted = last_read.size() > kExcerptBytes ? what.find(last_read) : std::string::npos;
    if (quoted != std::string::npos) what.replace(quoted, last_read.size(), excerpt(last_read));
    fail(source_, "not valid JSON: " + prefix + what);
  }

 private:
  struct Frame {
    bool array = false;
    std::size_t index = 0;  // the element being read (arrays)
    std::string key;        // the value being read (objects)
    std::set<std::string> keys;
  };

  bool value(bool result) {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return result;
  }

  // "vectors[1][2]" of the value being read (or of `pending_key` in the innermost object).
  std::string where(const std::string& pending_key = {}) const {
    std::string out;
    for (std::size_t k = 0; k < frames_.size(); ++k) {
      const Frame& f = frames_[k];
      const bool last = k + 1 == frames_.size();
      if (f.array) {
        out += "[" + std::to_string(f.index) + "]";
      } else {
        const std::string& name = last && !pending_key.empty() ? pending_key : f.key;
        if (name.empty()) continue;
        out += (out.empty() ? "" : ".") + excerpt(name);
      }
    }
    return out;
  }

  nlohmann::detail::json_sax_dom_parser<nlohmann::json> dom_;
  const std::string& source_;
  std::vector<Frame> frames_;
};

}  // namespace

nlohmann::json parse_object(std::string_view text, const std::string& source) {
  nlohmann::json root;
  TrackingSax sax(root, source);
  nlohmann::json::sax_parse(text.begin(), text.end(), &sax);
  if (!root.is_object()) fail(source, "the top level must be a JSON object {...}");
  return root;
}

void reject_unknown_fields(const nlohmann::json& root, const std::string& source,
                           std::initializer_list<const char*> allowed) {
  for (const auto& item : root.items()) {
    const bool known = std::any_of(allowed.begin(), allowed.end(),
                                   [&](const char* name) { return item.key() == name; });
    if (!known) fail(source, "unknown field \"" + excerpt(item.key()) + "\"");
  }
}

namespace {

double read_number(const nlohmann::json& value, const std::string& source,
                   const std::string& where) {
  if (!value.is_number()) fail(source, where + ": expected a number");
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(source, where + ": not a finite number");
  return x;
}

}  // namespace

template <int Rows>
Eigen::Matrix<double, Rows, Eigen::Dynamic> read_vectors(const nlohmann::json& value,
                                                         const std::string& source,
                                                         const std::string& field) {
  if (!value.is_array())
    fail(source, field + ": expected a list of " + std::to_string(Rows) + "-element lists");
  Eigen::Matrix<double, Rows, Eigen::Dynamic> out(Rows, value.size());
  for (std::size_t j = 0; j < value.size(); ++j) {
    const std::string where = field + "[" + std::to_string(j) + "]";
    const nlohmann::json& item = value[j];
    if (!item.is_array() || item.size() != Rows) {
      fail(source, where + ": expected " + std::to_string(Rows) + " numbers, got " +
                       (item.is_array() ? std::to_string(item.size())
                                        : std::string("a ") + item.type_name()));
    }
    for (int i = 0; i < Rows; ++i) {
      out(i, j) = read_number(item[i], source, where + "[" + std::to_string(i) + "]");
    }
  }
  return out;
}

template Eigen::Matrix<double, 2, Eigen::Dynamic> read_vectors<2>(const nlohmann::json&,
                                                                  const std::string&,
                                                                  const std::string&);
template Eigen::Matrix<double, 3, Eigen::Dynamic> read_vectors<3>(const nlohmann::json&,
                                                                  const std::string&,
                                                                  const std::string&);

Eigen::VectorXd read_numbers(const nlohmann::json& value, const std::string& source,
                             const std::string& field) {
  if (!value.is_array()) fail(source, field + ": expected a list of numbers");
  Eigen::VectorXd out(value.size());
  for (std::size_t i = 0; i < value.size(); ++i) {
    out(i) = read_number(value[i], source, field + "[" + std::to_string(i) + "]");
  }
  return out;
}

std::string read_string(const nlohmann::json& value, const std::string& source,
                        const std::string& field) {
  if (!value.is_string()) fail(source, field + ": expected a string");
  return value.get<std::string>();
}

nlohmann::json vector_rows(const Eigen::Matrix3Xd& m) {
  nlohmann::json list = nlohmann::json::array();
  for (Eigen::Index j = 0; j < m.cols(); ++j) list.push_back({m(0, j), m(1, j), m(2, j)});
  return list;
}

}  // namespace vantage::io::internal
