// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file LocalFrame.h
/// Survey coordinates (Documentation/Architecture.md, "The local frame"). Lidar and
/// photogrammetry clouds come in projected coordinates: x and y near 1e5-1e7 with
/// millimetre detail. The reconstruction computes in double, but what follows it works in
/// single precision (VTK's contour filters, PLY and STL files), and at 1e7 a float resolves
/// 1. A cloud far from the origin for its size is therefore reconstructed in a local frame,
/// its coordinates minus a shift, and the front ends put every output back in the user's
/// coordinates in double precision.

#include "sltk/cloud/PointCloud.h"

#include <array>
#include <string>

namespace sltk
{

/// How far from the origin, in extents of the cloud, the centre of its box may lie on
/// an axis before that axis is shifted: within it a float still resolves 1e-6 of the
/// extent (16 x 2^-24), so the clouds of the thesis and the shared clouds (at most 3
/// extents away) are reconstructed exactly as they are given.
inline constexpr double LocalFrameDistance = 16.0;

/// The shift of the local frame of a cloud whose bounding box is `box`: on each axis
/// whose centre lies more than LocalFrameDistance largest extents from the origin, the
/// centre rounded to a multiple of the power of two at or above the largest extent;
/// zero on the other axes. A coordinate minus the shift is then exact in double
/// (Sterbenz's lemma: both lie within a factor 2 of each other), so the local cloud is
/// the user's to the last bit, only moved.
std::array<double, 3> localFrameShift(const Box<3>& box);

/// True when `shift` moves no axis (the cloud is near the origin).
bool isZeroShift(const std::array<double, 3>& shift);

/// Subtracts `shift` from every point of `cloud`.
void moveToLocalFrame(PointCloud<3>& cloud, const std::array<double, 3>& shift);

/// The detail a position in a message keeps, as a fraction of the cloud's extent: a
/// survey cloud at 1e7 with an extent of 100 m is located to the millimetre.
inline constexpr double PositionResolution = 1e-5;

/// The significant digits that print a coordinate of magnitude up to `largest` to
/// PositionResolution of `extent`: at least 6 (a stream's default, enough near the
/// origin), at most 17 (a double's). Six digits would print x = 10000012.345 as 1e+07.
int positionDigits(double largest, double extent);

/// "(x, y, z)" (D coordinates of `p`) with positionDigits for a cloud of `extent`.
std::string formatPosition(const double* p, int dims, double extent);

} // namespace sltk
