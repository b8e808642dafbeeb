/*
 * Depth and stencil of the fragment back end.
 *
 * Depth values, exactly (one rule for the test and for the write, so the
 * early and late paths store the same bits):
 *
 *  From the rasterizer: q->z[i] is the Z register, Zfixed in units of
 *  2^-frac_bits, and FULL = (2^z_bits - 1) << frac_bits means depth 1.0.
 *  Zc = clamp(Zfixed, LO, HI), where [LO, HI] is [0, FULL] (depth [0, 1])
 *  or, with the depth clamp (rs.depth_clamp), the Z registers of the
 *  primitive's viewport's min(n, f) and max(n, f), which lie inside it.
 *  For an N-bit unorm buffer (Z16, Z24 in any of its four packings, Z32)
 *
 *        stored = floor((2 * Zc * (2^N - 1) + FULL) / (2 * FULL))
 *
 *  i.e. Zc / FULL * (2^N - 1) rounded to nearest, halves up, computed in
 *  integers with no intermediate rounding.  The register's fraction bits take
 *  part: a profile with fewer integer bits than the buffer (seed: z_bits 19
 *  into a 24-bit buffer) is rescaled, not padded with zero bits, so depth 1.0
 *  (Zfixed = FULL) stores 2^24 - 1 and depth 0.5 of the register lands on
 *  the nearest of the buffer's codes, using the 12 fraction bits the walker
 *  carries; the buffer then holds more distinct values than the profile's 19
 *  integer bits, exactly those the register can reach.  When N == z_bits
 *  (wide profile into Z24) the rule reduces to rounding the register to an
 *  integer: (Zc + 2^(frac_bits-1)) >> frac_bits.
 *  For Z32F: stored = (float)((double)Zc / FULL), the quotient correctly
 *  rounded to float (rounding to double first is innocuous for a division,
 *  53 >= 2*24 + 2).
 *
 *  Written by the shader: d = out->depth[i] clamped to [0, 1] (NaN -> 0);
 *  unorm N: floor(d * (2^N - 1) + 1/2) computed exactly in integers from the
 *  float's bits; Z32F: d itself.  With the depth clamp, a d below LO / FULL
 *  (exactly) stores what Zc = LO stores, one above HI / FULL what HI does:
 *  both rules round the exact depth to the buffer monotonically, so that is
 *  the shader's value clamped in buffer units to the bounds' values, which
 *  validation computes once per viewport (struct rast_zrange).
 *
 * The compare is "fragment func buffer" in those units.  Stencil per GL ES:
 * (ref & valuemask) func (stencil & valuemask), then the face's fail, zfail
 * or zpass op, written through the writemask.  The back face uses
 * stencil[1] and stencil_ref[1] only when stencil[1].enabled (gallium's
 * two-sided flag); stencil[0].enabled switches the whole test.
 */
#include <string.h>
#include <stddef.h>
#include "rast/backend/backend_priv.h"

#if defined(__GNUC__)
#define RAST_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define RAST_ALWAYS_INLINE inline
#endif

/* ------------------------------------------------------------------ */
/* Conversions.                                                         */

#if defined(__SIZEOF_INT128__)
__extension__ typedef unsigned __int128 rast_u128;

static uint64_t muldiv_round_wide(uint64_t z, uint64_t full, uint64_t max)
{
   rast_u128 n = (rast_u128)z * max * 2 + full;
   return (uint64_t)(n / ((rast_u128)full * 2));
}
#else
/* 128-bit numerator as hi:lo, bit-serial division: only for unorm32
 * buffers with profiles whose FULL * 2^33 overflows 64 bits. */
static uint64_t muldiv_round_wide(uint64_t z, uint64_t full, uint64_t max)
{
   uint64_t zl = z & 0xffffffffu, zh = z >> 32;
   uint64_t p0 = zl * max, p1 = zh * max;           /* max < 2^32 */
   uint64_t lo = p0 + (p1 << 32);
   uint64_t hi = (p1 >> 32) + (lo < p0);
   hi = (hi << 1) | (lo >> 63);                      /* * 2 */
   lo <<= 1;
   uint64_t lo2 = lo + full;
   hi += lo2 < lo;
   lo = lo2;
   uint64_t d = full * 2, rem = 0, q = 0;
   for (int b = 127; b >= 0; b--) {
      uint64_t bit = b >= 64 ? (hi >> (b - 64)) & 1 : (lo >> b) & 1;
      rem = (rem << 1) | bit;
      q <<= 1;
      if (rem >= d) { rem -= d; q |= 1; }
   }
   return q;
}
#endif

