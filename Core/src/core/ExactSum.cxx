// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/core/ExactSum.h"

#include "sltk/exec/Communicator.h"

#include <cmath>

namespace sltk
{

namespace
{
constexpr int DigitBits = 32;
constexpr std::int64_t DigitMask = (std::int64_t(1) << DigitBits) - 1;
constexpr int LowestExponent = -1074; ///< the weight of bit 0

/// The number of significant bits of v > 0.
int bitLength(std::uint64_t v)
{
  int n = 0;
  for (; v != 0; v >>= 1)
  {
    ++n;
  }
  return n;
}
} // namespace

void ExactSum::carry()
{
  for (int i = 0; i + 1 < Digits; ++i)
  {
    const std::int64_t c = this->Words[i] >> DigitBits; // floor division: the digit left in [0, 2^32)
    this->Words[i] -= c * (std::int64_t(1) << DigitBits);
    this->Words[i + 1] += c;
  }
  this->Adds = 0;
}

void ExactSum::add(double x)
{
  if (!std::isfinite(x))
  {
    this->NonFinite += x;
    return;
  }
  if (x == 0.0)
  {
    return;
  }
  int exponent = 0;
  const double fraction = std::frexp(std::fabs(x), &exponent); // |x| = fraction 2^exponent, fraction in [0.5, 1)
  std::uint64_t mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53)); // exact: 53 bits
  int position = exponent - 53 - LowestExponent;                                 // the weight of its bit 0
  if (position < 0)                                                              // a subnormal: its low bits are zeros
  {
    mantissa >>= -position;
    position = 0;
  }
  const int digit = position / DigitBits;
  const int shift = position % DigitBits;
  const std::int64_t sign = x < 0.0 ? -1 : 1;
  const std::uint64_t low = (mantissa & static_cast<std::uint64_t>(DigitMask)) << shift; // < 2^63
  const std::uint64_t high = (mantissa >> DigitBits) << shift;                           // < 2^53
  this->Words[digit] += sign * static_cast<std::int64_t>(low & static_cast<std::uint64_t>(DigitMask));
  this->Words[digit + 1] +=
    sign * static_cast<std::int64_t>((low >> DigitBits) + (high & static_cast<std::uint64_t>(DigitMask)));
  this->Words[digit + 2] += sign * static_cast<std::int64_t>(high >> DigitBits);
  if (++this->Adds == AddsBetweenCarries)
  {
    this->carry();
  }
}

ExactSum& ExactSum::operator+=(const ExactSum& other)
{
  ExactSum o = other;
  o.carry();
  this->carry();
  for (int i = 0; i < Digits; ++i)
  {
    this->Words[i] += o.Words[i];
  }
  this->NonFinite += other.NonFinite;
  this->Adds = 2; // digits below 2^33: as after two additions
  return *this;
}

void ExactSum::reduceOver(const Communicator& comm)
{
  this->carry(); // every digit in [0, 2^32) but the last: the ranks' sums stay far below 2^63
  comm.allReduce(this->Words.data(), Digits, ReduceOp::Sum);
  this->NonFinite = comm.allReduce(this->NonFinite, ReduceOp::Sum);
  this->carry();
}

double ExactSum::value() const
{
  if (this->NonFinite != 0.0 || std::isnan(this->NonFinite))
  {
    return this->NonFinite;
  }
  ExactSum v = *this;
  v.carry();
  const bool negative = v.Words[Digits - 1] < 0;
  if (negative)
  {
    for (auto& w : v.Words)
    {
      w = -w;
    }
    v.carry();
  }
  int top = Digits - 1;
  while (top >= 0 && v.Words[top] == 0)
  {
    --top;
  }
  if (top < 0)
  {
    return 0.0;
  }
  const auto bit = [&v](int i) { return (v.Words[i / DigitBits] >> (i % DigitBits)) & 1; };
  const int bits = top * DigitBits + bitLength(static_cast<std::uint64_t>(v.Words[top]));
  double magnitude = 0.0;
  if (bits <= 53) // exact: a subnormal or a small normal
  {
    const std::uint64_t small =
      static_cast<std::uint64_t>(v.Words[0]) | (top > 0 ? static_cast<std::uint64_t>(v.Words[1]) << DigitBits : 0);
    magnitude = std::ldexp(static_cast<double>(small), LowestExponent);
  }
  else
  {
    // The top 53 bits, then round to nearest, ties to even, from the next bit and those below it.
    std::uint64_t kept = 0;
    for (int i = bits - 1; i >= bits - 53; --i)
    {
      kept = (kept << 1) | static_cast<std::uint64_t>(bit(i));
    }
    const int guard = bits - 54;
    bool sticky = false;
    for (int i = guard - 1; i >= 0 && !sticky; --i)
    {
      sticky = bit(i) != 0;
    }
    if (bit(guard) && (sticky || (kept & 1)))
    {
      ++kept;
    }
    magnitude = std::ldexp(static_cast<double>(kept), bits - 53 + LowestExponent);
  }
  return negative ? -magnitude : magnitude;
}

} // namespace sltk
