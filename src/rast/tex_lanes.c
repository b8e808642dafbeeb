/*
 * The texture unit's quad for dfx24 on lanes (2-D and 2-D array targets):
 * the quad's four coordinates enter the unit, give the LOD and are
 * addressed together through dfx_lanes.h, each lane the operations of
 * tex_fast.c's quad in its order; fetch and filtering, which read
 * memory per texel, stay per pixel (tex_fast_path.h).  Pixels of one quad
 * at different levels (a per-pixel bias or explicit LOD that differs) and
 * coordinates outside the coordinate input's direct range take the scalar
 * operations for that pixel or lane: the same operations, so the same bits.
 */
#include "rast/tex_fast_path.h"
#include "rast/lanes_fns.h"
#include "fixed/dfx_lanes.h"

typedef float lanes_v4f __attribute__((vector_size(16)));
typedef int32_t lanes_v4i __attribute__((vector_size(16)));

static inline __attribute__((always_inline)) struct dfxl splat(double v)
{
   struct dfxl r = { { v, v, v, v } };
   return r;
}


/* tex_fcoord: binary32 to the register, toward -inf.  A double holds the
 * float; truncating it to its digit's grid and stepping a negative one
 * down by a grid step when something was cut is the scalar path's
 * "m24 >> sh, + 1 if negative and bits dropped".  Zero, the range beyond
 * 2^-32 .. 2^32, inf, NaN and a step past L = 15 take tex_ns_coord. */
static inline __attribute__((always_inline)) struct dfxl
coord(const struct tex_unit *u, const float v[TEX_QUAD], struct tex_fst *x)
{
   lanes_v4f f;
   memcpy(&f, v, sizeof(f));
   const dfxl_d d = __builtin_convertvector(f, dfxl_d);
   const dfxl_d ad = dfxl_abs(d);
   const dfxl_i c = 37 - ((dfxl_exponent(d) + 1) & 3);
   dfxl_d r = dfxl_clear_low(d, c);
   r = dfxl_seld((r != d) & (d < 0), r - dfxl_grid(d), r);
   const dfxl_i direct = (ad >= 0x1p-32) & (dfxl_abs(r) < 0x1p32);
   struct dfxl o = { (dfxl_d)((dfxl_i)r & direct) };
   for (unsigned p = 0; p < TEX_QUAD; p++)
      if (!direct[p] && v[p] != 0.0f)
         o.v[p] = dfxl_value(tex_ns_coord(u->ns, TEX_NS_DFX, v[p], &x->n).d);
   return o;
}

/* floor(a) saturated to int32 (counted), as a double, and which lanes saturated. */
static inline __attribute__((always_inline)) dfxl_d
floor_int32(dfxl_d a, dfxl_i *sat, struct dfxl_stats *st)
{
   const dfxl_d fl = dfxl_floor(a);
   const dfxl_i hi = fl > (double)INT32_MAX, lo = fl < (double)INT32_MIN;
   *sat = hi | lo;
   st->sat -= *sat;
   return dfxl_seld(hi, (dfxl_d){ INT32_MAX, INT32_MAX, INT32_MAX, INT32_MAX },
                    dfxl_seld(lo, (dfxl_d){ INT32_MIN, INT32_MIN, INT32_MIN, INT32_MIN }, fl));
}

/* tex_ffloor with TEX_WEIGHT_BITS fraction bits: the integer part (floor),
 * saturated to int32 (counted, fraction 0 then), and the fraction's bits. */
static inline __attribute__((always_inline)) void
floor_frac(struct dfxl a, lanes_v4i *ip, lanes_v4i *frac, struct dfxl_stats *st)
{
   dfxl_i sat;
   const dfxl_d cl = floor_int32(a.v, &sat, st);
   const dfxl_d fr = dfxl_floor(a.v * (double)TEX_WEIGHT_ONE) - cl * (double)TEX_WEIGHT_ONE;
   *ip = __builtin_convertvector(cl, lanes_v4i);
   *frac = __builtin_convertvector(dfxl_seld(sat, (dfxl_d){ 0, 0, 0, 0 }, fr), lanes_v4i);
}

/* frac_of: c - floor(c) (floor saturated to int32, through binary32 into
 * the register as tex_fint), and the parity of floor(c). */
static inline __attribute__((always_inline)) struct dfxl
lanes_frac_of(struct dfxl c, dfxl_i *odd, struct dfxl_stats *st)
{
   dfxl_i sat;
   const dfxl_d cl = floor_int32(c.v, &sat, st);
   const lanes_v4i i = __builtin_convertvector(cl, lanes_v4i);
   *odd = __builtin_convertvector(i & 1, dfxl_i) != 0;
   const dfxl_d asf = __builtin_convertvector(__builtin_convertvector(cl, lanes_v4f), dfxl_d);
   return dfxl_sub(c, dfxl_from_int(asf, st), st);
}

