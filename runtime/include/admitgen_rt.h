/* SPDX-License-Identifier: MIT */
/*
 * admitgen_rt.h - recursive-convolution runtime for admitgen multipole boundary filters.
 * C99, freestanding-friendly: <stddef.h> and <stdint.h> only; no heap, no libm, no globals, reentrant.
 * Compiles as C99 and as C++.
 *
 * What it runs
 * ------------
 * A surface admittance G fitted by `admitgen fit` and discretised by `admitgen emit` into a generated
 * header (tables + a model struct per sample rate). Conventions: time dependence e^{+jwt}; the input u
 * is the wall pressure, the output y the normal particle velocity into the wall, both normalised
 * (G = rho*c*Y). Per sample n and node:
 *
 *   y^n = sum_k d_k u^{n-k}                                  FIR path (direct term + folded fast poles)
 *       + sum_q c_q x_q^n,        x_q^n = x_q + eps_q (u^n - x_q)               real poles, delta form
 *       + sum_s (cr_s xi_s^n + ci_s eta_s^n),                                     pairs, coupled form
 *         xi^n  = xi  + (e_r xi  - p_i eta + g u^n)
 *         eta^n = eta + (e_r eta + p_i xi)
 *
 * with eps = 1 - e^{-lambda T}, (1 + e_r) + j p_i = e^{-(alpha + j beta) T}, g = 1 - e^{-alpha T}: every
 * state is normalised so that |state| <= max |u| (its impulse response has L1 norm <= 1). The pair is
 * the Gold-Rader coupled (rotation x decay) form, contractive even under per-sample coefficient changes.
 * The split y^n = h0 u^n + s^{n-1} (instantaneous gain h0 = model->h0, history s from
 * admitgen_rt_history_f32) lets an FDTD/FV solver solve its boundary node implicitly:
 * u^n = (a^n - c s^{n-1}) / (1 + c h0), then admitgen_rt_commit_f32(u^n).
 *
 * Lifecycle (miniaudio/CMSIS style; the caller owns every byte)
 * ------------------------------------------------------------
 *   size_t bytes = admitgen_rt_state_bytes_f32(&model, n_nodes);      memory for n_nodes nodes
 *   admitgen_rt_init_f32(&inst, &model, fs_hz, n_nodes, mem, bytes);  checks ABI and rate, zeroes state
 *   admitgen_rt_process_f32(&inst, in, out, n_frames, stride);        any block size; in == out allowed
 *   admitgen_rt_reinit_f32(&inst, &other_model, fs_hz);               swap coefficients, keep the state
 *   admitgen_rt_reset_f32(&inst);                                     zero the state
 * mem must be aligned to ADMITGEN_RT_ALIGN bytes. Buffers: frame f of node i is in[f*stride + i], so
 * one call serves a planar mono buffer (n_nodes 1, stride 1), an interleaved multichannel buffer
 * (n_nodes = channels = stride) or every boundary node of a solver (one frame, n_nodes nodes).
 * State layout is structure-of-arrays, state[term][node]. Kernels: up to 8 nodes, each node runs a chunk of
 * frames through one term at a time with the state in a register (mono/stereo audio); more nodes, one fused
 * pass per frame over blocks of nodes with the accumulators in registers, vectorised (AVX2 chosen at run
 * time on x86-64, NEON on aarch64; define ADMITGEN_RT_NO_SIMD for scalar only). All paths give identical
 * bits (docs/runtime.md).
 *
 * Formats: _f32 (float), _q31 (Q1.31 = TI Q0.31 data), _q15 (Q1.15 data). The fixed-point kernels keep
 * Q1.31 states for both formats, 64-bit accumulators, per-term coefficient exponents and saturating
 * stores; their scaling, bounds and rounding are stated in docs/runtime.md, "Q formats and rounding".
 * Denormals: decaying float states become subnormal; set FTZ/DAZ in the audio thread (as miniaudio and
 * Steam Audio do) if the platform is slow on subnormals.
 */
#ifndef ADMITGEN_RT_H
#define ADMITGEN_RT_H

#include <stddef.h>
#include <stdint.h>

