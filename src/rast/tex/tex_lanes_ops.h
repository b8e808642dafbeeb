/*
 * The texture unit's operations on lanes for dfx24 (tex_lanes.c): the lane
 * types, the coordinates' entry and floor, the addressing of both axes with
 * the wrap modes, the texel gathers and the channel decode, and the linear
 * filter one channel of the lanes' pixels a vector.  Each lane does the
 * operations of tex_fast.c and tex_fast_path.h in their order.  Included by
 * tex_lanes.c alone, once per instruction set (DFXL_N, LANES_SUFFIX).
 */
#ifndef RAST_TEX_LANES_OPS_H
#define RAST_TEX_LANES_OPS_H

#include "rast/tex/tex_fast_path.h"
#include "rast/host/lanes_fns.h"
#include "fixed/dfx_lanes.h"
#ifdef __AVX__
#include <immintrin.h>
#endif

/* A lane a pixel (a quad, or a pair of quads with DFXL_N = 8: lanes.h),
 * and two lanes a pixel (the s then the t of the pixels; a filter's two
 * taps). */
typedef float lanes_f __attribute__((vector_size(4 * DFXL_N)));
typedef int32_t lanes_i __attribute__((vector_size(4 * DFXL_N)));
typedef float taps_f __attribute__((vector_size(8 * DFXL_N)));
typedef int32_t taps_i __attribute__((vector_size(8 * DFXL_N)));
typedef uint32_t taps_u __attribute__((vector_size(8 * DFXL_N)));
typedef float lanes_v4f __attribute__((vector_size(16)));

/* The quads a vector holds. */
#define QPV (DFXL_N / TEX_QUAD)

/* Two lanes a pixel from one (a, b side by side; a twice), and the halves. */
#if DFXL_N == 8
#define CONCAT(a, b) __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15)
#define LO(v) __builtin_shufflevector(v, v, 0, 1, 2, 3, 4, 5, 6, 7)
#define HI(v) __builtin_shufflevector(v, v, 8, 9, 10, 11, 12, 13, 14, 15)
#else
#define CONCAT(a, b) __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7)
#define LO(v) __builtin_shufflevector(v, v, 0, 1, 2, 3)
#define HI(v) __builtin_shufflevector(v, v, 4, 5, 6, 7)
#endif
#define TWICE(a) CONCAT(a, a)

static inline __attribute__((always_inline)) lanes_i splat_i(int32_t v)
{
   return (lanes_i){ 0 } + v;
}

/* Whether some lane of a comparison's mask is set. */
static inline __attribute__((always_inline)) bool any_taps(taps_i m)
{
#if DFXL_N == 8 && defined(__AVX512F__)
   return _mm512_test_epi32_mask((__m512i)m, (__m512i)m) != 0;
#elif defined(__AVX__)
   return _mm256_movemask_ps((__m256)m) != 0;
#else
   const lanes_i o = LO(m) | HI(m);
   int32_t r = 0;
   for (int i = 0; i < DFXL_N; i++)
      r |= o[i];
   return r != 0;
#endif
}

static inline __attribute__((always_inline)) struct dfxl splat(double v)
{
   struct dfxl r = { dfxl_splatd(v) };
   return r;
}


/* tex_fcoord for the quad's s and t together, on the binary32 bits of
 * the eight coordinates: toward -inf to the grid of the value's digit,
 * which is the scalar path's "m24 >> sh, + 1 if negative and bits
 * dropped" on binary32's own mantissa.  A digit holds 16 + (p + 32) mod 4
 * bits of a value with its leading one at 2^p, so with binary32's biased
 * exponent e (p = e - 127) the bits to drop are 8 - ((e + 1) & 3).  Adding
 * a grid step to a magnitude's bits is adding it to the magnitude: a carry
 * out of the mantissa lands on the next power of two.  The result has at
 * most 19 significant bits, so the doubles of the lanes hold it exactly.
 * Zero, the range beyond 2^-32 .. 2^32, inf, NaN and a step past L = 15
 * take tex_ns_coord. */
