#pragma once

/// Order statistics of Monte Carlo samples, defined so that a merged set of shards gives exactly
/// the numbers of one run over the same trials (values are taken in trial order).

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

}  // namespace vantage::simulate
