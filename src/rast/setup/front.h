/*
 * The front end's private state (rc->front_priv): setup, edge processing
 * (scan.c) and span processing (span.c).  Everything here is allocated once
 * per context; no primitive allocates.
 *
 * Attribute registers come in two families, both walked the seed's way
 * (left-edge register + Δ/Δy per scan line, then ∂/∂x per pixel):
 *   fix[]: fixed point, saturating.  fix[0] is Z (profile Z format); the
 *          rest are colour components (profile colour format, units 1/255).
 *   flt[]: float.  flt[0] is 1/w (gl_FragCoord.w); then the LINEAR
 *          components.  Only these nwalk registers are walked.  The vertex
 *          values (vflt) also hold the PERSPECTIVE components as A/w, after
 *          them: the perspective division evaluates each pixel from those
 *          (fr_tex, persp.c), so they have no edge or span registers.
 */
#ifndef FIXPIPE_FRONT_H
#define FIXPIPE_FRONT_H

#include <stddef.h>
#include "rast/rast_priv.h"
#include "fixed/fx_wide.h"
#include "fixed/numsys.h"

#define FR_MAX_COMP  (RAST_MAX_VARYINGS * 4)
#define FR_MAX_FIX   (1 + FR_MAX_COMP)
#define FR_MAX_FLT   (1 + FR_MAX_COMP)
#define FR_MAX_VERTS 4
#define FR_MAX_SECS  3
/* The quads the span processor holds for the back end: two of the
 * shader's groups where their perspective division is done together
 * (span.c's pair_impl), one otherwise. */
#define FR_AHEAD_MAX (2 * RAST_GROUP_MAX)
/* interp_axes.c's tables: the planes, and the columns or scan lines, of a
 * primitive they take at most. */
#define FR_AXES_PLANES 4
#define FR_AXES_MAX    2112

/* One shader input component: out in[var][chan], from vertex slot `slot`. */
struct fr_comp {
   uint8_t var, chan, slot;
   uint8_t rebase;               /* enum fr_rebase (PERSPECTIVE components) */
};

enum fr_rebase { FR_REBASE_NONE, FR_REBASE_INT, FR_REBASE_EVEN };

/* An edge register set: X_left or X_right with its slope, and (left edges
 * only) the attribute registers Z_left, R_left, ... and their Δ/Δy.
 *
 * Exactness (our addition; the seed leaves the rounding of the walk open):
 * x is the floor, in the XY format, of the exact intersection of the edge
 * through the fixed-point vertices with the scan line's pixel centres, and
 * rem/dy is the rest: exact = x + rem/dy, 0 <= rem < dy.  The slope register
 * holds floor((xb-xa)·S/dy) (dx/dy format) and step_rem its remainder, so the
 * walk is Bresenham's: the error term carries into x when it reaches dy, and
 * x never drifts from the exact edge. */
struct fr_edge {
   int64_t xa, ya, xb, yb;     /* end points, XY format, ya < yb */
   uint8_t a, b;               /* vertex indices of the end points */
   bool left;
   int64_t j_end;              /* last scan line this edge is stepped to */

   int64_t x, rem, dy;         /* X register and Bresenham error term */
   int64_t step, step_rem;     /* dx/dy register (on X's grid) and its remainder */

   int64_t fix[FR_MAX_FIX], fix_step[FR_MAX_FIX];
   float flt[FR_MAX_FLT], flt_step[FR_MAX_FLT];
};

/* A y-interval of the polygon bounded by one left and one right edge: the
 * halves A and B of a general triangle, or up to three for a line's
 * parallelogram. */
struct fr_section {
   int64_t ytop, ybot;         /* XY format */
   struct fr_edge *l, *r;
   int64_t j0, j1;             /* scan lines, inclusive; empty if j0 > j1 */
};

/* One scan line's result of edge processing. */
struct fr_row {
   bool valid;                 /* inside the polygon's and the clip's rows */
   int64_t xs, xe;             /* clipped span, inclusive; empty if xs > xe */
   int64_t xl;                 /* X_left register */
   float xl_frac;              /* its remainder rem/dy, for the float walk */
   int64_t fix[FR_MAX_FIX];
   float flt[FR_MAX_FLT];
};

struct rast_front;
typedef void (*fr_pair_func)(struct rast_context *rc, struct rast_front *fr, int64_t y);

