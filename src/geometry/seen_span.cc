#include "geometry/seen_span.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace parkloc::geometry {
namespace {

// Sample k of n at the centre of its cell, so the samples cover [0, 1] evenly.
double centreOf(int k, int n) { return (k + 0.5) / n; }

// First and last index whose share reaches `min_share`; empty when none does.
std::optional<std::pair<int, int>> seenRange(const std::vector<double>& shares, double min_share) {
  int first = -1, last = -1;
  for (int k = 0; k < static_cast<int>(shares.size()); ++k)
    if (shares[k] >= min_share) {
      if (first < 0) first = k;
      last = k;
    }
  if (first < 0) return std::nullopt;
  return std::make_pair(first, last);
}

}  // namespace

std::optional<ParameterSpan> seenSpan(const std::function<bool(double u, double v)>& seen,
                                      const SeenSpanOptions& options) {
  const int nu = std::max(options.samples_u, 1), nv = std::max(options.samples_v, 1);
  std::vector<unsigned char> grid(static_cast<size_t>(nu) * nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) grid[i * nv + j] = seen(centreOf(i, nu), centreOf(j, nv)) ? 1 : 0;

  std::vector<double> column_share(nu, 0.0);
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) column_share[i] += grid[i * nv + j];
    column_share[i] /= nv;
  }
  const auto columns = seenRange(column_share, options.min_share);
  if (!columns) return std::nullopt;
  const int span = columns->second - columns->first + 1;
  std::vector<double> row_share(nv, 0.0);
  for (int j = 0; j < nv; ++j) {
    for (int i = columns->first; i <= columns->second; ++i) row_share[j] += grid[i * nv + j];
    row_share[j] /= span;
  }
  const auto rows = seenRange(row_share, options.min_share);
  if (!rows) return std::nullopt;

  ParameterSpan out;
  out.u0 = static_cast<double>(columns->first) / nu;
  out.u1 = static_cast<double>(columns->second + 1) / nu;
  out.v0 = static_cast<double>(rows->first) / nv;
  out.v1 = static_cast<double>(rows->second + 1) / nv;
  return out;
}

}  // namespace parkloc::geometry
