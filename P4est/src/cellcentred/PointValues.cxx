// SPDX-License-Identifier: GPL-2.0-or-later
#include "PointValues.h"

#include <cstring>
#include <limits>
#include <numeric>

namespace sltk
{
namespace p4est
{

namespace
{

/// A rank's answers to the points it was sent (NaN where it holds none: ok false).
template <int D>
std::vector<double> answer(const CellTree<D>& tree, const LeafGraph<D>& graph,
  const std::vector<CellPolynomial<D>>& polynomials, const std::vector<std::array<double, D>>& asked, bool& ok)
{
  std::vector<int> leaf;
  tree.locate(asked, leaf);
  std::vector<double> values(asked.size(), std::numeric_limits<double>::quiet_NaN());
  for (size_t k = 0; k < asked.size(); ++k)
  {
    const int i = leaf[k];
    if (i >= 0 && i < graph.Owned)
    {
      values[k] = polynomials[static_cast<size_t>(i)].eval(asked[k]);
    }
    else
    {
      ok = false;
    }
  }
  return values;
}

} // namespace

template <int D>
Status valuesAtPoints(const CellTree<D>& tree, const LeafGraph<D>& graph,
  const std::vector<CellPolynomial<D>>& polynomials, const std::vector<std::array<double, D>>& points,
  std::vector<double>& values)
{
  using Point = std::array<double, D>;
  const Communicator& comm = tree.communicator();
  std::vector<int> leaf;
  tree.locate(points, leaf);
  values.assign(points.size(), 0.0);
  std::vector<Point> remote;
  std::vector<size_t> remoteIndex;
  for (size_t k = 0; k < points.size(); ++k)
  {
    const int i = leaf[k];
    if (i >= 0 && i < graph.Owned)
    {
      values[k] = polynomials[static_cast<size_t>(i)].eval(points[k]);
    }
    else
    {
      remote.push_back(points[k]);
      remoteIndex.push_back(k);
    }
  }
  bool ok = true;
  if (comm.size() == 1)
  {
    ok = remote.empty();
  }
  else
  {
    // Every remote point to the owner of its leaf, grouped by rank.
    std::vector<int> owner;
    tree.owners(remote, owner);
    std::vector<size_t> order(remote.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&owner](size_t a, size_t b) { return owner[a] < owner[b]; });
    std::vector<Point> sent(remote.size());
    std::vector<std::int64_t> sentBytes(static_cast<size_t>(comm.size()), 0);
    for (size_t m = 0; m < order.size(); ++m)
    {
      sent[m] = remote[order[m]];
      sentBytes[static_cast<size_t>(owner[order[m]])] += static_cast<std::int64_t>(sizeof(Point));
    }
    std::vector<unsigned char> bytes;
    std::vector<std::int64_t> askedBytes;
    comm.allToAllV(sent.data(), sentBytes, bytes, askedBytes);
    std::vector<Point> asked(bytes.size() / sizeof(Point));
    if (!asked.empty())
    {
      std::memcpy(static_cast<void*>(asked.data()), bytes.data(), asked.size() * sizeof(Point));
    }
    const std::vector<double> answers = answer<D>(tree, graph, polynomials, asked, ok);
    // The answers go back in the order asked; each rank's come back in the order sent.
    std::vector<std::int64_t> answerBytes(askedBytes.size());
    for (size_t r = 0; r < askedBytes.size(); ++r)
    {
      answerBytes[r] =
        askedBytes[r] / static_cast<std::int64_t>(sizeof(Point)) * static_cast<std::int64_t>(sizeof(double));
    }
    std::vector<std::int64_t> receivedBytes;
    comm.allToAllV(answers.data(), answerBytes, bytes, receivedBytes);
    for (size_t m = 0; m < order.size(); ++m)
    {
      double value;
      std::memcpy(&value, bytes.data() + m * sizeof(double), sizeof(double));
      values[remoteIndex[order[m]]] = value;
    }
  }
  return comm.agree(ok ? Status::ok()
                       : Status::numericalFailure("the cell-centred SL step sent a foot to a rank that does not hold "
                                                  "its leaf (the partition and the leaf table disagree)"));
}

template Status valuesAtPoints<2>(const CellTree<2>&, const LeafGraph<2>&, const std::vector<CellPolynomial<2>>&,
  const std::vector<std::array<double, 2>>&, std::vector<double>&);
template Status valuesAtPoints<3>(const CellTree<3>&, const LeafGraph<3>&, const std::vector<CellPolynomial<3>>&,
  const std::vector<std::array<double, 3>>&, std::vector<double>&);

} // namespace p4est
} // namespace sltk
