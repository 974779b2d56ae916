// SPDX-License-Identifier: BSD-3-Clause
// The cloud's statistics on ranks that hold only their part of it
// (Documentation/Distributed.md, "Points to their owners"): run under
// `mpirun -np P sltkBenchCloudRanks --cloud FILE.xyz`. Each rank takes the share
// of the file a parallel read leaves it, the points move to the owners of
// their slabs, and h_P, the density spacing, the outlier test, the noise and
// the local sparsity factors are computed there, the automatic K_P's probe
// (at C_dx 1, with the local offset) runs on them; last the cloud is thinned
// there (cells of 2.5 density spacings, as `--thin 2.5`), and the thinned cloud's components (the summary's)
// and groups far apart (the advice of separate runs) are found there. Per phase, the busiest rank's time,
// point-to-point and collective megabytes, the queries answered with other ranks' points, and the points held per rank
// against the cloud; then whether each value is the one-rank value bit for bit (rank 0 computes it from the whole
// cloud).
#include "common/BenchCli.h"
#include "common/ReadXyz.h"

#include "sltk/cloud/CloudCleaning.h"
#include "sltk/cloud/CloudFileShares.h"
#include "sltk/cloud/CloudNoise.h"
#include "sltk/cloud/CloudOutliers.h"
#include "sltk/cloud/CloudSpacing.h"
#include "sltk/cloud/CloudThinning.h"
#include "sltk/cloud/LocalSpacing.h"
#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/core/ExactSum.h"
#include "sltk/exec/CountingCommunicator.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/mpi/MpiCommunicator.h"
#include "sltk/recon/AutomaticParameters.h"
#include "sltk/recon/PointClusters.h"
#include "sltk/recon/StoppingRule.h"

#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <functional>

