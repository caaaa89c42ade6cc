#pragma once
/// @file inlining.hpp
/// The circuit engine's inlining controls, shared by the laws, the quasi-steady solve and
/// the generated kernels.

#include "hstmon/code_size.hpp"

/// Inlined into the caller even at -O2's limits: a compiled model's node solves, sweeps
/// and Jacobian become one straight-line function with the full vector in registers.
/// HSTMON_CIRCUIT_LAMBDA_INLINE does the same for a generated node balance's lambda (called
/// from the inline first Newton step and from the bracketed solve).
/// HSTMON_CIRCUIT_NOINLINE keeps an evaluation out of its callers, so that the caller's
/// frame does not carry the evaluation's (firmware stack: frames on one path add up).
#if defined(__GNUC__)
#define HSTMON_CIRCUIT_INLINE inline __attribute__((always_inline))
#define HSTMON_CIRCUIT_NOINLINE __attribute__((noinline))
#define HSTMON_CIRCUIT_LAMBDA_INLINE __attribute__((always_inline))
#else
#define HSTMON_CIRCUIT_INLINE inline
#define HSTMON_CIRCUIT_NOINLINE
#define HSTMON_CIRCUIT_LAMBDA_INLINE
#endif

/// A rare path (the bracketed Newton solve) kept out of line on hosts, where the fused
/// usual tick inlines everything else into one function (its size, its registers); left to
/// the compiler on firmware, where a call frame of its own would add to the stack.
#if defined(__GNUC__) && !HSTMON_FLASH_LEAN
#define HSTMON_CIRCUIT_RARE __attribute__((noinline))
#else
#define HSTMON_CIRCUIT_RARE
#endif

/// The laws (laws.hpp): always inlined on hosts, where the compiled kernels' fused usual
/// tick wants them in its one function; the compiler's choice on firmware, where inlining
/// every law into the interpreter's switches costs flash and stack.
#if defined(__GNUC__) && !HSTMON_FLASH_LEAN
#define HSTMON_CIRCUIT_LAW inline __attribute__((always_inline))
#else
#define HSTMON_CIRCUIT_LAW inline
#endif

/// Everything a function calls inlined into it (GCC's flatten): the compiled model's fused
/// usual tick, whose stages then share registers and loads.
#if defined(__GNUC__)
#define HSTMON_CIRCUIT_FLATTEN __attribute__((flatten))
#else
#define HSTMON_CIRCUIT_FLATTEN
#endif
