#include "output_file.h"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <system_error>

#include "vantage/plot/figure.h"

namespace vantage::plot::internal {

OutputFile::OutputFile(std::filesystem::path target) : target_(std::move(target)) {
  temporary_ = target_.parent_path() /
               ("." + target_.filename().string() + "." + std::to_string(::getpid()) + ".tmp");
  stream_ = std::fopen(temporary_.c_str(), "wb");
  if (!stream_) {
    throw RenderError("cannot write " + target_.string() + ": " + std::strerror(errno));
  }
}

OutputFile::~OutputFile() {
  if (stream_) std::fclose(stream_);
  if (!committed_) {
    std::error_code ec;
    std::filesystem::remove(temporary_, ec);
  }
}

void OutputFile::write(const void* data, std::size_t size) {
  if (failed_ || size == 0) return;
  if (std::fwrite(data, 1, size, stream_) != size) failed_ = true;
}

void OutputFile::commit() {
  const bool flushed = std::fflush(stream_) == 0 && !std::ferror(stream_);
  const bool closed = std::fclose(stream_) == 0;
  stream_ = nullptr;
  if (failed_ || !flushed || !closed) {
    throw RenderError("cannot write " + target_.string() + ": " + std::strerror(errno));
  }
  std::error_code ec;
  std::filesystem::rename(temporary_, target_, ec);
  if (ec) throw RenderError("cannot write " + target_.string() + ": " + ec.message());
  committed_ = true;
}

CsvWriter::CsvWriter(const std::filesystem::path& target, const std::string& header)
    : file_(target) {
  file_.write(header.data(), header.size());
  file_.write("\n", 1);
}

void CsvWriter::separator() {
  if (row_started_) file_.write(",", 1);
  row_started_ = true;
}

CsvWriter& CsvWriter::operator<<(double value) {
  separator();
  char buffer[64];
  const std::to_chars_result end = std::to_chars(buffer, buffer + sizeof(buffer), value);
  file_.write(buffer, static_cast<std::size_t>(end.ptr - buffer));
  return *this;
}

CsvWriter& CsvWriter::operator<<(long value) {
  separator();
  const std::string text = std::to_string(value);
  file_.write(text.data(), text.size());
  return *this;
}

CsvWriter& CsvWriter::operator<<(const std::string& text) {
  separator();
  if (text.find_first_of(",\"\r\n") == std::string::npos) {
    file_.write(text.data(), text.size());
    return *this;
  }
  // RFC 4180: the field in double quotes, each double quote doubled (a marker's name may hold a
  // comma).
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  quoted += '"';
  file_.write(quoted.data(), quoted.size());
  return *this;
}

void CsvWriter::end_row() {
  file_.write("\n", 1);
  row_started_ = false;
}

}  // namespace vantage::plot::internal
