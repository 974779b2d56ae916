// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudThinning.h"

#include "RankParts.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sltk
{

namespace
{
Status checkCell(double cell)
{
  return cell > 0.0 && std::isfinite(cell) ? Status::ok()
                                           : Status::invalidArgument("the thinning cell must be positive and finite");
}

/// The cells of edge `cell` anchored at the box's minimum: their count per
/// axis, and the number of a point's cell (x fastest).
template <int D>
struct ThinningCells
{
  Box<D> Bounds;
  double Cell = 0.0;
  std::array<std::int64_t, D> Count{};

  Status set(const Box<D>& box, double cell)
  {
    SLTK_RETURN_IF_ERROR(checkCell(cell));
    this->Bounds = box;
    this->Cell = cell;
    double total = 1.0;
    for (int a = 0; a < D; ++a)
    {
      const double c = std::floor(box.extent(a) / cell) + 1.0;
      total *= c;
      this->Count[a] = static_cast<std::int64_t>(std::min(c, 4e18));
    }
    if (!(total < 4e18))
    {
      return Status::invalidArgument("the thinning cell is too small for the cloud's extent: use a larger one");
    }
    return Status::ok();
  }
  /// The cell's index along axis a of coordinate x.
  std::int64_t along(int a, double x) const
  {
    const auto i = static_cast<std::int64_t>(std::floor((x - this->Bounds.Min[a]) / this->Cell));
    return std::min(this->Count[a] - 1, std::max<std::int64_t>(0, i));
  }
  std::int64_t number(const std::array<double, D>& p) const
  {
    std::int64_t id = 0;
    for (int a = D - 1; a >= 0; --a)
    {
      id = id * this->Count[a] + this->along(a, p[a]);
    }
    return id;
  }
  /// The cell numbers per index along axis a (the product of the faster axes' counts).
  std::int64_t stride(int a) const
  {
    std::int64_t s = 1;
    for (int b = 0; b < a; ++b)
    {
      s *= this->Count[b];
    }
    return s;
  }
};

/// A point on its way to the rank that averages its cell.
template <int D>
struct CellPoint
{
  std::int64_t Cell;
  std::int64_t Id; ///< its global index: the cell's points are added in this order
  std::array<double, D> X;
};

/// The mean of points given one by one in their order (the cloud's).
template <int D>
class CellMean
{
public:
  void add(const std::array<double, D>& x)
  {
    for (int a = 0; a < D; ++a)
    {
      this->Sum[a] += x[a];
    }
    ++this->Count;
  }
  std::array<double, D> value() const
  {
    std::array<double, D> mean = this->Sum;
    for (int a = 0; a < D; ++a)
    {
      mean[a] /= static_cast<double>(this->Count);
    }
    return mean;
  }

private:
  std::array<double, D> Sum{};
  std::int64_t Count = 0;
};

/// The cell means of `points` sorted by (cell, global index): `means` in cell order, `cells` their numbers.
template <int D>
void cellMeans(
  const std::vector<CellPoint<D>>& points, std::vector<std::array<double, D>>& means, std::vector<std::int64_t>& cells)
{
  for (size_t b = 0; b < points.size();)
  {
    CellMean<D> mean;
    size_t e = b;
    for (; e < points.size() && points[e].Cell == points[b].Cell; ++e)
    {
      mean.add(points[e].X);
    }
    means.push_back(mean.value());
    cells.push_back(points[b].Cell);
    b = e;
  }
}

template <int D>
void sortByCell(std::vector<CellPoint<D>>& points)
{
  std::sort(points.begin(), points.end(),
    [](const CellPoint<D>& a, const CellPoint<D>& b) { return a.Cell != b.Cell ? a.Cell < b.Cell : a.Id < b.Id; });
}

/// A rank's cells sharing the axes slower than the slabs' axis (`Slower`): on
/// that row of cells, lower ranks hold lower cell numbers.
struct RowCount
{
  std::int64_t Slower;
  std::int64_t Rank;
  std::int64_t Cells;
};

/// The global index of every cell mean of this rank (`cells`, sorted): the
/// number of non-empty cells with a lower number on every rank. A cell's rank
/// grows with its index along the slabs' axis, so on one row of the slower
/// axes the ranks' cells come in rank order: the rows' counts per rank,
/// gathered, place every cell.
std::vector<std::int64_t> globalCellIndices(
  const std::vector<std::int64_t>& cells, std::int64_t rowLength, const Communicator& comm)
{
  std::vector<RowCount> mine;
  for (const std::int64_t c : cells)
  {
    const std::int64_t row = c / rowLength;
    if (mine.empty() || mine.back().Slower != row)
    {
      mine.push_back({ row, comm.rank(), 0 });
    }
    ++mine.back().Cells;
  }
  std::vector<RowCount> all = comm.allGatherV(mine);
  std::sort(all.begin(), all.end(),
    [](const RowCount& a, const RowCount& b) { return a.Slower != b.Slower ? a.Slower < b.Slower : a.Rank < b.Rank; });
  std::vector<std::int64_t> first; // the global index of the first cell of each of this rank's rows
  std::int64_t before = 0;
  for (const RowCount& r : all)
  {
    if (r.Rank == comm.rank())
    {
      first.push_back(before);
    }
    before += r.Cells;
  }
  std::vector<std::int64_t> index(cells.size());
  size_t row = 0;
  for (size_t j = 0; j < cells.size(); ++j)
  {
    if (j > 0 && cells[j] / rowLength != cells[j - 1] / rowLength)
    {
      ++row;
    }
    index[j] = first[row]++;
  }
  return index;
}
} // namespace

template <int D>
Status thinCloud(const PointCloud<D>& cloud, double cell, PointCloud<D>& thinned)
{
  SLTK_RETURN_IF_ERROR(checkCell(cell));
  if (cloud.Points.empty())
  {
    thinned.Points.clear();
    return Status::ok();
  }
  ThinningCells<D> cells;
  SLTK_RETURN_IF_ERROR(cells.set(boundingBox(cloud), cell));
  // (cell number, point index) sorted: each cell's points in their input order.
  std::vector<CellPoint<D>> keyed(cloud.Points.size());
  for (size_t k = 0; k < cloud.Points.size(); ++k)
  {
    keyed[k] = { cells.number(cloud.Points[k]), static_cast<std::int64_t>(k), cloud.Points[k] };
  }
  sortByCell(keyed);
  PointCloud<D> out;
  std::vector<std::int64_t> numbers;
  cellMeans<D>(keyed, out.Points, numbers);
  thinned = std::move(out);
  return Status::ok();
}

template <int D>
Status thinOnRanks(OwnedPoints<D>& points, double cell, const Communicator& comm, std::int64_t& total)
{
  SLTK_RETURN_IF_ERROR(checkCell(cell));
  SLTK_RETURN_IF_ERROR(comm.agree(points.Cuts.ranks() == comm.size()
      ? Status::ok()
      : Status::invalidArgument("thinOnRanks: the points' cuts are not for the ranks running")));
  const Box<D> box = boundingBoxOverRanks(points.Cloud, comm);
  ThinningCells<D> cells;
  if (comm.allReduce(points.Owned, ReduceOp::Sum) == 0)
  {
    total = 0;
    return Status::ok();
  }
  SLTK_RETURN_IF_ERROR(cells.set(box, cell));
  // Each cell is averaged by the rank of its lower face along the slabs' axis
  // (non-decreasing in the cell's index along it): the points of cells that
  // straddle a cut move there.
  const int axis = points.Cuts.Axis;
  const auto averager = [&](std::int64_t along)
  { return points.Cuts.ownerOf(box.Min[axis] + static_cast<double>(along) * cell); };
  // The points of the cells this rank averages stay out of the exchange, and
  // the others are placed once in rank order (counted first): the records are
  // one copy of the points (two for a moment as the received ones join them),
  // where per-rank lists, the send buffer and the received copy were three.
  const size_t ranks = static_cast<size_t>(comm.size());
  const auto rankOf = [&](const std::array<double, D>& x)
  { return static_cast<size_t>(averager(cells.along(axis, x[axis]))); };
  std::vector<std::int64_t> counts;
  std::vector<CellPoint<D>> mine;
  std::vector<CellPoint<D>> send = groupByRank<CellPoint<D>>(
    ranks, counts,
    [&](const auto& emit)
    {
      for (size_t j = 0; j < points.Ids.size(); ++j)
      {
        if (points.Mine[j])
        {
          const auto& x = points.Cloud.Points[j];
          emit(rankOf(x), [&](size_t) { return CellPoint<D>{ cells.number(x), points.Ids[j], x }; });
        }
      }
    },
    comm.rank(), &mine);
  const SlabCuts cuts = points.Cuts;
  const double halo = points.Halo;
  points = OwnedPoints<D>(); // the records hold them; the means replace them
  std::vector<CellPoint<D>> received = comm.allToAllRecords(send, counts);
  send = {};
  mine.insert(mine.end(), received.begin(), received.end());
  received = {};
  sortByCell(mine);
  std::vector<std::array<double, D>> means;
  std::vector<std::int64_t> numbers;
  cellMeans<D>(mine, means, numbers);
  mine = {};
  const std::vector<std::int64_t> ids = globalCellIndices(numbers, cells.stride(axis) * cells.Count[axis], comm);
  total = comm.allReduce(static_cast<std::int64_t>(means.size()), ReduceOp::Sum);
  return sendToOwners<D>(means, ids, cuts, halo, comm, points);
}

template Status thinCloud(const PointCloud<2>&, double, PointCloud<2>&);
template Status thinCloud(const PointCloud<3>&, double, PointCloud<3>&);
template Status thinOnRanks(OwnedPoints<2>&, double, const Communicator&, std::int64_t&);
template Status thinOnRanks(OwnedPoints<3>&, double, const Communicator&, std::int64_t&);

} // namespace sltk
