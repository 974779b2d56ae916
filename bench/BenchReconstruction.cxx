// SPDX-License-Identifier: BSD-3-Clause
/// \file BenchReconstruction.cxx
/// Algorithm 1 (thesis 4.3-4.5) on the data sets of 4.5.3-4.5.5, printed per
/// run next to the thesis's Tables 4.2-4.7 (read from thesis_tables.json).
///
/// Synthetic cases (exact signed distance known, clouds built in [-1, 1]^d as
/// in 4.5, so that the library's unit-box scale is 1):
///  - circle:      64 points at angles 2 pi k / 64 on the unit circle (4.5.3), 5 runs (Table 4.2);
///  - square:      24 points on the square |x| + |y| = 1 (rotated 45 degrees), its 4 corners
///                 and 5 equispaced points inside each side (h_P = sqrt(2) / 6), 5 runs (Table 4.3);
///  - sphere:      icosahedron subdivided 4 times, vertices projected on the unit sphere,
///                 10 * 4^4 + 2 = 2562 points, 3 runs (Table 4.4);
///  - cubespheres: cube of edge 0.8, a sphere of radius 0.25 centred at the middle of an edge and
///                 two of radius 0.15 at the two vertices of the opposite edge (4.5.4), rotated,
///                 sampled quasi-uniformly with 2346 points, rescaled to [-1, 1]^3, 3 runs (Table 4.5).
///
/// L1 error (4.5.1; the text gives no formula): the library's phi is cut at
/// +-gamma = +-4 dx (1.49)/(1.51), so the main column is
///   L1 = dx^d * sum over all nodes of |phi_j - cut(phi*(x_j))|, cut(s) = max(-gamma, min(gamma, s)),
/// and the second column restricts the sum to the band |phi*| < gamma
/// (no cut needed there). The per-run phi is obtained by calling reconstruct
/// with Runs = 1..R (the grids of run r do not depend on R: GridPlan.cxx).
///
/// E_2 of the exact shape (4.1) is printed for circle, square and sphere (fine
/// quadrature of the exact curve/surface, brute-force d_P): the thesis quotes
/// about 7.10e-2 for the circle (4.5.3), the limit our runs should approach.
///
/// Real scans (4.5.5; --scans): energies and Err_P converted to the unit box
/// of 4.5 (scale s = half the largest bounding-box extent: Err_P / s,
/// E_2 / s^((d+1)/2), the library's own conversion in Reconstruction.cxx).
///
/// This is a benchmark: it prints tables, never pass/fail. Each comparison
/// prints ours/thesis and a factor-1.5 verdict: "within" (1/1.5 <= ratio <= 1.5),
/// "better"/"worse" for errors, "lower"/"higher" for energies.
///
/// Usage: sltkBenchReconstruction [--case NAME[,NAME...]] [--interp q1,weno3,cweno,cwenoz]
///          [--threads N] [--tables PATH] [--data DIR] [--scans] [--cdx C] [--kp K] [--runs R]
///          [--noise SIGMA] [--tolerance T] [--final-only] [--padding P] [--log]
///   default cases: circle,square,sphere,cubespheres; also noisycircle, noisysphere (10% noise, larger
///   final eta; --noise sets sigma, default 0.1 = 10% of the radius);
///   --scans: bunny,teapot,fandisk,knot,knotellipse,frog
///   --tolerance: threshold of the stopping rule (4.33), default 1e-4
///   --final-only: synthetic cases run once with R runs (L1 of the last run only; half the work for R = 3)
///   default interpolators: q1,weno3,cweno in 2D, q1,weno3 in 3D and for the scans
///   --log prints the library's per-run phase times (the context's logger)
///   --padding: cells of padding per side of the synthetic cases (library default 10; the thesis's square grids are
///   padding 8)

#include "sltk/exec/Context.h"
#include "sltk/exec/Memory.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/recon/Reconstruction.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;
const double NaN = std::nan("");

// ---------------------------------------------------------------------------
// A tiny reader for thesis_tables.json: follows a path of keys in document
// order and returns the array (or scalar) after the last one as text tokens.
// ---------------------------------------------------------------------------
class ThesisTables
{
public:
  explicit ThesisTables(const std::string& path)
  {
    std::ifstream in(path);
    if (in)
    {
      std::stringstream s;
      s << in.rdbuf();
      this->Text = s.str();
    }
  }

  bool loaded() const { return !this->Text.empty(); }

  std::vector<std::string> tokens(const std::vector<std::string>& path) const
  {
    std::vector<std::string> out;
    size_t pos = 0;
    for (const std::string& key : path)
    {
      pos = this->Text.find("\"" + key + "\"", pos);
      if (pos == std::string::npos)
      {
        return out;
      }
      pos += key.size() + 2;
    }
    pos = this->Text.find_first_not_of(" \t\r\n:", pos);
    if (pos == std::string::npos)
    {
      return out;
    }
    const bool array = this->Text[pos] == '[';
    const size_t end = array ? this->Text.find(']', pos) : this->Text.find_first_of(",}", pos);
    if (end == std::string::npos)
    {
      return out;
    }
    const std::string body = this->Text.substr(array ? pos + 1 : pos, end - (array ? pos + 1 : pos));
    std::stringstream s(body);
    std::string item;
    while (std::getline(s, item, ','))
    {
      item.erase(std::remove_if(item.begin(), item.end(), [](char c) { return c == '"' || std::isspace(c); }),
        item.end());
      out.push_back(item);
    }
    return out;
  }

  std::vector<double> numbers(const std::vector<std::string>& path) const
  {
    std::vector<double> out;
    for (const std::string& t : this->tokens(path))
    {
      char* end = nullptr;
      const double v = std::strtod(t.c_str(), &end);
      out.push_back(end && *end == '\0' && !t.empty() ? v : NaN);
    }
    return out;
  }

private:
  std::string Text;
};