/** ABI of the model structs below; generated headers refuse to compile against another one. */
#define ADMITGEN_RT_ABI_VERSION 1
/** Required alignment (bytes) of the state memory handed to *_init (one cache line; AVX-512 safe). */
#define ADMITGEN_RT_ALIGN 64

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__) || defined(__clang__)
#define ADMITGEN_RT_NODISCARD __attribute__((warn_unused_result))
#else
#define ADMITGEN_RT_NODISCARD
#endif

#if defined(__cplusplus)
#define ADMITGEN_RT_RESTRICT __restrict
#else
#define ADMITGEN_RT_RESTRICT restrict
#endif

/** Result codes (int32_t; 0 success, negative failure). Limits and misuse (docs/runtime.md): every
 *  entry point checks its arguments before it touches memory and returns one of these; on failure
 *  nothing is written (instance, state, output).
 *   ADMITGEN_RT_INVALID_ARGS     n_nodes <= 0, n_frames < 0
 *   ADMITGEN_RT_NULL_POINTER     inst, model, mem, pIn, pU or pHist NULL; an instance never initialised
 *                                (inst->model NULL); a model table NULL while its count is not 0
 *   ADMITGEN_RT_ABI_MISMATCH     model->abi_version != ADMITGEN_RT_ABI_VERSION
 *   ADMITGEN_RT_RATE_MISMATCH    fs_hz != model->fs_hz (coefficients are only valid at their own rate)
 *   ADMITGEN_RT_SHAPE_MISMATCH   reinit with other n_fir, n_real or n_pair
 *   ADMITGEN_RT_BUFFER_TOO_SMALL bytes < *_state_bytes(model, n_nodes)
 *   ADMITGEN_RT_MISALIGNED       mem not aligned to ADMITGEN_RT_ALIGN
 *   ADMITGEN_RT_TOO_LARGE        n_nodes > ADMITGEN_RT_MAX_NODES, or the state size or the last buffer
 *                                index (n_frames - 1) * stride + n_nodes does not fit in size_t
 *   ADMITGEN_RT_BAD_STRIDE       stride < n_nodes (frames would overlap)
 *   ADMITGEN_RT_BAD_MODEL        a count outside 0..ADMITGEN_RT_MAX_TERMS; fixed point: a shift outside
 *                                1..62, or mantissas whose 64-bit sums could overflow (a pair's
 *                                |e_r| + |p_i| + |g| > 2^31, the output table's sum |m| > 2^31)
 *  Float input: NaN and +-Inf are not rejected (that would cost a test per sample); they propagate by
 *  IEEE arithmetic into the states and outputs of that node only (nodes never mix), until
 *  *_reset. Fixed-point input has no such values; every store saturates. */
typedef int32_t admitgen_rt_result;
#define ADMITGEN_RT_SUCCESS 0
#define ADMITGEN_RT_INVALID_ARGS (-2)
#define ADMITGEN_RT_NULL_POINTER (-3)
#define ADMITGEN_RT_ABI_MISMATCH (-10)
#define ADMITGEN_RT_RATE_MISMATCH (-11)
#define ADMITGEN_RT_SHAPE_MISMATCH (-12)
#define ADMITGEN_RT_BUFFER_TOO_SMALL (-13)
#define ADMITGEN_RT_MISALIGNED (-14)
#define ADMITGEN_RT_TOO_LARGE (-15)
#define ADMITGEN_RT_BAD_STRIDE (-16)
#define ADMITGEN_RT_BAD_MODEL (-17)

/** Largest node count of one instance (larger counts: ADMITGEN_RT_TOO_LARGE; split the boundary). */
#define ADMITGEN_RT_MAX_NODES (1 << 24)
/** Largest n_fir, n_real and n_pair of a model. */
#define ADMITGEN_RT_MAX_TERMS 64

/** Discretisation methods (model->method). */
#define ADMITGEN_RT_METHOD_MATCHED_EXP 1 /**< exact poles e^{-aT}, least-squares refitted numerators */

/** A constant message for a result code (never NULL). */
const char *admitgen_rt_result_description(admitgen_rt_result result);

/* ------------------------------------------------------------------------------------------------ */
/* Models: filled by generated headers as static const data (place them in flash/ROM).                */