static inline __attribute__((always_inline)) void
coords(const struct tex_unit *u, const struct tex_quad *q, struct dfxl *cs, struct dfxl *ct,
       struct tex_fst *x)
{
   /* Each quad's s and t read as the two vectors they are: the compiled
    * shader stores them one vector each just before the call, and one load
    * over both would wait for the two stores to reach the cache, as the
    * processor forwards a load from one store only (docs/datapath.md,
    * "Coordinates read as they were stored"). */
   typedef int32_t v4i __attribute__((vector_size(16)));
   v4i s0, t0;
   memcpy(&s0, q[0].s, sizeof(s0));
   memcpy(&t0, q[0].t, sizeof(t0));
   taps_i v;                                    /* the lanes' s, then their t */
#if DFXL_N == 8
   typedef int32_t v8i __attribute__((vector_size(32)));
   v4i s1, t1;
   memcpy(&s1, q[1].s, sizeof(s1));
   memcpy(&t1, q[1].t, sizeof(t1));
   const v8i s = __builtin_shufflevector(s0, s1, 0, 1, 2, 3, 4, 5, 6, 7);
   const v8i t = __builtin_shufflevector(t0, t1, 0, 1, 2, 3, 4, 5, 6, 7);
   v = __builtin_shufflevector(s, t, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
#else
   v = __builtin_shufflevector(s0, t0, 0, 1, 2, 3, 4, 5, 6, 7);
#endif
   const taps_i drop = 8 - (((v >> 23) + 1) & 3);
   const taps_i kept = (taps_i)((taps_u)v & (((taps_u){ 0 } - 1) << (taps_u)drop));
   const taps_i down = (kept != v) & (v < 0);
   const taps_i r = kept + (down & (1 << drop));
   const int32_t lo = 0x2f800000, hi = 0x4f800000;      /* 2^-32, 2^32 */
   const taps_i direct = ((v & INT32_MAX) >= lo) & ((r & INT32_MAX) < hi);
   const taps_f f = (taps_f)(r & direct);
   cs->v = __builtin_convertvector(LO(f), dfxl_d);
   ct->v = __builtin_convertvector(HI(f), dfxl_d);
   const taps_i other = ~direct & ((v & INT32_MAX) != 0);
   if (__builtin_expect(!any_taps(other), 1))
      return;
   for (unsigned p = 0; p < DFXL_N; p++) {
      const struct tex_quad *qp = &q[p / TEX_QUAD];
      if (other[p])
         cs->v[p] = dfxl_value(tex_ns_coord(u->ns, TEX_NS_DFX, qp->s[p % TEX_QUAD], &x->n).d);
      if (other[DFXL_N + p])
         ct->v[p] = dfxl_value(tex_ns_coord(u->ns, TEX_NS_DFX, qp->t[p % TEX_QUAD], &x->n).d);
   }
}

/* s minus the linear filter's texel offset (the unit's k_texel_offset, a
 * register dfx24 holds exactly): the difference itself where the adder's
 * aligner cannot change it (dfx_lanes.h), nearly always. */
_Static_assert(TEX_WEIGHT_BITS == 8, "DFXL_TEXEL_OFFSET is 1/2 - 2^-(TEX_WEIGHT_BITS + 1)");
static inline __attribute__((always_inline)) struct dfxl
sub_texel_offset(struct dfxl s, struct dfxl_stats *st)
{
   if (__builtin_expect(dfxl_sub_texel_offset_direct(s.v), 1))
      return dfxl_sub_texel_offset(s, st);
   return dfxl_sub(s, splat(DFXL_TEXEL_OFFSET), st);
}

/* floor(a) saturated to int32 (counted), as a double, and which lanes saturated. */
static inline __attribute__((always_inline)) dfxl_d
floor_int32(dfxl_d a, dfxl_i *sat, struct dfxl_stats *st)
{
   const dfxl_d fl = dfxl_floor(a);
   const dfxl_i hi = fl > (double)INT32_MAX, lo = fl < (double)INT32_MIN;
   *sat = hi | lo;
   st->sat -= *sat;
   return dfxl_seld(hi, dfxl_splatd(INT32_MAX), dfxl_seld(lo, dfxl_splatd(INT32_MIN), fl));
}

/* tex_ffloor with TEX_WEIGHT_BITS fraction bits: the integer part (floor),
 * saturated to int32 (counted, fraction 0 then), and the fraction's bits.
 * `bounded`: a clamped coordinate, scaled, which tex_bind.c's bounds keep
 * far inside int32, so that nothing saturates and nothing is checked. */
static inline __attribute__((always_inline)) void
floor_frac(struct dfxl a, const bool bounded, lanes_i *ip, lanes_i *frac,
           struct dfxl_stats *st)
{
   dfxl_i sat = dfxl_splat(0);
   const dfxl_d cl = bounded ? dfxl_floor(a.v) : floor_int32(a.v, &sat, st);
   const dfxl_d fr = dfxl_floor(a.v * (double)TEX_WEIGHT_ONE) - cl * (double)TEX_WEIGHT_ONE;
   *ip = __builtin_convertvector(cl, lanes_i);
   *frac = __builtin_convertvector(bounded ? fr : dfxl_seld(sat, dfxl_splatd(0), fr), lanes_i);
}

/* frac_of: c - floor(c) (floor saturated to int32, through binary32 into
 * the register as tex_fint), and the parity of floor(c); c itself where
 * c is in [-1, 0), those lanes in *below (tex_addr.c's frac_of; the
 * difference c + 1 there raises no range event, so computing it on every
 * lane counts what the scalar path counts). */
static inline __attribute__((always_inline)) struct dfxl
lanes_frac_of(struct dfxl c, dfxl_i *odd, dfxl_i *below, struct dfxl_stats *st)
{
   dfxl_i sat;
   const dfxl_d cl = floor_int32(c.v, &sat, st);
   const lanes_i i = __builtin_convertvector(cl, lanes_i);
   *odd = __builtin_convertvector(i & 1, dfxl_i) != 0;
   *below = cl == dfxl_splatd(-1);
   /* 0 <= c < 2^16, nearly every coordinate: the difference itself */
   if (__builtin_expect(dfxl_sub_floor_direct(c.v), 1))
      return dfxl_sub_floor(c, cl, st);
   const dfxl_d asf = __builtin_convertvector(__builtin_convertvector(cl, lanes_f), dfxl_d);
   struct dfxl f = dfxl_sub(c, dfxl_from_int(asf, st), st);
   f.v = dfxl_seld(*below, c.v, f.v);
   return f;
}

/* An axis's constants on the lanes (tex_bind.c's laxis, the size): the
 * same in every lane, or, where both axes go through the address unit in
 * one vector, each lane its own axis's. */
struct lanes_axis {
   dfxl_d scale, lo, hi;
   lanes_i size;
};

static inline __attribute__((always_inline)) struct lanes_axis
axis_of(const struct tex_unit *u, unsigned l, unsigned a)
{
   const struct lanes_axis r = { dfxl_splatd(u->laxis[l][a][0]), dfxl_splatd(u->laxis[l][a][1]),
                                 dfxl_splatd(u->laxis[l][a][2]), splat_i(u->axis[l][a].size) };
   return r;
}

static inline __attribute__((always_inline)) struct dfxl
clamp(struct dfxl c, const struct lanes_axis *ax)
{
   c.v = dfxl_seld(c.v < ax->lo, ax->lo, dfxl_seld(c.v > ax->hi, ax->hi, c.v));
   return c;
}

/* mask ? a : b on int32 lanes (mask a vector comparison). */
static inline __attribute__((always_inline)) lanes_i seli(lanes_i mask, lanes_i a, lanes_i b)
{
   return (a & mask) | (b & ~mask);
}

/* tex_clampi and tex_inside on the lanes. */
static inline __attribute__((always_inline)) lanes_i clampi(lanes_i i, int32_t lo, lanes_i h)
{
   const lanes_i l = splat_i(lo);
   return seli(i < l, l, seli(i > h, h, i));
}

static inline __attribute__((always_inline)) lanes_i inside(lanes_i i, lanes_i size)
{
   return seli((i >= 0) & (i < size), i, splat_i(-1));
}

/* One axis of the lanes' addresses: the two texel indices (-1: the
 * border) and the weight of the second, per pixel. */
struct lanes_addr {
   lanes_i i0, i1, w;
};

/* tex_fast_path.h's addr on the quad. */
static inline __attribute__((always_inline)) void
lanes_addr_of(const struct tex_unit *u, const bool linear, unsigned wrap,
              const struct lanes_axis *ax, struct dfxl c, struct lanes_addr *a,
              struct dfxl_stats *st)
{
   bool border = false, bounded = false;
   dfxl_i odd;
   lanes_i i, w;
   const lanes_i size = ax->size, last = size - 1;
   const lanes_i zero = splat_i(0);
   switch (wrap) {
   case TEX_WRAP_REPEAT: {
      dfxl_i below;
      const struct dfxl s = dfxl_mul(lanes_frac_of(c, &odd, &below, st), (struct dfxl){ ax->scale },
                                     st);
      const lanes_i period = __builtin_convertvector(below, lanes_i) & size;
      if (!linear) {
         floor_frac(s, false, &i, &w, st);
         a->i0 = a->i1 = clampi(i + period, 0, last);
         a->w = zero;
         return;
      }
      floor_frac(sub_texel_offset(s, st), false, &i, &w, st);
      const lanes_i k = clampi(i + period, -1, last);
      a->i0 = seli(k < 0, last, k);
      a->i1 = seli(k + 1 >= size, zero, k + 1);
      a->w = w;
      return;
   }
   case TEX_WRAP_MIRROR_REPEAT: {
      dfxl_i below;
      const struct dfxl f = lanes_frac_of(c, &odd, &below, st);
      struct dfxl_stats ev = DFXL_STATS(st->optimistic);
      const struct dfxl m = dfxl_sub(splat(u->lk_one), f, &ev);
      /* the scalar path subtracts where odd and not below */
      dfxl_merge_where(st, &ev, odd & ~below);
      c.v = dfxl_seld(below, dfxl_abs(c.v), dfxl_seld(odd, m.v, f.v));
      break;
   }
   default: {
      bool mirror;
      clamp_mode(wrap, linear, &mirror, &border);
      if (mirror)
         c.v = dfxl_abs(c.v);
      c = clamp(c, ax);
      bounded = true;
      break;
   }
   }
   struct dfxl s = dfxl_mul(c, (struct dfxl){ ax->scale }, st);
   if (!linear) {
      floor_frac(s, bounded, &i, &w, st);
      a->i0 = a->i1 = border ? inside(i, size) : clampi(i, 0, last);
      a->w = zero;
      return;
   }
   s = sub_texel_offset(s, st);
   floor_frac(s, bounded, &i, &w, st);
   /* the scalar path's i + 1 in 64 bits: INT32_MAX + 1 is outside and
    * above every size, as INT32_MAX itself */
   const lanes_i i1 = i - (i != splat_i(INT32_MAX));
   a->w = w;
   if (border) {
      a->i0 = inside(i, size);
      a->i1 = inside(i1, size);
   } else {
      a->i0 = clampi(i, 0, last);
      a->i1 = clampi(i1, 0, last);
   }
}

/* The 4-byte layouts (tex_fast_path.h's fetch and tap) for the whole quad,
 * a channel of up to eight taps in one vector: where the scalar path
 * decodes a texel and blends four channels at a time, these decode and
 * blend one channel of every tap, the same IEEE operations element by
 * element, for the units tex_bind.c marks `lanes_soa`.  Shadow samplers
 * and other layouts take the per-pixel taps. */
/* The taps' words at byte offsets `off` (lanes whose tap is in the
 * texture; the others read the level's first texel and are replaced by
 * the border afterwards). */
static inline __attribute__((always_inline)) taps_i
gather(const struct tex_level *lv, taps_i off)
{
#if DFXL_N == 8 && defined(__AVX512F__)
   return (taps_i)_mm512_i32gather_epi32((__m512i)off, (const void *)lv->data, 1);
#elif defined(__AVX2__) && DFXL_N == 4
   return (taps_i)_mm256_i32gather_epi32((const int *)(const void *)lv->data, (__m256i)off, 1);
#else
   taps_i w;
   for (unsigned k = 0; k < 2 * DFXL_N; k++) {
      uint32_t t;
      memcpy(&t, lv->data + off[k], 4);
      w[k] = (int32_t)t;
   }
   return w;
#endif
}

/* Offsets of taps (x, y) in the level, in pixels' layers `zoff` (bytes);
 * `out`: the taps outside the texture, when the wrap modes have a border. */
static inline __attribute__((always_inline)) taps_i
soa_offsets(const struct tex_level *lv, taps_i x, taps_i y, taps_i zoff, bool border,
            taps_i *out)
{
   const int32_t rs = (int32_t)lv->row_stride;
   const taps_i off = zoff + y * rs + x * 4;
   *out = (taps_i){ 0 };
   if (!border)
      return off;
   *out = (x | y) < 0;
   return off & ~*out;
}

/* (word >> shift) & mask of the channel: one byte shuffle where the set
 * has it. */
static inline __attribute__((always_inline)) taps_i
channel_byte(const struct tex_lanes_channel *c, taps_i words)
{
#if DFXL_N == 8 && defined(__AVX512BW__)
   const __m128i pick = _mm_loadu_si128((const __m128i *)(const void *)c->pick);
   return (taps_i)_mm512_shuffle_epi8((__m512i)words, _mm512_broadcast_i32x4(pick));
#elif DFXL_N == 4 && defined(__AVX2__)
   const __m128i pick = _mm_loadu_si128((const __m128i *)(const void *)c->pick);
   return (taps_i)_mm256_shuffle_epi8((__m256i)words, _mm256_broadcastsi128_si256(pick));
#else
   return (words >> c->shift) & c->mask;
#endif
}

/* Result channel `ch` of the words (tex_unorm8 of its byte after the
 * swizzle, tex_bind.c's lanes_channels), the border where outside.
 * Without a border the channel is not a constant one (constant_channel
 * takes those), so its `add` is 0, and v + 0 is v for v >= 0. */
static inline __attribute__((always_inline)) taps_f
soa_channel(const struct tex_unit *u, taps_i words, bool border, taps_i out, unsigned ch)
{
   const struct tex_lanes_channel *c = &u->lanes_ch[ch];
   const taps_f v = __builtin_convertvector(channel_byte(c, words), taps_f) * (1.0f / 255.0f);
   if (!border)
      return v;
   const taps_f bv = (taps_f){ 0 } + c->border;
   return (taps_f)(((taps_i)(v + c->add) & ~out) | ((taps_i)bv & out));
}

/* A result channel that is one value at every tap (a swizzle's 0 or 1, an
 * RGBX texture's alpha) where no tap can be the border: the filter gives
 * that value itself (a + f (a - a) is a, f >= 0), so it is not decoded or
 * filtered.  Decided by the unit's state, the same for every call. */
static inline __attribute__((always_inline)) bool
constant_channel(const struct tex_unit *u, bool border, unsigned ch)
{
   return !border && (u->lanes_const >> ch & 1);
}

/* lerp4 per element: a + f (b - a), f the weight over TEX_WEIGHT_ONE. */
static inline __attribute__((always_inline)) lanes_f weights(lanes_i w)
{
   return __builtin_convertvector(w, lanes_f) * (1.0f / TEX_WEIGHT_ONE);
}

/* The linear filter of soa_level2 on its taps' words: w0 holds taps
 * (i0, j0) and (i0, j1), w1 (i1, j0) and (i1, j1); o0, o1 the taps
 * outside (the border). */
static inline __attribute__((always_inline)) void
soa_filter2(const struct tex_unit *u, const bool border, const struct lanes_addr *A,
            const struct lanes_addr *B, taps_i w0, taps_i o0, taps_i w1, taps_i o1,
            lanes_f out[4])
{
   const lanes_f fa = weights(A->w), fb = weights(B->w);
   const taps_f fa2 = TWICE(fa);
#pragma GCC unroll 4
   for (unsigned ch = 0; ch < 4; ch++) {
      if (constant_channel(u, border, ch)) {
         out[ch] = (lanes_f){ 0 } + u->lanes_ch[ch].add;
         continue;
      }
      const taps_f t0 = soa_channel(u, w0, border, o0, ch),
                   t1 = soa_channel(u, w1, border, o1, ch);
      const taps_f e = t0 + fa2 * (t1 - t0);
      const lanes_f e0 = LO(e), e1 = HI(e);
      out[ch] = e0 + fb * (e1 - e0);
   }
}

/* tex_fast_path.h's level for two dimensions, one channel of the lanes'
 * pixels per vector, the result channels (after the swizzle).  `border`:
 * whether a tap can be outside (the wrap modes). */
static inline __attribute__((always_inline)) void
soa_level2(const struct tex_unit *u, const bool linear, const bool border, unsigned l,
           const struct lanes_addr *A, const struct lanes_addr *B, lanes_i zoff,
           lanes_f out[4])
{
   const struct tex_level *lv = &u->view.level[l];
   const taps_i z = TWICE(zoff);
   if (!linear) {
      taps_i o;
      const taps_i w = gather(lv, soa_offsets(lv, TWICE(A->i0), TWICE(B->i0), z, border, &o));
#pragma GCC unroll 4
      for (unsigned ch = 0; ch < 4; ch++)
         out[ch] = constant_channel(u, border, ch) ? (lanes_f){ 0 } + u->lanes_ch[ch].add
                                                   : LO(soa_channel(u, w, border, o, ch));
      return;
   }
   /* taps (i0, j0) and (i0, j1) in one vector, (i1, j0) and (i1, j1) in the other */
   const taps_i y = CONCAT(B->i0, B->i1);
   taps_i o0, o1;
   const taps_i w0 = gather(lv, soa_offsets(lv, TWICE(A->i0), y, z, border, &o0));
   const taps_i w1 = gather(lv, soa_offsets(lv, TWICE(A->i1), y, z, border, &o1));
   soa_filter2(u, border, A, B, w0, o0, w1, o1, out);
}

/* What a quad function is specialised for (a negative field: read from
 * the unit per quad): the wrap modes of s and t, whether the texels take
 * the one-channel-per-vector filter, whether the LOD is left out (the
 * sampler cannot use it: tex_unit_lod_unused). */
struct quad_kind {
   int ws, wt, soa;
   bool nolod;
};

/* Whether a wrap mode (negative: not known here) can put a tap outside. */
static inline __attribute__((always_inline)) bool may_border(int wrap, bool linear)
{
   if (wrap < 0)
      return true;
   bool mirror, border;
   clamp_mode((unsigned)wrap, linear, &mirror, &border);
   return border;
}

#endif
