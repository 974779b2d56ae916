// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file AlwaysInline.h
/// SLTK_ALWAYS_INLINE: a small function the compiler must inline into its
/// caller, for the inner loops whose callers the compiler would otherwise
/// leave calling it (Documentation/Profile.md: a call that returns a struct
/// through memory stalls on the store that writes it).

#if defined(__GNUC__)
#define SLTK_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define SLTK_ALWAYS_INLINE inline
#endif