/* Coefficient tables: the one definition of their layout. fir holds d_0..d_{n_fir-1}; real holds one row of
 * ADMITGEN_RT_*_REAL_WIDTH entries per real pole and pair one row of ADMITGEN_RT_*_PAIR_WIDTH entries per
 * pair, entry j of row t at [WIDTH * t + j]; the index macros name j. cr = 2 Re c, ci = -2 Im c. Fixed-point
 * scaling of each entry: docs/runtime.md, "Q formats and rounding". */
/** f32 real pole row {eps, c}. */
#define ADMITGEN_RT_F32_REAL_WIDTH 2
#define ADMITGEN_RT_F32_REAL_EPS 0
#define ADMITGEN_RT_F32_REAL_C 1
/** f32 pair row {e_r, p_i, g, cr, ci}. */
#define ADMITGEN_RT_F32_PAIR_WIDTH 5
#define ADMITGEN_RT_F32_PAIR_ER 0
#define ADMITGEN_RT_F32_PAIR_PI 1
#define ADMITGEN_RT_F32_PAIR_G 2
#define ADMITGEN_RT_F32_PAIR_CR 3
#define ADMITGEN_RT_F32_PAIR_CI 4
/** q31/q15 real pole row {eps mantissa, shift, c mantissa}. */
#define ADMITGEN_RT_Q_REAL_WIDTH 3
#define ADMITGEN_RT_Q_REAL_EPS 0
#define ADMITGEN_RT_Q_REAL_SHIFT 1
#define ADMITGEN_RT_Q_REAL_C 2
/** q31/q15 pair row {e_r, p_i, g, shift, cr, ci} (mantissas, shift the term's exponent). */
#define ADMITGEN_RT_Q_PAIR_WIDTH 6
#define ADMITGEN_RT_Q_PAIR_ER 0
#define ADMITGEN_RT_Q_PAIR_PI 1
#define ADMITGEN_RT_Q_PAIR_G 2
#define ADMITGEN_RT_Q_PAIR_SHIFT 3
#define ADMITGEN_RT_Q_PAIR_CR 4
#define ADMITGEN_RT_Q_PAIR_CI 5

/** Names a field in a model initialiser (generated headers fill every field by name):
 *  ADMITGEN_RT_FIELD(n_fir) 6 is the designated initialiser .n_fir = 6 in C99 and C++20, where the compiler
 *  checks the name (C++20 also the order). C++ before C++20 has no designated initialisers: there it is the
 *  positional 6, in declaration order, which the C++20 build of the runtime tests proves. */
#if !defined(__cplusplus) || __cplusplus >= 202002L
#define ADMITGEN_RT_FIELD(name) .name =
#else
#define ADMITGEN_RT_FIELD(name)
#endif

/** Float model; tables in the f32 layout above. */
typedef struct admitgen_rt_model_f32 {
  uint32_t abi_version; /**< ADMITGEN_RT_ABI_VERSION of the generator */
  int32_t fs_hz;        /**< the only sample rate these coefficients are valid for */
  int32_t method;       /**< ADMITGEN_RT_METHOD_* */
  int32_t n_fir, n_real, n_pair;
  float h0; /**< instantaneous gain: y^n = h0 u^n + s^{n-1} */
  const float *fir;
  const float *real;
  const float *pair;
} admitgen_rt_model_f32;

/** Q31 model (B = 31); tables in the q layout above. State-update coefficients: value =
 *  mantissa * 2^-(31 + shift), one shift per term (delta form: eps keeps 31 significant bits however small
 *  lambda*T is). Output table (fir, c, cr, ci): value = mantissa * 2^(y_exp - 31) with one exponent for the
 *  table; the kernel only needs acc_shift = 31 + out_shift - y_exp. Output y_q31 represents
 *  y * 2^-out_shift. */
typedef struct admitgen_rt_model_q31 {
  uint32_t abi_version;
  int32_t fs_hz;
  int32_t method;
  int32_t n_fir, n_real, n_pair;
  int32_t out_shift; /**< output scaling: y_q31 = y * 2^-out_shift; 2^out_shift >= L1 norm of h */
  int32_t acc_shift; /**< right shift of the 64-bit accumulator to the output (1..62) */
  const int32_t *fir;
  const int32_t *real;
  const int32_t *pair;
} admitgen_rt_model_q31;

