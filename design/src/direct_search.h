#pragma once

// Private to vantage::design: the direct optimiser that augment_layout() runs after the greedy
// steps for comparison, choosing all K additions at once.

#include "designer.h"
#include "vantage/design/augment.h"

namespace vantage::design::internal {

/// With options.candidates_only: every K-subset of the candidates, when there are at most
/// direct_starts * direct_evaluations_per_start of them (otherwise skipped, with a message).
/// expected_t: the t the best subsets are expected near (the greedy answer's), for
/// Designer::prepare().
DirectResult exhaustive_candidates(const Layout& layout, const AugmentOptions& options,
                                   double expected_t, Designer* designer);

/// Otherwise: NLopt Subplex over the 3K numbers of the K additions, multi-start from the greedy
/// answer (`greedy`, first options.add steps) and options.direct_starts - 1 seeded random
/// starts; the best point any start evaluated wins. Built without NLopt: not run (kSkipped, the
/// message says "not run: built without NLopt").
DirectResult multistart_search(const Layout& layout, const AugmentOptions& options,
                               const AugmentResult& greedy, Designer* designer);

}  // namespace vantage::design::internal
