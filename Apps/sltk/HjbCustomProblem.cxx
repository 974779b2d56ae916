// SPDX-License-Identifier: BSD-3-Clause
#include "HjbCustomProblem.h"

#include <vtkCWENOHJBSolver.h>

namespace sltkcli
{

const char* hjbCustomUsage = R"USAGE(
custom problems, v_t + max_a { -f_D(t,x,a) . Dv - f_C(t,x,a) } = 0 (thesis (3.1)-(3.4)), by formulas in
x, y, z, t, a1, a2, a3 (+ - * / % ^, comparisons, c ? a : b, sin ... exp log sqrt abs atan2 hypot min max
clamp if, pi, e); --fx starts one:
  --fx F --fy F --fz F   dynamics f_D, one component per axis used
  --cost F               running cost f_C (default 0)
  --v0 F                 initial datum v0(x, y, z)
  --obstacle F           state constraint g(x, y, z): v = max(v, g) (3.39); ReachTime is written (3.40)
  --exact F              exact solution v(t, x, y, z): adds l1_error and linf_error
  --argmin1 F --argmin2 F --argmin3 F   closed-form argmin a*(t, x, y, z), one formula per control
                         component: replaces the search (one evaluation per node and step)
  --nodes NX[,NY[,NZ]]   nodes per axis; their count is the dimension (default 81,81)
  --domain X0,X1[,Y0,Y1[,Z0,Z1]]   the box (default [-1, 1] per axis)
  --periodic AXES        periodic axes, e.g. x or x,y (default none: linear extrapolation)
  --controls KIND        none | box | ball | sphere (default none: pure transport)
  --control-dim M        dimension of a = (a1, ..., aM) (default 1)
  --control-lower A,...  --control-upper A,...    box corners (default -1 and 1)
  --control-center A,... --control-radius R       ball / sphere (default 0 and 1)
  --rk 1|2|3             RK order of the characteristics (default 3)
  --tabulation N         tabulated controls per axis of A before the local search (default 33)
  --warm-start N         after the first step, search a coarse N^q grid of A and an N^q grid around
                         each node's previous argmin instead of tabulating A (default 0: off; 5 suits Test 4)
  --tolerance TOL        local search tolerance (default 1e-8)
  --reach                write ReachTime also without an obstacle
example (thesis Test 4): sltk hjb --fx=-a1 --fy=-a2 --cost "(a1^2+a2^2)/2" --v0 "max(1-x^2-y^2,0)"
  --nodes 81,81 --domain -2,2,-2,2 --controls ball --control-dim 2 --control-radius 2.2 --rk 1
  --courant 1.25 --final-time 0.5
)USAGE";

const std::vector<std::string>& hjbCustomOptionNames()
{
  static const std::vector<std::string> names = { "fx", "fy", "fz", "cost", "v0", "obstacle", "exact", "argmin1",
    "argmin2", "argmin3", "nodes", "domain", "periodic", "controls", "control-dim", "control-lower", "control-upper",
    "control-center", "control-radius", "rk", "tabulation", "warm-start", "tolerance" };
  return names;
}

bool hasHjbCustomProblem(const Options& opt)
{
  return opt.has("fx") || opt.has("fy") || opt.has("fz");
}

namespace
{
/// The first three values of `v`, padded with `pad`.
void copy3(const std::vector<double>& v, double* out, double pad)
{
  for (size_t k = 0; k < 3; ++k)
  {
    out[k] = k < v.size() ? v[k] : pad;
  }
}
} // namespace