double at(const std::vector<double>& v, size_t i)
{
  return i < v.size() ? v[i] : NaN;
}

std::string at(const std::vector<std::string>& v, size_t i)
{
  return i < v.size() ? v[i] : std::string("-");
}

/// ours/thesis and the factor-1.5 verdict.
std::string compare(double ours, double thesis, bool energy)
{
  if (!std::isfinite(thesis) || !(thesis > 0.0) || !std::isfinite(ours))
  {
    return "      -       ";
  }
  const double r = ours / thesis;
  const char* verdict = r > 1.5 ? (energy ? "higher" : "worse") : (r < 1.0 / 1.5 ? (energy ? "lower" : "better") : "within");
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

template <int D>
std::string gridText(const sltk::GridSpec<D>& g)
{
  std::string s;
  for (int a = 0; a < D; ++a)
  {
    s += (a ? "x" : "") + std::to_string(g.Dims[a]);
  }
  return s;
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

// ---------------------------------------------------------------------------
// Synthetic clouds and their exact signed distances (4.5.3, 4.5.4)
// ---------------------------------------------------------------------------
template <int D>
using Point = std::array<double, D>;
template <int D>
using Sdf = std::function<double(const Point<D>&)>;

/// 4.5.3: "64 points uniformly chosen on a circle of radius 1" (h_P = 2 sin(pi/64) = 0.0981).
sltk::PointCloud<2> circleCloud()
{
  sltk::PointCloud<2> c;
  for (int k = 0; k < 64; ++k)
  {
    c.Points.push_back({ std::cos(2.0 * Pi * k / 64.0), std::sin(2.0 * Pi * k / 64.0) });
  }
  return c;
}

double circleSdf(const Point<2>& x)
{
  return std::hypot(x[0], x[1]) - 1.0;
}

/// 4.5.3: 24 points on a square rotated by 45 degrees, in [-1, 1]^2: the
/// diamond |x| + |y| = 1, corners included, 6 equal segments per side.
sltk::PointCloud<2> squareCloud()
{
  const Point<2> corners[4] = { { 1.0, 0.0 }, { 0.0, 1.0 }, { -1.0, 0.0 }, { 0.0, -1.0 } };
  sltk::PointCloud<2> c;
  for (int s = 0; s < 4; ++s)
  {
    const Point<2>& a = corners[s];
    const Point<2>& b = corners[(s + 1) % 4];
    for (int k = 0; k < 6; ++k)
    {
      const double t = k / 6.0;
      c.Points.push_back({ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) });
    }
  }
  return c;
}

/// Exact signed distance to the diamond: a box of half-side 1/sqrt(2) in the
/// coordinates rotated by 45 degrees.
double squareSdf(const Point<2>& x)
{
  const double h = 1.0 / std::sqrt(2.0);
  const double u = std::fabs((x[0] + x[1]) * h) - h;
  const double v = std::fabs((x[0] - x[1]) * h) - h;
  return std::hypot(std::max(u, 0.0), std::max(v, 0.0)) + std::min(std::max(u, v), 0.0);
}

/// Icosahedron subdivided `levels` times (midpoints), vertices on the unit sphere.
sltk::PointCloud<3> icosphereCloud(int levels)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Point<3>> v = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t },
    { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  std::vector<std::array<int, 3>> f = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 },
    { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  auto normalise = [](Point<3>& p) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (double& c : p)
    {
      c /= n;
    }
  };
  for (auto& p : v)
  {
    normalise(p);
  }
  for (int l = 0; l < levels; ++l)
  {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      const auto it = midpoint.find(key);
      if (it != midpoint.end())
      {
        return it->second;
      }
      Point<3> m = { 0.5 * (v[a][0] + v[b][0]), 0.5 * (v[a][1] + v[b][1]), 0.5 * (v[a][2] + v[b][2]) };
      normalise(m);
      v.push_back(m);
      midpoint[key] = static_cast<int>(v.size()) - 1;
      return static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> g;
    for (const auto& tri : f)
    {
      const int ab = mid(tri[0], tri[1]);
      const int bc = mid(tri[1], tri[2]);
      const int ca = mid(tri[2], tri[0]);
      g.push_back({ tri[0], ab, ca });
      g.push_back({ tri[1], bc, ab });
      g.push_back({ tri[2], ca, bc });
      g.push_back({ ab, bc, ca });
    }
    f = std::move(g);
  }
  sltk::PointCloud<3> c;
  c.Points = v;
  return c;
}

/// "10% of normally distributed noise" (4.5.3 Fig. 4.8, 4.5.4 Fig. 4.11; the text
/// gives no formula): every coordinate of every point gets an independent
/// N(0, sigma^2) perturbation with sigma = 10% of the radius (1), fixed seed.
template <int D>
sltk::PointCloud<D> withNoise(sltk::PointCloud<D> cloud, double sigma, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  for (auto& p : cloud.Points)
  {
    for (double& x : p)
    {
      x += normal(rng);
    }
  }
  return cloud;
}

/// Table 4.1 for runs 1 and 2, then eta = `finalEta` from run 3 on (the noisy
/// tests raise eta in the last run only: Fig. 4.8, Fig. 4.11).
std::vector<sltk::RunParameters> scheduleWithFinalEta(double finalEta)
{
  return { sltk::table41(1), sltk::table41(2), { 2.0, finalEta } };
}

double sphereSdf(const Point<3>& x)
{
  return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - 1.0;
}

