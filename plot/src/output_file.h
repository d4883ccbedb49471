#pragma once

// A file written under a temporary name beside its target and renamed into place on commit(),
// so that a failure never leaves a partial file. Private to vantage::plot.

#include <cstdio>
#include <filesystem>
#include <string>

namespace vantage::plot::internal {

class OutputFile {
 public:
  /// Opens "<dir>/.<name>.<pid>.tmp" for writing. Throws RenderError when it cannot.
  explicit OutputFile(std::filesystem::path target);
  ~OutputFile();  ///< removes the temporary file unless committed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::FILE* stream() { return stream_; }
  /// Appends bytes; a failure is remembered and reported by commit().
  void write(const void* data, std::size_t size);
  /// Flushes, closes and renames to the target. Throws RenderError on any write error.
  void commit();
  const std::filesystem::path& target() const { return target_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::FILE* stream_ = nullptr;
  bool failed_ = false;
  bool committed_ = false;
};

/// CSV with a header line; numbers are written in the shortest form that reads back to the same
/// double (std::to_chars).
class CsvWriter {
 public:
  CsvWriter(const std::filesystem::path& target, const std::string& header);
  CsvWriter& operator<<(double value);
  CsvWriter& operator<<(long value);
  CsvWriter& operator<<(int value) { return *this << static_cast<long>(value); }
  /// A text field, in double quotes (RFC 4180) when it holds ',', '"' or a line break.
  CsvWriter& operator<<(const std::string& text);
  CsvWriter& operator<<(const char* text) { return *this << std::string(text); }
  void end_row();
  void commit() { file_.commit(); }

 private:
  void separator();
  OutputFile file_;
  bool row_started_ = false;
};

}  // namespace vantage::plot::internal