/* The texture path's perspective division (persp.c): the vector method of
 * seed 002, in the number system of rast_set_texfmt.  Per primitive, the
 * vertex values 1/w and A/w in the system with their differences
 * Δ1 = v1 - v0, Δ2 = v2 - v0, and the reciprocal of the doubled area; per
 * pixel, the edge-vector coefficients a, b from exact integer edge
 * functions, then v0 + a·Δ1 + b·Δ2 and (A/w) · recip(1/w).  Nothing rounded
 * is carried from one pixel to the next.  The functions are chosen per
 * number system at validation. */
typedef void (*fr_tex_begin_func)(struct rast_front *fr, int64_t x, int64_t y);
/* divide: the quad has covered pixels; ahead: how many of the next three
 * quads of the row have too, one after the other (the lanes divide them
 * with this one) */
typedef void (*fr_tex_quad_func)(struct rast_front *fr, struct rast_quad *q, bool divide,
                                 unsigned ahead);

/* One plane in the system: its value at V0 and the differences to V1, V2. */
struct fr_plane {
   ns_val v0, d1, d2;
};

struct fr_tex {
   const struct numsys *ns;
   const struct numsys *fns;            /* binary32, for COLOR components */
   fr_tex_begin_func begin;
   fr_tex_quad_func quad;
   /* ---- per primitive ---- */
   int64_t x0, y0;                      /* V0, XY format */
   int64_t e1x, e1y, e2x, e2y;          /* V1 - V0, V2 - V0 */
   int64_t a_dx, a_dy, b_dx, b_dy;      /* exact steps of a's, b's numerator per pixel */
   /* det·2^-k lies in [1/2, 1): numerators and det enter the system with the
    * same exact scale, so a fixed format holds a, b in [0, 1] whatever the
    * triangle's size */
   unsigned k;
   struct fx_format kfmt;               /* { 0, k }: the numerators as fixed point */
   float fscale;                        /* 2^-k */
   ns_val rdet;                         /* recip(det·2^-k) */
   float frdet;                         /* the same in binary32, for COLOR */
   struct fr_plane pl[1 + FR_MAX_COMP]; /* 0: 1/w; 1 + j: PERSPECTIVE component j */
   struct fr_plane fow;                 /* 1/w in binary32, for COLOR */
   /* ---- per quad row: a's and b's numerators at the current quad's left
    *      pixel centres, both scan lines (exact integers, stepped) ---- */
   int64_t an[2], bn[2];
   /* COLOR components (wide profile: perspective colour) and array layers
    * (rast_varying.float_mask) are not texture coordinates: they keep
    * binary32 (their planes hold floats). */
   bool any_color, is_color[FR_MAX_COMP];
   struct ns_stats st;                  /* moved to rast_stats per quad row */
   struct dfx_stats dst;
   bool reference;                      /* the generic quad for every system (tests) */
   /* the generic quad's form for rc->texfmt (persp.c's enum tex_kind):
    * what rast_interp_perspective_at evaluates with */
   uint8_t kind;
   /* ---- the skips of the dfx24 lanes (interp_lanes.c), per primitive:
    *      a plane whose differences are both zero is its v0 ---- */
   bool lanes;                          /* t->quad is the lanes' */
   double lv[1 + FR_MAX_COMP][3];       /* pl[] as the lanes hold them: v0, Δ1, Δ2 */
   double lrdet;
   bool skip;                           /* skips taken (not RAST_OPT_NOSKIP) */
   bool f32;                            /* four quads on binary32 lanes first (not RAST_OPT_NOF32) */
   bool w_const;                        /* 1/w constant: w = recip(v0) once */
   bool w_one;                          /* and exactly 1: A · w is A */
   double lw;                           /* that w, as the lanes hold it */
   /* with w constant: the range events of recip(v0) and of the constant
    * components' products, which every pixel counts */
   struct dfx_stats const_ev;
   /* the planes evaluated per pixel (1/w unless constant, then the
    * components that are not), as lv[] indices, and where each goes in
    * the quad (component's float offset in rast_quad.in) */
   unsigned ln;
   uint8_t lidx[1 + FR_MAX_COMP];
   uint16_t lout[1 + FR_MAX_COMP];
   /* which of those planes' two terms (a·Δ1 bit 0, b·Δ2 bit 1) have a
    * nonzero difference (FR_TERM_*); a zero one is left out, and how many
    * are: the lanes' skip of a plane that follows one edge */
   uint8_t lterm[1 + FR_MAX_COMP];
#define FR_TERM_A 1u
#define FR_TERM_B 2u
   unsigned n_zero_terms;
   /* the constant components (A/w constant) likewise, and with w constant
    * their values */
   unsigned n_const;
   uint8_t cidx[FR_MAX_COMP];
   uint16_t cout[FR_MAX_COMP];
   float cval[FR_MAX_COMP];
   uint64_t n_const_w, n_const_comp;    /* moved to rast_stats per quad row */
   uint64_t n_zero_terms_quads;         /* the same: terms left out, per quad */
   uint64_t n_divided;                  /* quads divided, the same */
   /* the lanes' quads in pairs or fours: the next quads' planes, divided
    * with this one's, wait in `next` (rast_quad.in's layout, the planes'
    * offsets), `pending` of them from next[n_next - pending] */
   unsigned pending, n_next;
   unsigned lookahead;                  /* quads the lanes divide ahead: 0, 1 or 3 */
   float next[3][RAST_MAX_VARYINGS * 4 * RAST_QUAD_SIZE];
   /* The lanes with the skips, and a back end taking groups of quads
    * (rc->quads): a covered quad's numerators wait in num[] with the
    * quad, and the group is divided together when it goes to the back
    * end, wherever its quads lie on the primitive's rows
    * (rast_interp_divide_group): four to a call where a row has fewer. */
   unsigned nrec;                       /* quads waiting to be divided */
   int64_t num[FR_AHEAD_MAX][4];        /* an[0], an[1], bn[0], bn[1] of each */
   /* A primitive whose every plane follows one screen axis (interp_axes.c):
    * `axes` 0 no, -1 yes but its tables not made yet, 1 made; the planes'
    * values per pixel column from col_x0 and per scan line from row_y0
    * (each plane in one of the two: by_x[i]), for plane i of the ln. */
   int axes;
   int64_t axes_hx, axes_hy;            /* the pixel's sampling offsets they were made for */
   int64_t col_x0, row_y0;
   unsigned ncols, nrows;
   bool by_x[FR_AXES_PLANES];
   float col[FR_AXES_PLANES][FR_AXES_MAX], row[FR_AXES_PLANES][FR_AXES_MAX];
};

