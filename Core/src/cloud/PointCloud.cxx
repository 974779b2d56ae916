// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/PointCloud.h"

#include "sltk/exec/Communicator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace sltk
{

template <int D>
Box<D> boundingBox(const PointCloud<D>& cloud)
{
  Box<D> box;
  box.Min.fill(std::numeric_limits<double>::infinity());
  box.Max.fill(-std::numeric_limits<double>::infinity());
  for (const auto& p : cloud.Points)
  {
    for (int a = 0; a < D; ++a)
    {
      box.Min[a] = std::min(box.Min[a], p[a]);
      box.Max[a] = std::max(box.Max[a], p[a]);
    }
  }
  return box;
}

namespace
{
template <int D>
double distance(const std::array<double, D>& p, const std::array<double, D>& q)
{
  double s = 0.0;
  for (int a = 0; a < D; ++a)
  {
    s += (p[a] - q[a]) * (p[a] - q[a]);
  }
  return std::sqrt(s);
}

std::array<double, 3> cross(const std::array<double, 3>& x, const std::array<double, 3>& y)
{
  return { x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0] };
}
double norm(const std::array<double, 3>& x)
{
  return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}
template <int D>
std::array<double, 3> from(const std::array<double, D>& p, const std::array<double, D>& origin)
{
  std::array<double, 3> v{};
  for (int a = 0; a < D; ++a)
  {
    v[a] = p[a] - origin[a];
  }
  return v;
}

/// The point with the largest measure: its value, its global index and its place;
/// Index -1 when no point measures more than 0.
template <int D>
struct Farthest
{
  double Value = 0.0;
  std::int64_t Index = -1;
  std::array<double, D> X{};
};

/// A point with a non-finite coordinate: its global index and that coordinate.
struct NonFinite
{
  std::int64_t Index;
  double Value;
};

/// The points the validation reads: the whole cloud on one rank (`comm` null),
/// each rank's share of it (global indices firstId, firstId + 1, ...), or the
/// points each rank owns among those it holds (`ids` their global indices,
/// `mine` the owned ones: OwnedPoints, PointOwners.h); every answer reduced
/// over the ranks to the whole cloud's, the same on every rank.
template <int D>
class ValidationView
{
public:
  ValidationView(const PointCloud<D>& share, std::int64_t firstId, const Communicator* comm)
    : Share(share)
    , FirstId(firstId)
    , Comm(comm)
  {
  }
  ValidationView(const PointCloud<D>& held, const std::vector<std::int64_t>& ids, const std::vector<std::uint8_t>& mine,
    const Communicator& comm)
    : Share(held)
    , Ids(&ids)
    , Mine(&mine)
    , Comm(&comm)
  {
  }

  std::int64_t count() const
  {
    std::int64_t n = 0;
    for (size_t k = 0; k < this->Share.Points.size(); ++k)
    {
      n += this->counted(k) ? 1 : 0;
    }
    return this->Comm ? this->Comm->allReduce(n, ReduceOp::Sum) : n;
  }

  /// The point of the lowest global index with a non-finite coordinate, and that coordinate.
  bool firstNonFinite(NonFinite& found) const
  {
    std::vector<NonFinite> local;
    for (size_t k = 0; k < this->Share.Points.size() && (local.empty() || this->Ids); ++k)
    {
      for (int a = 0; a < D && this->counted(k); ++a)
      {
        if (!std::isfinite(this->Share.Points[k][a]) && (local.empty() || this->id(k) < local[0].Index))
        {
          local.assign(1, { this->id(k), this->Share.Points[k][a] });
          break;
        }
      }
    }
    const std::vector<NonFinite> all = this->Comm ? this->Comm->allGatherV(local) : local;
    if (all.empty())
    {
      return false;
    }
    found = *std::min_element(
      all.begin(), all.end(), [](const NonFinite& x, const NonFinite& y) { return x.Index < y.Index; });
    return true;
  }

  Box<D> box() const
  {
    Box<D> b;
    b.Min.fill(std::numeric_limits<double>::infinity());
    b.Max.fill(-std::numeric_limits<double>::infinity());
    for (size_t k = 0; k < this->Share.Points.size(); ++k)
    {
      for (int a = 0; a < D && this->counted(k); ++a)
      {
        b.Min[a] = std::min(b.Min[a], this->Share.Points[k][a]);
        b.Max[a] = std::max(b.Max[a], this->Share.Points[k][a]);
      }
    }
    if (this->Comm)
    {
      this->Comm->allReduce(b.Min.data(), D, ReduceOp::Min);
      this->Comm->allReduce(b.Max.data(), D, ReduceOp::Max);
    }
    return b;
  }

  /// The place of the point of global index `index`.
  std::array<double, D> point(std::int64_t index) const
  {
    std::array<double, D> x;
    x.fill(std::numeric_limits<double>::infinity());
    if (!this->Ids)
    {
      const std::int64_t k = index - this->FirstId;
      if (k >= 0 && k < this->Share.size())
      {
        x = this->Share.Points[static_cast<size_t>(k)];
      }
    }
    for (size_t k = 0; this->Ids && k < this->Share.Points.size(); ++k)
    {
      x = this->counted(k) && this->id(k) == index ? this->Share.Points[k] : x;
    }
    if (this->Comm)
    {
      this->Comm->allReduce(x.data(), D, ReduceOp::Min); // one rank holds it, the others +inf
    }
    return x;
  }

  /// The point of the largest measure(p) > 0, the lowest index among equal ones
  /// (one rank's scan keeps the first strictly larger).
  template <class Measure>
  Farthest<D> farthest(Measure measure) const
  {
    const auto better = [](const Farthest<D>& x, const Farthest<D>& than)
    { return x.Value > than.Value || (x.Value == than.Value && x.Value > 0.0 && x.Index < than.Index); };
    Farthest<D> best;
    for (size_t k = 0; k < this->Share.Points.size(); ++k)
    {
      if (this->counted(k))
      {
        const Farthest<D> here{ measure(this->Share.Points[k]), this->id(k), this->Share.Points[k] };
        best = better(here, best) ? here : best;
      }
    }
    if (!this->Comm)
    {
      return best;
    }
    Farthest<D> over;
    for (const Farthest<D>& f : this->Comm->allGatherV(std::vector<Farthest<D>>{ best }))
    {
      over = better(f, over) ? f : over;
    }
    return over;
  }

private:
  std::int64_t id(size_t k) const { return this->Ids ? (*this->Ids)[k] : this->FirstId + static_cast<std::int64_t>(k); }
  bool counted(size_t k) const { return !this->Mine || (*this->Mine)[k]; }

  const PointCloud<D>& Share;
  const std::vector<std::int64_t>* Ids = nullptr;
  const std::vector<std::uint8_t>* Mine = nullptr;
  std::int64_t FirstId = 0;
  const Communicator* Comm;
};

/// validateCloud's checks on the points `view` reads, in its order, with its messages.
template <int D>
Status validatePoints(const ValidationView<D>& view)
{
  const std::string dim = std::to_string(D) + "D";
  const std::int64_t n = view.count();
  if (n == 0)
  {
    return Status::invalidArgument("the point cloud is empty: give at least " + std::to_string(D + 1) +
      " points that are not all on one " + (D == 2 ? "line" : "plane"));
  }
  NonFinite bad{};
  if (view.firstNonFinite(bad))
  {
    return Status::invalidArgument("point " + std::to_string(bad.Index) + " has a non-finite coordinate (" +
      std::to_string(bad.Value) + "): remove NaN/Inf points before reconstructing");
  }
  if (n < D + 1)
  {
    return Status::invalidArgument("the point cloud has " + std::to_string(n) + " point(s); a " + dim +
      " reconstruction needs at least " + std::to_string(D + 1));
  }
  const Box<D> box = view.box();
  double diameter = 0.0, magnitude = 0.0;
  for (int a = 0; a < D; ++a)
  {
    diameter = std::max(diameter, box.extent(a));
    magnitude = std::max({ magnitude, std::fabs(box.Min[a]), std::fabs(box.Max[a]) });
  }
  // Beyond this, squared distances (h_P, the distance function) overflow double.
  constexpr double LargestCoordinate = 1e150;
  if (!(magnitude <= LargestCoordinate) || !std::isfinite(diameter))
  {
    std::ostringstream m;
    m << "coordinates reach " << magnitude
      << ", beyond what distances in double precision can hold (1e150): rescale the cloud (e.g. divide the "
         "coordinates by its extent) before reconstructing";
    return Status::invalidArgument(m.str());
  }
  if (diameter == 0.0)
  {
    return Status::invalidArgument("all " + std::to_string(n) + " points coincide: nothing to reconstruct");
  }
  // A grid of ~1e4 cells per side needs ~1e-8 relative resolution to stay accurate.
  if (diameter < 1e-8 * magnitude)
  {
    return Status::invalidArgument("the cloud's extent (" + std::to_string(diameter) +
      ") is too small against its distance from the origin (" + std::to_string(magnitude) +
      "): its coordinates carry too few digits for the grid; translate the points near the origin where they are "
      "made, before they are rounded to double");
  }
  // Two well-separated points: the first one and the one farthest from it; then the
  // largest distance of any point from the line through them, and from the plane
  // through them and the point that has it (zero for collinear, coplanar clouds).
  const std::array<double, D> p0 = view.point(0);
  const Farthest<D> first = view.farthest([&](const std::array<double, D>& p) { return distance<D>(p0, p); });
  const std::array<double, D> p1 = first.Index >= 0 ? first.X : p0;
  const auto u = from<D>(p1, p0);
  const double len = norm(u);
  const Farthest<D> offLine =
    view.farthest([&](const std::array<double, D>& p) { return norm(cross(u, from<D>(p, p0))) / len; });
  const std::string closed = D == 2 ? "a closed curve" : "a closed surface";
  if (offLine.Value <= 1e-12 * diameter)
  {
    return Status::invalidArgument("all points lie on one line: " + closed + " cannot be reconstructed from them");
  }
  if constexpr (D == 3)
  {
    const auto normal = cross(from<3>(p1, p0), from<3>(offLine.X, p0));
    const double nn = norm(normal);
    const Farthest<D> offPlane = view.farthest(
      [&](const std::array<double, 3>& p)
      {
        const auto v = from<3>(p, p0);
        return std::fabs(normal[0] * v[0] + normal[1] * v[1] + normal[2] * v[2]) / nn;
      });
    if (offPlane.Value <= 1e-12 * diameter)
    {
      return Status::invalidArgument("all points lie on one plane: a closed surface cannot be reconstructed from "
                                     "them; for a planar outline, give the points a constant z (a 2D "
                                     "reconstruction)");
    }
  }
  return Status::ok();
}

/// The refusal of `count` points on one process (more than MaximumIndexedPoints).
Status tooManyPoints(std::int64_t count, const char* what)
{
  return Status::outOfMemory(std::string(what) + " has " + std::to_string(count) + " points, more than the " +
    std::to_string(MaximumIndexedPoints) +
    " one process indexes: read it on more MPI ranks (mpirun -np N), or thin it first");
}
} // namespace