static bool muldiv_fits64(uint64_t full, uint64_t max)
{
   return full <= UINT64_MAX / (2 * max + 1);
}

/* The rule in the header comment, for callers outside the quad loop
 * (tests and the slow path).  z must already be clamped to [0, full]. */
uint32_t rast_z_to_unorm(uint64_t z, uint64_t full, uint64_t max)
{
   if (muldiv_fits64(full, max))
      return (uint32_t)((2 * z * max + full) / (2 * full));
   return (uint32_t)muldiv_round_wide(z, full, max);
}

/* The division by D = 2·full, a state's constant, as a multiply: 40 cycles
 * or so a pixel where the multiply takes 4.  D = 2^s · B with B odd, and
 * floor(n / D) = floor(t / B) for t = floor(n / 2^s).  With t < 2^a,
 * B < 2^b, k = a + b and m = ceil(2^k / B) = (2^k + e) / B, 0 <= e < B:
 * t·m / 2^k = t / B + t·e / (B·2^k), and t·e < 2^k, so the second term is
 * below 1/B, and t / B's fraction is at most (B - 1) / B: the floor is
 * t / B's.  m < 2^(a + 1) and t·m < 2^(2a + 1): both fit where a < 64. */
#if defined(__SIZEOF_INT128__)
bool rast_zdiv_init(struct rast_zdiv *d, uint64_t full, uint64_t max)
{
   if (!full || !muldiv_fits64(full, max))
      return false;
   const uint64_t D = 2 * full, nmax = 2 * full * max + full;
   d->s = (unsigned)__builtin_ctzll(D);
   const uint64_t B = D >> d->s, tmax = nmax >> d->s;
   const unsigned a = tmax ? 64 - (unsigned)__builtin_clzll(tmax) : 1;
   const unsigned b = 64 - (unsigned)__builtin_clzll(B);
   d->k = a + b;
   if (a >= 64 || d->k > 127)
      return false;
   d->m = (uint64_t)((((rast_u128)1 << d->k) + B - 1) / B);
   return true;
}

uint32_t rast_zdiv_to_unorm(const struct rast_zdiv *d, uint64_t z, uint64_t full, uint64_t max)
{
   const uint64_t t = (2 * z * max + full) >> d->s;
   return (uint32_t)(((rast_u128)t * d->m) >> d->k);
}

/* Whether the same floor(t / B) comes from a division of doubles, as the
 * group's lanes take it (backend_lanes.c): every t below 2^53 is a double
 * exactly, and the quotient's rounding never reaches the next integer
 * where half its ulp is below 1/B (a quotient that is not an integer lies
 * at least 1/B below the next one).  The quotient is at most max, below
 * 2^nbits, where the ulp is at most 2^(nbits - 53). */
static bool zdiv_exact_in_doubles(const struct rast_zdiv *d, uint64_t full, uint64_t max)
{
   const uint64_t B = (2 * full) >> d->s;
   const rast_u128 tmax = ((rast_u128)2 * full * max + full) >> d->s;
   const unsigned nbits = max ? 64 - (unsigned)__builtin_clzll(max) : 1;
   return tmax < ((rast_u128)1 << 53) && nbits < 53 && B < (UINT64_C(1) << (53 - nbits));
}
#else
static bool zdiv_exact_in_doubles(const struct rast_zdiv *d, uint64_t full, uint64_t max)
{
   (void)d; (void)full; (void)max;
   return false;
}

bool rast_zdiv_init(struct rast_zdiv *d, uint64_t full, uint64_t max)
{
   (void)d; (void)full; (void)max;
   return false;
}

uint32_t rast_zdiv_to_unorm(const struct rast_zdiv *d, uint64_t z, uint64_t full, uint64_t max)
{
   (void)d;
   return rast_z_to_unorm(z, full, max);
}
#endif

/* d in [0, 1]: floor(d * (2^nbits - 1) + 1/2) without rounding on the way:
 * d = m * 2^(e - 150), and m * (2^nbits - 1) < 2^56. */