std::string setHjbCustomProblem(Options& opt, vtkCWENOHJBSolver* solver)
{
  const std::vector<double> nodes = opt.numbers("nodes", 1, 3, { 81, 81 });
  const std::vector<double> domain = opt.numbers("domain", 2, 6, {});
  const std::vector<double> lower = opt.numbers("control-lower", 1, 3, { -1, -1, -1 });
  const std::vector<double> upper = opt.numbers("control-upper", 1, 3, { 1, 1, 1 });
  const std::vector<double> center = opt.numbers("control-center", 1, 3, { 0, 0, 0 });
  const double radius = opt.number("control-radius", 1.0);
  const double controlDim = opt.number("control-dim", 1.0);
  const double rk = opt.number("rk", 3.0);
  const double tabulation = opt.number("tabulation", 33.0);
  const double tolerance = opt.number("tolerance", 1e-8);
  const double warmStart = opt.number("warm-start", 0.0);
  if (!opt.ok())
  {
    return opt.error();
  }
  if (domain.size() % 2 != 0)
  {
    return "--domain takes pairs lower,upper per axis, got " + std::to_string(domain.size()) + " numbers";
  }
  int dims[3] = { 1, 1, 1 };
  for (size_t a = 0; a < nodes.size(); ++a)
  {
    if (nodes[a] < 5 || nodes[a] > 100000 || nodes[a] != static_cast<int>(nodes[a]))
    {
      return "--nodes takes whole numbers from 5 to 100000 per axis";
    }
    dims[a] = static_cast<int>(nodes[a]);
  }
  double bounds[6] = { -1, 1, -1, 1, -1, 1 };
  for (size_t k = 0; k < domain.size(); ++k)
  {
    bounds[k] = domain[k];
  }
  int periodic[3] = { 0, 0, 0 };
  const std::string axes = opt.value("periodic", "");
  for (size_t k = 0; k < axes.size(); ++k)
  {
    const char c = axes[k];
    if ((c == 'x' || c == 'y' || c == 'z') && (k + 1 == axes.size() || axes[k + 1] == ','))
    {
      periodic[c - 'x'] = 1;
    }
    else if (c != ',')
    {
      return "--periodic takes axis names x, y, z separated by commas, got '" + axes + "'";
    }
  }
  const std::string kind = opt.value("controls", "none");
  const char* kinds[] = { "none", "box", "ball", "sphere" };
  int controlSet = -1;
  for (int k = 0; k < 4; ++k)
  {
    controlSet = kind == kinds[k] ? k : controlSet;
  }
  if (controlSet < 0)
  {
    return "unknown control set '" + kind + "': use none, box, ball or sphere";
  }
  if (controlDim != 1 && controlDim != 2 && controlDim != 3)
  {
    return "--control-dim must be 1, 2 or 3";
  }
  if (rk != 1 && rk != 2 && rk != 3)
  {
    return "--rk must be 1, 2 or 3";
  }
  if (tabulation < 1 || tabulation > 1000 || tabulation != static_cast<int>(tabulation))
  {
    return "--tabulation must be a whole number from 1 to 1000";
  }
  if (warmStart < 0 || warmStart > 15 || warmStart != static_cast<int>(warmStart))
  {
    return "--warm-start must be a whole number from 0 (off) to 15";
  }
  if (!(tolerance >= 0.0 && tolerance <= 1.0))
  {
    return "--tolerance must be in [0, 1]";
  }
  double v3[3];
  solver->SetPreset(vtkCWENOHJBSolver::CUSTOM);
  solver->SetDynamicsX(opt.value("fx", "0").c_str());
  solver->SetDynamicsY(opt.value("fy", "0").c_str());
  solver->SetDynamicsZ(opt.value("fz", "0").c_str());
  solver->SetRunningCost(opt.value("cost", "").c_str());
  solver->SetInitialValue(opt.value("v0", "").c_str());
  solver->SetObstacle(opt.value("obstacle", "").c_str());
  solver->SetExactSolution(opt.value("exact", "").c_str());
  solver->SetArgminA1(opt.value("argmin1", "").c_str());
  solver->SetArgminA2(opt.value("argmin2", "").c_str());
  solver->SetArgminA3(opt.value("argmin3", "").c_str());
  solver->SetDimensions(dims);
  solver->SetDomainBounds(bounds);
  solver->SetPeriodicAxes(periodic);
  solver->SetControlSet(controlSet);
  solver->SetControlDimension(static_cast<int>(controlDim));
  copy3(lower, v3, 0.0);
  solver->SetControlLowerBound(v3);
  copy3(upper, v3, 0.0);
  solver->SetControlUpperBound(v3);
  copy3(center, v3, 0.0);
  solver->SetControlCenter(v3);
  solver->SetControlRadius(radius);
  solver->SetRKOrder(static_cast<int>(rk));
  solver->SetTabulationPoints(static_cast<int>(tabulation));
  solver->SetWarmStartPoints(static_cast<int>(warmStart));
  solver->SetMinimizerTolerance(tolerance);
  solver->SetComputeReachableSet(opt.has("reach") ? 1 : 0);
  return "";
}

} // namespace sltkcli
