// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReadXyz.h
/// The benchmarks' reader of `.xyz` clouds (no VTK): x y z per line.

#include "sltk/cloud/PointCloud.h"

#include <fstream>
#include <sstream>
#include <string>

namespace sltkbench
{

/// x y z per line; other lines are skipped. False when nothing was read.
inline bool readXyz(const std::string& path, sltk::PointCloud<3>& cloud)
{
  std::ifstream in(path);
  if (!in)
  {
    return false;
  }
  std::string line;
  while (std::getline(in, line))
  {
    std::istringstream s(line);
    std::array<double, 3> p{};
    if (s >> p[0] >> p[1] >> p[2])
    {
      cloud.Points.push_back(p);
    }
  }
  return !cloud.Points.empty();
}

} // namespace sltkbench
