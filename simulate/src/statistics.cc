#include "vantage/simulate/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vantage::simulate {

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
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.median = s.mean = s.p95 = s.max = nan;
    return s;
  }
  std::sort(finite.begin(), finite.end());
  const std::size_t n = finite.size();
  s.median = n % 2 ? finite[n / 2] : 0.5 * (finite[n / 2 - 1] + finite[n / 2]);
  s.mean = sum / static_cast<double>(n);
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(n)));
  s.p95 = finite[std::max<std::size_t>(rank, 1) - 1];
  s.max = finite.back();
  return s;
}

}  // namespace vantage::simulate
