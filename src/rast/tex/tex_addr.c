/*
 * Address computation: one coordinate register (in the number system) to
 * texel indices and a bilinear weight, one function per wrap mode and
 * filter, chosen at bind.
 *
 * Periodic modes (REPEAT, MIRRORED_REPEAT) wrap the normalized coordinate
 * first (its fraction: exact in every number system, but in [-1, 0), see
 * frac_of) and scale the result
 * (< 1) by the level size, so the texel address keeps its precision
 * whatever the coordinate's magnitude and whatever the size (NPOT needs no
 * divider: the index lies in [-1, size]).  Clamp modes clamp the
 * coordinate to a small interval before scaling, so no clamp mode can
 * saturate the scaled register.  Linear filtering subtracts half a texel
 * (less half a weight LSB) after scaling; the weight is the fraction's top
 * TEX_WEIGHT_BITS bits, so it is rounded to nearest.
 */
#include "rast/tex/tex_priv.h"

static inline ns_val sub(const struct tex_unit *u, ns_val a, ns_val b)
{
   return u->ns->sub(u->ns, a, b, u->stats);
}

static inline ns_val mul(const struct tex_unit *u, ns_val a, ns_val b)
{
   return u->ns->mul(u->ns, a, b, u->stats);
}

static inline int64_t floor_w(const struct tex_unit *u, ns_val a, uint32_t *w)
{
   return u->ns->floor_frac(u->ns, a, w, TEX_WEIGHT_BITS, u->stats);
}

/* The fraction c - floor(c) and the parity of floor(c).  For c in [-1, 0)
 * the fraction 1 + c lies where a floating register's grid is coarser than
 * c's own (dfx24: 2^-19 near 1), so it would round across a texel boundary
 * that c itself resolves: there c is returned unchanged and *below set, and
 * the caller adds the period after scaling (a texel index: exact). */
static inline ns_val frac_of(const struct tex_unit *u, ns_val c, bool *odd, bool *below)
{
   uint32_t unused;
   int64_t fl = u->ns->floor_frac(u->ns, c, &unused, 0, u->stats);
   *odd = fl & 1;
   *below = fl == -1;
   return *below ? c : sub(u, c, tex_ns_int(u, fl));
}

/* ---- REPEAT ---- */

static void repeat_nearest(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                           struct tex_addr *a)
{
   bool odd, below;
   uint32_t w;
   int64_t i = floor_w(u, mul(u, frac_of(u, c, &odd, &below), ax->scale), &w);
   if (below)
      i += ax->size;
   a->i0 = tex_clampi(i, 0, ax->size - 1);   /* only a saturated register gets out */
   a->i1 = a->i0;
   a->w = 0;
}

static void repeat_linear(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                          struct tex_addr *a)
{
   bool odd, below;
   ns_val t = sub(u, mul(u, frac_of(u, c, &odd, &below), ax->scale), u->k_texel_offset);
   int64_t i = floor_w(u, t, &a->w);
   if (below)
      i += ax->size;
   i = tex_clampi(i, -1, ax->size - 1);
   a->i0 = i < 0 ? ax->size - 1 : (int32_t)i;
   a->i1 = i + 1 >= ax->size ? 0 : (int32_t)i + 1;
}

/* ---- MIRRORED_REPEAT: fold into [0, 1], then as CLAMP_TO_EDGE ---- */

static inline ns_val mirror(const struct tex_unit *u, ns_val c)
{
   bool odd, below;
   ns_val f = frac_of(u, c, &odd, &below);
   /* [-1, 0) mirrors to -c, exactly */
   return below ? tex_ns_abs(u->kind, c) : odd ? sub(u, u->k_one, f) : f;
}

static void edge_nearest_of(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                            struct tex_addr *a)
{
   uint32_t w;
   int64_t i = floor_w(u, mul(u, c, ax->scale), &w);
   a->i0 = a->i1 = tex_clampi(i, 0, ax->size - 1);
   a->w = 0;
}

static void edge_linear_of(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                           struct tex_addr *a)
{
   int64_t i = floor_w(u, sub(u, mul(u, c, ax->scale), u->k_texel_offset), &a->w);
   a->i0 = tex_clampi(i, 0, ax->size - 1);
   a->i1 = tex_clampi(i + 1, 0, ax->size - 1);
}

static void border_nearest_of(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                              struct tex_addr *a)
{
   uint32_t w;
   int64_t i = floor_w(u, mul(u, c, ax->scale), &w);
   a->i0 = a->i1 = tex_inside(i, ax->size);
   a->w = 0;
}

static void border_linear_of(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                             struct tex_addr *a)
{
   int64_t i = floor_w(u, sub(u, mul(u, c, ax->scale), u->k_texel_offset), &a->w);
   a->i0 = tex_inside(i, ax->size);
   a->i1 = tex_inside(i + 1, ax->size);
}