/// 4.5.4 Cube&Spheres, in the object's own frame: cube [-0.4, 0.4]^3 (edge 0.8),
/// sphere R = 0.25 at the middle (0, 0.4, 0.4) of an edge, spheres R = 0.15 at
/// the vertices (+-0.4, -0.4, -0.4) of the opposite edge. The rotation (about
/// z by 30, y by 25, x by 15 degrees) aligns no face or edge with the grid; the
/// result is centred and scaled so that its bounding box has half-extent 1.
struct CubeSpheres
{
  struct Ball
  {
    Point<3> C;
    double R;
  };
  Ball Balls[3] = { { { 0.0, 0.4, 0.4 }, 0.25 }, { { 0.4, -0.4, -0.4 }, 0.15 }, { { -0.4, -0.4, -0.4 }, 0.15 } };
  double Rot[3][3]{};     ///< object frame -> world
  Point<3> Centre{};      ///< world bounding-box centre (before scaling)
  double Scale = 1.0;     ///< world half-extent

  CubeSpheres()
  {
    const double a = 30.0 * Pi / 180.0, b = 25.0 * Pi / 180.0, c = 15.0 * Pi / 180.0;
    const double rz[3][3] = { { std::cos(a), -std::sin(a), 0 }, { std::sin(a), std::cos(a), 0 }, { 0, 0, 1 } };
    const double ry[3][3] = { { std::cos(b), 0, std::sin(b) }, { 0, 1, 0 }, { -std::sin(b), 0, std::cos(b) } };
    const double rx[3][3] = { { 1, 0, 0 }, { 0, std::cos(c), -std::sin(c) }, { 0, std::sin(c), std::cos(c) } };
    double t[3][3]{};
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        for (int k = 0; k < 3; ++k)
        {
          t[i][j] += rz[i][k] * ry[k][j];
        }
      }
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        for (int k = 0; k < 3; ++k)
        {
          this->Rot[i][j] += t[i][k] * rx[k][j];
        }
      }
    }
  }

  /// Signed distance in the object frame: min of the four (exact outside the
  /// union; inside, near the junction curves, an under-estimate of |phi*|).
  double objectSdf(const Point<3>& p) const
  {
    double q[3];
    for (int a = 0; a < 3; ++a)
    {
      q[a] = std::fabs(p[a]) - 0.4;
    }
    const double outside = std::sqrt(std::pow(std::max(q[0], 0.0), 2) + std::pow(std::max(q[1], 0.0), 2) +
      std::pow(std::max(q[2], 0.0), 2));
    double s = outside + std::min(std::max(q[0], std::max(q[1], q[2])), 0.0);
    for (const Ball& b : this->Balls)
    {
      s = std::min(s, std::sqrt(std::pow(p[0] - b.C[0], 2) + std::pow(p[1] - b.C[1], 2) + std::pow(p[2] - b.C[2], 2)) - b.R);
    }
    return s;
  }

  Point<3> toWorld(const Point<3>& p) const
  {
    Point<3> w{};
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        w[i] += this->Rot[i][j] * p[j];
      }
      w[i] = (w[i] - this->Centre[i]) / this->Scale;
    }
    return w;
  }

  /// Exact SDF at a point of the benchmark's (unit-box) frame.
  double sdf(const Point<3>& x) const
  {
    Point<3> w, p{};
    for (int i = 0; i < 3; ++i)
    {
      w[i] = x[i] * this->Scale + this->Centre[i];
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        p[i] += this->Rot[j][i] * w[j]; // R^T
      }
    }
    return this->objectSdf(p) / this->Scale;
  }

  /// Quasi-uniform samples of the union's surface with spacing s: cell-centred
  /// k x k lattices on the cube faces, Fibonacci points on the spheres (counts
  /// proportional to area, the first sphere's count adjusted by `extra`),
  /// keeping only the points on the union's boundary.
  std::vector<Point<3>> sample(double s, int extra) const
  {
    std::vector<Point<3>> out;
    const int k = std::max(1, static_cast<int>(std::lround(0.8 / s)));
    for (int axis = 0; axis < 3; ++axis)
    {
      for (int side = -1; side <= 1; side += 2)
      {
        for (int i = 0; i < k; ++i)
        {
          for (int j = 0; j < k; ++j)
          {
            Point<3> p{};
            p[axis] = 0.4 * side;
            p[(axis + 1) % 3] = -0.4 + (i + 0.5) * 0.8 / k;
            p[(axis + 2) % 3] = -0.4 + (j + 0.5) * 0.8 / k;
            bool hidden = false;
            for (const Ball& b : this->Balls)
            {
              hidden = hidden ||
                std::pow(p[0] - b.C[0], 2) + std::pow(p[1] - b.C[1], 2) + std::pow(p[2] - b.C[2], 2) < b.R * b.R;
            }
            if (!hidden)
            {
              out.push_back(p);
            }
          }
        }
      }
    }
    for (int bi = 0; bi < 3; ++bi)
    {
      const Ball& b = this->Balls[bi];
      const int n = std::max(4, static_cast<int>(std::lround(4.0 * Pi * b.R * b.R / (s * s))) + (bi == 0 ? extra : 0));
      for (int m = 0; m < n; ++m)
      {
        const double z = 1.0 - 2.0 * (m + 0.5) / n;
        const double r = std::sqrt(1.0 - z * z);
        const double phi = 2.399963229728653 * m;
        const Point<3> p = { b.C[0] + b.R * r * std::cos(phi), b.C[1] + b.R * r * std::sin(phi), b.C[2] + b.R * z };
        // Drop points inside the cube or another ball (strictly).
        bool hidden = std::fabs(p[0]) < 0.4 && std::fabs(p[1]) < 0.4 && std::fabs(p[2]) < 0.4;
        for (int bj = 0; bj < 3; ++bj)
        {
          const Ball& o = this->Balls[bj];
          hidden = hidden ||
            (bj != bi &&
              std::pow(p[0] - o.C[0], 2) + std::pow(p[1] - o.C[1], 2) + std::pow(p[2] - o.C[2], 2) < o.R * o.R);
        }
        if (!hidden)
        {
          out.push_back(p);
        }
      }
    }
    return out;
  }

  /// 2346 points (4.5.4), mapped to the unit box.
  sltk::PointCloud<3> cloud(int target)
  {
    // Bisection on the spacing for a count just above the target, then trim
    // the first sphere's Fibonacci count to hit it exactly where possible.
    double lo = 0.005, hi = 0.2;
    for (int it = 0; it < 60; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      (static_cast<int>(this->sample(mid, 0).size()) > target ? lo : hi) = mid;
    }
    std::vector<Point<3>> pts = this->sample(lo, 0);
    for (int extra = 0; extra > -200 && static_cast<int>(pts.size()) > target; --extra)
    {
      pts = this->sample(lo, extra - 1);
    }
    this->Centre = { 0, 0, 0 };
    this->Scale = 1.0;
    std::vector<Point<3>> world;
    for (const auto& p : pts)
    {
      world.push_back(this->toWorld(p));
    }
    Point<3> mn = world[0], mx = world[0];
    for (const auto& w : world)
    {
      for (int a = 0; a < 3; ++a)
      {
        mn[a] = std::min(mn[a], w[a]);
        mx[a] = std::max(mx[a], w[a]);
      }
    }
    double half = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      this->Centre[a] = 0.5 * (mn[a] + mx[a]);
      half = std::max(half, 0.5 * (mx[a] - mn[a]));
    }
    this->Scale = half;
    sltk::PointCloud<3> c;
    for (const auto& p : pts)
    {
      c.Points.push_back(this->toWorld(p));
    }
    return c;
  }
};

