// SPDX-License-Identifier: BSD-3-Clause
#include "WritePieces.h"

#include "WriteAtomically.h"
#include "XmlDataSettings.h"
#include "sltk/core/LowerCase.h"

#include <vtkAlgorithm.h>
#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkXMLPHyperTreeGridWriter.h>
#include <vtkXMLPImageDataWriter.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <type_traits>
#include <unistd.h>

namespace fs = std::filesystem;

namespace sltkcli
{
namespace
{
/// FILE.pvti's (or FILE.phtg's) folder, its stem, its piece folder and the
/// extensions of the summary and of a piece.
struct PieceNames
{
  fs::path Folder, Stem, Pieces;
  std::string Summary, Piece;
  explicit PieceNames(const std::string& path)
    : Folder(fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path())
    , Stem(fs::path(path).stem())
    , Pieces(Folder / Stem)
    , Summary(fs::path(path).extension().string())
    , Piece(sltk::lowerCase(Summary) == ".phtg" ? ".htg" : ".vti")
  {
  }
};

/// Every rank's value of `flag`, AND-ed.
bool allTrue(vtkMultiProcessController* controller, bool flag)
{
  int mine = flag ? 1 : 0, all = mine;
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    controller->AllReduce(&mine, &all, 1, vtkCommunicator::MIN_OP);
  }
  return all == 1;
}
} // namespace

std::string pieceFolderProblem(const std::string& path)
{
  const PieceNames names(path);
  std::error_code error;
  if (!fs::exists(names.Pieces, error))
  {
    return "";
  }
  // STEM_<digits>.vti (or .htg), compared as text: the stem may hold any character.
  const std::string prefix = names.Stem.string() + "_";
  const auto isPiece = [&](const std::string& name)
  {
    if (name.size() <= prefix.size() + names.Piece.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - names.Piece.size(), names.Piece.size(), names.Piece) != 0)
    {
      return false;
    }
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - names.Piece.size());
    return std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  bool pieces = fs::is_directory(names.Pieces, error);
  for (auto it = fs::directory_iterator(names.Pieces, error); pieces && !error && it != fs::directory_iterator();
       it.increment(error))
  {
    pieces = it->is_regular_file(error) && isPiece(it->path().filename().string());
  }
  if (pieces && !error)
  {
    return "";
  }
  return "-o " + path + " writes its pieces into the folder " + names.Pieces.string() +
    ", which exists and holds other files: choose another output name or move that folder";
}

namespace
{
/// `text` with XML's five special characters escaped (an attribute's value).
std::string xmlEscaped(const std::string& text)
{
  std::string out;
  for (const char c : text)
  {
    switch (c)
    {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// FILE.vtm beside FILE.phtg: a multiblock of the ranks' pieces, one block each.
/// ParaView 5.11 opens it (and its Slice and Contour run on it), where its
/// vtkXMLPHyperTreeGridReader crashes on the .phtg (Documentation/Toolchain.md).
bool writePieceIndex(const fs::path& path, const PieceNames& names, int pieces)
{
  std::ofstream out(path);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt32\">\n  <vtkMultiBlockDataSet>\n";
  for (int k = 0; k < pieces; ++k)
  {
    const std::string piece = names.Stem.string() + "/" + names.Stem.string() + "_" + std::to_string(k) + names.Piece;
    out << "    <DataSet index=\"" << k << "\" name=\"rank " << k << "\" file=\"" << xmlEscaped(piece) << "\"/>\n";
  }
  out << "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
  out.close();
  return static_cast<bool>(out);
}

template <class Writer>
sltk::Status writePiecesWith(const std::string& path, vtkAlgorithm* producer, vtkMultiProcessController* controller)
{
  const int size = controller ? controller->GetNumberOfProcesses() : 1;
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  constexpr bool trees = std::is_same<Writer, vtkXMLPHyperTreeGridWriter>::value;
  const PieceNames names(path);
  int owner = static_cast<int>(::getpid()); // rank 0's process names the temporary folder
  if (size > 1)
  {
    controller->Broadcast(&owner, 1, 0);
  }
  const fs::path temporary = names.Folder / ("." + names.Stem.string() + ".part" + std::to_string(owner));
  std::error_code error;
  bool ready = rank != 0 || fs::create_directory(temporary, error);
  if (!allTrue(controller, ready))
  {
    return sltk::Status::ioError("could not write " + path + ": check that its folder exists and is writable");
  }
  const fs::path summary = temporary / (names.Stem.string() + names.Summary);
  const fs::path pieces = temporary / names.Stem;
  const fs::path mine = pieces / (names.Stem.string() + "_" + std::to_string(rank) + names.Piece);
  setPendingPaths({ mine.string(), rank == 0 ? summary.string() : "" }, { pieces.string(), temporary.string() });

  vtkNew<Writer> writer;
  writer->SetInputConnection(producer->GetOutputPort());
  if constexpr (trees)
  {
    writer->SetDataModeToBinary(); // as writeHyperTreeGrid (Documentation/Toolchain.md: the appended mode)
    useFastXmlData(writer, false);
  }
  else
  {
    useFastXmlData(writer);
  }
  writer->SetFileName(summary.string().c_str());
  writer->SetNumberOfPieces(size);
  writer->SetStartPiece(rank);
  writer->SetEndPiece(rank);
  writer->SetUseSubdirectory(true);
  writer->SetController(controller);
  const fs::path index = temporary / (names.Stem.string() + ".vtm");
  const bool written = writer->Write() == 1 && fs::exists(mine, error) &&
    (rank != 0 || (fs::exists(summary, error) && (!trees || writePieceIndex(index, names, size))));
  const bool everyRank = allTrue(controller, written);
  bool moved = everyRank;
  if (rank == 0)
  {
    if (everyRank && pieceFolderProblem(path).empty())
    {
      fs::remove_all(names.Pieces, error); // an earlier run's pieces only (pieceFolderProblem)
      fs::rename(pieces, names.Pieces, error);
      moved = !error;
      fs::rename(summary, names.Folder / (names.Stem.string() + names.Summary), error);
      moved = moved && !error;
      if (trees)
      {
        fs::rename(index, names.Folder / (names.Stem.string() + ".vtm"), error);
        moved = moved && !error;
      }
    }
    else
    {
      moved = false;
    }
    fs::remove_all(temporary, error);
  }
  setPendingPaths({}, {});
  if (!allTrue(controller, moved))
  {
    return sltk::Status::ioError("could not write " + path +
      (everyRank ? ": moving the finished pieces failed" : ": a rank could not write its piece (disk full?)"));
  }
  return sltk::Status::ok();
}
} // namespace

sltk::Status writeImagePieces(const std::string& path, vtkAlgorithm* producer, vtkMultiProcessController* controller)
{
  return writePiecesWith<vtkXMLPImageDataWriter>(path, producer, controller);
}

sltk::Status writeHyperTreeGridPieces(
  const std::string& path, vtkAlgorithm* producer, vtkMultiProcessController* controller)
{
  return writePiecesWith<vtkXMLPHyperTreeGridWriter>(path, producer, controller);
}

} // namespace sltkcli
