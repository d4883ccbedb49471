#pragma once

/// What this build of vantage contains: the CMake options of README.md ("Build options") that
/// change what the library does, asked at run time so that a caller (a front end, a test) can say
/// what was skipped instead of guessing.

namespace vantage {

/// True when vantage was built with NLopt (CMake option VANTAGE_WITH_NLOPT, the default). Without
/// it, the parts that need a local optimiser run nothing and report kWithoutNlopt as the reason:
/// the cross-check of the global worst viewpoint (sdp::crosscheck_worst_viewpoint, `vantage
/// analyze`), the direct minimisation of J_2d (minimize_affine_residual) and the continuous
/// direct optimiser of design::augment_layout (the greedy steps and the exhaustive search over
/// the candidates need no NLopt and run either way).
bool built_with_nlopt();

/// The reason a part that needs NLopt gives when it did not run.
inline constexpr char kWithoutNlopt[] = "built without NLopt";

}  // namespace vantage