/// E_2 of the exact curve/surface (4.1) with p = 2: sqrt(sum w |d_P(x)|^2)
/// over a fine quadrature (x, w) of it, d_P by brute force. The thesis quotes
/// about 7.10e-2 for the circle (4.5.3, the dashed line of Fig. 4.7).
template <int D>
double surfaceEnergy(const sltk::PointCloud<D>& cloud, const std::vector<std::pair<Point<D>, double>>& quadrature)
{
  double sum = 0.0;
  for (const auto& q : quadrature)
  {
    double best = 1e300;
    for (const auto& p : cloud.Points)
    {
      double d2 = 0.0;
      for (int a = 0; a < D; ++a)
      {
        d2 += (q.first[a] - p[a]) * (q.first[a] - p[a]);
      }
      best = std::min(best, d2);
    }
    sum += q.second * best;
  }
  return std::sqrt(sum);
}

std::vector<std::pair<Point<2>, double>> circleQuadrature(int n)
{
  std::vector<std::pair<Point<2>, double>> q;
  for (int k = 0; k < n; ++k)
  {
    const double t = 2.0 * Pi * (k + 0.5) / n;
    q.push_back({ { std::cos(t), std::sin(t) }, 2.0 * Pi / n });
  }
  return q;
}

std::vector<std::pair<Point<2>, double>> squareQuadrature(int perSide)
{
  const Point<2> corners[4] = { { 1.0, 0.0 }, { 0.0, 1.0 }, { -1.0, 0.0 }, { 0.0, -1.0 } };
  std::vector<std::pair<Point<2>, double>> q;
  for (int s = 0; s < 4; ++s)
  {
    const Point<2>& a = corners[s];
    const Point<2>& b = corners[(s + 1) % 4];
    for (int k = 0; k < perSide; ++k)
    {
      const double t = (k + 0.5) / perSide;
      q.push_back({ { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) }, std::sqrt(2.0) / perSide });
    }
  }
  return q;
}

std::vector<std::pair<Point<3>, double>> sphereQuadrature(int n)
{
  std::vector<std::pair<Point<3>, double>> q;
  for (int k = 0; k < n; ++k)
  {
    const double z = 1.0 - 2.0 * (k + 0.5) / n;
    const double r = std::sqrt(1.0 - z * z);
    q.push_back({ { r * std::cos(2.399963229728653 * k), r * std::sin(2.399963229728653 * k), z }, 4.0 * Pi / n });
  }
  return q;
}

// ---------------------------------------------------------------------------
// L1 errors against the exact SDF (4.5.1)
// ---------------------------------------------------------------------------
template <int D>
std::pair<double, double> l1Errors(const sltk::GridField<D>& phi, const Sdf<D>& exact, double gammaFactor)
{
  const auto& g = phi.spec();
  const double gamma = gammaFactor * g.Spacing[0];
  double cell = 1.0;
  for (int a = 0; a < D; ++a)
  {
    cell *= g.Spacing[a];
  }
  double cut = 0.0, band = 0.0;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    std::array<sltk::Index, D> i{};
    Point<D> x{};
    sltk::Index rest = k;
    for (int a = 0; a < D; ++a)
    {
      i[a] = rest % g.Dims[a];
      rest /= g.Dims[a];
      x[a] = g.coordinate(a, i[a]);
    }
    const double e = exact(x);
    const double v = phi(i);
    cut += std::fabs(v - std::max(-gamma, std::min(gamma, e)));
    if (std::fabs(e) < gamma)
    {
      band += std::fabs(v - e);
    }
  }
  return { cut * cell, band * cell };
}

// ---------------------------------------------------------------------------
// Options
// ---------------------------------------------------------------------------
struct Args
{
  std::vector<std::string> Cases;
  std::vector<std::string> Interps;
  int Threads = 1;
  std::string Tables = "/work/shared/reference/thesis_tables.json";
  std::string Data = "/work/shared/data/clouds";
  bool Scans = false;
  double Cdx = NaN;
  double Kp = NaN;
  int Runs = 0;
  bool Log = false;
  double Tolerance = NaN; ///< threshold of (4.33); NaN: the library's 1e-4
  bool FinalOnly = false; ///< synthetic cases: one R-run call, L1 of run R only
  double Noise = 0.1;     ///< sigma of the noisy cases: "10% noise" on the unit circle / sphere (withNoise)
  int Padding = -1;       ///< cells of padding per side; < 0: the library's default
};

