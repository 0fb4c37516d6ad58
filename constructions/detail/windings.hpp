#pragma once
// The windings a Hermite construction tries (G1 and G2, docs/g1_hermite.md "Windings"): the
// turning target is Δ_k = base + 2πk with base = φ1 − φ0, both end angles relative to the chord
// in (−π, π]. Given a winding, only that k; otherwise every k with |Δ_k| ≤ max_turning, least
// |Δ_k| first (on a tie the lesser |k|, then the left turn), so the first curve found is the
// least-turning one.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lac/common/error.hpp"

namespace lac::detail {

/// At most 205 windings (|Δ| ≤ 200π, |base| < 2π): a fixed buffer, no allocation on the fast path
/// (and not zeroed: only the first n are read).
struct Windings {
  std::array<int, 208> k;
  std::size_t n = 0;
  void push_back(int v) { k[n++] = v; }
  int front() const { return k[0]; }
  const int* begin() const { return k.data(); }
  const int* end() const { return k.data() + n; }
};

inline double turning_of(double base, int k) { return base + 2 * std::numbers::pi * k; }

/// The windings to try, in order (max_turning ≤ 200π, validated by the caller).
inline Windings windings_to_try(double base, std::optional<int> winding, double max_turning) {
  Windings w;
  if (winding) {
    w.push_back(*winding);
    return w;
  }
  constexpr double two_pi = 2 * std::numbers::pi;
  const int k_lo = std::max(-101, static_cast<int>(std::ceil((-max_turning - base) / two_pi))) - 1;
  const int k_hi = std::min(101, static_cast<int>(std::floor((max_turning - base) / two_pi))) + 1;
  for (int k = k_lo; k <= k_hi; ++k)
    if (std::abs(turning_of(base, k)) <= max_turning) w.push_back(k);
  // A strict total order on distinct k (the keys tie only for equal k): std::sort, no buffer.
  std::sort(w.k.data(), w.k.data() + w.n, [&](int a, int b) {
    const double ta = std::abs(turning_of(base, a)), tb = std::abs(turning_of(base, b));
    if (ta != tb) return ta < tb;
    if (std::abs(a) != std::abs(b)) return std::abs(a) < std::abs(b);
    return turning_of(base, a) > turning_of(base, b);
  });
  return w;
}

/// " turning a, b: why; turning c: why2": the turnings excluded by a proof, grouped by argument
/// (proofs: (turning, the argument's text)).
inline std::string proofs_text(const std::vector<std::pair<double, std::string>>& proofs) {
  std::string m;
  std::vector<bool> used(proofs.size(), false);
  for (std::size_t i = 0; i < proofs.size(); ++i) {
    if (used[i]) continue;
    std::string list;
    for (std::size_t j = i; j < proofs.size(); ++j)
      if (!used[j] && proofs[j].second == proofs[i].second) {
        list += (list.empty() ? "" : ", ") + format_number(proofs[j].first);
        used[j] = true;
      }
    m += (i == 0 ? " " : "; ") + std::string("turning ") + list + ": " + proofs[i].second;
  }
  return m;
}

}  // namespace lac::detail