uint32_t rast_float_to_unorm(float d, unsigned nbits)
{
   uint32_t b;
   memcpy(&b, &d, sizeof b);
   unsigned e = (b >> 23) & 0xff;
   uint64_t m = b & 0x7fffff;
   if (e)
      m |= 0x800000;
   else
      e = 1;
   unsigned s = 150 - e;            /* >= 23 because d <= 1 */
   if (s > 60)
      return 0;
   uint64_t max = (nbits >= 32 ? UINT64_C(0xffffffff) : (UINT64_C(1) << nbits) - 1);
   return (uint32_t)((m * max + (UINT64_C(1) << (s - 1))) >> s);
}

/* The bounds are registers of the state and the viewport, [0, FULL]
 * without the depth clamp: one code path either way, no flag per pixel. */
static inline uint64_t clamp_z(const struct rast_backend *be, int64_t z)
{
   const int64_t lo = (int64_t)be->zr.lo, hi = (int64_t)be->zr.hi;
   return (uint64_t)(z < lo ? lo : z > hi ? hi : z);
}

static inline float clamp_depth(float d)
{
   if (!(d > 0.0f))
      return 0.0f;                   /* NaN too */
   return d < 1.0f ? d : 1.0f;
}

/* N == z_bits: the rule is rounding the register to an integer. */
static void zconv_shift(const struct rast_backend *be, const struct rast_quad *q,
                        const struct rast_shaded_quad *out, union rast_zq *z)
{
   (void)out;
   const unsigned f = be->z_frac;
   const uint64_t half = f ? UINT64_C(1) << (f - 1) : 0;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      z->u[i] = (uint32_t)((clamp_z(be, q->z[i]) + half) >> f);
}

static void zconv_div(const struct rast_backend *be, const struct rast_quad *q,
                      const struct rast_shaded_quad *out, union rast_zq *z)
{
   (void)out;
   const uint64_t full = be->z_full, max = be->z_max;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      z->u[i] = (uint32_t)((2 * clamp_z(be, q->z[i]) * max + full) / (2 * full));
}

static void zconv_mul(const struct rast_backend *be, const struct rast_quad *q,
                      const struct rast_shaded_quad *out, union rast_zq *z)
{
   (void)out;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      z->u[i] = rast_zdiv_to_unorm(&be->zdiv, clamp_z(be, q->z[i]), be->z_full, be->z_max);
}

static void zconv_div_wide(const struct rast_backend *be, const struct rast_quad *q,
                           const struct rast_shaded_quad *out, union rast_zq *z)
{
   (void)out;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      z->u[i] = (uint32_t)muldiv_round_wide(clamp_z(be, q->z[i]), be->z_full, be->z_max);
}

static void zconv_float(const struct rast_backend *be, const struct rast_quad *q,
                        const struct rast_shaded_quad *out, union rast_zq *z)
{
   (void)out;
   const double full = (double)be->z_full;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      z->f[i] = (float)((double)clamp_z(be, q->z[i]) / full);
}

static void zconv_shader_unorm(const struct rast_backend *be, const struct rast_quad *q,
                               const struct rast_shaded_quad *out, union rast_zq *z)
{
   (void)q;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      z->u[i] = rast_float_to_unorm(clamp_depth(out->depth[i]), be->z_nbits);
}

static void zconv_shader_float(const struct rast_backend *be, const struct rast_quad *q,
                               const struct rast_shaded_quad *out, union rast_zq *z)
{
   (void)be; (void)q;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      z->f[i] = clamp_depth(out->depth[i]);
}

/* The depth clamp of a shader's depth: its value in buffer units clamped
 * to the bounds' (the header comment says why that is the exact clamp). */
static void zconv_shader_unorm_clamp(const struct rast_backend *be, const struct rast_quad *q,
                                     const struct rast_shaded_quad *out, union rast_zq *z)
{
   (void)q;
   const uint32_t lo = be->zr.code_lo.u, hi = be->zr.code_hi.u;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      const uint32_t u = rast_float_to_unorm(clamp_depth(out->depth[i]), be->z_nbits);
      z->u[i] = u < lo ? lo : u > hi ? hi : u;
   }
}

static void zconv_shader_float_clamp(const struct rast_backend *be, const struct rast_quad *q,
                                     const struct rast_shaded_quad *out, union rast_zq *z)
{
   (void)q;
   const float lo = be->zr.code_lo.f, hi = be->zr.code_hi.f;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      const float d = clamp_depth(out->depth[i]);
      z->f[i] = d < lo ? lo : d > hi ? hi : d;
   }
}

