#include "vantage/simulate/statistics.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace vantage::simulate {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The nearest-rank position of the 95th percentile among n samples (1-based).
long p95_rank(long n) {
  return std::max<long>(1, static_cast<long>(std::ceil(0.95 * static_cast<double>(n))));
}

constexpr int kDropped = 52 - SummaryAccumulator::kHistogramBits;  // mantissa bits below a bucket

std::int64_t bits_of(double x) {
  std::int64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

double double_of(std::int64_t bits) {
  double x = 0.0;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

}  // namespace

Summary summarize(const std::vector<double>& values) {
  std::vector<double> finite;
  finite.reserve(values.size());
  double sum = 0.0;
  for (double v : values) {
    if (std::isnan(v)) continue;
    finite.push_back(v);
    sum += v;
  }
  Summary s;
  s.count = static_cast<long>(finite.size());
  if (finite.empty()) {
    s.median = s.mean = s.p95 = s.max = kNaN;
    return s;
  }
  std::sort(finite.begin(), finite.end());
  const std::size_t n = finite.size();
  s.median = n % 2 ? finite[n / 2] : 0.5 * (finite[n / 2 - 1] + finite[n / 2]);
  s.mean = sum / static_cast<double>(n);
  s.p95 = finite[static_cast<std::size_t>(p95_rank(s.count)) - 1];
  s.max = finite.back();
  return s;
}

std::int64_t SummaryAccumulator::key_of(double x) {
  if (x == 0.0) x = 0.0;  // -0 and +0 share a bucket
  // For x >= 0 the bit pattern grows with the value; negative values mirror it below zero.
  return x >= 0.0 ? bits_of(x) >> kDropped : -(bits_of(-x) >> kDropped) - 1;
}

double SummaryAccumulator::midpoint_of(std::int64_t key) {
  if (key < 0) return -midpoint_of(-key - 1);
  const double lo = double_of(key << kDropped);
  const double hi = double_of((key + 1) << kDropped);
  if (!std::isfinite(hi)) return lo;  // the last bucket below infinity, or infinity itself
  return lo + 0.5 * (hi - lo);
}

void SummaryAccumulator::add(double x) {
  if (std::isnan(x)) return;
  if (count_ == 0) min_ = max_ = x;
  min_ = std::min(min_, x);
  max_ = std::max(max_, x);
  ++count_;
  sum_ += x;
  if (approximate()) {
    const std::int64_t key = key_of(x);
    std::vector<long>& binade = buckets_[key >> kHistogramBits];
    if (binade.empty()) binade.assign(std::size_t{1} << kHistogramBits, 0);
    ++binade[static_cast<std::size_t>(key & ((std::int64_t{1} << kHistogramBits) - 1))];
    return;
  }
  exact_.push_back(x);
  if (count_ > kExactSamples) spill();
}

void SummaryAccumulator::spill() {
  std::vector<double> values;
  values.swap(exact_);
  buckets_.clear();
  for (double x : values) {
    const std::int64_t key = key_of(x);
    std::vector<long>& binade = buckets_[key >> kHistogramBits];
    if (binade.empty()) binade.assign(std::size_t{1} << kHistogramBits, 0);
    ++binade[static_cast<std::size_t>(key & ((std::int64_t{1} << kHistogramBits) - 1))];
  }
}

double SummaryAccumulator::from_histogram(long rank) const {
  long seen = 0;
  for (const auto& [high, counts] : buckets_) {
    for (std::size_t low = 0; low < counts.size(); ++low) {
      seen += counts[low];
      if (seen >= rank) {
        const std::int64_t key =
            high * (std::int64_t{1} << kHistogramBits) + static_cast<std::int64_t>(low);
        return std::clamp(midpoint_of(key), min_, max_);
      }
    }
  }
  return max_;
}

Summary SummaryAccumulator::summary() const {
  if (!approximate()) return summarize(exact_);
  Summary s;
  s.count = count_;
  s.mean = sum_ / static_cast<double>(count_);
  s.max = max_;
  s.median = count_ % 2 ? from_histogram(count_ / 2 + 1)
                        : 0.5 * (from_histogram(count_ / 2) + from_histogram(count_ / 2 + 1));
  s.p95 = from_histogram(p95_rank(count_));
  return s;
}

}  // namespace vantage::simulate
