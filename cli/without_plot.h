#pragma once

// The `vantage` command built without vantage::plot (VANTAGE_WITH_PLOT=OFF, as `make demo`
// builds it): what `vantage plot` and `vantage design --plot` say instead of drawing.

namespace vantage::cli {

/// The reason, after "plot: " or "--plot: " (exit status 2, nothing written).
inline constexpr char kWithoutPlot[] =
    "this vantage was built without figures (VANTAGE_WITH_PLOT=OFF); `make test` builds them, "
    "or configure with -DVANTAGE_WITH_PLOT=ON";

}  // namespace vantage::cli
