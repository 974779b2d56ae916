// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/core/Status.h"

#include <gtest/gtest.h>

namespace
{
sltk::Status failsWhenNegative(int v)
{
  if (v < 0)
  {
    return sltk::Status::invalidArgument("v = " + std::to_string(v) + " must be >= 0");
  }
  return sltk::Status::ok();
}

sltk::Status chain(int v)
{
  SLTK_RETURN_IF_ERROR(failsWhenNegative(v));
  return sltk::Status::notImplemented("reached the end");
}
} // namespace

TEST(Status, DefaultIsOk)
{
  sltk::Status s;
  EXPECT_TRUE(s.isOk());
  EXPECT_TRUE(static_cast<bool>(s));
  EXPECT_EQ(s.toString(), "ok");
}

TEST(Status, CarriesCodeAndMessage)
{
  auto s = sltk::Status::outOfMemory("grid of 1e12 nodes");
  EXPECT_FALSE(s.isOk());
  EXPECT_EQ(s.code(), sltk::StatusCode::OutOfMemory);
  EXPECT_EQ(s.toString(), "out of memory: grid of 1e12 nodes");
}

TEST(Status, ReturnIfErrorPropagatesFirstFailure)
{
  EXPECT_EQ(chain(-1).code(), sltk::StatusCode::InvalidArgument);
  EXPECT_EQ(chain(-1).message(), "v = -1 must be >= 0");
  EXPECT_EQ(chain(1).code(), sltk::StatusCode::NotImplemented);
}

TEST(Status, EveryCodeHasAName)
{
  for (int c = 0; c <= static_cast<int>(sltk::StatusCode::IOError); ++c)
  {
    EXPECT_STRNE(sltk::toString(static_cast<sltk::StatusCode>(c)), "unknown");
  }
}
