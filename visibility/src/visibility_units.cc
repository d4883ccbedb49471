#include "visibility_units.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>

#include "vantage/analysis/common.h"

namespace vantage::visibility::internal {
namespace {

// Without a certain marker, the greedy bound pairs every unit with the others; beyond this many
// units the patch (a large one) keeps its other bounds and is split.
constexpr int kMaxFreeUnits = 48;
// Up to this many mixed units, the bound takes the best of every choice of units (exact).
constexpr int kMaxEnumeratedUnits = 12;
// The mixed markers of a patch in units; unit index 0 stands for the certain markers.
struct Units {
  int certain = 0;
  std::vector<int> of;     // per marker: its unit (1..), 0 when certain, -1 when hidden
  std::vector<int> size;   // per unit (index 0 unused)
  std::vector<int> klass;  // per unit: its cone class when at its cone's edge, else -1
  int count() const { return static_cast<int>(size.size()) - 1; }
};

Units group(const ConeClasses& classes, const std::vector<Seen>& seen) {
  const int n = static_cast<int>(seen.size());
  Units u;
  u.of.assign(static_cast<std::size_t>(n), -1);
  u.size = {0};
  u.klass = {-1};
  std::vector<int> class_unit(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i) {
    if (seen[i] == Seen::kVisible) {
      ++u.certain;
      u.of[i] = 0;
    }
    if (!is_mixed(seen[i])) continue;
    int& shared = class_unit[static_cast<std::size_t>(classes.of(i))];
    if (seen[i] == Seen::kConeEdge && shared >= 0) {
      u.of[i] = shared;
    } else {
      u.of[i] = static_cast<int>(u.size.size());
      u.size.push_back(0);
      u.klass.push_back(seen[i] == Seen::kConeEdge ? classes.of(i) : -1);
      if (seen[i] == Seen::kConeEdge) shared = u.of[i];
    }
    ++u.size[static_cast<std::size_t>(u.of[i])];
  }
  return u;
}

// w(x, y): the least pair bound between units x and y (x == y: within x), 1 without pairs.
class Weights {
 public:
  Weights(const Units& units, const PatchMarkers& patch) : side_(units.count() + 1) {
    w_.assign(static_cast<std::size_t>(side_) * side_, 1.0);
    for (int k : patch.pairs) {
      const auto [i, j] = patch.pair_of[static_cast<std::size_t>(k)];
      const int x = units.of[i], y = units.of[j];
      if (x == 0 && y == 0) continue;  // bound 2's pairs
      const double b =
          sin_plus(std::abs(patch.centre.dot(patch.u.col(k))), patch.cos_r, patch.sin_r);
      double& wxy = at(x, y);
      wxy = std::min(wxy, b);
      at(y, x) = wxy;
    }
  }
  double operator()(int x, int y) const { return w_[index(x, y)]; }

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(x) * static_cast<std::size_t>(side_) +
           static_cast<std::size_t>(y);
  }
  double& at(int x, int y) { return w_[index(x, y)]; }
  int side_;
  std::vector<double> w_;
};

// Every choice of units holding `need` markers and one of each pair in `apart`: the least pair
// bound among the certain markers' pairs with them and their own pairs, at its best. A choice
// that is enough stops growing, since more units only add pairs.
double best_choice(const Units& units, const Weights& w, int need,
                   const std::vector<std::pair<int, int>>& apart, const CollinearTest* collinear) {
  const int side = units.count() + 1;
  std::vector<int> chosen;
  std::vector<char> in(static_cast<std::size_t>(side), 0);
  auto covers = [&] {
    for (const auto& [x, y] : apart) {
      if (!in[x] && !in[y]) return false;
    }
    return true;
  };
  // The certain markers and those of the chosen units, increasing, on one line.
  std::vector<int> markers;
  auto on_one_line = [&] {
    if (collinear == nullptr) return false;
    markers.clear();
    for (std::size_t i = 0; i < units.of.size(); ++i) {
      const int x = units.of[i];
      if (x == 0 || (x > 0 && in[static_cast<std::size_t>(x)]))
        markers.push_back(static_cast<int>(i));
    }
    return (*collinear)(markers);
  };
  double best = 0.0;
  std::function<void(int, int, double)> choose = [&](int next, int size, double value) {
    if (value <= best) return;
    // Enough markers, one of each pair that cannot both hide, and not on one line: trackable.
    // More units only add pairs, so the choice stops growing.
    if (size >= need && covers() && !on_one_line()) {
      best = value;
      return;
    }
    for (int x = next; x < side; ++x) {
      double with = std::min({value, w(0, x), w(x, x)});
      for (int y : chosen) with = std::min(with, w(x, y));
      chosen.push_back(x);
      in[x] = 1;
      choose(x + 1, size + units.size[static_cast<std::size_t>(x)], with);
      in[x] = 0;
      chosen.pop_back();
    }
  };
  choose(1, 0, 1.0);
  return best;
}

// Many units (a large patch): the best units by w(anchor, U) and w(U, U) until `size` more
// markers are seen. Any choice of units that large holds a unit at most this.
double threshold(const Units& units, const Weights& w, int anchor, int size) {
  std::vector<std::pair<double, int>> by_value;
  for (int x = 1; x <= units.count(); ++x) {
    if (x != anchor) {
      by_value.emplace_back(std::min(w(anchor, x), w(x, x)),
                            units.size[static_cast<std::size_t>(x)]);
    }
  }
  std::sort(by_value.begin(), by_value.end(), std::greater<>());
  int taken = 0;
  for (const auto& [value, count] : by_value) {
    taken += count;
    if (taken >= size) return value;
  }
  return 0.0;  // too few markers: pruned before (fewer than min_visible can be seen)
}

}  // namespace

