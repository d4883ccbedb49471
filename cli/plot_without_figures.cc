// `vantage plot` in a vantage built without vantage::plot (VANTAGE_WITH_PLOT=OFF): the subcommand
// stays, so that `vantage plot ...` says why there are no figures instead of calling the
// subcommand unknown. Its arguments are accepted as given and not checked.

#include <string>

#include "command.h"
#include "without_plot.h"

namespace vantage::cli {

Command add_plot_command(CLI::App& root) {
  CLI::App* sub = root.add_subcommand(
      "plot",
      "Figures of a layout: not in this build (built without figures, VANTAGE_WITH_PLOT=OFF)");
  sub->allow_extras();
  return {sub, []() -> int { throw InvalidArgument(std::string("plot: ") + kWithoutPlot); }};
}

}  // namespace vantage::cli