std::vector<std::string> split(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
  {
    if (!item.empty())
    {
      out.push_back(item);
    }
  }
  return out;
}

bool interpolatorOf(const std::string& name, sltk::InterpolatorKind& kind, std::string& thesisKey)
{
  thesisKey = "";
  if (name == "q1")
  {
    kind = sltk::InterpolatorKind::Q1;
    thesisKey = "Q1";
  }
  else if (name == "weno3" || name == "weno")
  {
    kind = sltk::InterpolatorKind::Weno3;
    thesisKey = "WENO";
  }
  else if (name == "cweno")
  {
    kind = sltk::InterpolatorKind::Cweno;
  }
  else if (name == "cwenoz")
  {
    kind = sltk::InterpolatorKind::CwenoZ;
  }
  else
  {
    return false;
  }
  return true;
}

// ---------------------------------------------------------------------------
// Synthetic tables 4.2-4.5
// ---------------------------------------------------------------------------
template <int D>
struct SyntheticCase
{
  std::string Name;
  std::string TableKey;
  std::string Title;
  sltk::PointCloud<D> Cloud;
  Sdf<D> Exact;
  int Runs = 3;
  double SurfaceEnergy = NaN; ///< E_2 of the exact shape, when computed
};

template <int D>
void runSynthetic(const SyntheticCase<D>& c, const std::vector<std::string>& interps, const Args& args,
  const ThesisTables& thesis, const sltk::Context& ctx, const std::vector<sltk::RunParameters>& schedule = {})
{
  const int runs = args.Runs > 0 ? args.Runs : c.Runs;
  std::printf("\n=== %s: %lld points, %d runs, C_dx = %g, K_P = %g ===\n", c.Title.c_str(),
    static_cast<long long>(c.Cloud.size()), runs, std::isfinite(args.Cdx) ? args.Cdx : 1.0,
    std::isfinite(args.Kp) ? args.Kp : 2.0);
  if (std::isfinite(c.SurfaceEnergy))
  {
    std::printf("E_2 of the exact shape (4.1), fine quadrature: %.4e\n", c.SurfaceEnergy);
  }
  const auto thesisGrid = c.TableKey.empty() ? std::vector<std::string>{} : thesis.tokens({ c.TableKey, "grid" });
  for (size_t r = 0; r < schedule.size(); ++r)
  {
    std::printf("run %zu%s: p = %g, eta = %g\n", r + 1, r + 1 == schedule.size() ? " and later" : "", schedule[r].P,
      schedule[r].Eta);
  }
  for (const std::string& name : interps)
  {
    sltk::InterpolatorKind kind{};
    std::string key;
    if (!interpolatorOf(name, kind, key))
    {
      std::printf("unknown interpolator %s\n", name.c_str());
      continue;
    }
    if (c.TableKey.empty())
    {
      key.clear(); // no thesis table for this case
    }
    sltk::ReconstructionOptions options;
    options.Interpolator = kind;
    options.Schedule = schedule; // empty: Table 4.1
    if (std::isfinite(args.Tolerance))
    {
      options.Tolerance = args.Tolerance;
    }
    if (std::isfinite(args.Cdx))
    {
      options.CellSizeFactor = args.Cdx;
    }
    if (std::isfinite(args.Kp))
    {
      options.OutsideThresholdFactor = args.Kp;
    }
    if (args.Padding >= 0)
    {
      options.Padding = args.Padding;
    }
    const std::vector<double> tl1 = key.empty() ? std::vector<double>{} : thesis.numbers({ c.TableKey, key, "l1" });
    const std::vector<double> ten = key.empty() ? std::vector<double>{} : thesis.numbers({ c.TableKey, key, "energy" });
    const std::vector<double> terr =
      key.empty() ? std::vector<double>{} : thesis.numbers({ c.TableKey, key, "err_cloud" });
    const std::vector<double> tit =
      key.empty() ? std::vector<double>{} : thesis.numbers({ c.TableKey, "iterations_runs_1_3", key });
    const std::vector<double> tsec =
      key.empty() ? std::vector<double>{} : thesis.numbers({ c.TableKey, "seconds_runs_1_3", key });

    // Runs = 1..R: run r of the R-run call is the last run of the r-run call
    // (checked below on grid, iterations and Err_P). --final-only: the R-run call
    // alone, L1 of the last run only.
    std::vector<std::pair<double, double>> l1(static_cast<size_t>(runs), { NaN, NaN });
    std::vector<sltk::RunRecord<D>> last(static_cast<size_t>(runs));
    sltk::ReconstructionResult<D> full;
    double fullSeconds = 0.0;
    bool failed = false;
    for (int r = args.FinalOnly ? runs : 1; r <= runs && !failed; ++r)
    {
      options.Runs = r;
      sltk::ReconstructionResult<D> res;
      const auto t0 = std::chrono::steady_clock::now();
      const sltk::Status s = sltk::reconstruct(c.Cloud, options, ctx, res);
      const double wall = seconds(t0);
      if (!s.isOk())
      {
        std::printf("%s: reconstruction with %d runs failed: %s\n", name.c_str(), r, s.message().c_str());
        failed = true;
        break;
      }
      l1[static_cast<size_t>(r - 1)] = l1Errors<D>(res.SignedDistance, c.Exact, options.GammaFactor);
      last[static_cast<size_t>(r - 1)] = res.Runs.back();
      if (r == runs)
      {
        full = std::move(res);
        fullSeconds = wall;
      }
    }
    if (failed)
    {
      continue;
    }
    if (args.FinalOnly)
    {
      std::copy(full.Runs.begin(), full.Runs.end(), last.begin());
    }
    std::printf("\n--- %s (h_P = %.4g) ---\n", name.c_str(), full.CloudSpacing);
    std::printf("%-2s %-12s %-12s %5s %5s | %-9s %-9s %-9s %-14s | %-9s %-9s %-14s | %-9s %-9s %-14s | %8s\n", "r",
      "grid", "thesis grid", "iter", "th.it", "L1(cut)", "L1(band)", "thesis", "ratio 1.5?", "E_2", "thesis",
      "ratio 1.5?", "Err_P", "thesis", "ratio 1.5?", "seconds");
    bool consistent = true;
    for (int r = 0; r < runs; ++r)
    {
      const auto& run = full.Runs[static_cast<size_t>(r)];
      const auto& alone = last[static_cast<size_t>(r)];
      consistent = consistent && gridText<D>(alone.Grid) == gridText<D>(run.Grid) &&
        alone.Iterations == run.Iterations && alone.CloudError == run.CloudError;
      const size_t i = static_cast<size_t>(r);
      const double tIt = at(tit, i);
      std::printf("%-2d %-12s %-12s %5d %5s | %s %s %s %s | %s %s %s | %s %s %s | %8.3f\n", r + 1,
        gridText<D>(run.Grid).c_str(), at(thesisGrid, i).c_str(), run.Iterations,
        std::isfinite(tIt) ? std::to_string(static_cast<int>(tIt)).c_str() : "-", sci(l1[i].first).c_str(),
        sci(l1[i].second).c_str(), sci(at(tl1, i)).c_str(), compare(l1[i].first, at(tl1, i), false).c_str(),
        sci(run.Energy).c_str(), sci(at(ten, i)).c_str(), compare(run.Energy, at(ten, i), true).c_str(),
        sci(run.CloudError).c_str(), sci(at(terr, i)).c_str(), compare(run.CloudError, at(terr, i), false).c_str(),
        run.Seconds);
    }
    double first3 = 0.0;
    for (int r = 0; r < std::min(runs, 3); ++r)
    {
      first3 += full.Runs[static_cast<size_t>(r)].Seconds;
    }
    std::printf("wall %.3f s for %d runs (runs 1-3: %.3f s; thesis runs 1-3: %s s)%s\n", fullSeconds, runs, first3,
      tsec.empty() ? "-" : sci(tsec[0]).c_str(),
      consistent ? "" : "  NOTE: run r of the full call differs from the r-run call");
  }
}

