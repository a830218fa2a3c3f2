/* SPDX-License-Identifier: MIT */
/*
 * rt_bitexact_checks.h - the checks of rt_bitexact.c, included once per format. The includer defines FMT
 * (f32, q31 or q15), T (the sample type), MODEL (the emitted model), INPUT(k) (golden input sample k as a T),
 * RT_FIXED (1 for q31/q15: golden outputs and limit cycles are checked too) and, for fixed formats, GOLD_OUT
 * and ZERO_DECAY (the header's bound on samples to exactly 0). Its end undefines FMT, T, GOLD_OUT and
 * ZERO_DECAY (MODEL and INPUT stay for the includer). No include guard on purpose.
 */
#define RT_CAT2(a, b) a##b
#define RT_CAT(a, b) RT_CAT2(a, b)
#define RT_FN(name) RT_CAT(name##_, FMT)
#define RT_RT(name) RT_CAT(RT_CAT(admitgen_rt_, name), RT_CAT(_, FMT))
#define INST RT_CAT(admitgen_rt_, FMT)
#define PROCESS_ISA RT_CAT(RT_CAT(admitgen_rt__process_, FMT), _isa)

static T RT_FN(in)[MAX_NODES * FRAMES_MANY], RT_FN(out_a)[MAX_NODES * FRAMES_MANY], RT_FN(out_b)[MAX_NODES * FRAMES_MANY];

static void RT_FN(init)(INST *inst, int32_t n, int slot) {
  const admitgen_rt_result r = RT_RT(init)(inst, &MODEL, 48000, n, rt_slot(slot), SLOT_BYTES);
  RT_CHECK(r == ADMITGEN_RT_SUCCESS, "init %ld nodes: %s", (long)n, admitgen_rt_result_description(r));
}

/* 1 + 2: golden input through one node in one call (fixed formats: equal to the golden output), then in
 * blocks of 1, 7, 64, 1024 frames: equal to the one call. */
static void RT_FN(golden_and_blocks)(void) {
  static const int32_t sizes[4] = {1, 7, 64, 1024};
  INST inst;
  int32_t s, i;
  for (i = 0; i < N_GOLD; ++i) RT_FN(in)[i] = INPUT(i);
  RT_FN(init)(&inst, 1, 0);
  RT_RT(process)(&inst, RT_FN(in), RT_FN(out_a), N_GOLD, 1);
#if RT_FIXED
  for (i = 0; i < N_GOLD && RT_FN(out_a)[i] == GOLD_OUT[i]; ++i) {
  }
  RT_CHECK(i == N_GOLD, "golden vector differs at sample %ld: %ld vs %ld", (long)i, (long)RT_FN(out_a)[i],
           (long)GOLD_OUT[i]);
  printf("%s: golden vectors bit-exact (%d samples)\n", RT_STR(FMT), N_GOLD);
#endif
  for (s = 0; s < 4; ++s) {
    int32_t pos = 0;
    RT_FN(init)(&inst, 1, 0);
    while (pos < N_GOLD) {
      const int32_t len = N_GOLD - pos < sizes[s] ? N_GOLD - pos : sizes[s];
      RT_RT(process)(&inst, RT_FN(in) + pos, RT_FN(out_b) + pos, len, 1);
      pos += len;
    }
    RT_CHECK(memcmp(RT_FN(out_a), RT_FN(out_b), sizeof(T) * N_GOLD) == 0, "blocks of %ld frames differ", (long)sizes[s]);
  }
  printf("%s: blocks of 1/7/64/1024 frames bit-identical to one call\n", RT_STR(FMT));
}

/* Input of node i at frame f: the golden input shifted by 97 i samples (every node different). */
static T RT_FN(node_input)(int32_t i, int32_t f) { return INPUT((f + 97 * i) % N_GOLD); }

/* 3: n nodes in a buffer of stride n + 1 (every path: small-n up to 8 nodes, vector + scalar blocks above)
 * against single-node runs of each node's input, bit for bit. */
