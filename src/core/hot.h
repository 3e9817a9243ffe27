// VERIDEM_HOT_INLINE: force inlining of a small physics function into the contact loops. The
// contact law is called from two loops (pairs, walls); without it GCC keeps one out-of-line copy,
// and every contact then pays a call plus the zeroing of ~200 bytes of argument structs.
#pragma once

#if defined(__GNUC__)
#define VERIDEM_HOT_INLINE [[gnu::always_inline]] inline
#else
#define VERIDEM_HOT_INLINE inline
#endif
