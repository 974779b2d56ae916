// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/levelset/FastSweeping.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sltk
{

namespace
{
/// The Godunov update with precomputed spacings h and weights w = 1 / h^2.
inline double godunovUpdate(const double* a, const double* h, const double* w, int dims)
{
  // Sort the neighbour values ascending (dims <= 3), carrying the spacings.
  double v[3] = { a[0], 0.0, 0.0 };
  double hs[3] = { h[0], 0.0, 0.0 };
  double ws[3] = { w[0], 0.0, 0.0 };
  for (int k = 1; k < dims; ++k)
  {
    int m = k;
    for (; m > 0 && a[k] < v[m - 1]; --m)
    {
      v[m] = v[m - 1];
      hs[m] = hs[m - 1];
      ws[m] = ws[m - 1];
    }
    v[m] = a[k];
    hs[m] = h[k];
    ws[m] = w[k];
  }
  if (!(v[0] < std::numeric_limits<double>::infinity()))
  {
    return std::numeric_limits<double>::infinity();
  }
  // One axis: u = a_0 + h_0; add axes while the solution exceeds the next value.
  double u = v[0] + hs[0];
  double sw = ws[0];
  double swa = ws[0] * v[0];
  double swa2 = ws[0] * v[0] * v[0];
  for (int m = 1; m < dims; ++m)
  {
    if (u <= v[m])
    {
      break;
    }
    // sum_k w_k (u - v_k)^2 = 1 over the first m + 1 axes.
    sw += ws[m];
    swa += ws[m] * v[m];
    swa2 += ws[m] * v[m] * v[m];
    const double disc = swa * swa - sw * (swa2 - 1.0);
    u = (swa + std::sqrt(std::max(0.0, disc))) / sw;
  }
  return u;
}
} // namespace

double godunovEikonal(const double* a, const double* h, int dims)
{
  double w[3] = { 1.0, 1.0, 1.0 };
  for (int k = 0; k < dims; ++k)
  {
    w[k] = 1.0 / (h[k] * h[k]);
  }
  return godunovUpdate(a, h, w, dims);
}

template <int D>
Status fastSweep(GridField<D, double>& u, const std::vector<std::uint8_t>& frozen, const Context& ctx,
  const FastSweepingOptions& options, FastSweepingReport* report)
{
  const GridSpec<D>& g = u.spec();
  if (static_cast<Index>(frozen.size()) != g.nodeCount())
  {
    return Status::invalidArgument("fast sweeping: the frozen mask must have one entry per grid node");
  }
  // Treat 2D as 3D with one layer: n = 1 and no neighbours along z.
  Index n[3] = { 1, 1, 1 };
  Index s[3] = { 0, 0, 0 };
  double h[3] = { 1.0, 1.0, 1.0 };
  double w[3] = { 1.0, 1.0, 1.0 };
  double minH = std::numeric_limits<double>::infinity();
  for (int a = 0; a < D; ++a)
  {
    n[a] = g.Dims[a];
    s[a] = u.strides()[a];
    h[a] = g.Spacing[a];
    w[a] = 1.0 / (h[a] * h[a]);
    minH = std::min(minH, h[a]);
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double tolerance = options.Tolerance * minH;
  double* p = u.origin();
  const std::uint8_t* fixedNode = frozen.data();
  // Locking (Bak, McLaughlin and Renzi 2010): a node is recomputed only when a
  // neighbour changed since its last update. Skipped updates would reproduce
  // the value already applied, so the result is that of the plain method.
  std::vector<std::uint8_t> active(frozen.size());
  for (size_t k = 0; k < frozen.size(); ++k)
  {
    active[k] = frozen[k] ? 0 : 1;
  }
  std::uint8_t* live = active.data();
  const Index nodeStep[3] = { 1, n[0], n[0] * n[1] };
  FastSweepingReport local;
  for (int cycle = 0; cycle < options.MaxCycles; ++cycle)
  {
    double change = 0.0;
    for (int order = 0; order < (1 << D); ++order)
    {
      const bool back[3] = { (order & 1) != 0, (order & 2) != 0, (order & 4) != 0 };
      for (Index kk = 0; kk < n[2]; ++kk)
      {
        const Index k = back[2] ? n[2] - 1 - kk : kk;
        for (Index jj = 0; jj < n[1]; ++jj)
        {
          const Index j = back[1] ? n[1] - 1 - jj : jj;
          const Index lineNode = n[0] * (j + n[1] * k);
          const Index lineOffset = j * s[1] + k * s[2];
          for (Index ii = 0; ii < n[0]; ++ii)
          {
            const Index i = back[0] ? n[0] - 1 - ii : ii;
            const Index node = lineNode + i;
            if (!live[node])
            {
              continue;
            }
            live[node] = 0;
            double* q = p + lineOffset + i * s[0];
            const Index idx[3] = { i, j, k };
            double nb[3];
            for (int a = 0; a < D; ++a)
            {
              const double lo = idx[a] > 0 ? q[-s[a]] : inf;
              const double hi = idx[a] < n[a] - 1 ? q[s[a]] : inf;
              nb[a] = std::min(lo, hi);
            }
            const double v = godunovUpdate(nb, h, w, D);
            if (v < *q)
            {
              change = std::max(change, std::isfinite(*q) ? *q - v : inf);
              *q = v;
              for (int a = 0; a < D; ++a)
              {
                if (idx[a] > 0)
                {
                  live[node - nodeStep[a]] = !fixedNode[node - nodeStep[a]];
                }
                if (idx[a] < n[a] - 1)
                {
                  live[node + nodeStep[a]] = !fixedNode[node + nodeStep[a]];
                }
              }
            }
          }
        }
      }
    }
    local.Cycles = cycle + 1;
    local.LastChange = change;
    if (change <= tolerance)
    {
      local.Converged = true;
      break;
    }
    if (ctx.interrupter().wasInterrupted())
    {
      if (report)
      {
        *report = local;
      }
      return Status::aborted();
    }
  }
  if (report)
  {
    *report = local;
  }
  return Status::ok();
}

template Status fastSweep(GridField<2, double>&, const std::vector<std::uint8_t>&, const Context&,
  const FastSweepingOptions&, FastSweepingReport*);
template Status fastSweep(GridField<3, double>&, const std::vector<std::uint8_t>&, const Context&,
  const FastSweepingOptions&, FastSweepingReport*);

} // namespace sltk
