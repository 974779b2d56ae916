// SPDX-License-Identifier: BSD-3-Clause
#include "HjbCustomProblem.h"

#include "CliOptions.h"

#include <vtkCWENOHJBSolver.h>

namespace sltkcli
{

const char* const HjbCustomProblem::Group = "Custom problem (--fx starts one)";

const char* const HjbCustomProblem::Help =
  "Custom problems, v_t + max_a { -f_D(t,x,a) . Dv - f_C(t,x,a) } = 0 (thesis (3.1)-(3.4)),\n"
  "by formulas in x, y, z, t, a1, a2, a3 (+ - * / % ^, comparisons, c ? a : b, sin ... exp\n"
  "log sqrt abs atan2 hypot min max clamp if, pi, e); --fx starts one (options below).\n";

namespace
{
/// "x", "x,y", ...: the periodic axes; false when malformed.
bool parsePeriodic(const std::string& axes, int periodic[3])
{
  for (size_t k = 0; k < axes.size(); ++k)
  {
    const char c = axes[k];
    if ((c == 'x' || c == 'y' || c == 'z') && (k + 1 == axes.size() || axes[k + 1] == ','))
    {
      periodic[c - 'x'] = 1;
    }
    else if (c != ',')
    {
      return false;
    }
  }
  return true;
}

/// The first three values of `v`, padded with `pad`.
void copy3(const std::vector<double>& v, double* out, double pad)
{
  for (size_t k = 0; k < 3; ++k)
  {
    out[k] = k < v.size() ? v[k] : pad;
  }
}
} // namespace

void HjbCustomProblem::addOptions(CLI::App* app)
{
  const size_t before = app->get_options().size();
  const auto formula = [app](const std::string& name, std::string& value, const std::string& description)
  { app->add_option(name, value, description)->option_text("F"); };
  formula("--fx", this->Dynamics[0], "dynamics f_D: its x component (one component per axis used)");
  formula("--fy", this->Dynamics[1], "its y component");
  formula("--fz", this->Dynamics[2], "its z component");
  formula("--cost", this->Cost, "running cost f_C (default 0)");
  formula("--v0", this->InitialValue, "initial datum v0(x, y, z)");
  formula(
    "--obstacle", this->Obstacle, "state constraint g(x, y, z): v = max(v, g) (3.39); ReachTime is\nwritten (3.40)");
  formula("--exact", this->Exact, "exact solution v(t, x, y, z): adds l1_error and linf_error");
  formula("--argmin1", this->Argmin[0],
    "closed-form argmin a*(t, x, y, z), one formula per control\ncomponent: replaces "
    "the search (one evaluation per node\nand step)");
  formula("--argmin2", this->Argmin[1], "a2* (with --argmin1)");
  formula("--argmin3", this->Argmin[2], "a3* (with --argmin1 and --argmin2)");
  addNumberList(app, "--nodes", this->Nodes, 1, 3, "nodes per axis; their count is the dimension (default 81,81)")
    ->option_text("NX[,NY[,NZ]]");
  addNumberList(app, "--domain", this->Domain, 2, 6, "the box (default [-1, 1] per axis)")
    ->option_text("X0,X1[,Y0,Y1[,Z0,Z1]]");
  app->add_option("--periodic", this->Periodic, "periodic axes, e.g. x or x,y (default none: linear extrapolation)")
    ->check(CLI::Validator(
      [](std::string& axes)
      {
        int periodic[3] = { 0, 0, 0 };
        return parsePeriodic(axes, periodic) ? std::string()
                                             : "takes axis names x, y, z separated by commas, got '" + axes + "'";
      },
      ""))
    ->option_text("AXES");
  addChoice(
    app, "--controls", "control set", { "none", "box", "ball", "sphere" },
    [this](size_t k) { this->ControlSet = static_cast<int>(k); },
    "none | box | ball | sphere (default none: pure transport)")
    ->option_text("KIND");
  addNumber(app, "--control-dim", this->ControlDimension, "dimension of a = (a1, ..., aM) (default 1)")
    ->check(withinRange("ControlDimension"))
    ->option_text("M");
  addNumberList(app, "--control-lower", this->Lower, 1, 3, "box corner (default -1)")->option_text("A,...");
  addNumberList(app, "--control-upper", this->Upper, 1, 3, "box corner (default 1)")->option_text("A,...");
  addNumberList(app, "--control-center", this->Center, 1, 3, "ball / sphere centre (default 0)")->option_text("A,...");
  addNumber(app, "--control-radius", this->Radius, "ball / sphere radius (default 1)")->option_text("R");
  addNumber(app, "--rk", this->RKOrder, "RK order of the characteristics: 1, 2 or 3 (default 3)")
    ->check(within(1, 3))
    ->option_text("1|2|3");
  addNumber(app, "--tabulation", this->Tabulation,
    "tabulated controls per axis of A before the local search\n(1 to 1000, default 33)")
    ->check(withinRange("TabulationPoints"))
    ->option_text("N");
  addNumber(app, "--warm-start", this->WarmStart,
    "after the first step, search a coarse N^q grid of A and an N^q\ngrid around each node's previous argmin "
    "instead of tabulating A\n(0 to 15, default 0: off; 5 suits Test 4)")
    ->check(withinRange("WarmStartPoints"))
    ->option_text("N");
  addNumber(app, "--tolerance", this->Tolerance, "local search tolerance, in [0, 1] (default 1e-8)")
    ->check(withinRange("MinimizerTolerance"))
    ->option_text("TOL");
  app->add_flag("--reach", this->Reach, "write ReachTime also without an obstacle");
  app->add_flag("--control-per-step", this->ControlPerStep,
    "one control per time step instead of one per RK stage (PerStageControls\noff; the stages' controls A^nu "
    "are needed for high order)");
  const std::vector<CLI::Option*> options = app->get_options();
  for (size_t k = before; k < options.size(); ++k)
  {
    options[k]->group(Group);
  }
}

std::string HjbCustomProblem::apply(vtkCWENOHJBSolver* solver) const
{
  if (this->Domain.size() % 2 != 0)
  {
    return "--domain takes pairs lower,upper per axis, got " + std::to_string(this->Domain.size()) + " numbers";
  }
  // Options for an axis or a control the problem does not have are mistakes, not ignored.
  const size_t dimension = this->Nodes.size();
  const std::string problem =
    std::to_string(dimension) + "D problem (--nodes gives " + std::to_string(dimension) + " axes)";
  if (!this->Domain.empty() && this->Domain.size() != 2 * dimension)
  {
    return "--domain gives " + std::to_string(this->Domain.size() / 2) + " axes for a " + problem +
      ": give one lower,upper pair per axis";
  }
  const char* const components[3] = { "--fx", "--fy", "--fz" };
  for (size_t a = dimension; a < 3; ++a)
  {
    if (this->Dynamics[a] != "0") // the default: an unused axis does not move
    {
      return std::string(components[a]) + " is given for a " + problem + ": drop it or add an axis to --nodes";
    }
  }
  for (size_t k = static_cast<size_t>(this->ControlDimension); k < 3; ++k)
  {
    if (!this->Argmin[k].empty())
    {
      return "--argmin" + std::to_string(k + 1) + " is given for " + std::to_string(this->ControlDimension) +
        " control(s) (--control-dim): drop it or raise --control-dim";
    }
  }
  int dims[3] = { 1, 1, 1 };
  for (size_t a = 0; a < this->Nodes.size(); ++a)
  {
    if (this->Nodes[a] < 5 || this->Nodes[a] > 100000 || this->Nodes[a] != static_cast<int>(this->Nodes[a]))
    {
      return "--nodes takes whole numbers from 5 to 100000 per axis";
    }
    dims[a] = static_cast<int>(this->Nodes[a]);
  }
  double bounds[6] = { -1, 1, -1, 1, -1, 1 };
  for (size_t k = 0; k < this->Domain.size(); ++k)
  {
    bounds[k] = this->Domain[k];
  }
  int periodic[3] = { 0, 0, 0 };
  parsePeriodic(this->Periodic, periodic); // checked by the parser
  double v3[3];
  solver->SetPreset(vtkCWENOHJBSolver::CUSTOM);
  solver->SetDynamicsX(this->Dynamics[0].c_str());
  solver->SetDynamicsY(this->Dynamics[1].c_str());
  solver->SetDynamicsZ(this->Dynamics[2].c_str());
  solver->SetRunningCost(this->Cost.c_str());
  solver->SetInitialValue(this->InitialValue.c_str());
  solver->SetObstacle(this->Obstacle.c_str());
  solver->SetExactSolution(this->Exact.c_str());
  solver->SetArgminA1(this->Argmin[0].c_str());
  solver->SetArgminA2(this->Argmin[1].c_str());
  solver->SetArgminA3(this->Argmin[2].c_str());
  solver->SetDimensions(dims);
  solver->SetDomainBounds(bounds);
  solver->SetPeriodicAxes(periodic);
  solver->SetControlSet(this->ControlSet);
  solver->SetControlDimension(this->ControlDimension);
  copy3(this->Lower, v3, 0.0);
  solver->SetControlLowerBound(v3);
  copy3(this->Upper, v3, 0.0);
  solver->SetControlUpperBound(v3);
  copy3(this->Center, v3, 0.0);
  solver->SetControlCenter(v3);
  solver->SetControlRadius(this->Radius);
  solver->SetRKOrder(this->RKOrder);
  solver->SetTabulationPoints(this->Tabulation);
  solver->SetWarmStartPoints(this->WarmStart);
  solver->SetMinimizerTolerance(this->Tolerance);
  solver->SetComputeReachableSet(this->Reach ? 1 : 0);
  solver->SetPerStageControls(this->ControlPerStep ? 0 : 1);
  return "";
}

} // namespace sltkcli
