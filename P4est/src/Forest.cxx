// SPDX-License-Identifier: GPL-2.0-or-later
#include "sltk/p4est/Forest.h"

#include "P4estSupport.h"

#include <p8est.h>
#include <p8est_connectivity.h>
#include <p8est_extended.h>

namespace sltk
{
namespace p4est
{

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

Status Forest::createUniform(const Communicator& comm, int level, std::unique_ptr<Forest>& forest)
{
  forest.reset();
  if (level < 0 || level > 18)
  {
    return Status::invalidArgument("octree level " + std::to_string(level) + " is outside 0..18");
  }
  MPI_Comm mpiComm = MPI_COMM_NULL;
  SLTK_RETURN_IF_ERROR(p4estCommunicator(comm, mpiComm));
  auto impl = std::make_unique<Impl>();
  impl->Rank = comm.rank();
  impl->Connectivity = p8est_connectivity_new_unitcube();
  // Uniform refinement to `level` at creation: min_quadrants 0, fill_uniform 1.
  impl->Tree = p8est_new_ext(mpiComm, impl->Connectivity, 0, level, 1, 0, nullptr, nullptr);
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

} // namespace p4est
} // namespace sltk