template <int D>
Status validateCloud(const PointCloud<D>& cloud)
{
  if (cloud.size() > MaximumIndexedPoints)
  {
    return tooManyPoints(cloud.size(), "the cloud");
  }
  return validatePoints(ValidationView<D>(cloud, 0, nullptr));
}

template <int D>
Status validateCloudShares(const PointCloud<D>& share, std::int64_t firstId, const Communicator& comm)
{
  // The view's first point, first non-finite point and ties read the shares in rank order.
  struct Share
  {
    std::int64_t First, Count;
  };
  std::int64_t next = 0;
  for (const Share& s : comm.allGatherV(std::vector<Share>{ { firstId, share.size() } }))
  {
    if (s.First != next)
    {
      return Status::invalidArgument("validateCloudShares: the ranks' shares are not consecutive in rank order");
    }
    if (s.Count > MaximumIndexedPoints)
    {
      return tooManyPoints(s.Count, "a rank's share of the cloud");
    }
    next += s.Count;
  }
  return validatePoints(ValidationView<D>(share, firstId, &comm));
}

template <int D>
Status validateOwnedPoints(const PointCloud<D>& held, const std::vector<std::int64_t>& ids,
  const std::vector<std::uint8_t>& mine, const Communicator& comm)
{
  const bool shaped = ids.size() == held.Points.size() && mine.size() == held.Points.size();
  if (comm.anyRank(!shaped))
  {
    return Status::invalidArgument("validateOwnedPoints: one index and one owner flag a held point");
  }
  return validatePoints(ValidationView<D>(held, ids, mine, comm));
}

