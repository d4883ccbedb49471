#include "vantage/analysis/mesh_report.h"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace vantage {
namespace {

constexpr double kLargestMetres = 10.0;        // a body up to 10 m: in mm it would be 10 mm
constexpr double kSmallestMillimetres = 30.0;  // a body from 30 mm: in m it would be 30 m

/// One triangle's use of an edge between welded vertices lo < hi.
struct EdgeUse {
  std::uint32_t lo, hi;
  std::uint32_t triangle : 31;
  std::uint32_t forward : 1;  ///< the triangle goes lo -> hi
};

/// Union-find over the triangles with the parity of each against its root: two triangles in one
/// set agree on their winding iff their parities are equal.
class Windings {
 public:
  explicit Windings(std::size_t n) : parent_(n), flip_(n, 0) {
    for (std::size_t k = 0; k < n; ++k) parent_[k] = static_cast<std::uint32_t>(k);
  }

  /// The root of t and t's parity against it (the path is compressed).
  std::pair<std::uint32_t, bool> find(std::uint32_t t) {
    std::uint32_t root = t;
    bool parity = false;
    while (parent_[root] != root) {
      parity ^= flip_[root] != 0;
      root = parent_[root];
    }
    for (bool p = parity; parent_[t] != t;) {
      const std::uint32_t next = parent_[t];
      const bool next_parity = p ^ (flip_[t] != 0);
      parent_[t] = root;
      flip_[t] = p;
      t = next;
      p = next_parity;
    }
    return {root, parity};
  }

  /// Records that a and b are wound alike (opposite = false) or against each other. A record
  /// that contradicts earlier ones (a one-sided patch) is dropped.
  void join(std::uint32_t a, std::uint32_t b, bool opposite) {
    const auto [root_a, parity_a] = find(a);
    const auto [root_b, parity_b] = find(b);
    if (root_a == root_b) return;
    parent_[root_b] = root_a;
    flip_[root_b] = parity_a ^ parity_b ^ opposite;
  }

  /// In each set, the number of triangles of the smaller parity class, summed.
  long minority() {
    std::vector<std::uint32_t> count[2] = {std::vector<std::uint32_t>(parent_.size(), 0),
                                           std::vector<std::uint32_t>(parent_.size(), 0)};
    for (std::uint32_t t = 0; t < parent_.size(); ++t) {
      const auto [root, parity] = find(t);
      ++count[parity][root];
    }
    long total = 0;
    for (std::size_t r = 0; r < parent_.size(); ++r) total += std::min(count[0][r], count[1][r]);
    return total;
  }

 private:
  std::vector<std::uint32_t> parent_;
  std::vector<char> flip_;
};

/// Every edge use of the non-degenerate triangles, sorted by edge; counts the degenerate ones.
std::vector<EdgeUse> edge_uses(const Mesh& mesh, const std::vector<int>& weld, MeshReport* out) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * static_cast<std::size_t>(mesh.triangles.cols()));
  for (Eigen::Index k = 0; k < mesh.triangles.cols(); ++k) {
    std::uint32_t v[3];
    for (int c = 0; c < 3; ++c) {
      v[c] = static_cast<std::uint32_t>(weld[static_cast<std::size_t>(mesh.triangles(c, k))]);
    }
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) {
      ++out->degenerate_triangles;
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = v[c], b = v[(c + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(k), a < b});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi);
  });
  return uses;
}

/// Calls edge(first, count) for each edge: its `count` uses start at uses[first] (sorted).
template <typename Edge>
void for_each_edge(const std::vector<EdgeUse>& uses, Edge&& edge) {
  for (std::size_t k = 0; k < uses.size();) {
    std::size_t end = k + 1;
    while (end < uses.size() && uses[end].lo == uses[k].lo && uses[end].hi == uses[k].hi) ++end;
    edge(k, end - k);
    k = end;
  }
}

/// The edge counts and the winding of the triangles from their sorted edge uses.
void count_edges(const std::vector<EdgeUse>& uses, std::size_t triangles, MeshReport* out) {
  Windings windings(triangles);
  for_each_edge(uses, [&](std::size_t k, std::size_t count) {
    if (count == 1) {
      ++out->boundary_edges;
    } else if (count > 2) {
      ++out->non_manifold_edges;
    } else {
      const bool same_direction = uses[k].forward == uses[k + 1].forward;
      out->inconsistent_edges += same_direction;
      windings.join(uses[k].triangle, uses[k + 1].triangle, same_direction);
    }
  });
  out->triangles_against_neighbours = windings.minority();
}