static void RT_FN(node_counts)(void) {
  static const int32_t counts[5] = {1, 2, 5, 13, 1024};
  int32_t c, i, f;
  for (c = 0; c < 5; ++c) {
    const int32_t n = counts[c], stride = n + 1, frames = n > 13 ? FRAMES_MANY - 1 : FRAMES_FEW;
    INST many, one;
    int32_t bad = -1;
    for (f = 0; f < frames; ++f)
      for (i = 0; i < stride; ++i) RT_FN(in)[f * stride + i] = i < n ? RT_FN(node_input)(i, f) : (T)0;
    RT_FN(init)(&many, n, 0);
    RT_RT(process)(&many, RT_FN(in), RT_FN(out_a), frames, stride);
    for (i = 0; i < n && bad < 0; ++i) {
      for (f = 0; f < frames; ++f) RT_FN(in)[f] = RT_FN(node_input)(i, f);
      RT_FN(init)(&one, 1, 1);
      RT_RT(process)(&one, RT_FN(in), RT_FN(out_b), frames, 1);
      for (f = 0; f < frames; ++f)
        if (RT_FN(out_b)[f] != RT_FN(out_a)[f * stride + i]) bad = i;
      for (f = 0; f < frames; ++f) RT_FN(in)[f * stride + i] = RT_FN(node_input)(i, f); /* restore */
    }
    RT_CHECK(bad < 0, "%ld nodes: node %ld differs from its single-node run", (long)n, (long)bad);
  }
  printf("%s: 1/2/5/13/1024 nodes (stride n+1) bit-identical to single-node runs\n", RT_STR(FMT));
}

/* 4: the vector kernels (when built and supported: the best, and AVX2 where AVX-512 is the best) against the
 * scalar kernel: outputs and states. */
static void RT_FN(simd_vs_scalar)(void) {
  static const int isas[2] = {ADMITGEN_RT_ISA_BEST, ADMITGEN_RT_ISA_AVX2};
  const int32_t n = MAX_NODES, frames = FRAMES_MANY;
  int32_t i, k;
  for (k = 0; k < 2; ++k) {
    INST a, b;
    int same;
    for (i = 0; i < n * frames; ++i) RT_FN(in)[i] = RT_FN(node_input)(i % n, i / n);
    RT_FN(init)(&a, n, 0);
    RT_FN(init)(&b, n, 1);
    PROCESS_ISA(&a, RT_FN(in), RT_FN(out_a), frames, n, isas[k]);
    PROCESS_ISA(&b, RT_FN(in), RT_FN(out_b), frames, n, ADMITGEN_RT_ISA_SCALAR);
    same = memcmp(RT_FN(out_a), RT_FN(out_b), sizeof(T) * (size_t)(n * frames)) == 0 &&
           memcmp(rt_slot(0), rt_slot(1), RT_RT(state_bytes)(&MODEL, n)) == 0;
    RT_CHECK(same, "vector kernels (%s) and scalar kernel differ", rt_simd_name(isas[k], RT_FIXED));
    printf("%s: %ld nodes x %ld frames, vector kernels (%s) vs scalar: outputs and states bit-identical\n", RT_STR(FMT),
           (long)n, (long)frames, rt_simd_name(isas[k], RT_FIXED));
  }
}

#if RT_FIXED
static int RT_FN(states_zero)(const INST *inst) {
  const int32_t n = inst->n_nodes;
  int32_t k;
  for (k = 0; k < MODEL.n_real * n; ++k)
    if (inst->x[k] != 0) return 0;
  for (k = 0; k < MODEL.n_pair * n; ++k)
    if (inst->xi[k] != 0 || inst->eta[k] != 0) return 0;
  return 1;
}

/* 5: no limit cycle: after full-scale noise, zero input brings outputs and states to exactly 0 within the
 * header's bound, on the small-n path (1 node) and the block path (MAX_NODES nodes). */
