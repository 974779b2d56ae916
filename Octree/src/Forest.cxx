// SPDX-License-Identifier: GPL-2.0-or-later
#include "sltk/octree/Forest.h"

#include <mpi.h>
#include <p8est.h>
#include <p8est_connectivity.h>
#include <p8est_extended.h>

namespace sltk
{
namespace octree
{

namespace
{
/// p4est_init registers a package once per process; a second call aborts
/// (Documentation/Toolchain.md, "Pitfalls"), e.g. when ParaView already loaded p4est.
void initialiseOnce()
{
  if (p4est_package_id < 0)
  {
    sc_init(sc_MPI_COMM_NULL, 0, 0, nullptr, SC_LP_SILENT);
    p4est_init(nullptr, SC_LP_SILENT);
  }
}
} // namespace

struct Forest::Impl
{
  p8est_connectivity_t* Connectivity = nullptr;
  p8est_t* Tree = nullptr;
  int Rank = 0;
  ~Impl()
  {
    if (this->Tree)
    {
      p8est_destroy(this->Tree);
    }
    if (this->Connectivity)
    {
      p8est_connectivity_destroy(this->Connectivity);
    }
  }
};

Forest::Forest(std::unique_ptr<Impl> impl)
  : P(std::move(impl))
{
}

Forest::~Forest() = default;

Status Forest::createUniform(void* mpiComm, int level, std::unique_ptr<Forest>& forest)
{
  forest.reset();
  if (level < 0 || level > 18)
  {
    return Status::invalidArgument("octree level " + std::to_string(level) + " is outside 0..18");
  }
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised)
  {
    return Status::invalidArgument("MPI is not initialised: call MPI_Init (pvpython/pvbatch do) first");
  }
  initialiseOnce();
  MPI_Comm comm = mpiComm ? *static_cast<MPI_Comm*>(mpiComm) : MPI_COMM_WORLD;
  auto impl = std::make_unique<Impl>();
  MPI_Comm_rank(comm, &impl->Rank);
  impl->Connectivity = p8est_connectivity_new_unitcube();
  // Uniform refinement to `level` at creation: min_quadrants 0, fill_uniform 1.
  impl->Tree = p8est_new_ext(comm, impl->Connectivity, 0, level, 1, 0, nullptr, nullptr);
  forest.reset(new Forest(std::move(impl)));
  return Status::ok();
}

std::int64_t Forest::globalOctants() const
{
  return static_cast<std::int64_t>(this->P->Tree->global_num_quadrants);
}

std::int64_t Forest::localOctants() const
{
  return static_cast<std::int64_t>(this->P->Tree->local_num_quadrants);
}

int Forest::rank() const
{
  return this->P->Rank;
}

} // namespace octree
} // namespace sltk