/* ------------------------------------------------------------------ */
/* Buffer access.                                                       */

static const unsigned zfamily_cpp[RAST_ZF_COUNT] = { 0, 2, 4, 4, 4, 4, 8 };

static inline uint8_t *zs_pixel(const struct rast_backend *be, int x, int y, unsigned cpp)
{
   return be->zs_base + (ptrdiff_t)y * be->zs_stride + (ptrdiff_t)x * (ptrdiff_t)cpp;
}

static RAST_ALWAYS_INLINE uint32_t load32(const uint8_t *p)
{
   uint32_t v;
   memcpy(&v, p, 4);
   return v;
}

static RAST_ALWAYS_INLINE void store32(uint8_t *p, uint32_t v)
{
   memcpy(p, &v, 4);
}

/* Unorm depth of the integer families (bit pattern of the float for F32*). */
static RAST_ALWAYS_INLINE uint32_t zread(enum rast_zfamily fam, const uint8_t *p)
{
   switch (fam) {
   case RAST_ZF_U16: { uint16_t v; memcpy(&v, p, 2); return v; }
   case RAST_ZF_U24LO: return load32(p) & 0xffffffu;
   case RAST_ZF_U24HI: return load32(p) >> 8;
   default: return load32(p);
   }
}

static RAST_ALWAYS_INLINE void zwrite(enum rast_zfamily fam, uint8_t *p, uint32_t z)
{
   switch (fam) {
   case RAST_ZF_U16: { uint16_t v = (uint16_t)z; memcpy(p, &v, 2); break; }
   case RAST_ZF_U24LO: store32(p, (load32(p) & 0xff000000u) | z); break;
   case RAST_ZF_U24HI: store32(p, (load32(p) & 0xffu) | (z << 8)); break;
   default: store32(p, z); break;
   }
}

/* The depth and stencil tests' comparison, on the integer registers and
 * on binary32 depth alike. */
#define RAST_CMP(name, type)                                                   \
   static RAST_ALWAYS_INLINE bool name(enum rast_func f, type a, type b)     \
   {                                                                         \
      switch (f) {                                                           \
      case RAST_FUNC_NEVER: return false;                                    \
      case RAST_FUNC_LESS: return a < b;                                     \
      case RAST_FUNC_EQUAL: return a == b;                                   \
      case RAST_FUNC_LEQUAL: return a <= b;                                  \
      case RAST_FUNC_GREATER: return a > b;                                  \
      case RAST_FUNC_NOTEQUAL: return a != b;                                \
      case RAST_FUNC_GEQUAL: return a >= b;                                  \
      default: return true;                                                  \
      }                                                                      \
   }
RAST_CMP(cmp_u, uint32_t)
RAST_CMP(cmp_f, float)
#undef RAST_CMP

static RAST_ALWAYS_INLINE bool ztest(enum rast_zfamily fam, enum rast_func f,
                                    const uint8_t *p, const union rast_zq *z, unsigned i)
{
   if (fam == RAST_ZF_F32 || fam == RAST_ZF_F32S8) {
      float b;
      memcpy(&b, p, 4);
      return cmp_f(f, z->f[i], b);
   }
   return cmp_u(f, z->u[i], zread(fam, p));
}

/* ------------------------------------------------------------------ */
/* Depth only: one function per family x func x write, the state being   */
/* compile-time constants of each instance.                             */

static RAST_ALWAYS_INLINE unsigned
depth_only(const struct rast_backend *be, int x, int y, unsigned mask,
           const union rast_zq *z, enum rast_zfamily fam, enum rast_func f, bool write)
{
   const unsigned cpp = zfamily_cpp[fam];
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(mask & (1u << i)))
         continue;
      uint8_t *p = zs_pixel(be, rast_qx(x, i), rast_qy(y, i), cpp);
      if (!ztest(fam, f, p, z, i))
         mask &= ~(1u << i);
      else if (write)
         zwrite(fam, p, z->u[i]);   /* F32*: the float's bits */
   }
   return mask;
}

