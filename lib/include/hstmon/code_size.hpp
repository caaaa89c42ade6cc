#pragma once
/// @file code_size.hpp
/// Inlining policy by target. On microcontrollers (Arm M-profile) flash is the scarce
/// resource: a helper called from every RK4 stage is kept out of line there (one copy,
/// a call per use), while hosts and application processors inline it for speed. The
/// arithmetic is identical either way, so results do not depend on the choice.
/// Override with -DHSTMON_FLASH_LEAN=0 or 1.

#ifndef HSTMON_FLASH_LEAN
#if defined(__ARM_ARCH_PROFILE) && (__ARM_ARCH_PROFILE == 'M')
#define HSTMON_FLASH_LEAN 1
#else
#define HSTMON_FLASH_LEAN 0
#endif
#endif

/// The models' fused usual tick (CompiledModel and ThesisReducedModel kHasUsualTick; the
/// observer takes it: observer.hpp), a switch of its own: on where flash is not scarce (the
/// default follows HSTMON_FLASH_LEAN), and a microcontroller image may turn it on with
/// -DHSTMON_USUAL_TICK=1 while its helpers stay out of line. The results are the general
/// tick's bit for bit either way; it costs flash (the fused tick beside the general one).
#ifndef HSTMON_USUAL_TICK
#if HSTMON_FLASH_LEAN
#define HSTMON_USUAL_TICK 0
#else
#define HSTMON_USUAL_TICK 1
#endif
#endif

/// Marks a function to keep out of line where HSTMON_FLASH_LEAN is 1 (GCC, Clang).
#if HSTMON_FLASH_LEAN && defined(__GNUC__)
#define HSTMON_LEAN_NOINLINE __attribute__((noinline))
#else
#define HSTMON_LEAN_NOINLINE
#endif

/// Out of line (GCC, Clang): a rare per-channel path, so the nominal loop calling it stays
/// small enough to unroll (HSTMON_UNROLL, GCC: the per-channel loop overhead is ~1/4 of the
/// nominal tick outside the observer on the Cortex-M4F). Override with -DHSTMON_NOINLINE=.
#ifndef HSTMON_NOINLINE
#if defined(__GNUC__)
#define HSTMON_NOINLINE __attribute__((noinline))
#else
#define HSTMON_NOINLINE
#endif
#endif

/// Out of line and cold (GCC, Clang): a path taken rarely enough that the usual tick's
/// code should neither inline it nor lay it out beside the hot path.
#ifndef HSTMON_COLD
#if defined(__GNUC__)
#define HSTMON_COLD __attribute__((noinline, cold))
#else
#define HSTMON_COLD
#endif
#endif

/// Full unrolling of a loop whose trip count is a compile-time constant (GCC; elsewhere the
/// compiler's choice): the per-channel and per-state loops of a tick, whose overhead is a
/// large share of it on the Cortex-M4F. Override with -DHSTMON_UNROLL=.
#ifndef HSTMON_UNROLL
#if defined(__GNUC__) && !defined(__clang__)
#define HSTMON_UNROLL _Pragma("GCC unroll 8")
#else
#define HSTMON_UNROLL
#endif
#endif
