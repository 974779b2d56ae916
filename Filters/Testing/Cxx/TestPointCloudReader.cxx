// SPDX-License-Identifier: BSD-3-Clause
// vtkSLPointCloudReader, the text clouds of the CLI in ParaView: a cloud with
// comments, a header, commas, semicolons, tabs and extra columns gives its exact
// points and one vertex per point; every refused file gives the CLI's message
// with its file and line, a failed update and an empty output (never a part of
// the cloud), also after a good file.
#include "FilterTestCheck.h"
#include "vtkSLPointCloudReader.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using sltktest::check;

namespace
{
/// Keeps the text of the last event it observes (an error or a warning).
class EventText : public vtkCommand
{
public:
  static EventText* New() { return new EventText; }
  void Execute(vtkObject*, unsigned long, void* data) override { this->Text = static_cast<const char*>(data); }
  std::string Text;
};

std::string writeFile(const std::filesystem::path& folder, const std::string& name, const std::string& text)
{
  const std::filesystem::path path = folder / name;
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

/// The good cloud: every accepted separator, comment and extra column.
const char* const GoodCloud = "# scan of a test piece\n"
                              "x,y,z,nx,ny,nz\n"
                              "\n"
                              "0.1,0.2,0.3,0,0,1\n"
                              "// a comment in the C++ way\n"
                              "  # an indented comment\n"
                              "-1e-3;+2.5;7\n"
                              "4\t5\t6\r\n"
                              "   8 9 10   \n"
                              "1.5 2.5 3.5 red\n";
const std::vector<std::array<double, 3>> GoodPoints = { { 0.1, 0.2, 0.3 }, { -1e-3, 2.5, 7.0 }, { 4.0, 5.0, 6.0 },
  { 8.0, 9.0, 10.0 }, { 1.5, 2.5, 3.5 } };

/// The reader's output holds exactly `expected`, in double, vertex i on point i.
void checkPoints(
  vtkSLPointCloudReader* reader, const std::vector<std::array<double, 3>>& expected, const std::string& what)
{
  vtkPolyData* cloud = reader->GetOutput();
  const auto n = static_cast<vtkIdType>(expected.size());
  check(cloud->GetNumberOfPoints() == n,
    what + ": " + std::to_string(n) + " points, got " + std::to_string(cloud->GetNumberOfPoints()));
  check(cloud->GetPoints() && cloud->GetPoints()->GetDataType() == VTK_DOUBLE, what + ": points in double");
  check(cloud->GetNumberOfVerts() == n && cloud->GetNumberOfCells() == n, what + ": one vertex cell per point");
  for (vtkIdType i = 0; i < std::min(n, cloud->GetNumberOfPoints()); ++i)
  {
    std::array<double, 3> x{};
    cloud->GetPoint(i, x.data());
    check(x == expected[static_cast<size_t>(i)], what + ": point " + std::to_string(i) + " exact");
  }
  vtkIdType cell = 0;
  auto vertices = vtk::TakeSmartPointer(cloud->GetVerts()->NewIterator());
  for (vertices->GoToFirstCell(); !vertices->IsDoneWithTraversal(); vertices->GoToNextCell(), ++cell)
  {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    vertices->GetCurrentCell(size, ids);
    check(size == 1 && ids[0] == cell, what + ": vertex " + std::to_string(cell) + " is point " + std::to_string(cell));
  }
}

struct RefusedFile
{
  std::string Name;
  std::string Text;
  std::vector<std::string> Words; ///< in the error message
};

/// The reader, after a good file, refuses `path` with `words` and an empty output.
void checkRefused(vtkSLPointCloudReader* reader, EventText* errors, const std::string& goodPath,
  const std::string& path, const std::vector<std::string>& words)
{
  reader->SetFileName(goodPath.c_str());
  reader->Update();
  check(reader->GetOutput()->GetNumberOfPoints() == static_cast<vtkIdType>(GoodPoints.size()),
    "the good cloud again before " + path);
  errors->Text.clear();
  reader->SetFileName(path.c_str());
  const vtkTypeBool updated = reader->UpdatePiece(0, 1, 0);
  check(!updated, path + ": the update fails");
  for (const std::string& word : words)
  {
    check(contains(errors->Text, word), path + ": the error says '" + word + "': " + errors->Text);
  }
  vtkPolyData* cloud = reader->GetOutput();
  check(cloud->GetNumberOfPoints() == 0 && cloud->GetNumberOfCells() == 0,
    path + ": empty output, got " + std::to_string(cloud->GetNumberOfPoints()) + " points");
}
} // namespace

int main(int argc, char* argv[])
{
  const std::filesystem::path folder =
    argc > 1 ? std::filesystem::path(argv[1]) : std::filesystem::temp_directory_path() / "sltk-point-cloud-reader";
  std::filesystem::create_directories(folder);

  vtkNew<vtkSLPointCloudReader> reader;
  vtkNew<EventText> errors;
  vtkNew<EventText> warnings;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->AddObserver(vtkCommand::WarningEvent, warnings);

  // A good cloud, as .xyz and as .csv (the class reads every text format of the CLI).
  const std::string good = writeFile(folder, "good.xyz", GoodCloud);
  for (const std::string& path : { good, writeFile(folder, "good.csv", GoodCloud) })
  {
    reader->SetFileName(path.c_str());
    check(reader->UpdatePiece(0, 1, 0) != 0 && errors->Text.empty(), path + ": read without error: " + errors->Text);
    checkPoints(reader, GoodPoints, path);
  }
  check(std::string(reader->GetFileName()) == (folder / "good.csv").string(), "GetFileName gives the file set");

  // A Leica .pts file: a count line, then x y z intensity r g b.
  const std::string leica =
    writeFile(folder, "scan.pts", "3\n0.5 1.5 2.5 -1773 51 45 58\n1 2 3 -1500 10 20 30\n-4 5e-2 6 0 0 0 0\n");
  reader->SetFileName(leica.c_str());
  check(reader->UpdatePiece(0, 1, 0) != 0 && errors->Text.empty(), "a .pts count line is read: " + errors->Text);
  checkPoints(reader, { { 0.5, 1.5, 2.5 }, { 1.0, 2.0, 3.0 }, { -4.0, 0.05, 6.0 } }, leica);

  // Only comments and a header: no points, no error, a warning naming the file.
  const std::string noPoints = writeFile(folder, "header-only.xyz", "# nothing yet\nx y z\n\n");
  reader->SetFileName(noPoints.c_str());
  check(reader->UpdatePiece(0, 1, 0) != 0 && errors->Text.empty(), "a header alone is read without error");
  checkPoints(reader, {}, noPoints);
  check(contains(warnings->Text, "holds no points"), "a file without points is named: " + warnings->Text);

  // Every refused file: the CLI's message with the file and line, an empty output.
  std::string binary = "0 0 0\n1 0 0\n0 1";
  binary += '\0';
  binary += " 0\n";
  std::string manyPoints; // a part of the cloud that must not come out
  for (int i = 0; i < 1000; ++i)
  {
    manyPoints += std::to_string(i) + " 0 0\n";
  }
  const std::vector<RefusedFile> refused = {
    { "nul-byte.xyz", binary, { "nul-byte.xyz:3: binary data in a text point cloud" } },
    { "letters.xyz", "0 0 0\n1 0 0\n0 1 0.02abc\n0 0 1\n", { "letters.xyz:3: '0.02abc' is not a number" } },
    { "unprintable.xyz", "0 0 0\n1 0 0\n0 1 0.5\x01\x02\n",
      { "unprintable.xyz:3: binary data in a text point cloud" } },
    { "two-columns.xyz", "0 0 0\n1 0 0\n0 1\n",
      { "two-columns.xyz:3: expected three coordinates per line (x y z), got 2" } },
    { "second-header.txt", "x y z\n0 0 0\nx y z\n", { "second-header.txt:3: expected three coordinates", "got 0" } },
    { "bad-last-line.pts", manyPoints + "7 8\n", { "bad-last-line.pts:1001: expected three coordinates per line" } },
    { "empty.xyz", "", { "empty.xyz' is empty (0 bytes): it holds no points" } },
    { "cut-short.pts", "4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n",
      { "cut-short.pts: its first line announces 4 points, it holds 3" } },
    { "count-later.pts", "2\n0 0 0\n1 0 0\n7\n0 1 0\n",
      { "count-later.pts:4: expected three coordinates per line (x y z), got 1" } },
  };
  for (const RefusedFile& file : refused)
  {
    checkRefused(reader, errors, good, writeFile(folder, file.Name, file.Text), file.Words);
  }
  std::filesystem::create_directories(folder / "scans.xyz");
  checkRefused(
    reader, errors, good, (folder / "scans.xyz").string(), { "scans.xyz' is a folder: give a point-cloud file" });
  checkRefused(reader, errors, good, (folder / "nowhere.xyz").string(),
    { "cannot open '" + (folder / "nowhere.xyz").string() + "': check the path and the permissions" });

  // No file name: an error, no output.
  vtkNew<vtkSLPointCloudReader> unnamed;
  unnamed->AddObserver(vtkCommand::ErrorEvent, errors);
  errors->Text.clear();
  check(unnamed->UpdatePiece(0, 1, 0) == 0 && contains(errors->Text, "no FileName"), "no file name: " + errors->Text);

  if (sltktest::failures() == 0)
  {
    std::cout << "point cloud reader ok\n";
  }
  return sltktest::failures() == 0 ? 0 : 1;
}