static void RT_FN(limit_cycles)(void) {
  static const int32_t counts[2] = {1, MAX_NODES};
  int32_t c, i, f;
  uint32_t rng = 12345u;
  for (c = 0; c < 2; ++c) {
    const int32_t n = counts[c];
    INST inst;
    int32_t steps = -1;
    RT_FN(init)(&inst, n, 0);
    for (f = 0; f < 256; ++f) {
      for (i = 0; i < n; ++i) RT_FN(in)[i] = (T)(rt_rng_next(&rng) >> (32 - 8 * (int)sizeof(T)));
      RT_RT(process)(&inst, RT_FN(in), RT_FN(out_a), 1, n);
    }
    for (i = 0; i < n; ++i) RT_FN(in)[i] = 0;
    for (f = 1; f <= ZERO_DECAY && steps < 0; ++f) {
      int32_t nonzero = 0;
      RT_RT(process)(&inst, RT_FN(in), RT_FN(out_a), 1, n);
      for (i = 0; i < n; ++i) nonzero += RT_FN(out_a)[i] != 0;
      if (nonzero == 0 && RT_FN(states_zero)(&inst)) steps = f;
    }
    RT_CHECK(steps >= 0, "%ld nodes: not exactly 0 after %d zero samples", (long)n, ZERO_DECAY);
    printf("%s: %ld node(s): zero input after full-scale noise: states and output exactly 0 after %ld samples (bound %d)\n",
           RT_STR(FMT), (long)n, (long)steps, ZERO_DECAY);
  }
}

#endif

/* 6: history = the output of a u = 0 frame, state untouched; commit = one processed frame. 2 nodes: small-n
 * path; 13: the scalar block; 80 (x86-64): history and process through different vector kernels (f32: the
 * per-term blocks and the small-model form, AVX-512 and AVX2). */
#define RT_HC_MAX 80
static void RT_FN(history_commit)(void) {
  static const int32_t counts[3] = {2, 13, RT_HC_MAX};
  int32_t c, i, f;
  for (c = 0; c < 3; ++c) {
    const int32_t n = counts[c];
    const size_t bytes = RT_RT(state_bytes)(&MODEL, n);
    INST inst, probe;
    T hist[RT_HC_MAX], zero[RT_HC_MAX], y[RT_HC_MAX], u[RT_HC_MAX];
    int ok = 1;
    RT_FN(init)(&inst, n, 0);
    RT_FN(init)(&probe, n, 1);
    for (i = 0; i < n; ++i) zero[i] = 0;
    for (f = 0; f < 300; ++f) {
      for (i = 0; i < n; ++i) u[i] = RT_FN(node_input)(i, f);
      RT_RT(history)(&inst, hist);
      memcpy(rt_slot(2), rt_slot(0), bytes);
      memcpy(rt_slot(1), rt_slot(0), bytes);
      probe.head = inst.head;
      RT_RT(process)(&probe, zero, RT_FN(out_a), 1, n);
      ok &= memcmp(rt_slot(2), rt_slot(0), bytes) == 0 && memcmp(hist, RT_FN(out_a), sizeof(T) * (size_t)n) == 0;
      memcpy(rt_slot(1), rt_slot(0), bytes);
      probe.head = inst.head;
      RT_RT(commit)(&inst, u, y);
      RT_RT(process)(&probe, u, RT_FN(out_a), 1, n);
      ok &= memcmp(y, RT_FN(out_a), sizeof(T) * (size_t)n) == 0 && memcmp(rt_slot(1), rt_slot(0), bytes) == 0;
    }
    RT_CHECK(ok, "%ld nodes: history/commit differ from process", (long)n);
  }
  printf("%s: history = output of a zero frame (state untouched), commit = process, 2, 13 and %d nodes, 300 frames\n",
         RT_STR(FMT), RT_HC_MAX);
}
#undef RT_HC_MAX

static void RT_FN(all)(void) {
  RT_FN(golden_and_blocks)();
  RT_FN(node_counts)();
  RT_FN(simd_vs_scalar)();
#if RT_FIXED
  RT_FN(limit_cycles)();
#endif
  RT_FN(history_commit)();
}

#undef RT_FN
#undef RT_RT
#undef INST
#undef GOLD_IN
#undef GOLD_OUT
#undef PROCESS_ISA
#undef FMT
#undef T
#undef GOLD_OUT
#undef ZERO_DECAY