template Box<2> boundingBox(const PointCloud<2>&);
template Box<3> boundingBox(const PointCloud<3>&);
template Status validateCloud(const PointCloud<2>&);
template Status validateCloud(const PointCloud<3>&);
template Status validateCloudShares(const PointCloud<2>&, std::int64_t, const Communicator&);
template Status validateCloudShares(const PointCloud<3>&, std::int64_t, const Communicator&);
template Status validateOwnedPoints(
  const PointCloud<2>&, const std::vector<std::int64_t>&, const std::vector<std::uint8_t>&, const Communicator&);
template Status validateOwnedPoints(
  const PointCloud<3>&, const std::vector<std::int64_t>&, const std::vector<std::uint8_t>&, const Communicator&);

bool flattenIfPlanar(const PointCloud<3>& cloud, PointCloud<2>& flat, double& z)
{
  return !cloud.Points.empty() && flattenIfPlanar(cloud, boundingBox(cloud), flat, z);
}

bool flattenIfPlanar(const PointCloud<3>& cloud, const Box<3>& whole, PointCloud<2>& flat, double& z)
{
  if (!(whole.Min[2] <= whole.Max[2]) || whole.extent(2) != 0.0)
  {
    return false;
  }
  z = whole.Min[2];
  flat.Points.resize(cloud.Points.size());
  for (size_t k = 0; k < cloud.Points.size(); ++k)
  {
    flat.Points[k] = { cloud.Points[k][0], cloud.Points[k][1] };
  }
  return true;
}

} // namespace sltk