static inline __attribute__((always_inline)) struct dfxl
clamp(struct dfxl c, const double lh[3])
{
   const double l = lh[1], h = lh[2];
   c.v = dfxl_seld(c.v < l, splat(l).v, dfxl_seld(c.v > h, splat(h).v, c.v));
   return c;
}

struct lanes_addr {
   int32_t i0[TEX_QUAD], i1[TEX_QUAD];
   uint32_t w[TEX_QUAD];
};

/* tex_fast_path.h's addr on the quad. */
static inline __attribute__((always_inline)) void
lanes_addr_of(const struct tex_unit *u, const bool linear, unsigned wrap, const struct tex_axis *ax,
              const double lax[3], struct dfxl c, struct lanes_addr *a, struct dfxl_stats *st)
{
   bool border = false;
   dfxl_i odd;
   lanes_v4i i, w;
   const int32_t size = ax->size;
   switch (wrap) {
   case TEX_WRAP_REPEAT: {
      const struct dfxl s = dfxl_mul(lanes_frac_of(c, &odd, st), splat(lax[0]), st);
      if (!linear) {
         floor_frac(s, &i, &w, st);
         for (unsigned p = 0; p < TEX_QUAD; p++) {
            a->i0[p] = a->i1[p] = tex_clampi(i[p], 0, size - 1);
            a->w[p] = 0;
         }
         return;
      }
      floor_frac(dfxl_sub(s, splat(u->lk_texel_offset), st), &i, &w, st);
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         const int32_t k = tex_clampi(i[p], -1, size - 1);
         a->i0[p] = k < 0 ? size - 1 : k;
         a->i1[p] = k + 1 >= size ? 0 : k + 1;
         a->w[p] = (uint32_t)w[p];
      }
      return;
   }
   case TEX_WRAP_MIRROR_REPEAT: {
      const struct dfxl f = lanes_frac_of(c, &odd, st);
      struct dfxl_stats ev = { dfxl_splat(0), dfxl_splat(0) };
      const struct dfxl m = dfxl_sub(splat(u->lk_one), f, &ev);
      st->sat += ev.sat & odd;                   /* the scalar path subtracts where odd */
      st->flush += ev.flush & odd;
      c.v = dfxl_seld(odd, m.v, f.v);
      break;
   }
   default: {
      bool mirror;
      clamp_mode(wrap, linear, &mirror, &border);
      if (mirror)
         c.v = dfxl_abs(c.v);
      c = clamp(c, lax);
      break;
   }
   }
   struct dfxl s = dfxl_mul(c, splat(lax[0]), st);
   if (!linear) {
      floor_frac(s, &i, &w, st);
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         a->i0[p] = a->i1[p] = border ? tex_inside(i[p], size) : tex_clampi(i[p], 0, size - 1);
         a->w[p] = 0;
      }
      return;
   }
   s = dfxl_sub(s, splat(u->lk_texel_offset), st);
   floor_frac(s, &i, &w, st);
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      const int64_t k = i[p];
      a->w[p] = (uint32_t)w[p];
      if (border) {
         a->i0[p] = tex_inside(k, size);
         a->i1[p] = tex_inside(k + 1, size);
      } else {
         a->i0[p] = tex_clampi(k, 0, size - 1);
         a->i1[p] = tex_clampi(k + 1, 0, size - 1);
      }
   }
}

/* tex_fast_path.h's level for two dimensions, the quad's addresses at once. */
static inline __attribute__((always_inline)) void
level2(const struct tex_unit *u, const bool linear, unsigned l, struct dfxl cs, struct dfxl ct,
       const int layer[TEX_QUAD], const float ref[TEX_QUAD], v4f out[TEX_QUAD],
       struct dfxl_stats *st)
{
   const struct tex_level *lv = &u->view.level[l];
   const struct tex_axis *ax = u->axis[l];
   struct lanes_addr A, B;
   lanes_addr_of(u, linear, u->samp.wrap[0], &ax[0], u->laxis[l][0], cs, &A, st);
   lanes_addr_of(u, linear, u->samp.wrap[1], &ax[1], u->laxis[l][1], ct, &B, st);
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      const int z = layer[p];
      if (!linear) {
         out[p] = tap(u, lv, A.i0[p], B.i0[p], z, ref[p]);
         continue;
      }
      out[p] = lerp4(lerp4(tap(u, lv, A.i0[p], B.i0[p], z, ref[p]),
                           tap(u, lv, A.i1[p], B.i0[p], z, ref[p]), A.w[p]),
                     lerp4(tap(u, lv, A.i0[p], B.i1[p], z, ref[p]),
                           tap(u, lv, A.i1[p], B.i1[p], z, ref[p]), A.w[p]),
                     B.w[p]);
   }
}