/** Q15 model: as Q31 with B = 15 and int16 tables (shifts stored in the same int16 tables); or, "q15 with 32-bit
 *  coefficients" (docs/runtime.md, "Q formats and rounding"), B = 31 and int32 tables in fir32/real32/pair32 (then
 *  fir/real/pair are unused and NULL): Q1.15 data, the q31 coefficient tables, the same 64-bit kernel (the
 *  generator chooses it when 16-bit coefficients cannot hold a model, as CMSIS-DSP's 32x64 biquads do). */
typedef struct admitgen_rt_model_q15 {
  uint32_t abi_version;
  int32_t fs_hz;
  int32_t method;
  int32_t n_fir, n_real, n_pair;
  int32_t out_shift;
  int32_t acc_shift;
  const int16_t *fir;
  const int16_t *real;
  const int16_t *pair;
  const int32_t *fir32;  /**< NULL: 16-bit coefficients (fir/real/pair); set: 32-bit coefficients, B = 31 */
  const int32_t *real32;
  const int32_t *pair32;
} admitgen_rt_model_q15;

/* ------------------------------------------------------------------------------------------------ */
/* Instances: transparent, caller-owned; every pointer points into the caller's state memory.         */

typedef struct admitgen_rt_f32 {
  const admitgen_rt_model_f32 *model;
  int32_t n_nodes;
  int32_t head;  /**< ring position of u^{n-1} in hist */
  float *x;      /**< [n_real][n_nodes] */
  float *xi;     /**< [n_pair][n_nodes] */
  float *eta;    /**< [n_pair][n_nodes] */
  float *hist;   /**< [n_fir-1][n_nodes] ring of past inputs */
  float *u;      /**< [n_nodes] scratch: current input (allows in == out) */
  float *acc;    /**< [n_nodes] scratch: output accumulator */
} admitgen_rt_f32;

typedef struct admitgen_rt_q31 {
  const admitgen_rt_model_q31 *model;
  int32_t n_nodes;
  int32_t head;
  int32_t *x, *xi, *eta, *hist, *u; /**< Q1.31 states, same layout as the f32 instance */
  int64_t *acc;                     /**< [n_nodes] 64-bit accumulators */
} admitgen_rt_q31;

typedef struct admitgen_rt_q15 {
  const admitgen_rt_model_q15 *model;
  int32_t n_nodes;
  int32_t head;
  int32_t *x, *xi, *eta, *hist, *u; /**< Q1.31 states (wider than the Q1.15 data) */
  int64_t *acc;
} admitgen_rt_q15;

/* ------------------------------------------------------------------------------------------------ */
/* f32                                                                                                */

/** Bytes of state memory for n_nodes nodes (0 if the arguments are invalid or the size does not fit in
 *  size_t; *_init then names the reason). */
size_t admitgen_rt_state_bytes_f32(const admitgen_rt_model_f32 *model, int32_t n_nodes);
/** Binds model and memory, checks ABI (ADMITGEN_RT_ABI_MISMATCH), that model->fs_hz == fs_hz
 *  (ADMITGEN_RT_RATE_MISMATCH: the coefficients are only valid at their own rate), size and alignment;
 *  zeroes the state. */
ADMITGEN_RT_NODISCARD admitgen_rt_result admitgen_rt_init_f32(admitgen_rt_f32 *inst, const admitgen_rt_model_f32 *model,
                                                              int32_t fs_hz, int32_t n_nodes, void *mem, size_t bytes);
/** Replaces the coefficients and keeps the state (material morphing without a click). The new model
 *  must have the same n_fir, n_real, n_pair (ADMITGEN_RT_SHAPE_MISMATCH) and rate. */
ADMITGEN_RT_NODISCARD admitgen_rt_result admitgen_rt_reinit_f32(admitgen_rt_f32 *inst, const admitgen_rt_model_f32 *model,
                                                                int32_t fs_hz);
