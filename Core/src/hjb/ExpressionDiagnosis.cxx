// SPDX-License-Identifier: BSD-3-Clause
// findNonFiniteFormula() and withNonFiniteDiagnosis(): see ExpressionDiagnosis.h.
#include "ExpressionDiagnosis.h"

#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace sltk
{
const char* const NonFiniteFix = "give formulas that are finite on the whole domain and control set (guard "
                                 "divisions, logarithms and roots, e.g. max(x, 1e-9))";

double axisSpacing(const HjbExpressionSpec& spec, int axis)
{
  const Index n = spec.Nodes[static_cast<size_t>(axis)];
  const bool periodic = spec.Bounds[static_cast<size_t>(axis)] == Boundary::Periodic;
  return (spec.Upper[static_cast<size_t>(axis)] - spec.Lower[static_cast<size_t>(axis)]) /
    static_cast<double>(periodic ? n : n - 1);
}

HjbGrid wholeGrid(const HjbExpressionSpec& spec)
{
  HjbGrid g;
  g.Dimension = spec.Dimension;
  for (int a = 0; a < spec.Dimension; ++a)
  {
    g.Dims[a] = spec.Nodes[static_cast<size_t>(a)];
    g.Origin[a] = spec.Lower[static_cast<size_t>(a)];
    g.Spacing[a] = axisSpacing(spec, a);
  }
  return g;
}

std::vector<std::array<double, 3>> sampleControls(const HjbExpressionSpec& spec)
{
  using Control = std::array<double, 3>;
  const int m = spec.ControlDimension;
  std::vector<Control> samples;
  switch (spec.Controls)
  {
    case ControlKind::None:
      samples.push_back(Control{});
      break;
    case ControlKind::Box:
      for (int corner = 0; corner < (1 << m); ++corner)
      {
        Control a{};
        for (int j = 0; j < m; ++j)
        {
          a[j] = (corner >> j & 1) ? spec.ControlUpper[j] : spec.ControlLower[j];
        }
        samples.push_back(a);
      }
      samples.push_back(Control{});
      for (int j = 0; j < m; ++j)
      {
        samples.back()[j] = 0.5 * (spec.ControlLower[j] + spec.ControlUpper[j]);
      }
      break;
    case ControlKind::Ball:
    case ControlKind::Sphere:
      if (spec.Controls == ControlKind::Ball)
      {
        samples.push_back(spec.ControlCenter);
      }
      for (int j = 0; j < m; ++j)
      {
        for (const double side : { -1.0, 1.0 })
        {
          Control a = spec.ControlCenter;
          a[j] += side * spec.ControlRadius;
          samples.push_back(a);
        }
      }
      break;
    case ControlKind::Finite:
      samples.assign(spec.ControlPoints.begin(), spec.ControlPoints.end());
      break;
  }
  return samples;
}

namespace
{
using Control = std::array<double, 3>;

std::string describe(
  const Expression& e, double value, const double (&v)[SlotCount], int dimension, int controls, bool withTime)
{
  static const char* const names[SlotCount] = { "x", "y", "z", "t", "a1", "a2", "a3" };
  std::ostringstream out;
  out << e.what() << " '" << e.text() << "' is "
      << (std::isnan(value) ? "NaN"
             : value > 0.0  ? "+Inf"
                            : "-Inf")
      << " at ";
  const char* separator = "";
  for (int k = 0; k < SlotCount; ++k)
  {
    const bool shown =
      (k >= SlotX && k < SlotX + dimension) || (k == SlotT && withTime) || (k >= SlotA && k < SlotA + controls);
    if (shown && e.uses(k))
    {
      out << separator << names[k] << " = " << v[k];
      separator = ", ";
    }
  }
  if (*separator == '\0')
  {
    out << "every point";
  }
  return out.str();
}
} // namespace

std::string findNonFiniteFormula(const HjbExpressionSpec& spec, const CompiledHjbExpressions& compiled,
  const HjbGrid& grid, double t, FormulaScope scope)
{
  const int dimension = spec.Dimension;
  const int controls = spec.Controls == ControlKind::None ? 0 : spec.ControlDimension;
  std::vector<const Expression*> ofControls;
  for (int d = 0; d < dimension; ++d)
  {
    ofControls.push_back(&compiled.Dynamics[static_cast<size_t>(d)]);
  }
  ofControls.push_back(&compiled.Cost);
  std::vector<const Expression*> ofState;
  if (compiled.Initial.isCompiled())
  {
    ofState.push_back(&compiled.Initial);
  }
  if (compiled.HasObstacle)
  {
    ofState.push_back(&compiled.Obstacle);
  }
  const std::vector<Control> samples =
    scope == FormulaScope::AllFormulas ? sampleControls(spec) : std::vector<Control>{};
  const long long nodes = grid.Dims[0] * grid.Dims[1] * grid.Dims[2];
  double v[SlotCount] = {};
  for (long long k = 0; k < nodes; ++k)
  {
    long long rest = k;
    for (int a = 0; a < 3; ++a)
    {
      const long long i = rest % grid.Dims[a];
      rest /= grid.Dims[a];
      v[SlotX + a] = a < dimension ? grid.Origin[a] + static_cast<double>(i) * grid.Spacing[a] : 0.0;
    }
    v[SlotT] = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      v[SlotA + a] = 0.0;
    }
    for (const Expression* e : ofState)
    {
      const double value = e->evaluate(v);
      if (!std::isfinite(value))
      {
        return describe(*e, value, v, dimension, 0, false);
      }
    }
    v[SlotT] = t;
    for (const Control& a : samples)
    {
      for (int j = 0; j < 3; ++j)
      {
        v[SlotA + j] = j < controls ? a[j] : 0.0;
      }
      for (const Expression* e : ofControls)
      {
        const double value = e->evaluate(v);
        if (!std::isfinite(value))
        {
          return describe(*e, value, v, dimension, controls, true);
        }
      }
    }
  }
  return {};
}