#define DEPTH_FN(FAM, FUNC, W) \
   static unsigned depth_##FAM##_##FUNC##_##W(const struct rast_backend *be, int x, int y, \
                                              unsigned mask, const union rast_zq *z, bool ff) \
   { (void)ff; return depth_only(be, x, y, mask, z, RAST_ZF_##FAM, RAST_FUNC_##FUNC, W); }

#define DEPTH_FUNCS_W(FAM, W) \
   DEPTH_FN(FAM, NEVER, W) DEPTH_FN(FAM, LESS, W) DEPTH_FN(FAM, EQUAL, W) \
   DEPTH_FN(FAM, LEQUAL, W) DEPTH_FN(FAM, GREATER, W) DEPTH_FN(FAM, NOTEQUAL, W) \
   DEPTH_FN(FAM, GEQUAL, W) DEPTH_FN(FAM, ALWAYS, W)

#define DEPTH_FUNCS(FAM) DEPTH_FUNCS_W(FAM, 0) DEPTH_FUNCS_W(FAM, 1)

DEPTH_FUNCS(U16)
DEPTH_FUNCS(U24LO)
DEPTH_FUNCS(U24HI)
DEPTH_FUNCS(U32)
DEPTH_FUNCS(F32)
DEPTH_FUNCS(F32S8)

#define DEPTH_ROW_W(FAM, W) { \
   depth_##FAM##_NEVER_##W, depth_##FAM##_LESS_##W, depth_##FAM##_EQUAL_##W, \
   depth_##FAM##_LEQUAL_##W, depth_##FAM##_GREATER_##W, depth_##FAM##_NOTEQUAL_##W, \
   depth_##FAM##_GEQUAL_##W, depth_##FAM##_ALWAYS_##W }
#define DEPTH_ROW(FAM) { DEPTH_ROW_W(FAM, 0), DEPTH_ROW_W(FAM, 1) }

static const rast_zs_func depth_table[RAST_ZF_COUNT][2][8] = {
   [RAST_ZF_U16] = DEPTH_ROW(U16),
   [RAST_ZF_U24LO] = DEPTH_ROW(U24LO),
   [RAST_ZF_U24HI] = DEPTH_ROW(U24HI),
   [RAST_ZF_U32] = DEPTH_ROW(U32),
   [RAST_ZF_F32] = DEPTH_ROW(F32),
   [RAST_ZF_F32S8] = DEPTH_ROW(F32S8),
};

/* ------------------------------------------------------------------ */
/* Stencil, with or without depth: the generic path.                    */

static unsigned stencil_cpp(enum rast_zs_layout l)
{
   switch (l) {
   case RAST_ZS_S8: return 1;
   case RAST_ZS_Z32F_S8X24: return 8;
   default: return 4;
   }
}

static inline uint8_t sread(enum rast_zs_layout l, const uint8_t *p)
{
   switch (l) {
   case RAST_ZS_Z24_S8: return (uint8_t)(load32(p) >> 24);
   case RAST_ZS_Z32F_S8X24: return p[4];   /* bits 0..7 of the second dword, little endian */
   default: return p[0];                   /* S8_Z24 (bits 0..7), S8 */
   }
}

static inline void swrite(enum rast_zs_layout l, uint8_t *p, uint8_t s)
{
   switch (l) {
   case RAST_ZS_Z24_S8: store32(p, (load32(p) & 0xffffffu) | ((uint32_t)s << 24)); break;
   case RAST_ZS_Z32F_S8X24: p[4] = s; break;
   default: p[0] = s; break;
   }
}

static inline uint8_t stencil_op(enum rast_stencil_op op, uint8_t s, uint8_t ref)
{
   switch (op) {
   case RAST_STENCIL_ZERO: return 0;
   case RAST_STENCIL_REPLACE: return ref;
   case RAST_STENCIL_INCR: return s == 255 ? 255 : (uint8_t)(s + 1);
   case RAST_STENCIL_DECR: return s == 0 ? 0 : (uint8_t)(s - 1);
   case RAST_STENCIL_INCR_WRAP: return (uint8_t)(s + 1);
   case RAST_STENCIL_DECR_WRAP: return (uint8_t)(s - 1);
   case RAST_STENCIL_INVERT: return (uint8_t)~s;
   default: return s;
   }
}

static unsigned zs_generic(const struct rast_backend *be, int x, int y, unsigned mask,
                           const union rast_zq *z, bool front_facing)
{
   const unsigned face = (!front_facing && be->two_sided) ? 1 : 0;
   const struct rast_stencil_face *sf = &be->stencil[face];
   const uint8_t ref = be->stencil_ref[face];
   const uint8_t sref = ref & sf->valuemask;
   const enum rast_zfamily fam = be->zfamily;
   const unsigned cpp = stencil_cpp(be->zs_layout);

   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(mask & (1u << i)))
         continue;
      uint8_t *p = zs_pixel(be, rast_qx(x, i), rast_qy(y, i), cpp);
      const uint8_t s = sread(be->zs_layout, p);
      const bool spass = cmp_u(sf->func, sref, s & sf->valuemask);
      bool zpass = true;
      if (spass && be->depth_test)
         zpass = ztest(fam, be->depth_func, p, z, i);

      enum rast_stencil_op op = !spass ? sf->fail_op : !zpass ? sf->zfail_op : sf->zpass_op;
      uint8_t ns = stencil_op(op, s, ref);
      ns = (uint8_t)((s & ~sf->writemask) | (ns & sf->writemask));
      if (ns != s)
         swrite(be->zs_layout, p, ns);

      if (spass && zpass) {
         if (be->depth_write)
            zwrite(fam, p, z->u[i]);
      } else {
         mask &= ~(1u << i);
      }
   }
   return mask;
}