admitgen_rt_result admitgen_rt_reset_f32(admitgen_rt_f32 *inst);
/** Filters n_frames frames of every node: node i of frame f is pIn[f*stride + i] (stride >= n_nodes).
 *  pIn == pOut is allowed; pOut may be NULL (advance the state only). Every entry point from here on
 *  returns ADMITGEN_RT_SUCCESS or a code of "Limits and misuse" above (then nothing is written);
 *  n_frames = 0 does nothing. */
admitgen_rt_result admitgen_rt_process_f32(admitgen_rt_f32 *inst, const float *pIn, float *pOut, int32_t n_frames, int32_t stride);
/** History s^{n-1} of every node (pHist[n_nodes]): the output the next frame would give for u = 0. */
admitgen_rt_result admitgen_rt_history_f32(const admitgen_rt_f32 *inst, float *pHist);
/** Commits one frame u^n (pU[n_nodes]) after an implicit solve; writes y^n to pY if not NULL. */
admitgen_rt_result admitgen_rt_commit_f32(admitgen_rt_f32 *inst, const float *pU, float *pY);

/* ------------------------------------------------------------------------------------------------ */
/* q31 / q15: same lifecycle. Scaling and Overflow Behavior: docs/runtime.md, "Q formats and rounding"
 * (summarised in every generated header next to the tables).                                          */

size_t admitgen_rt_state_bytes_q31(const admitgen_rt_model_q31 *model, int32_t n_nodes);
ADMITGEN_RT_NODISCARD admitgen_rt_result admitgen_rt_init_q31(admitgen_rt_q31 *inst, const admitgen_rt_model_q31 *model,
                                                              int32_t fs_hz, int32_t n_nodes, void *mem, size_t bytes);
ADMITGEN_RT_NODISCARD admitgen_rt_result admitgen_rt_reinit_q31(admitgen_rt_q31 *inst, const admitgen_rt_model_q31 *model,
                                                                int32_t fs_hz);
admitgen_rt_result admitgen_rt_reset_q31(admitgen_rt_q31 *inst);
admitgen_rt_result admitgen_rt_process_q31(admitgen_rt_q31 *inst, const int32_t *pIn, int32_t *pOut, int32_t n_frames, int32_t stride);
/** History of every node (pHist[n_nodes], output units): exactly the output process would give next for u = 0,
 *  state unchanged. With the instantaneous gain h0 (the header's dequantised d_0 * 2^(y_exp - 31)):
 *  y^n = h0 u^n + s^{n-1} up to the output rounding. */
admitgen_rt_result admitgen_rt_history_q31(const admitgen_rt_q31 *inst, int32_t *pHist);
/** Commits one frame u^n (pU[n_nodes]) after an implicit solve; writes y^n to pY if not NULL. */
admitgen_rt_result admitgen_rt_commit_q31(admitgen_rt_q31 *inst, const int32_t *pU, int32_t *pY);

size_t admitgen_rt_state_bytes_q15(const admitgen_rt_model_q15 *model, int32_t n_nodes);
ADMITGEN_RT_NODISCARD admitgen_rt_result admitgen_rt_init_q15(admitgen_rt_q15 *inst, const admitgen_rt_model_q15 *model,
                                                              int32_t fs_hz, int32_t n_nodes, void *mem, size_t bytes);
ADMITGEN_RT_NODISCARD admitgen_rt_result admitgen_rt_reinit_q15(admitgen_rt_q15 *inst, const admitgen_rt_model_q15 *model,
                                                                int32_t fs_hz);
admitgen_rt_result admitgen_rt_reset_q15(admitgen_rt_q15 *inst);
admitgen_rt_result admitgen_rt_process_q15(admitgen_rt_q15 *inst, const int16_t *pIn, int16_t *pOut, int32_t n_frames, int32_t stride);
admitgen_rt_result admitgen_rt_history_q15(const admitgen_rt_q15 *inst, int16_t *pHist);
admitgen_rt_result admitgen_rt_commit_q15(admitgen_rt_q15 *inst, const int16_t *pU, int16_t *pY);

#ifdef __cplusplus
}
#endif

#endif /* ADMITGEN_RT_H */
