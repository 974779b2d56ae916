// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSLPointCloudReader
 * @brief   Reads a text point cloud (.xyz .txt .csv .pts: x y z per line) into
 *          a vtkPolyData, the reading of the `sltk` command line.
 *
 * Each line gives a point by its first three numbers, separated by spaces,
 * tabs, commas or semicolons; further columns (normals, colours) are ignored.
 * Blank lines and lines starting with '#' or '/' are skipped, and so is one
 * header line (such as "x,y,z") before the first point. A first line that
 * holds one whole number is the point count of a Leica .pts file: the file is
 * refused when it holds another number of points (cut short, or scans joined).
 *
 * Output: a vtkPolyData with the points in double and one vertex cell per
 * point, so that ParaView draws them as points (no Glyph needed); the
 * reconstruction filters take it as it is.
 *
 * A file that cannot be read is refused with the command line's message
 * (vtkErrorMacro) and an empty output, never a part of the cloud: a folder, a
 * missing or unreadable file, an empty file (0 bytes), binary data, a token
 * that is not a number among a line's first three, fewer than three numbers
 * on a line; the messages name the file and the line
 * ("cloud.xyz:3: '0.02abc' is not a number").
 *
 * In the ParaView plugin it is the reader of .xyz, .pts and .txt files
 * (Plugin/XML/PointCloudReader.xml.in); .csv stays with ParaView's CSV reader
 * there, this class reads it as the command line does.
 */
#ifndef vtkSLPointCloudReader_h
#define vtkSLPointCloudReader_h

#include "SLTKFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class SLTKFILTERS_EXPORT vtkSLPointCloudReader : public vtkPolyDataAlgorithm
{
public:
  static vtkSLPointCloudReader* New();
  vtkTypeMacro(vtkSLPointCloudReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The text cloud to read.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

protected:
  vtkSLPointCloudReader();
  ~vtkSLPointCloudReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;

private:
  vtkSLPointCloudReader(const vtkSLPointCloudReader&) = delete;
  void operator=(const vtkSLPointCloudReader&) = delete;
};

#endif