// ---------------------------------------------------------------------------
// Real scans (4.5.5)
// ---------------------------------------------------------------------------
struct ScanCase
{
  std::string Name;
  std::string File;
  std::string TableKey; ///< "" when the thesis has no per-run table
  std::string GridKey;  ///< key of table_4_8_grids
  double Cdx = 1.0;
  double Kp = 2.0;
  sltk::InitialGuess Guess = sltk::InitialGuess::OutsideMarking;
  int MaxIterations = 100;
  std::string Note;
};

bool readXyz(const std::string& path, sltk::PointCloud<3>& cloud)
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
    Point<3> p{};
    if (s >> p[0] >> p[1] >> p[2])
    {
      cloud.Points.push_back(p);
    }
  }
  return !cloud.Points.empty();
}

void runScan(const ScanCase& c, const std::vector<std::string>& interps, const Args& args, const ThesisTables& thesis,
  const sltk::Context& ctx)
{
  sltk::PointCloud<3> cloud;
  if (!readXyz(args.Data + "/" + c.File, cloud))
  {
    std::printf("\n=== %s: cannot read %s/%s, skipped ===\n", c.Name.c_str(), args.Data.c_str(), c.File.c_str());
    return;
  }
  const sltk::Box<3> box = sltk::boundingBox(cloud);
  double scale = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    scale = std::max(scale, 0.5 * box.extent(a));
  }
  const double cdx = std::isfinite(args.Cdx) ? args.Cdx : c.Cdx;
  const double kp = std::isfinite(args.Kp) ? args.Kp : c.Kp;
  const int runs = args.Runs > 0 ? args.Runs : 3;
  std::printf("\n=== %s: %s, %lld points, unit-box scale %.6g, C_dx = %g, K_P = %g, guess %s, %d runs %s===\n",
    c.Name.c_str(), c.File.c_str(), static_cast<long long>(cloud.size()), scale, cdx, kp,
    c.Guess == sltk::InitialGuess::OutsideMarking ? "outside marking" : "bounding ellipsoid", runs, c.Note.c_str());
  const auto thesisGrid = thesis.tokens({ "table_4_8_grids", c.GridKey });
  const auto thesisMinutes = thesis.numbers({ "table_4_9_minutes", c.GridKey });
  for (const std::string& name : interps)
  {
    sltk::InterpolatorKind kind{};
    std::string key;
    if (!interpolatorOf(name, kind, key))
    {
      std::printf("unknown interpolator %s\n", name.c_str());
      continue;
    }
    sltk::ReconstructionOptions options;
    options.Runs = runs;
    options.Interpolator = kind;
    options.CellSizeFactor = cdx;
    options.OutsideThresholdFactor = kp;
    options.Guess = c.Guess;
    options.MaxIterations = c.MaxIterations;
    const bool table = !c.TableKey.empty() && !key.empty();
    const std::vector<double> ten = table ? thesis.numbers({ c.TableKey, key, "energy" }) : std::vector<double>{};
    const std::vector<double> terr = table ? thesis.numbers({ c.TableKey, key, "err_cloud" }) : std::vector<double>{};
    sltk::ReconstructionResult<3> res;
    const auto t0 = std::chrono::steady_clock::now();
    const sltk::Status s = sltk::reconstruct(cloud, options, ctx, res);
    const double wall = seconds(t0);
    std::printf("\n--- %s (h_P = %.4g user, %.4g unit box)%s ---\n", name.c_str(), res.CloudSpacing,
      res.CloudSpacing / scale, s.isOk() ? "" : (" FAILED: " + s.message()).c_str());
    std::printf("%-2s %-12s %-12s %5s | %-9s %-9s %-14s | %-9s %-9s %-14s | %8s %9s %10s\n", "r", "grid",
      "thesis grid", "iter", "E_2 unit", "thesis", "ratio 1.5?", "Err_P unit", "thesis", "ratio 1.5?", "seconds",
      "s/iter", "mean band");
    const double energyScale = std::pow(scale, 2.0); // E_2 ~ length^((2 + d - 1) / 2), d = 3
    for (size_t r = 0; r < res.Runs.size(); ++r)
    {
      const auto& run = res.Runs[r];
      const double e = run.Energy / energyScale;
      const double err = run.CloudError / scale;
      std::printf("%-2zu %-12s %-12s %5d | %s %s %s | %s %s %s | %8.2f %9.4f %10lld\n", r + 1,
        gridText<3>(run.Grid).c_str(), at(thesisGrid, r).c_str(), run.Iterations, sci(e).c_str(),
        sci(at(ten, r)).c_str(), compare(e, at(ten, r), true).c_str(), sci(err).c_str(), sci(at(terr, r)).c_str(),
        compare(err, at(terr, r), false).c_str(), run.Seconds, run.Iterations ? run.Seconds / run.Iterations : 0.0,
        static_cast<long long>(run.MeanBandSize));
    }
    const double tmin = key == "Q1" ? at(thesisMinutes, 1) : (key == "WENO" ? at(thesisMinutes, 2) : NaN);
    std::printf("wall %.2f s; peak RSS of the process so far %.1f MiB; thesis %s min on %s MPI ranks\n", wall,
      static_cast<double>(sltk::peakResidentBytes()) / (1024.0 * 1024.0), sci(tmin).c_str(),
      std::isfinite(at(thesisMinutes, 0)) ? std::to_string(static_cast<int>(at(thesisMinutes, 0))).c_str() : "-");
  }
}