/* The per-pixel independent interpolators of Z and colour (seeds 001,
 * 002; interp_modes.c): what a primitive gives them once. */
struct fr_modes {
   bool on;                    /* the primitive takes rc->interp's mode (points: the walk) */
   int64_t vx[3], vy[3];       /* the three vertices, XY format */
   int64_t e1x, e1y, e2x, e2y; /* V1 - V0, V2 - V0 */
   int64_t det;                /* (V1 - V0) x (V2 - V0), 2 XY fraction bits' worth */
   int64_t rdet;               /* 002: round(2^(k + W) / det), k the bits of |det| */
   unsigned rshift;            /* 002: a = n_a · rdet >> rshift (k) */
   int64_t v[3][FR_MAX_FIX];   /* 001: the vertices' registers */
   int64_t d1[FR_MAX_FIX], d2[FR_MAX_FIX];   /* 002: A1 - A0, A2 - A0 */
   int64_t wmin, wmax;         /* the weight format's range */
   unsigned wbits;             /* its fraction bits, W */
   int64_t row0;               /* the first scan line (the baseline count) */
};

struct rast_front {
   /* ---- chosen in rast_front_validate, and again when the primitive
    *      changes between points and the rest (rast_front_begin) ---- */
   bool points;                /* the inputs are classified for rast_point */
   unsigned ncolor, nlin, npersp, nconst;
   struct fr_comp color[FR_MAX_COMP], lin[FR_MAX_COMP], persp[FR_MAX_COMP],
                  cnst[FR_MAX_COMP];
   unsigned nfix, nflt, nwalk; /* 1 + ncolor; 1 + nlin + npersp; 1 + nlin */
   unsigned nfix_walk;         /* the fix registers the edges walk: nfix_scan, or 0 in a
                                * per-pixel mode (FIXPIPE_INTERP), set per primitive */
   /* The scan-line walk's fix registers: nfix, or 0 where nothing reads Z
    * and there is no colour register (no depth test, no gl_FragCoord, no
    * RTL vectors): the Z walk skipped, counted in skip_z (docs/datapath.md). */
   unsigned nfix_scan;
   int64_t fix_min[FR_MAX_FIX], fix_max[FR_MAX_FIX];
   struct fx_sat *fix_sat[FR_MAX_FIX];
   struct fx_format fix_fmt[FR_MAX_FIX];
   int64_t S;                  /* one pixel in the XY format */
   int64_t H;                  /* the pixel centre's offset in the XY format */
   /* Where the walk samples a pixel, its offset in the XY format: the
    * centre (H, H), or one sample's position on a multisampled target
    * (msaa.c).  Lines and points place their vertices by H alone. */
   int64_t Hx, Hy;
   int64_t row_bias;           /* 1 with the bottom-edge rule: ceil(v + 1 ulp) */
   double z_scale;             /* Z register -> window depth */
   float color_scale;          /* colour register -> [0, 1] */
   float inv_S;
   fr_pair_func pair;          /* span processor specialised for the inputs */
   struct fr_tex tex;          /* the perspective division's registers */
   struct fr_modes md;         /* FIXPIPE_INTERP's registers */