namespace
{
class DiagnosedSolver final : public HjbSolver
{
public:
  DiagnosedSolver(std::unique_ptr<HjbSolver> solver, HjbExpressionSpec spec, SharedHjbExpressions compiled)
    : Inner(std::move(solver))
    , Spec(std::move(spec))
    , Compiled(std::move(compiled))
  {
  }
  const HjbGrid& grid() const override { return this->Inner->grid(); }
  double timeStep() const override { return this->Inner->timeStep(); }
  Index stepCount() const override { return this->Inner->stepCount(); }
  double startTime() const override { return this->Inner->startTime(); }
  Index stepsDone() const override { return this->Inner->stepsDone(); }
  double evaluationsPerNode() const override { return this->Inner->evaluationsPerNode(); }
  void result(HjbRunResult& out) const override { this->Inner->result(out); }
  void readValues(Index first, Index count, double* out) override { this->Inner->readValues(first, count, out); }
  void writeValues(Index first, Index count, const double* values) override
  {
    this->Inner->writeValues(first, count, values);
  }

  Status advanceTo(double t, const Context& ctx) override
  {
    Status status = this->Inner->advanceTo(t, ctx);
    if (status.code() != StatusCode::NumericalFailure)
    {
      return status;
    }
    const double start = this->Inner->time();
    std::string cause;
    for (const double at : { start, start + this->Inner->timeStep() })
    {
      cause = findNonFiniteFormula(this->Spec, *this->Compiled, wholeGrid(this->Spec), at, FormulaScope::AllFormulas);
      if (!cause.empty())
      {
        break;
      }
    }
    if (cause.empty())
    {
      return Status::numericalFailure(status.message() +
        "; every formula is finite at the grid nodes, so the values overflowed between them or grew without "
        "bound: check the formulas between the nodes, the size of the domain and the final time");
    }
    return Status::numericalFailure(status.message() + ": " + cause + "; " + NonFiniteFix);
  }

private:
  std::unique_ptr<HjbSolver> Inner;
  HjbExpressionSpec Spec;
  SharedHjbExpressions Compiled;
};
} // namespace

std::unique_ptr<HjbSolver> withNonFiniteDiagnosis(
  std::unique_ptr<HjbSolver> solver, const HjbExpressionSpec& spec, SharedHjbExpressions compiled)
{
  if (!solver)
  {
    return solver;
  }
  HjbExpressionSpec copy = spec;
  copy.InitialValues.clear(); // checked finite when the solver was made
  return std::make_unique<DiagnosedSolver>(std::move(solver), std::move(copy), std::move(compiled));
}

} // namespace sltk