std::string count(long n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

UnitsHint units_of(double largest) {
  if (largest > 0.0 && largest <= kLargestMetres) return UnitsHint::kMetres;
  if (largest >= kSmallestMillimetres) return UnitsHint::kMillimetres;
  return UnitsHint::kUnclear;
}

}  // namespace

const char* to_string(UnitsHint hint) {
  switch (hint) {
    case UnitsHint::kMetres:
      return "metres";
    case UnitsHint::kMillimetres:
      return "millimetres";
    case UnitsHint::kUnclear:
      break;
  }
  return "unclear";
}

std::optional<UnitsHint> parse_units_hint(std::string_view text) {
  for (UnitsHint hint : {UnitsHint::kMetres, UnitsHint::kMillimetres, UnitsHint::kUnclear}) {
    if (text == to_string(hint)) return hint;
  }
  return std::nullopt;
}

MeshReport mesh_report(const Mesh& mesh) {
  mesh.validate();
  MeshReport out;
  out.triangles = static_cast<long>(mesh.triangles.cols());
  {
    const std::vector<int> weld = first_identical_vertex(mesh.vertices);
    for (std::size_t v = 0; v < weld.size(); ++v) out.vertices += weld[v] == static_cast<int>(v);
    count_edges(edge_uses(mesh, weld, &out), static_cast<std::size_t>(out.triangles), &out);
  }
  out.closed = out.boundary_edges == 0 && out.non_manifold_edges == 0;
  out.manifold = out.non_manifold_edges == 0;
  out.consistently_wound = out.inconsistent_edges == 0;
  out.bounding_box_size = mesh.vertices.rowwise().maxCoeff() - mesh.vertices.rowwise().minCoeff();
  out.units_hint = units_of(out.bounding_box_size.maxCoeff());
  return out;
}

MeshPatches mesh_patches(const Mesh& mesh) {
  mesh.validate();
  const std::size_t n = static_cast<std::size_t>(mesh.triangles.cols());
  MeshReport counts;
  const std::vector<EdgeUse> uses = edge_uses(mesh, first_identical_vertex(mesh.vertices), &counts);
  Windings windings(n);
  std::vector<char> degenerate(n, 1);
  for (const EdgeUse& use : uses) degenerate[use.triangle] = 0;
  std::vector<std::uint32_t> open_triangles;  // of a boundary or non-manifold edge
  for_each_edge(uses, [&](std::size_t k, std::size_t count) {
    if (count == 2) {
      windings.join(uses[k].triangle, uses[k + 1].triangle, uses[k].forward == uses[k + 1].forward);
    } else {
      for (std::size_t u = k; u < k + count; ++u) open_triangles.push_back(uses[u].triangle);
    }
  });
  MeshPatches out;
  out.patch.assign(n, -1);
  out.flipped.assign(n, 0);
  std::vector<int> of_root(n, -1);
  for (std::size_t t = 0; t < n; ++t) {
    if (degenerate[t]) continue;
    const auto [root, parity] = windings.find(static_cast<std::uint32_t>(t));
    if (of_root[root] < 0) of_root[root] = out.count++;
    out.patch[t] = of_root[root];
    out.flipped[t] = parity;
  }
  out.closed.assign(static_cast<std::size_t>(out.count), 1);
  for (std::uint32_t t : open_triangles) out.closed[static_cast<std::size_t>(out.patch[t])] = 0;
  return out;
}

std::string MeshReport::warning(const std::string& name) const {
  std::vector<std::string> parts;
  if (boundary_edges > 0) {
    parts.push_back("is open (" + count(boundary_edges, "boundary edge", "boundary edges") + ")");
  }
  if (non_manifold_edges > 0) {
    parts.push_back("has " + count(non_manifold_edges, "edge", "edges") +
                    " shared by more than two triangles");
  }
  if (triangles_against_neighbours > 0) {
    parts.push_back(count(triangles_against_neighbours, "triangle is wound against its neighbours",
                          "triangles are wound against their neighbours"));
  } else if (inconsistent_edges > 0) {
    parts.push_back("its winding cannot be made consistent (" +
                    count(inconsistent_edges, "edge", "edges") +
                    " traversed the same way by both their triangles: a one-sided surface)");
  }
  if (parts.empty()) return "";
  std::string text = "body " + name + " " + parts[0];
  for (std::size_t k = 1; k < parts.size(); ++k) {
    text += (k + 1 == parts.size() ? " and " : ", ") + parts[k];
  }
  return text + ": occlusion and sampled normals may be wrong";
}

}  // namespace vantage