   /* ---- the primitive being drawn ---- */
   unsigned nverts;
   int64_t X[FR_MAX_VERTS], Y[FR_MAX_VERTS];
   int64_t vfix[FR_MAX_VERTS][FR_MAX_FIX];
   float vflt[FR_MAX_VERTS][FR_MAX_FLT];
   double rebase[FR_MAX_COMP];  /* per PERSPECTIVE component (rast_setup_rebase) */
   int64_t fix_dx[FR_MAX_FIX], fix_dy[FR_MAX_FIX];   /* per pixel */
   float flt_dx[FR_MAX_FLT], flt_dy[FR_MAX_FLT];
   struct fr_edge edge[FR_MAX_VERTS];
   struct fr_section sec[FR_MAX_SECS];
   unsigned nsec;

   struct fr_row row[2];       /* the two scan lines of a quad row */
   /* The span processor fills quad[npending].  With rc->quads a covered
    * quad waits among the `npending` for the next ones of its primitive,
    * and a full group (rc->fs.group) goes to the back end together (the
    * shader on eight or sixteen lanes); what the primitive sets once
    * (constants, facing) is in every quad. */
   struct rast_quad quad[FR_AHEAD_MAX];
   unsigned npending;
};

/* The primitive's facing, in every quad of a group. */
static inline void fr_set_facing(struct rast_front *fr, bool front)
{
   for (unsigned i = 0; i < FR_AHEAD_MAX; i++)
      fr->quad[i].front_facing = front;
}

/* The sample a multisampled walk shades at, in every quad of a group. */
static inline void fr_set_sample(struct rast_front *fr, unsigned sample)
{
   for (unsigned i = 0; i < FR_AHEAD_MAX; i++)
      fr->quad[i].sample = (uint8_t)sample;
}

/* What nq quads divided count besides their lanes' events, however they
 * were divided (interp_lanes.c, interp_axes.c): the skips, and the events
 * of the values computed once per primitive, for every pixel. */
static inline void fr_tex_counted(struct fr_tex *t, unsigned nq)
{
   if (t->w_const) {
      t->dst.sat += t->const_ev.sat * RAST_QUAD_SIZE * nq;
      t->dst.flush += t->const_ev.flush * RAST_QUAD_SIZE * nq;
      t->n_const_w += nq;
   }
   t->n_const_comp += t->n_const * nq;
   t->n_zero_terms_quads += t->n_zero_terms * nq;
}

/* interp_axes.c: whether the primitive's planes each follow one screen
 * axis (set by the perspective set-up), and the waiting quads' planes from
 * its tables, true, where they are. */
void rast_interp_axes_setup(struct rast_front *fr);
bool rast_interp_axes_fill(struct rast_context *rc, struct rast_front *fr);

/* The waiting quads' perspective division (persp.c), and its range
 * events moved to the counters when `row_done`. */
void rast_interp_divide_group(struct rast_context *rc, struct rast_front *fr, bool row_done);

/* The waiting quads to the back end, the shader's group at a time (a lone
 * quad by itself). */
static inline void fr_quads_out(struct rast_context *rc, struct rast_front *fr)
{
   const unsigned g = rc->fs.group > 1 ? rc->fs.group : 1;
   for (unsigned k = 0; k < fr->npending; k += g) {
      const unsigned n = fr->npending - k < g ? fr->npending - k : g;
      if (n == 1)
         rc->quad(rc, &fr->quad[k]);
      else
         rc->quads(rc, &fr->quad[k], n);
   }
   fr->npending = 0;
}

/* The quads left waiting at the end of a primitive go as they are.  They
 * are of this thread's rows, so they count here whoever's row came last. */
static inline void fr_quads_flush(struct rast_context *rc, struct rast_front *fr)
{
   if (fr->npending) {
      const bool counting = rc->counting;
      rast_count_stretch(rc, true);
      if (fr->tex.nrec)
         rast_interp_divide_group(rc, fr, true);
      fr_quads_out(rc, fr);
      rast_count_stretch(rc, counting);
   }
}

static inline struct rast_front *rast_front(struct rast_context *rc)
{
   return (struct rast_front *)rc->front_priv;
}

