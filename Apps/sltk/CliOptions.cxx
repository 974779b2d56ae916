// SPDX-License-Identifier: BSD-3-Clause
#include "CliOptions.h"

#include "sltk/recon/AutomaticParameters.h"
#include "sltk/recon/OptionRanges.h"

#include "sltk/core/LowerCase.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sltkcli
{

namespace
{
/// The whole of `text` as a finite number.
bool parseNumber(const std::string& text, double& v)
{
  try
  {
    size_t used = 0;
    v = std::stod(text, &used);
    return used == text.size() && std::isfinite(v);
  }
  catch (const std::exception&)
  {
    return false;
  }
}

/// "v1,v2,..." as numbers; false when one is malformed.
bool parseNumberList(const std::string& text, std::vector<double>& values)
{
  values.clear();
  std::stringstream in(text);
  std::string item;
  double v = 0.0;
  while (std::getline(in, item, ','))
  {
    if (!parseNumber(item, v))
    {
      return false;
    }
    values.push_back(v);
  }
  return !text.empty() && text.back() != ','; // getline drops a trailing empty item
}

/// A transform: a number, rewritten as a whole one for an int option (CLI11 then converts it).
CLI::Validator numberText(bool whole)
{
  return CLI::Validator(
    [whole](std::string& text)
    {
      double v = 0.0;
      if (!parseNumber(text, v) || (whole && (v != std::floor(v) || std::fabs(v) > 2e9)))
      {
        return std::string(whole ? "expects a whole number, got '" : "expects a number, got '") + text + "'";
      }
      if (whole)
      {
        text = std::to_string(static_cast<long long>(v));
      }
      return std::string();
    },
    "");
}

/// A check: `known(text)`, else "unknown <what> 'text': use <list>".
CLI::Validator namedCheck(
  const std::string& what, const std::function<bool(const std::string&)>& known, const std::string& list)
{
  CLI::Validator check([=](std::string& text)
    { return known(text) ? std::string() : "unknown " + what + " '" + text + "': use " + list; },
    "");
  return check.non_modifying();
}

} // namespace

CLI::Option* addNumber(CLI::App* app, const std::string& name, double& value, const std::string& description)
{
  return app->add_option(name, value, description)->transform(numberText(false));
}

CLI::Option* addNumber(CLI::App* app, const std::string& name, int& value, const std::string& description)
{
  return app->add_option(name, value, description)->transform(numberText(true));
}

CLI::Validator within(double low, double high, bool lowOpen)
{
  std::ostringstream range;
  if (std::isinf(high))
  {
    range << (lowOpen ? "> " : ">= ") << low;
  }
  else
  {
    range << "in " << (lowOpen ? "(" : "[") << low << ", " << high << "]";
  }
  CLI::Validator check(
    [=, text = range.str()](std::string& input)
    {
      const double v = std::stod(input); // a number: addNumber's transform ran first
      const bool inside = (lowOpen ? v > low : v >= low) && v <= high;
      return inside ? std::string() : "must be " + text + ", got " + input;
    },
    "");
  return check.non_modifying();
}

CLI::Validator withinRange(const char* property)
{
  const sltk::OptionRange* r = sltk::findOptionRange(property);
  std::ostringstream range;
  range << "in [" << r->Min << ", " << r->Max << "]" << (r->ZeroIsAutomatic ? " (or 0: automatic)" : "");
  CLI::Validator check(
    [r, text = range.str()](std::string& input)
    {
      const double v = std::stod(input); // a number: addNumber's transform ran first
      return sltk::inOptionRange(*r, v) ? std::string() : "must be " + text + ", got " + input;
    },
    "");
  return check.non_modifying();
}

CLI::Option* addNumberList(CLI::App* app, const std::string& name, std::vector<double>& values, size_t minCount,
  size_t maxCount, const std::string& description)
{
  CLI::Validator check(
    [=](std::string& text)
    {
      std::vector<double> parsed;
      if (parseNumberList(text, parsed) && parsed.size() >= minCount && parsed.size() <= maxCount)
      {
        return std::string();
      }
      return "expects " + std::to_string(minCount) +
        (maxCount > minCount ? " to " + std::to_string(maxCount) : std::string()) + " comma-separated numbers, got '" +
        text + "'";
    },
    "");
  return app
    ->add_option_function<std::string>(
      name, [&values](const std::string& text) { parseNumberList(text, values); }, description)
    ->check(check.non_modifying());
}

CLI::Option* addChoice(CLI::App* app, const std::string& name, const std::string& what,
  const std::vector<std::string>& names, const std::function<void(size_t)>& chosen, const std::string& description)
{
  const auto known = [names](const std::string& text)
  { return std::find(names.begin(), names.end(), text) != names.end(); };
  return app
    ->add_option_function<std::string>(
      name,
      [names, chosen](const std::string& text)
      { chosen(static_cast<size_t>(std::find(names.begin(), names.end(), text) - names.begin())); },
      description)
    ->check(namedCheck(what, known, sltk::orList(names)));
}

namespace
{
/// --interpolator NAME: the reconstruction's (every kind, and "auto") or the HJB solver's kinds.
CLI::Option* addInterpolatorChoice(CLI::App* app, const std::string& defaultText, bool reconstruction,
  const std::function<void(std::optional<sltk::InterpolatorKind>)>& chosen)
{
  constexpr const char* AutomaticName = "auto";
  std::string description = "spatial reconstruction at the feet of the characteristics (default " + defaultText + "):";
  std::vector<std::string> names;
  if (reconstruction)
  {
    std::ostringstream line;
    line << "\n  " << AutomaticName << ": lsq-q1 on a cloud whose noise is below " << sltk::AutomaticInterpolatorNoise
         << " h_P, else weno3\n    (the choice and the noise are logged)";
    description += line.str();
    names.emplace_back(AutomaticName);
  }
  for (const sltk::InterpolatorInfo& info : sltk::Interpolators)
  {
    if (reconstruction || sltk::offeredByHjb(info.Kind))
    {
      description += std::string("\n  ") + info.Name + ": " + info.Description;
      names.emplace_back(info.Name);
    }
  }
  const auto isAutomatic = [reconstruction](const std::string& text)
  { return reconstruction && sltk::lowerCase(text) == AutomaticName; };
  const auto known = [reconstruction, isAutomatic](const std::string& text)
  {
    sltk::InterpolatorKind parsed;
    return isAutomatic(text) ||
      (sltk::parseInterpolator(text, parsed) && (reconstruction || sltk::offeredByHjb(parsed)));
  };
  return app
    ->add_option_function<std::string>(
      "--interpolator",
      [chosen, isAutomatic](const std::string& text)
      {
        sltk::InterpolatorKind kind{};
        if (!isAutomatic(text) && sltk::parseInterpolator(text, kind))
        {
          chosen(kind);
          return;
        }
        chosen(std::nullopt);
      },
      description)
    ->check(namedCheck("interpolator", known, sltk::orList(names)))
    ->option_text("NAME");
}
} // namespace

CLI::Option* addInterpolatorOption(CLI::App* app, sltk::InterpolatorKind& kind, const std::string& defaultName)
{
  return addInterpolatorChoice(
    app, defaultName, false, [&kind](std::optional<sltk::InterpolatorKind> chosen) { kind = chosen.value_or(kind); });
}

CLI::Option* addReconstructionInterpolatorOption(CLI::App* app, std::optional<sltk::InterpolatorKind>& kind)
{
  return addInterpolatorChoice(
    app, "auto", true, [&kind](std::optional<sltk::InterpolatorKind> chosen) { kind = chosen; });
}

CLI::Option* addThreadsOption(CLI::App* app, int& threads)
{
  return addNumber(app, "--threads", threads,
    "threads (default 0: the cores shared by the ranks on a node,\nat most VTK_SMP_MAX_THREADS; at most 1024)")
    ->check(withinRange("NumberOfThreads"))
    ->option_text("T");
}

CLI::App* addCloudCommand(CLI::App& sltk, const std::string& name, const std::string& description, std::string& cloud)
{
  CLI::App* app = sltk.add_subcommand(name, description);
  app->footer(""); // the clouds are listed here, not sltk's footer
  app->add_option("CLOUD", cloud, "the point cloud (.ply .xyz .txt .csv .pts .obj .vtp .vtu .vtk)")
    ->required()
    ->type_name("");
  return app;
}

void addPlanOptions(CLI::App* app, sltk::ReconstructionOptions& options)
{
  addNumber(app, "--runs", options.Runs, "runs, each halving the cell size (default 3)")->option_text("R");
  addNumber(app, "--cdx", options.CellSizeFactor,
    "C_dx of (4.36): first-run cell size in units of h_P (default:\nautomatic, 1 or the smallest that fits "
    "--memory-budget)")
    ->option_text("C");
  addNumber(app, "--max-level", options.MaximumLevel,
    "the thesis's octree level instead of --cdx: the finest cell is the\ncloud's largest extent / 2^L (5.1), run 1 at "
    "level L - R + 1 (5.10)")
    ->option_text("L")
    ->excludes("--cdx")
    ->check(withinRange("MaximumLevel"));
  addNumber(app, "--kp", options.OutsideThresholdFactor,
    "K_P: initial surface at K h_P from the cloud (default: automatic,\nthe K of 2-32, at least 2 C_dx, that encloses "
    "the most; the "
    "thesis: 2, 10 for scans\nwith holes)")
    ->option_text("K");
  app
    ->add_option_function<double>(
      "--memory-budget",
      [&options](double mb)
      { options.MemoryBudget = static_cast<std::uint64_t>(mb * static_cast<double>(sltk::BytesPerMB)); },
      "MB for the automatic C_dx (default 0: 1024); with --cdx, grids beyond\nit are refused (default: the memory "
      "available; under mpirun, for the windows\nof the ranks on each machine, and an automatic C_dx grows until "
      "they fit)")
    ->transform(numberText(false))
    ->check(withinRange("MemoryBudget"))
    ->option_text("MB");
  addNumber(app, "--padding", options.Padding, "empty cells around the cloud on every side (default 10)")
    ->check(withinRange("Padding"))
    ->option_text("N");
  app->add_flag_callback(
    "--uniform-offset", [&options]() { options.LocalOffset = false; },
    "run 1's initial surface at K_P h_P everywhere (the thesis), not K_P h_P\ntimes the local sparsity of the cloud");
  app->add_flag_callback(
    "--thesis-stopping", [&options]() { options.FollowFarPoints = false; },
    "stop a run by the energy rule (4.33) alone, even while the surface is\nstill approaching points left far from it");
  app->add_flag_callback(
    "--feet-everywhere", [&options]() { options.FeetWithinBeta = false; },
    "interpolate the SL step's feet on the whole band (the thesis), not only\nwithin beta of the surface");
  app->add_flag_callback(
    "--seed-far-points", [&options]() { options.SeedFarPoints = true; },
    "start each run after the first from the previous run's surface united\nwith balls around the points it left "
    "outside (thin parts a coarse run\nlost grow back; off by default: it can add a piece)");
  app->add_flag_callback(
    "--no-cleaning", [&options]() { options.Cleaning.Automatic = false; },
    "use the cloud as given (no automatic outlier removal or thinning)");
  addChoice(
    app, "--initial", "initial guess", { "outside", "sphere", "ellipsoid" }, // InitialGuess values 0, 1, 2
    [&options](size_t k) { options.Guess = static_cast<sltk::InitialGuess>(k); },
    "initial surface: outside (4.4.4: external marking) | sphere | ellipsoid\naround the cloud (default outside)")
    ->option_text("NAME");
  app->add_flag("--remove-outliers", options.Cleaning.RemoveOutliers,
    "drop points whose mean distance to 8 neighbours is above mean + S sigma\n(default: only when gross outliers "
    "exist)");
  addNumber(app, "--outlier-sigma", options.Cleaning.Outliers.Deviations, "the S of --remove-outliers (default 3)")
    ->option_text("S");
  addNumber(app, "--thin", options.Cleaning.ThinningFactor,
    "average the points in voxels of F x the density spacing (merged,\noverlapping scans: h_P (4.36) is then taken "
    "on the thinned cloud);\ndefault: 2.5 when the cloud is denser than the finest grid")
    ->option_text("F");
}

} // namespace sltkcli
