#pragma once

/// Order statistics of Monte Carlo samples, defined so that a merged set of shards gives exactly
/// the numbers of one run over the same trials (values are taken in trial order).

#include <cstdint>
#include <map>
#include <vector>

namespace vantage::simulate {

/// Median, mean, 95th percentile and maximum of the finite samples.
struct Summary {
  long count = 0;       ///< finite samples (NaN = not measured, e.g. no translation)
  double median = 0.0;  ///< middle sample, or the mean of the two middle ones (count even)
  double mean = 0.0;    ///< sum in trial order / count
  double p95 = 0.0;     ///< nearest rank: the ceil(0.95 count)-th smallest sample
  double max = 0.0;
};

/// Summary of the finite entries of `values` (NaN entries are skipped). With no finite entry
/// every statistic is NaN and count is 0.
Summary summarize(const std::vector<double>& values);

/// summarize() of a stream of samples in memory that does not grow with their number: samples
/// are added one at a time, in trial order (so shards folded in trial order give one run's
/// numbers exactly, at any thread count). count, mean (the sum in the order of add(), / count)
/// and max are exact at any count. Up to kExactSamples finite samples, median and p95 are the
/// exact order statistics of summarize(); beyond, the samples go into a histogram whose buckets
/// are 2^-kHistogramBits of a binade wide (a sample's sign, binary exponent and first
/// kHistogramBits mantissa bits), and median and p95 are the midpoints of the buckets holding
/// the exact order statistics (clamped to the samples' range): within a relative
/// 2^-(kHistogramBits + 1) = 2.4e-4 of them. The histogram holds 2^kHistogramBits counts per
/// binade the samples reach (16 KiB each), so its size depends on the samples' range only.
class SummaryAccumulator {
 public:
  static constexpr long kExactSamples = 1L << 16;
  static constexpr int kHistogramBits = 11;

  /// Adds one sample; NaN is counted out (not measured), as summarize() skips it.
  void add(double x);
  Summary summary() const;
  /// True once the samples went into the histogram (more than kExactSamples finite ones).
  bool approximate() const { return !buckets_.empty(); }

 private:
  // The bucket's key: monotone in the value (sign, exponent and leading mantissa bits).
  static std::int64_t key_of(double x);
  static double midpoint_of(std::int64_t key);
  double from_histogram(long rank) const;
  void spill();

  long count_ = 0;
  double sum_ = 0.0;
  double min_ = 0.0;
  double max_ = 0.0;
  std::vector<double> exact_;
  /// Counts per binade: key >> kHistogramBits -> 2^kHistogramBits counts.
  std::map<std::int64_t, std::vector<long>> buckets_;
};

}  // namespace vantage::simulate