/* Saturating register update of one fixed attribute. */
static inline int64_t fr_fix_add(const struct rast_front *fr, unsigned k, int64_t a, int64_t b)
{
   int64_t v = a + b;
   if (v > fr->fix_max[k]) { fr->fix_sat[k]->high++; return fr->fix_max[k]; }
   if (v < fr->fix_min[k]) { fr->fix_sat[k]->low++; return fr->fix_min[k]; }
   return v;
}

static inline int64_t fr_fix_sat(const struct rast_front *fr, unsigned k, fx_i128 v)
{
   return fx_sat_i128(v, fr->fix_min[k], fr->fix_max[k],
                      &fr->fix_sat[k]->high, &fr->fix_sat[k]->low);
}

/* setup.c: which attribute registers the inputs use, and the span processor
 * that walks them.  Points keep every input constant except the varyings of
 * point_coord_mask, which walk as LINEAR (the sprite coordinate's plane). */
void rast_front_classify(struct rast_context *rc, struct rast_front *fr, bool points);

/* The front end ready for a primitive: state validated, inputs classified
 * for points or for lines and triangles. */
static inline struct rast_front *rast_front_begin(struct rast_context *rc, bool points)
{
   rast_validate(rc);
   struct rast_front *fr = rast_front(rc);
   if (fr->points != points)
      rast_front_classify(rc, fr, points);
   return fr;
}

/* llvmpipe's util_iround on x86-64 (its generic branch): halves away from
 * zero, after a float addition.  Lines and points snap with it. */
static inline int64_t rast_lp_iround(float f)
{
   if (!(f > -1e15f && f < 1e15f))      /* NaN, off any target: saturates later */
      f = f > 0 ? 1e15f : -1e15f;
   return f >= 0.0f ? (int64_t)(f + 0.5f) : (int64_t)(f - 0.5f);
}

/* setup.c: the attribute registers of vertex k from its float slots, and
 * the flat inputs from the provoking vertex. */
void rast_setup_attribs(struct rast_context *rc, struct rast_front *fr,
                        unsigned k, const float (*v)[4]);
/* setup.c: the integers rast_setup_attribs subtracts from the rebased
 * components, from the primitive's n vertices; before it. */
void rast_setup_rebase(struct rast_context *rc, struct rast_front *fr,
                       const float (*const *v)[4], unsigned n);
void rast_setup_constants(struct rast_front *fr, const float (*pv)[4]);

/* scan.c: edge processing over fr->sec[0..nsec) */
void rast_scan_sections(struct rast_context *rc, struct rast_front *fr);
/* scan.c: sections of a convex polygon fr->X/Y[0..nverts) (lines) */
void rast_scan_convex(struct rast_context *rc, struct rast_front *fr);

/* span.c */
fr_pair_func rast_interp_choose(const struct rast_context *rc, const struct rast_front *fr);
/* interp_modes.c: a primitive's registers for the interpolator of
 * rc->interp, on its vertices i0, i1, i2 (a line: two corners along it and
 * one across); the bounding box counted. */
void rast_interp_modes_setup(struct rast_context *rc, struct rast_front *fr, unsigned i0,
                             unsigned i1, unsigned i2);
/* A point: its registers are its vertex's in every mode, walked (constant). */
void rast_interp_modes_off(struct rast_front *fr);
/* persp.c: the perspective division's functions for rc->texfmt */
void rast_interp_perspective_choose(struct rast_context *rc, struct rast_front *fr);
/* persp.c: the perspective division's per-primitive set-up, with vertices
 * i0, i1, i2 of fr->X/Y and fr->vflt as V0, V1, V2 (a line: two corners along
 * it and one across, where every attribute is constant, so Δ2 = 0). */
void rast_interp_perspective_setup(struct rast_context *rc, struct rast_front *fr,
                                   unsigned i0, unsigned i1, unsigned i2);
/* persp.c: PERSPECTIVE component j of the primitive at four points of the
 * pass (XY format), by the generic quad's operations on the numerators
 * there: a pixel's centre gives the walk's bits (interpolateAt*,
 * interp_at.c). */
void rast_interp_perspective_at(struct rast_front *fr, unsigned j,
                                const int64_t px[RAST_QUAD_SIZE],
                                const int64_t py[RAST_QUAD_SIZE], float out[RAST_QUAD_SIZE]);
/* persp.c: with `on`, the perspective division takes its generic quad (the
 * reference the specialised ones must match bit for bit, test_persp_fast). */
void rast_interp_perspective_reference(struct rast_context *rc, bool on);

#endif
