#pragma once

// Private: the CSDP implementation of solve_lmi().

#include "vantage/sdp/lmi.h"

namespace vantage::sdp::internal {

/// Solves the LMI problem with CSDP's sdp() directly (no easy_sdp, no initparams: both read
/// param.csdp from the working directory). The problem must be validated by the caller.
SdpResult solve_with_csdp(const LmiProblem& problem, const SdpOptions& options);

/// Maps a CSDP return code onto SdpStatus (0..9 one to one, anything else kBackendError).
SdpStatus status_from_csdp_code(int code);

}  // namespace vantage::sdp::internal
