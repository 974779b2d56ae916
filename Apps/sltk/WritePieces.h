// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file WritePieces.h
/// `mpirun -np N sltk hjb -o FILE.pvti`: each rank writes its own block of the
/// image and rank 0 the `.pvti` that lists the blocks, with VTK's parallel XML
/// writer (vtkXMLPImageDataWriter): FILE.pvti and FILE/FILE_<rank>.vti, so no
/// rank ever holds the whole grid (Documentation/Distributed.md).
///
/// Whole or nothing, as writeAtomically(): the pieces and the .pvti are
/// written in a hidden temporary folder beside FILE and moved into place once
/// every rank has written its piece; an earlier run's piece folder FILE/ is
/// replaced, any other folder of that name is refused before any work.

#include "sltk/core/Status.h"

#include <string>

class vtkAlgorithm;
class vtkMultiProcessController;

namespace sltkcli
{

/// "" when `path`'s piece folder (FILE/ beside FILE.pvti or FILE.phtg) is
/// absent or holds only an earlier run's pieces (FILE_<n>.vti or .htg);
/// otherwise the problem and the fix.
std::string pieceFolderProblem(const std::string& path);

/// Writes the piece of `producer`'s output this rank was updated for
/// (UpdatePiece(rank, N, 0)); a collective call on `controller`'s ranks
/// (nullptr: one rank). Every rank returns the same status.
sltk::Status writeImagePieces(const std::string& path, vtkAlgorithm* producer, vtkMultiProcessController* controller);

/// The same for `mpirun -np N sltk reconstruct --octree -o FILE.phtg`: each
/// rank's hyper tree grid (its own trees) as FILE/FILE_<rank>.htg, listed by
/// FILE.phtg (vtkXMLPHyperTreeGridWriter) and by FILE.vtm, a multiblock of the
/// pieces that ParaView 5.11 opens (its .phtg reader crashes, Toolchain.md).
sltk::Status writeHyperTreeGridPieces(
  const std::string& path, vtkAlgorithm* producer, vtkMultiProcessController* controller);

} // namespace sltkcli