/// --log: the library's per-run phase times (distance, initial data, energy, SL step, reinit, metrics).
class PrintLogger : public sltk::Logger
{
public:
  void log(sltk::LogLevel level, const std::string& message) override
  {
    if (level <= sltk::LogLevel::Info)
    {
      std::printf("  [sltk] %s\n", message.c_str());
    }
  }
};

int usage()
{
  std::printf("usage: sltkBenchReconstruction [--case NAME[,NAME...]] [--interp q1,weno3,cweno,cwenoz] "
              "[--threads N] [--tables PATH] [--data DIR] [--scans] [--cdx C] [--kp K] [--runs R] [--noise SIGMA]\n"
              "         [--tolerance T] [--final-only] [--padding P] [--log]\n"
              "  synthetic cases: circle square sphere cubespheres (default), noisycircle noisysphere\n"
              "  scans (--scans): bunny teapot fandisk knot knotellipse frog\n");
  return 2;
}
} // namespace

int main(int argc, char** argv)
{
  Args args;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--case" && hasValue)
    {
      for (const auto& c : split(argv[++i]))
      {
        args.Cases.push_back(c);
      }
    }
    else if (a == "--interp" && hasValue)
    {
      args.Interps = split(argv[++i]);
    }
    else if (a == "--threads" && hasValue)
    {
      args.Threads = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--tables" && hasValue)
    {
      args.Tables = argv[++i];
    }
    else if (a == "--data" && hasValue)
    {
      args.Data = argv[++i];
    }
    else if (a == "--cdx" && hasValue)
    {
      args.Cdx = std::atof(argv[++i]);
    }
    else if (a == "--kp" && hasValue)
    {
      args.Kp = std::atof(argv[++i]);
    }
    else if (a == "--runs" && hasValue)
    {
      args.Runs = std::atoi(argv[++i]);
    }
    else if (a == "--final-only")
    {
      args.FinalOnly = true;
    }
    else if (a == "--tolerance" && hasValue)
    {
      args.Tolerance = std::atof(argv[++i]);
    }
    else if (a == "--padding" && hasValue)
    {
      args.Padding = std::atoi(argv[++i]);
    }
    else if (a == "--noise" && hasValue)
    {
      args.Noise = std::atof(argv[++i]);
    }
    else if (a == "--scans")
    {
      args.Scans = true;
    }
    else if (a == "--log")
    {
      args.Log = true;
    }
    else
    {
      return usage();
    }
  }
  if (args.Cases.empty())
  {
    args.Cases = args.Scans ? std::vector<std::string>{ "bunny", "teapot", "fandisk", "knot", "knotellipse", "frog" }
                            : std::vector<std::string>{ "circle", "square", "sphere", "cubespheres" };
  }
  const ThesisTables thesis(args.Tables);
  std::printf("SLTK reconstruction benchmark (thesis Algorithm 1, Tables 4.2-4.9); threads %d; thesis tables: %s\n",
    args.Threads, thesis.loaded() ? args.Tables.c_str() : "not found (comparison columns left empty)");
  sltk::ThreadPool pool(args.Threads);
  sltk::Context ctx;
  ctx.Executor = args.Threads > 1 ? &pool : nullptr;
  PrintLogger logger;
  if (args.Log)
  {
    ctx.Log = &logger;
  }
  const std::vector<std::string> interps2 = args.Interps.empty() ? std::vector<std::string>{ "q1", "weno3", "cweno" }
                                                                 : args.Interps;
  const std::vector<std::string> interps3 = args.Interps.empty() ? std::vector<std::string>{ "q1", "weno3" }
                                                                 : args.Interps;
  for (const std::string& name : args.Cases)
  {
    if (name == "circle")
    {
      // Table 4.2: five runs (grids 42 ... 344), Table 4.1 schedule.
      runSynthetic<2>({ name, "table_4_2_circle_64pts", "Table 4.2 circle", circleCloud(), circleSdf, 5,
                        surfaceEnergy<2>(circleCloud(), circleQuadrature(64000)) }, interps2,
        args, thesis, ctx);
    }
    else if (name == "square")
    {
      // Table 4.3: five runs (grids 30 ... 153).
      runSynthetic<2>({ name, "table_4_3_square_24pts", "Table 4.3 square rotated 45 degrees", squareCloud(),
                        squareSdf, 5, surfaceEnergy<2>(squareCloud(), squareQuadrature(16000)) },
        interps2, args, thesis, ctx);
    }
    else if (name == "noisycircle")
    {
      // Fig. 4.8: 10% noise, WENO, eta raised in the final run; eta = 5 gave the best L1 error,
      // eta = 35 degenerates. Errors against the exact circle's SDF.
      for (const double eta : { 1.0, 5.0, 10.0, 35.0 })
      {
        runSynthetic<2>({ name, "", "Fig. 4.8 circle, 10% noise, final eta = " + fmt(eta),
                          withNoise(circleCloud(), args.Noise, 2024), circleSdf, 3, NaN },
          interps2, args, thesis, ctx, scheduleWithFinalEta(eta));
      }
    }
    else if (name == "noisysphere")
    {
      // Fig. 4.11 second row: 10% noise, eta = 10 in the last run (and eta = 1 for comparison).
      for (const double eta : { 1.0, 10.0 })
      {
        runSynthetic<3>({ name, "", "Fig. 4.11 sphere, 10% noise, final eta = " + fmt(eta),
                          withNoise(icosphereCloud(4), args.Noise, 2024), sphereSdf, 3, NaN },
          interps3, args, thesis, ctx, scheduleWithFinalEta(eta));
      }
    }
    else if (name == "sphere")
    {
      // Table 4.4: the usual three runs on the 2562-point icosphere.
      runSynthetic<3>({ name, "table_4_4_sphere_2562pts", "Table 4.4 sphere (icosphere, 4 subdivisions)",
                        icosphereCloud(4), sphereSdf, 3,
                        surfaceEnergy<3>(icosphereCloud(4), sphereQuadrature(40000)) },
        interps3, args, thesis, ctx);
    }
    else if (name == "cubespheres")
    {
      CubeSpheres cs;
      sltk::PointCloud<3> cloud = cs.cloud(2346);
      const CubeSpheres frozen = cs;
      runSynthetic<3>({ name, "table_4_5_cube_spheres_2346pts", "Table 4.5 Cube&Spheres", std::move(cloud),
                        [frozen](const Point<3>& x) { return frozen.sdf(x); }, 3, NaN },
        interps3, args, thesis, ctx);
    }
    else if (name == "bunny")
    {
      // 4.5.5 / Table 4.7: C_dx = 2, K_P = 10 (holes in the bottom).
      runScan({ name, "bunny/bunny.xyz", "table_4_7_bunny_35947pts", "Bunny", 2.0, 10.0,
                sltk::InitialGuess::OutsideMarking, 100, "" },
        interps3, args, thesis, ctx);
    }
    else if (name == "teapot")
    {
      // teapot.obj is an open surface (1036 boundary edges): with K_P = 2 the outside marking
      // leaks inside and the WENO run 3 loses its front; K_P = 10 as for the thesis's scans with holes.
      runScan({ name, "teapot/teapot.xyz", "", "Teapot", 1.0, 10.0, sltk::InitialGuess::OutsideMarking, 100,
                "(3644-point mesh vertices; thesis cloud unknown) " },
        interps3, args, thesis, ctx);
    }
    else if (name == "fandisk")
    {
      // 4.5.4 "mechanical part": the thesis's 4102-point cloud is not available; fandisk is a substitute.
      runScan({ name, "fandisk/fandisk.xyz", "", "Mechanical part", 1.0, 2.0, sltk::InitialGuess::OutsideMarking,
                100, "(substitute for the 4102-point mechanical part: final Err_P Q1 7.59e-03, WENO 3.74e-03) " },
        interps3, args, thesis, ctx);
    }
    else if (name == "knot")
    {
      // 4.5.4: C_dx = 2, K_P = 10, usual initial data (thesis: 61, 23, 10 iterations, 10000 points).
      runScan({ name, "knot/knot1.xyz", "", "Knot", 2.0, 10.0, sltk::InitialGuess::OutsideMarking, 100,
                "(CGAL knot1, 3200 points; thesis 10000-point knot: 61/23/10 iterations) " },
        interps3, args, thesis, ctx);
    }
    else if (name == "knotellipse")
    {
      // 4.5.4: ellipsoid initial guess, at most 200 iterations (thesis: 120, 24, 14 iterations).
      runScan({ name, "knot/knot1.xyz", "", "Knot (ellipse)", 2.0, 10.0, sltk::InitialGuess::BoundingEllipsoid, 200,
                "(ellipsoid guess; thesis: 120/24/14 iterations) " },
        interps3, args, thesis, ctx);
    }
    else if (name == "frog")
    {
      // 4.5.5 / Table 4.6: K_P = 10 (the thesis's frog has 2512 points; ours 5429, another scan).
      runScan({ name, "frog/frog.xyz", "table_4_6_frog_2512pts", "Frog", 1.0, 10.0,
                sltk::InitialGuess::OutsideMarking, 100, "(5429 points, not the thesis's 2512-point frog) " },
        interps3, args, thesis, ctx);
    }
    else
    {
      std::printf("unknown case %s\n", name.c_str());
      return usage();
    }
  }
  return 0;
}