static void mirror_nearest(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                           struct tex_addr *a)
{
   edge_nearest_of(u, ax, mirror(u, c), a);
}

static void mirror_linear(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                          struct tex_addr *a)
{
   edge_linear_of(u, ax, mirror(u, c), a);
}

/* ---- clamp modes: clamp to [lo, hi] of the axis, then address ---- */

#define CLAMPED(c) tex_ns_clamp(u->kind, (c), ax->lo, ax->hi)
#define MIRRORED(c) tex_ns_clamp(u->kind, tex_ns_abs(u->kind, (c)), ax->lo, ax->hi)

static void edge_nearest(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                         struct tex_addr *a)
{
   edge_nearest_of(u, ax, CLAMPED(c), a);
}

static void edge_linear(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                        struct tex_addr *a)
{
   edge_linear_of(u, ax, CLAMPED(c), a);
}

/* CLAMP and CLAMP_TO_BORDER differ only in [lo, hi] (tex_bind.c). */
static void border_nearest(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                           struct tex_addr *a)
{
   border_nearest_of(u, ax, CLAMPED(c), a);
}

static void border_linear(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                          struct tex_addr *a)
{
   border_linear_of(u, ax, CLAMPED(c), a);
}

static void medge_nearest(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                          struct tex_addr *a)
{
   edge_nearest_of(u, ax, MIRRORED(c), a);
}

static void medge_linear(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                         struct tex_addr *a)
{
   edge_linear_of(u, ax, MIRRORED(c), a);
}

static void mborder_nearest(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                            struct tex_addr *a)
{
   border_nearest_of(u, ax, MIRRORED(c), a);
}

static void mborder_linear(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                           struct tex_addr *a)
{
   border_linear_of(u, ax, MIRRORED(c), a);
}

/* Seamless cube faces: the face coordinate clamped to [0, 1] (the face
 * projection keeps it there but for rounding), then the linear pair with
 * indices in [-1, size]: a tap beyond the face's edge is the neighbouring
 * face's, which the filter finds (tex_cube_across). */
void tex_addr_cube_seamless(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                            struct tex_addr *a)
{
   const ns_val cc = tex_ns_clamp(u->kind, c, u->k_zero, u->k_one);
   const int64_t i = floor_w(u, sub(u, mul(u, cc, ax->scale), u->k_texel_offset), &a->w);
   a->i0 = (int32_t)tex_clampi(i, -1, ax->size - 1);
   a->i1 = a->i0 + 1;
}

/* [wrap][filter]; the clamp bounds per mode are set in tex_bind.c. */
static const tex_addr_fn addr_table[TEX_WRAP_COUNT][2] = {
   [TEX_WRAP_REPEAT] = { repeat_nearest, repeat_linear },
   [TEX_WRAP_CLAMP] = { edge_nearest, border_linear },
   [TEX_WRAP_CLAMP_TO_EDGE] = { edge_nearest, edge_linear },
   [TEX_WRAP_CLAMP_TO_BORDER] = { border_nearest, border_linear },
   [TEX_WRAP_MIRROR_REPEAT] = { mirror_nearest, mirror_linear },
   [TEX_WRAP_MIRROR_CLAMP] = { medge_nearest, mborder_linear },
   [TEX_WRAP_MIRROR_CLAMP_TO_EDGE] = { medge_nearest, medge_linear },
   [TEX_WRAP_MIRROR_CLAMP_TO_BORDER] = { mborder_nearest, mborder_linear },
};

tex_addr_fn tex_addr_choose(enum tex_wrap wrap, enum tex_filter filter)
{
   return addr_table[wrap < TEX_WRAP_COUNT ? wrap : TEX_WRAP_CLAMP_TO_EDGE][filter != 0];
}

/* Whether the axis's wrap mode reflects coordinate c (the fold above took
 * the mirrored side): the linear filter's i0 and i1 are then in
 * decreasing coordinate order, which the filter does not mind but GL's
 * gather order does.  The floor is the one the address unit already took
 * (and counted): not counted again. */
bool tex_addr_mirrored(const struct tex_unit *u, unsigned axis, ns_val c)
{
   struct ns_stats again = { 0 };
   uint32_t unused;
   switch (u->samp.wrap[axis]) {
   case TEX_WRAP_MIRROR_REPEAT: {
      const int64_t fl = u->ns->floor_frac(u->ns, c, &unused, 0, &again);
      return (fl & 1) != 0;   /* odd periods, and [-1, 0) */
   }
   case TEX_WRAP_MIRROR_CLAMP:
   case TEX_WRAP_MIRROR_CLAMP_TO_EDGE:
   case TEX_WRAP_MIRROR_CLAMP_TO_BORDER:
      return tex_ns_neg(u->kind, c);
   default:
      return false;
   }
}
