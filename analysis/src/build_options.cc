#include "vantage/analysis/build_options.h"

namespace vantage {

bool built_with_nlopt() { return VANTAGE_WITH_NLOPT != 0; }

}  // namespace vantage