double sin_plus(double s, double cos_r, double sin_r) {
  if (s >= cos_r) return 1.0;
  return s * cos_r + std::sqrt(std::max(0.0, 1.0 - s * s)) * sin_r;
}

double needed_mixed_bound(const ConeClasses& classes, int min_visible, const PatchMarkers& patch) {
  const Units units = group(classes, patch.seen);
  const int need = min_visible - units.certain;
  const int count = units.count();
  std::vector<std::pair<int, int>> apart;
  for (int x = 1; x <= count && count <= kMaxEnumeratedUnits; ++x) {
    for (int y = x + 1; y <= count; ++y) {
      const int a = units.klass[static_cast<std::size_t>(x)];
      const int b = units.klass[static_cast<std::size_t>(y)];
      if (a >= 0 && b >= 0 && classes.hidden_apart(a, b)) apart.emplace_back(x, y);
    }
  }
  // Certain markers on one line need a unit off it, as too few need more.
  const bool certain_on_line = [&] {
    if (patch.collinear == nullptr) return false;
    std::vector<int> certain;
    for (std::size_t i = 0; i < units.of.size(); ++i) {
      if (units.of[i] == 0) certain.push_back(static_cast<int>(i));
    }
    return (*patch.collinear)(certain);
  }();
  if (need <= 0 && !certain_on_line && (apart.empty() || count > kMaxEnumeratedUnits)) return 1.0;
  if (units.certain == 0 && count > std::max(kMaxFreeUnits, kMaxEnumeratedUnits)) return 1.0;
  const Weights w(units, patch);
  if (count <= kMaxEnumeratedUnits) return best_choice(units, w, need, apart, patch.collinear);
  if (need <= 0) return 1.0;  // on a line, with many units: no bound (sound)
  if (units.certain > 0) return threshold(units, w, 0, need);
  // No certain marker: some unit U is seen; the rest follows as above, U's pairs included.
  double best = 0.0;
  for (int x = 1; x <= count; ++x) {
    const int rest = min_visible - units.size[static_cast<std::size_t>(x)];
    best = std::max(best, rest <= 0 ? w(x, x) : std::min(w(x, x), threshold(units, w, x, rest)));
  }
  return best;
}

}  // namespace vantage::visibility::internal
