// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file XmlDataSettings.h
/// How the CLI's VTK XML files hold their arrays: raw (not base64) appended
/// data compressed by LZ4. Measured on the bunny's signed distance with no
/// options (25.7M nodes, two arrays): 0.40 s and 222 MB against 11.9 s and
/// 277 MB for VTK's defaults (base64, zlib), 8.1 s and 208 MB for raw zlib
/// (bench/profile/phases.sh). ParaView and VTK read LZ4-compressed XML files.

#include <vtkXMLWriter.h>

namespace sltkcli
{

/// Raw appended data compressed by LZ4 (the hyper tree grid writers keep their
/// inline binary mode, Documentation/Toolchain.md; they take LZ4 too).
inline void useFastXmlData(vtkXMLWriter* writer, bool appended = true)
{
  writer->SetCompressorTypeToLZ4();
  if (appended)
  {
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
  }
}

} // namespace sltkcli
