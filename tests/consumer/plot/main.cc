// vantage::plot from an installed vantage: the design figure of a made-up design run, drawn
// through PLplot and cairo and written as PNG (libpng) with its CSV. Exit status 0 only when the
// PNG starts with the PNG signature and the CSV's ceiling rows are cos(pi / (2 m)) (docs/math.md
// §15), computed here independently.
//   vantage_consumer_plot DIR

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "vantage/plot/design_curve.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: vantage_consumer_plot DIR\n");
    return 2;
  }
  // The CSV carries doubles with 17 significant digits: equal to rounding.
  constexpr double kCsvRounding = 1e-15;
  constexpr double kPi = 3.14159265358979323846;

  vantage::plot::DesignCurve curve;
  curve.layout_name = "consumer";
  curve.n_vectors = {3, 4, 5};
  curve.pbar_min = {std::sqrt(2.0 / 3.0), 0.85, 0.9};
  const vantage::plot::FigureFiles files = vantage::plot::write_design_curve(curve, argv[1]);

  std::ifstream png(files.image, std::ios::binary);
  char signature[8] = {};
  png.read(signature, sizeof signature);
  const bool png_ok = png && std::string(signature, 8) == "\x89PNG\r\n\x1a\n";

  std::ifstream csv(files.csv);
  std::string line;
  int ceilings = 0;
  bool ceilings_ok = true;
  while (std::getline(csv, line)) {
    if (line.rfind("ceiling,", 0) != 0) continue;
    std::istringstream row(line.substr(8));
    long step = 0, m = 0;
    double value = 0.0;
    char comma = 0;
    row >> step >> comma >> m >> comma >> value;
    ceilings_ok =
        ceilings_ok && row && m >= 1 && std::abs(value - std::cos(kPi / (2.0 * m))) <= kCsvRounding;
    ++ceilings;
  }
  std::printf("design figure %s (png signature %s), %d ceiling rows %s\n",
              files.image.string().c_str(), png_ok ? "ok" : "BAD", ceilings,
              ceilings_ok ? "ok" : "BAD");
  return png_ok && ceilings > 0 && ceilings_ok ? 0 : 1;
}
