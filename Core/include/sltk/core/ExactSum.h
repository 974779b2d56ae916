// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ExactSum.h
/// The sum of doubles rounded once, to nearest (ties to even), whatever the
/// order of the terms and however they are split over threads or ranks: a
/// fixed-point accumulator wide enough for every finite double (Kulisch's long
/// accumulator), in 32-bit digits held in 64-bit words so that additions need
/// no carries until many have been made. The statistics over a whole cloud
/// spread over ranks (the outlier test's mean and deviation) use it to give
/// the one-rank value on any number of ranks (Documentation/Distributed.md,
/// "Points to their owners").

#include <array>
#include <cstdint>

namespace sltk
{

class Communicator;

class ExactSum
{
public:
  /// Adds x; infinities and NaN make the value infinite or NaN as a plain sum would.
  void add(double x);
  ExactSum& operator+=(const ExactSum& other);
  /// The exact sum of the terms, rounded once to the nearest double.
  double value() const;
  /// Every rank's sum added: the same value on every rank. Collective.
  void reduceOver(const Communicator& comm);

private:
  /// Bit 0 of digit 0 weighs 2^-1074 (the least subnormal); 70 digits of 32 bits
  /// reach above 2^1024 with room for 2^60 terms' carries.
  static constexpr int Digits = 70;
  /// Each addition adds under 2^33 to a word: carry before 2^29 of them.
  static constexpr std::int64_t AddsBetweenCarries = std::int64_t(1) << 29;

  void carry();

  std::array<std::int64_t, Digits> Words{};
  std::int64_t Adds = 0;  ///< additions since the last carry
  double NonFinite = 0.0; ///< the sum of the infinite and NaN terms
};

} // namespace sltk
