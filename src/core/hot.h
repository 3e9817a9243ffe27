// VERIDEM_HOT_INLINE: force inlining of a small physics function into the contact loops. The
// contact law is called from two loops (pairs, walls); without it GCC keeps one out-of-line copy,
// and every contact then pays a call plus the zeroing of ~200 bytes of argument structs.
#pragma once

#if defined(__GNUC__)
#define VERIDEM_HOT_INLINE [[gnu::always_inline]] inline
#else
#define VERIDEM_HOT_INLINE inline
#endif

// The same for a lambda (after its parameter list): a lambda inlined into a function of another
// instruction set must be always_inline to be compiled for that set.
#if defined(__GNUC__)
#define VERIDEM_INLINE_LAMBDA __attribute__((always_inline))
#else
#define VERIDEM_INLINE_LAMBDA
#endif