namespace
{
struct Phase
{
  const char* Name;
  double Seconds;
  sltk::CommTraffic Traffic;
  std::int64_t Remote;
  std::int64_t HeldMax;
};

/// Runs `step` on every rank and records the busiest rank's time and traffic.
Phase measure(const char* name, const sltk::CountingCommunicator& comm, const std::function<std::int64_t()>& step,
  const sltk::OwnedPoints<3>& points)
{
  comm.barrier();
  const sltk::CommTraffic before = comm.traffic();
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t remote = step();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const sltk::CommTraffic used = comm.traffic().since(before);
  double busiest[3] = { seconds, static_cast<double>(used.PointToPointBytes),
    static_cast<double>(used.CollectiveBytes) };
  comm.allReduce(busiest, 3, sltk::ReduceOp::Max);
  sltk::CommTraffic traffic;
  traffic.PointToPointBytes = static_cast<std::int64_t>(busiest[1]);
  traffic.CollectiveBytes = static_cast<std::int64_t>(busiest[2]);
  return { name, busiest[0], traffic, remote, comm.allReduce(points.held(), sltk::ReduceOp::Max) };
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int code = 0;
  {
    CLI::App app("The cloud's statistics on ranks that hold only their part of it");
    std::string path;
    int threads = 1;
    app.add_option("--cloud", path, "x y z per line")->required();
    app.add_option("--threads", threads, "threads per rank");
    if (const auto exit = sltkbench::parseCommandLine(app, argc, argv))
    {
      MPI_Finalize();
      return *exit;
    }
    std::unique_ptr<sltk::mpi::MpiCommunicator> world;
    sltk::mpi::MpiCommunicator::world(world);
    const sltk::CountingCommunicator comm(*world);
    sltk::PointCloud<3> cloud;
    if (!sltkbench::readXyz(path, cloud))
    {
      std::fprintf(stderr, "%s: no points\n", path.c_str());
      MPI_Finalize();
      return 1;
    }
    const std::int64_t n = cloud.size();
    const sltk::FileShare s = sltk::shareOf(0, n, comm.rank(), comm.size());
    const sltk::PointCloud<3> share{ { cloud.Points.begin() + s.Begin, cloud.Points.begin() + s.End } };
    sltk::ThreadPool pool(threads);
    sltk::Context ctx;
    ctx.Executor = &pool;

    sltk::OwnedPoints<3> owned;
    std::int64_t total = n;
    double spacing = 0.0, density = 0.0, noise = 0.0;
    sltk::OutlierReport outliers;
    sltk::OutlierOptions gross;
    gross.GrossRatio = sltk::GrossOutlierRatio;
    sltk::CloudSpacingOptions densityOptions;
    densityOptions.DensityNeighbours = 8;
    sltk::Status failed; // the first failure (the same on every rank)
    const auto check = [&failed](const sltk::Status& status)
    {
      if (failed.isOk() && !status.isOk())
      {
        failed = status;
      }
    };
    std::vector<Phase> phases;
    phases.push_back(measure(
      "points to owners", comm,
      [&]
      {
        const sltk::SlabCuts cuts = sltk::balancedCuts(share, comm);
        check(sltk::sendToOwners(share, sltk::firstGlobalIndex(share.size(), comm), cuts, 0.0, comm, owned));
        return std::int64_t(0);
      },
      owned));
    phases.push_back(measure(
      "outliers (k = 8, gross)", comm,
      [&]
      {
        check(sltk::removeOutliersOnRanks(owned, total, gross, comm, ctx, outliers));
        return std::int64_t(-1);
      },
      owned));
    phases.push_back(measure(
      "h_P (4.36)", comm,
      [&]
      {
        std::int64_t remote = 0;
        check(sltk::cloudSpacingOnRanks(owned, total, comm, ctx, spacing, {}, &remote));
        return remote;
      },
      owned));
    phases.push_back(measure(
      "density spacing (k = 8)", comm,
      [&]
      {
        std::int64_t remote = 0;
        check(sltk::cloudSpacingOnRanks(owned, total, comm, ctx, density, densityOptions, &remote));
        return remote;
      },
      owned));
    phases.push_back(measure(
      "noise", comm,
      [&]
      {
        check(sltk::cloudNoiseOnRanks(owned, total, spacing, comm, ctx, noise));
        return std::int64_t(-1);
      },
      owned));
    std::vector<double> sparsity;
    phases.push_back(measure(
      "sparsity factors (k = 16)", comm,
      [&]
      {
        std::int64_t remote = 0;
        check(sltk::sparsityFactorsOnRanks(
          owned, sltk::CloudCleaningOptions{}.DensityNeighbours, comm, ctx, sparsity, &remote));
        return remote;
      },
      owned));
    // The factors checked without gathering them: two exact sums over the owned points
    // (of rho and of rho times the global index + 1), the same for any split.
    sltk::ExactSum rhoSum, weightedSum;
    for (size_t j = 0; j < owned.Ids.size() && j < sparsity.size(); ++j)
    {
      if (owned.Mine[j])
      {
        rhoSum.add(sparsity[j]);
        weightedSum.add(sparsity[j] * static_cast<double>(owned.Ids[j] + 1));
      }
    }
    rhoSum.reduceOver(comm);
    weightedSum.reduceOver(comm);
    sltk::OutsideFactorChoice probe;
    const sltk::Box<3> bounds = sltk::boundingBoxOverRanks(owned.Cloud, comm);
    phases.push_back(measure(
      "K_P probe (C_dx 1)", comm,
      [&]
      {
        check(sltk::chooseOutsideFactorOnRanks(owned, bounds, spacing, spacing, sparsity, comm, ctx, probe));
        return std::int64_t(-1);
      },
      owned));
    std::int64_t thinned = 0;
    phases.push_back(measure(
      "thinning (2.5 density)", comm,
      [&]
      {
        check(sltk::thinOnRanks(owned, 2.5 * density, comm, thinned));
        return std::int64_t(-1);
      },
      owned));
    std::int64_t components = 0;
    phases.push_back(measure(
      "components (4 h_P or s)", comm,
      [&]
      {
        check(sltk::cloudComponentsOnRanks(owned, spacing, sltk::PieceLinkFactor,
          sltk::CloudCleaningOptions{}.DensityNeighbours, comm, ctx, components));
        return std::int64_t(-1);
      },
      owned));
    std::vector<sltk::Box<3>> groups;
    phases.push_back(measure(
      "groups (4 h_P links)", comm,
      [&]
      {
        check(sltk::groupBoxesOnRanks(owned, sltk::PieceLinkFactor * spacing, 16, comm, ctx, groups));
        return std::int64_t(-1);
      },
      owned));
    // The thinned points checked as the factors are.
    sltk::ExactSum thinSum;
    for (size_t j = 0; j < owned.Ids.size(); ++j)
    {
      for (int a = 0; owned.Mine[j] && a < 3; ++a)
      {
        thinSum.add(owned.Cloud.Points[j][a] * static_cast<double>(owned.Ids[j] + 1 + a));
      }
    }
    thinSum.reduceOver(comm);
    if (!failed.isOk())
    {
      if (comm.rank() == 0)
      {
        std::fprintf(stderr, "%s: %s\n", path.c_str(), failed.message().c_str());
      }
      MPI_Finalize();
      return 1;
    }
    if (comm.rank() == 0)
    {
      std::printf("%s: %lld points on %d rank(s), %d thread(s) each; slabs along axis %d\n", path.c_str(),
        static_cast<long long>(n), comm.size(), threads, owned.Cuts.Axis);
      std::printf(
        "%-26s %9s %12s %14s %10s %16s\n", "phase", "seconds", "p2p MB", "collective MB", "remote", "held max / N");
      for (const Phase& p : phases)
      {
        std::printf("%-26s %9.3f %12.3f %14.3f %10s %16.4f\n", p.Name, p.Seconds, p.Traffic.PointToPointBytes / 1e6,
          p.Traffic.CollectiveBytes / 1e6, p.Remote < 0 ? "-" : std::to_string(p.Remote).c_str(),
          static_cast<double>(p.HeldMax) / static_cast<double>(n));
      }
      // One rank's values from the whole cloud, as the reconstruction's plan computes them.
      sltk::PointCloud<3> kept;
      sltk::OutlierReport one;
      sltk::removeOutliers(cloud, gross, ctx, kept, one);
      const sltk::PointLocator<3> locator(kept);
      double oneSpacing = 0.0, oneDensity = 0.0, oneNoise = 0.0;
      sltk::cloudSpacing(locator, ctx, oneSpacing);
      sltk::cloudSpacing(locator, ctx, oneDensity, densityOptions);
      sltk::cloudNoise(locator, oneSpacing, ctx, oneNoise);
      std::vector<double> oneSparsity;
      sltk::sparsityFactors(locator, sltk::CloudCleaningOptions{}.DensityNeighbours, ctx, oneSparsity);
      sltk::ExactSum oneRho, oneWeighted;
      for (size_t j = 0; j < oneSparsity.size(); ++j)
      {
        oneRho.add(oneSparsity[j]);
        oneWeighted.add(oneSparsity[j] * static_cast<double>(j + 1));
      }
      sltk::OutsideFactorChoice oneProbe;
      sltk::chooseOutsideFactor(locator, sltk::boundingBox(kept), oneSpacing, oneSpacing, oneSparsity, ctx, oneProbe);
      sltk::PointCloud<3> oneThinned;
      sltk::thinCloud(kept, 2.5 * oneDensity, oneThinned);
      sltk::ExactSum oneThin;
      for (size_t j = 0; j < oneThinned.Points.size(); ++j)
      {
        for (int a = 0; a < 3; ++a)
        {
          oneThin.add(oneThinned.Points[j][a] * static_cast<double>(j + 1 + a));
        }
      }
      const sltk::PointLocator<3> thinnedLocator(oneThinned);
      const sltk::Index oneComponents = sltk::cloudComponents(
        thinnedLocator, oneSpacing, sltk::PieceLinkFactor, sltk::CloudCleaningOptions{}.DensityNeighbours, ctx);
      std::vector<sltk::Box<3>> oneGroups;
      sltk::groupBoxesOnRanks(sltk::ownedOnOneRank(oneThinned), sltk::PieceLinkFactor * oneSpacing, 16,
        sltk::serialCommunicator(), ctx, oneGroups);
      bool sameGroups = oneGroups.size() == groups.size();
      for (size_t g = 0; sameGroups && g < groups.size(); ++g)
      {
        sameGroups = oneGroups[g].Min == groups[g].Min && oneGroups[g].Max == groups[g].Max;
      }
      const bool same = sameGroups && oneComponents == components && oneProbe.Factor == probe.Factor &&
        oneProbe.EnclosedNodes == probe.EnclosedNodes && oneThinned.size() == thinned &&
        oneThin.value() == thinSum.value() && one.Removed == outliers.Removed && one.Threshold == outliers.Threshold &&
        oneSpacing == spacing && oneDensity == density && oneNoise == noise && oneRho.value() == rhoSum.value() &&
        oneWeighted.value() == weightedSum.value();
      std::printf("outliers removed %lld, h_P %.17g, density spacing %.17g, noise %.17g h_P, mean rho %.17g, "
                  "K_P %g, thinned to %lld, %lld component(s), %zu separate group(s): %s\n",
        static_cast<long long>(outliers.Removed), spacing, density, noise, rhoSum.value() / static_cast<double>(total),
        probe.Factor, static_cast<long long>(thinned), static_cast<long long>(components), groups.size(),
        same ? "the one-rank values bit for bit" : "DIFFERENT from one rank's");
      code = same ? 0 : 1;
    }
  }
  MPI_Finalize();
  return code;
}
