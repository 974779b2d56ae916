// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file MissedPlaces.h
/// Where a result that does not fit its cloud misses it (beyond the thesis): the
/// points the last run's surface leaves outside by more than misfitThreshold,
/// grouped by proximity (PointClusters.h), the largest groups with their size,
/// centre and bounds. A lost limb or handle is one group where it was; noise is
/// many small ones spread over the cloud. The points are found where each storage
/// holds phi (each rank its own) and gathered in the cloud's order, so every rank
/// reports the same places.

#include "sltk/cloud/PointCloud.h"
#include "sltk/exec/Communicator.h"
#include "sltk/recon/PointClusters.h"
#include "sltk/recon/ReconstructionOptions.h"
#include "sltk/recon/StoppingRule.h"

#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace sltk
{

/// One group of missed points: how many, their mean, their bounds (unit-box units
/// in a run, the user's in a result: recordsToUser).
template <int D>
struct MissedPlace
{
  Index Points = 0;
  std::array<double, D> Centre{};
  std::array<double, D> Lower{};
  std::array<double, D> Upper{};
};

/// How many of the largest groups a result names.
constexpr size_t MissedPlacesNamed = 3;

/// The groups of the points `local` (this rank's, beyond the misfit threshold) over
/// every rank, largest first (then by their first point), at most MissedPlacesNamed;
/// points closer than `link` are in one group. Collective.
template <int D>
std::vector<MissedPlace<D>> gatherMissedPlaces(
  const PointCloud<D>& cloud, const std::vector<OutsidePoint>& local, double link, const Communicator& comm)
{
  std::vector<OutsidePoint> all = comm.size() > 1 ? comm.allGatherV(local) : local;
  std::sort(all.begin(), all.end(), [](const OutsidePoint& a, const OutsidePoint& b) { return a.Point < b.Point; });
  const std::vector<Index> group = pointGroups(cloud, all, link);
  std::map<Index, MissedPlace<D>> places; // by the group's representative
  for (size_t j = 0; j < all.size(); ++j)
  {
    const auto& p = cloud.Points[static_cast<size_t>(all[j].Point)];
    auto [it, created] = places.try_emplace(group[j]);
    MissedPlace<D>& place = it->second;
    if (created)
    {
      place.Lower = place.Upper = p;
    }
    ++place.Points;
    for (int a = 0; a < D; ++a)
    {
      place.Centre[a] += p[a];
      place.Lower[a] = std::min(place.Lower[a], p[a]);
      place.Upper[a] = std::max(place.Upper[a], p[a]);
    }
  }
  std::vector<std::pair<Index, MissedPlace<D>>> ranked(places.begin(), places.end());
  std::stable_sort(
    ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.second.Points > b.second.Points; });
  std::vector<MissedPlace<D>> named;
  for (size_t k = 0; k < std::min(ranked.size(), MissedPlacesNamed); ++k)
  {
    MissedPlace<D> place = ranked[k].second;
    for (int a = 0; a < D; ++a)
    {
      place.Centre[a] /= static_cast<double>(place.Points);
    }
    named.push_back(place);
  }
  return named;
}

/// The places the last run of `options` misses when it does not fit the cloud (its
/// MisfitPoints above FitShare), from `band` (a storage's band: grid() and
/// outsidePoints(threshold), this rank's points) with h_P = `cloudSpacing`; none
/// after any other run or a run that failed (`ran` false). Points two misfit
/// thresholds apart are in one place. Collective: MisfitPoints is the same on every rank.
template <int D, class Band>
std::vector<MissedPlace<D>> missedPlacesAfterRun(const Band& band, const PointCloud<D>& cloud, double cloudSpacing,
  const ReconstructionOptions& options, int run, bool ran, const std::vector<RunRecord<D>>& runs,
  const Communicator& comm)
{
  if (!ran || run != options.Runs || runs.empty() || !(runs.back().MisfitPoints > FitShare))
  {
    return {};
  }
  const double threshold = misfitThreshold(band.grid().Spacing[0], cloudSpacing, options.GammaFactor);
  return gatherMissedPlaces(cloud, band.outsidePoints(threshold), 2.0 * threshold, comm);
}

} // namespace sltk