/* ------------------------------------------------------------------ */
/* Planning.                                                            */

static enum rast_zfamily zfamily_of(enum rast_zs_layout l, unsigned *nbits)
{
   switch (l) {
   case RAST_ZS_Z16: *nbits = 16; return RAST_ZF_U16;
   case RAST_ZS_Z24_S8: case RAST_ZS_Z24X8: *nbits = 24; return RAST_ZF_U24LO;
   case RAST_ZS_S8_Z24: case RAST_ZS_X8Z24: *nbits = 24; return RAST_ZF_U24HI;
   case RAST_ZS_Z32: *nbits = 32; return RAST_ZF_U32;
   case RAST_ZS_Z32F: *nbits = 0; return RAST_ZF_F32;
   case RAST_ZS_Z32F_S8X24: *nbits = 0; return RAST_ZF_F32S8;
   default: *nbits = 0; return RAST_ZF_NONE;
   }
}

static bool layout_has_stencil(enum rast_zs_layout l)
{
   return l == RAST_ZS_Z24_S8 || l == RAST_ZS_S8_Z24 ||
          l == RAST_ZS_Z32F_S8X24 || l == RAST_ZS_S8;
}

/* A depth range's end in the Z register, as set-up takes a vertex's depth
 * (rast_setup_attribs), from GL's [0, 1] (NaN: 0): never saturated. */
static uint64_t depth_register(const struct rast_profile *prof, float v)
{
   const double d = v > 0.0f ? (v < 1.0f ? (double)v : 1.0) : 0.0;
   const double zfull = (double)(INT64_C(1) << prof->z_bits) - 1.0;
   struct fx_sat none = { 0, 0 };
   return (uint64_t)fx_from_double(prof->z, d * zfull, &none);
}

/* Every viewport's bounds: its depth range's with the depth clamp, else
 * [0, FULL]; and their values in the buffer's units, by the register's
 * rule (zconv_float's, or the unorm rule that every zconv_* computes). */
static void zranges_plan(struct rast_backend *be, const struct rast_context *rc)
{
   const bool is_float = be->zfamily == RAST_ZF_F32 || be->zfamily == RAST_ZF_F32S8;
   for (unsigned i = 0; i < RAST_MAX_VIEWPORTS; i++) {
      struct rast_zrange *r = &be->zranges[i];
      r->lo = 0;
      r->hi = be->z_full;
      if (rc->rs.depth_clamp) {
         const uint64_t a = depth_register(rc->profile, rc->depth_ranges[i].n);
         const uint64_t b = depth_register(rc->profile, rc->depth_ranges[i].f);
         r->lo = a < b ? a : b;
         r->hi = a < b ? b : a;
      }
      if (is_float) {
         r->code_lo.f = (float)((double)r->lo / (double)be->z_full);
         r->code_hi.f = (float)((double)r->hi / (double)be->z_full);
      } else {
         r->code_lo.u = rast_z_to_unorm(r->lo, be->z_full, be->z_max);
         r->code_hi.u = rast_z_to_unorm(r->hi, be->z_full, be->z_max);
      }
   }
   be->zr = be->zranges[rc->vp_index < RAST_MAX_VIEWPORTS ? rc->vp_index
                                                          : RAST_MAX_VIEWPORTS - 1];
}

