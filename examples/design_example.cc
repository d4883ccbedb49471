// The inductive augmenter (design) and the Prop. 3 weights on a layout file: prints the initial
// global worst case, every greedy step, the direct optimum, the ceiling and the weights.
//
//   design_example examples/layouts/triad.json 3 [--candidates-only] [--no-direct]

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

#include "vantage/design/augment.h"
#include "vantage/design/weights.h"
#include "vantage/io/layout_file.h"

namespace {

void print_viewpoints(const std::vector<Eigen::Vector3d>& viewpoints) {
  for (const Eigen::Vector3d& a : viewpoints) {
    std::printf(" (%.4f, %.4f, %.4f)", a.x(), a.y(), a.z());
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: design_example LAYOUT.json K [--candidates-only] [--no-direct]\n");
    return 2;
  }
  try {
    const vantage::Layout layout = vantage::io::read_layout(argv[1]);
    vantage::design::AugmentOptions options;
    options.add = std::atoi(argv[2]);
    for (int i = 3; i < argc; ++i) {
      if (std::strcmp(argv[i], "--candidates-only") == 0) options.candidates_only = true;
      if (std::strcmp(argv[i], "--no-direct") == 0) options.run_direct = false;
    }
    const vantage::design::AugmentResult r = vantage::design::augment_layout(layout, options);
    std::printf("layout: %s (%s), status %s %s\n", layout.name.c_str(),
                vantage::to_string(layout.mode), vantage::design::to_string(r.status),
                r.message.c_str());
    std::printf(
        "initial: m = %d, pbar_min %.6f, ceiling %.6f, max error %.3f deg, coplanarity "
        "%.4f%s, worst viewpoints:",
        r.initial_vector_count, r.initial.pbar_min, r.initial_ceiling,
        r.initial.max_worst_case_error_deg, r.initial_coplanarity.smallest_singular_value,
        r.initial_coplanarity.nearly_coplanar ? " (nearly coplanar)" : "");
    print_viewpoints(r.initial.viewpoints);
    for (size_t s = 0; s < r.steps.size(); ++s) {
      const vantage::design::AugmentStep& st = r.steps[s];
      std::printf(
          "step %zu: added (%.4f, %.4f, %.4f)%s, m = %d, pbar_min %.6f, ceiling %.6f, "
          "max error %.3f deg, solves %ld, screened %ld\n  %s\n  worst viewpoints:",
          s + 1, st.added.x(), st.added.y(), st.added.z(),
          st.candidate_index >= 0 ? " [candidate]" : "", st.vector_count, st.worst.pbar_min,
          st.ceiling, st.worst.max_worst_case_error_deg, st.global_solves, st.screened,
          st.note.c_str());
      print_viewpoints(st.worst.viewpoints);
    }
    std::printf("final: pbar_min %.6f, coplanarity %.4f%s\n", r.final_pbar_min,
                r.final_coplanarity.smallest_singular_value,
                r.final_coplanarity.nearly_coplanar ? " (nearly coplanar)" : "");
    if (r.direct.status == vantage::design::DirectResult::Status::kOk) {
      std::printf("direct (%s): pbar_min %.6f, solves %ld, added:", r.direct.method.c_str(),
                  r.direct.worst.pbar_min, r.direct.global_solves);
      print_viewpoints(r.direct.added);
    } else {
      std::printf("direct: %s\n", r.direct.message.c_str());
    }
    const vantage::design::Weights w = vantage::design::layout_weights(layout);
    std::printf("weights: %s, min_weight %.6f, residual %.3g%s%s\n",
                vantage::design::to_string(w.status), w.min_weight, w.residual,
                w.suggestions.empty() ? "" : "; suggestion: ",
                w.suggestions.empty() ? "" : w.suggestions.front().text.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "design_example: %s\n", e.what());
    return 1;
  }
}
