// SPDX-License-Identifier: BSD-3-Clause
#include "reconstruction/Report.h"

#include <cstdio>

namespace sltkbench
{

double at(const std::vector<double>& v, size_t i)
{
  return i < v.size() ? v[i] : std::nan("");
}

std::string at(const std::vector<std::string>& v, size_t i)
{
  return i < v.size() ? v[i] : std::string("-");
}

std::string compare(double ours, double thesis, bool energy)
{
  if (!std::isfinite(thesis) || !(thesis > 0.0) || !std::isfinite(ours))
  {
    return "      -       ";
  }
  const double r = ours / thesis;
  const char* verdict =
    r > 1.5 ? (energy ? "higher" : "worse") : (r < 1.0 / 1.5 ? (energy ? "lower" : "better") : "within");
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%5.2f %-7s", r, verdict);
  return buf;
}

std::string sci(double v)
{
  if (!std::isfinite(v))
  {
    return "    -    ";
  }
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%9.3e", v);
  return buf;
}

std::string fmt(double v)
{
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", v);
  return buf;
}

double seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace sltkbench