/* tex_lod_diffs for two dimensions: the four differences in one vector. */
static inline __attribute__((always_inline)) int32_t
lod2(const struct tex_unit *u, struct dfxl cs, struct dfxl ct, struct dfxl_stats *st)
{
   const struct dfxl d1 = { { cs.v[1], cs.v[2], ct.v[1], ct.v[2] } };
   const struct dfxl d0 = { { cs.v[0], cs.v[0], ct.v[0], ct.v[0] } };
   const double ss = u->laxis[0][0][0], st_ = u->laxis[0][1][0];
   const struct dfxl sc = { { ss, ss, st_, st_ } };
   const dfxl_d m = dfxl_abs(dfxl_mul(dfxl_sub(d1, d0, st), sc, st).v);
   double rho = 0;
   for (unsigned i = 0; i < 4; i++)
      rho = m[i] > rho ? m[i] : rho;
   ns_val r = { .x = 0 };
   r.d = dfxl_fields(rho);
   return tex_lod_from_rho(u, r);
}

void LANES_FN(tex_dfx19_2d_lanes)(const struct tex_unit *u, const struct tex_quad *q,
                                  enum tex_lod_control ctl, float rgba[4][TEX_QUAD])
{
   if (ctl == TEX_LOD_DERIVS) {
      tex_unit_sample_generic(u, q, ctl, rgba);
      return;
   }
   struct tex_fst x = { { 0, 0 }, { 0, 0 } };
   struct dfxl_stats st = { dfxl_splat(0), dfxl_splat(0) };
   const bool array = u->view.target == TEX_TARGET_2D_ARRAY;
   const struct dfxl cs = coord(u, q->s, &x), ct = coord(u, q->t, &x);
   int layer[TEX_QUAD];
   int32_t lod[TEX_QUAD];
   v4f out[TEX_QUAD];
   for (unsigned p = 0; p < TEX_QUAD; p++)
      layer[p] = array ? layer_of(u, q->layer[p]) : 0;

   lods(ctl, tex_lod_from_diffs(ctl) ? lod2(u, cs, ct, &st) : 0, q, lod);

   int32_t cl[TEX_QUAD];
   for (unsigned p = 0; p < TEX_QUAD; p++)
      cl[p] = tex_clamp_lod(u, lod[p]);
   if (cl[0] == cl[1] && cl[0] == cl[2] && cl[0] == cl[3]) {
      unsigned l0, l1;
      uint32_t frac;
      enum tex_filter f;
      tex_unit_select(u, cl[0], &l0, &l1, &frac, &f);
      const bool linear = f != TEX_FILTER_NEAREST;
      if (linear)
         level2(u, true, l0, cs, ct, layer, q->ref, out, &st);
      else
         level2(u, false, l0, cs, ct, layer, q->ref, out, &st);
      if (frac) {
         v4f o1[TEX_QUAD];
         if (linear)
            level2(u, true, l1, cs, ct, layer, q->ref, o1, &st);
         else
            level2(u, false, l1, cs, ct, layer, q->ref, o1, &st);
         for (unsigned p = 0; p < TEX_QUAD; p++)
            out[p] = lerp4(out[p], o1[p], frac);
      }
   } else {
      /* levels differ inside the quad: pixel by pixel, as tex_fast.c */
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         ns_val c[3] = { { .x = 0 }, { .x = 0 }, { .x = 0 } };
         c[0].d = dfxl_fields(cs.v[p]);
         c[1].d = dfxl_fields(ct.v[p]);
         unsigned l0, l1;
         uint32_t frac;
         enum tex_filter f;
         tex_unit_select(u, cl[p], &l0, &l1, &frac, &f);
         out[p] = level_f(u, TEX_FK_DFX19, 2, f, l0, c, layer[p], q->ref[p], &x);
         if (frac)
            out[p] = lerp4(out[p], level_f(u, TEX_FK_DFX19, 2, f, l1, c, layer[p], q->ref[p],
                                           &x), frac);
      }
   }

   for (unsigned ch = 0; ch < 4; ch++) {
      const unsigned s = u->view.swizzle[ch];
      for (unsigned p = 0; p < TEX_QUAD; p++)
         rgba[ch][p] = s < 4 ? out[p][s] : s == TEX_SWZ_1 ? 1.0f : 0.0f;
   }
   dfxl_stats_add(&x.d, st);
   tex_fst_flush(&x, u->stats);
}