void rast_backend_viewport(struct rast_context *rc, unsigned vp)
{
   struct rast_backend *be = rc->back_priv;
   if (be)
      be->zr = be->zranges[vp < RAST_MAX_VIEWPORTS ? vp : RAST_MAX_VIEWPORTS - 1];
}

void rast_zs_plan(struct rast_backend *be, const struct rast_context *rc)
{
   const struct rast_depth_stencil_state *dsa = &rc->dsa;
   const struct rast_zs_target *zt = &rc->fb.zs;
   const enum rast_zs_layout layout = zt->base ? zt->layout : RAST_ZS_NONE;
   unsigned nbits;

   be->zs_base = be->zs_base0 = zt->base;
   be->zs_sample_stride = zt->sample_stride;
   be->zs_layers = zt->layers;
   be->zs_layer_stride = zt->layer_stride;
   be->zs_stride = zt->stride;
   be->zs_layout = layout;
   be->zfamily = zfamily_of(layout, &nbits);
   be->z_nbits = nbits;
   be->z_max = nbits ? (UINT64_C(1) << nbits) - 1 : 0;
   be->z_frac = rc->profile->z.frac_bits;
   be->z_full = ((UINT64_C(1) << rc->profile->z_bits) - 1) << be->z_frac;
   zranges_plan(be, rc);

   /* GL: without a depth buffer the depth test passes, without a stencil
    * buffer the stencil test passes, and nothing is written. */
   be->depth_test = dsa->depth_enabled && be->zfamily != RAST_ZF_NONE;
   be->depth_write = be->depth_test && dsa->depth_writemask;
   be->depth_func = dsa->depth_func;
   be->stencil_test = dsa->stencil[0].enabled && layout_has_stencil(layout);
   be->two_sided = dsa->stencil[1].enabled;
   be->stencil[0] = dsa->stencil[0];
   be->stencil[1] = dsa->stencil[1];
   be->stencil_ref[0] = rc->stencil_ref[0];
   be->stencil_ref[1] = rc->stencil_ref[1];

   if (be->stencil_test)
      be->zs = zs_generic;
   else if (be->depth_test && !(be->depth_func == RAST_FUNC_ALWAYS && !be->depth_write))
      be->zs = depth_table[be->zfamily][be->depth_write][be->depth_func & 7];
   else
      be->zs = NULL;

   be->zconv = NULL;
   be->zgroup = NULL;
   be->fb_w = (int)rc->fb.width;
   be->fb_h = (int)rc->fb.height;
   if (!be->depth_test)
      return;
   const bool is_float = be->zfamily == RAST_ZF_F32 || be->zfamily == RAST_ZF_F32S8;
   /* with the tests before the shader (early_fragment_tests) its depth
    * is not the fragment's: GL ignores it */
   const bool shader_depth = rc->fs.writes_depth && !rc->fs.early_tests;
   if (shader_depth && rc->rs.depth_clamp)
      be->zconv = is_float ? zconv_shader_float_clamp : zconv_shader_unorm_clamp;
   else if (shader_depth)
      be->zconv = is_float ? zconv_shader_float : zconv_shader_unorm;
   else if (is_float)
      be->zconv = zconv_float;
   else if (nbits == rc->profile->z_bits)
      be->zconv = zconv_shift;
   else if (!(rc->opts & RAST_OPT_SCALAR) && rast_zdiv_init(&be->zdiv, be->z_full, be->z_max))
      be->zconv = zconv_mul;
   else if (muldiv_fits64(be->z_full, be->z_max))
      be->zconv = zconv_div;
   else
      be->zconv = zconv_div_wide;

   /* A group's early test on lanes where the state is depth only on a
    * 24-bit buffer and the conversion the multiply's (RAST_OPT_SCALAR
    * keeps the per-quad functions) */
   if (be->zconv == zconv_mul && be->zs && !be->stencil_test &&
       be->zfamily == RAST_ZF_U24LO && rast_lanes()->zgroup &&
       zdiv_exact_in_doubles(&be->zdiv, be->z_full, be->z_max)) {
      be->zgroup = rast_lanes()->zgroup(be->depth_func, be->depth_write);
      be->zgroup_b = (double)((2 * be->z_full) >> be->zdiv.s);
   }
}
