/*
 * Fixed-function CSOs and set_* calls: translated into the model's state
 * once, when created or set, never per pixel.  Anything that changes what
 * the model draws first flushes what draw still holds.
 */
#include <math.h>

#include "util/u_memory.h"
#include "util/u_inlines.h"
#include "util/u_helpers.h"
#include "util/format/u_format.h"
#include "draw/draw_context.h"

#include "fp_context.h"

static enum rast_func fp_func(unsigned pipe_func)
{
   /* PIPE_FUNC_* are GL's order, as are RAST_FUNC_*. */
   return (enum rast_func)(pipe_func & 7);
}

static enum rast_blend_eq fp_blend_eq(unsigned f)
{
   switch (f) {
   case PIPE_BLEND_SUBTRACT: return RAST_BLEND_SUBTRACT;
   case PIPE_BLEND_REVERSE_SUBTRACT: return RAST_BLEND_REVERSE_SUBTRACT;
   case PIPE_BLEND_MIN: return RAST_BLEND_MIN;
   case PIPE_BLEND_MAX: return RAST_BLEND_MAX;
   default: return RAST_BLEND_ADD;
   }
}

static enum rast_blend_factor fp_blend_factor(unsigned f)
{
   switch (f) {
   case PIPE_BLENDFACTOR_ONE: return RAST_BF_ONE;
   case PIPE_BLENDFACTOR_SRC_COLOR: return RAST_BF_SRC_COLOR;
   case PIPE_BLENDFACTOR_SRC_ALPHA: return RAST_BF_SRC_ALPHA;
   case PIPE_BLENDFACTOR_DST_ALPHA: return RAST_BF_DST_ALPHA;
   case PIPE_BLENDFACTOR_DST_COLOR: return RAST_BF_DST_COLOR;
   case PIPE_BLENDFACTOR_SRC_ALPHA_SATURATE: return RAST_BF_SRC_ALPHA_SATURATE;
   case PIPE_BLENDFACTOR_CONST_COLOR: return RAST_BF_CONST_COLOR;
   case PIPE_BLENDFACTOR_CONST_ALPHA: return RAST_BF_CONST_ALPHA;
   case PIPE_BLENDFACTOR_SRC1_COLOR: return RAST_BF_SRC1_COLOR;
   case PIPE_BLENDFACTOR_SRC1_ALPHA: return RAST_BF_SRC1_ALPHA;
   case PIPE_BLENDFACTOR_ZERO: return RAST_BF_ZERO;
   case PIPE_BLENDFACTOR_INV_SRC_COLOR: return RAST_BF_INV_SRC_COLOR;
   case PIPE_BLENDFACTOR_INV_SRC_ALPHA: return RAST_BF_INV_SRC_ALPHA;
   case PIPE_BLENDFACTOR_INV_DST_ALPHA: return RAST_BF_INV_DST_ALPHA;
   case PIPE_BLENDFACTOR_INV_DST_COLOR: return RAST_BF_INV_DST_COLOR;
   case PIPE_BLENDFACTOR_INV_CONST_COLOR: return RAST_BF_INV_CONST_COLOR;
   case PIPE_BLENDFACTOR_INV_CONST_ALPHA: return RAST_BF_INV_CONST_ALPHA;
   case PIPE_BLENDFACTOR_INV_SRC1_COLOR: return RAST_BF_INV_SRC1_COLOR;
   case PIPE_BLENDFACTOR_INV_SRC1_ALPHA: return RAST_BF_INV_SRC1_ALPHA;
   default: return RAST_BF_ONE;
   }
}

static enum rast_stencil_op fp_stencil_op(unsigned op)
{
   switch (op) {
   case PIPE_STENCIL_OP_ZERO: return RAST_STENCIL_ZERO;
   case PIPE_STENCIL_OP_REPLACE: return RAST_STENCIL_REPLACE;
   case PIPE_STENCIL_OP_INCR: return RAST_STENCIL_INCR;
   case PIPE_STENCIL_OP_DECR: return RAST_STENCIL_DECR;
   case PIPE_STENCIL_OP_INCR_WRAP: return RAST_STENCIL_INCR_WRAP;
   case PIPE_STENCIL_OP_DECR_WRAP: return RAST_STENCIL_DECR_WRAP;
   case PIPE_STENCIL_OP_INVERT: return RAST_STENCIL_INVERT;
   default: return RAST_STENCIL_KEEP;
   }
}

/* ---- blend (alpha-to-coverage and dithering are ignored) ---- */

_Static_assert((int)PIPE_LOGICOP_CLEAR == (int)RAST_LOGICOP_CLEAR &&
               (int)PIPE_LOGICOP_COPY == (int)RAST_LOGICOP_COPY &&
               (int)PIPE_LOGICOP_SET == (int)RAST_LOGICOP_SET,
               "logic ops are translated by value");

static void *fp_create_blend_state(struct pipe_context *pipe, const struct pipe_blend_state *b)
{
   struct fp_blend_state *s = CALLOC_STRUCT(fp_blend_state);
   (void)pipe;
   if (!s)
      return NULL;
   s->base = *b;
   s->rast.independent = b->independent_blend_enable;
   /* PIPE_LOGICOP_* are GL's order, as are RAST_LOGICOP_*. */
   s->rast.logicop_enable = b->logicop_enable;
   s->rast.alpha_to_coverage = b->alpha_to_coverage;
   s->rast.logicop_func = (enum rast_logicop)(b->logicop_func & 15);
   for (unsigned i = 0; i < RAST_MAX_CBUFS; i++) {
      const struct pipe_rt_blend_state *rt = &b->rt[b->independent_blend_enable ? i : 0];
      struct rast_blend_target *t = &s->rast.rt[i];
      t->blend_enable = rt->blend_enable;
      t->rgb_eq = fp_blend_eq(rt->rgb_func);
      t->alpha_eq = fp_blend_eq(rt->alpha_func);
      t->rgb_src = fp_blend_factor(rt->rgb_src_factor);
      t->rgb_dst = fp_blend_factor(rt->rgb_dst_factor);
      t->alpha_src = fp_blend_factor(rt->alpha_src_factor);
      t->alpha_dst = fp_blend_factor(rt->alpha_dst_factor);
      t->colormask = rt->colormask & 0xf;
   }
   return s;
}

static void fp_bind_blend_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   draw_flush(fp->draw);
   fp->blend = cso;
   if (cso) {
      rast_set_blend(fp->rast, &fp->blend->rast);
   } else {
      struct rast_blend_state def;
      memset(&def, 0, sizeof(def));
      for (unsigned i = 0; i < RAST_MAX_CBUFS; i++) {
         def.rt[i].rgb_src = def.rt[i].alpha_src = RAST_BF_ONE;
         def.rt[i].rgb_dst = def.rt[i].alpha_dst = RAST_BF_ZERO;
         def.rt[i].colormask = 0xf;
      }
      rast_set_blend(fp->rast, &def);
   }
}

static void fp_delete_state(struct pipe_context *pipe, void *cso)
{
   (void)pipe;
   FREE(cso);
}

static void fp_set_blend_color(struct pipe_context *pipe, const struct pipe_blend_color *c)
{
   struct fp_context *fp = fp_context(pipe);
   draw_flush(fp->draw);
   rast_set_blend_color(fp->rast, c->color);
}

/* ---- depth, stencil (alpha test is lowered by st: PIPE_CAP_ALPHA_TEST 0) ---- */

static void *fp_create_dsa_state(struct pipe_context *pipe,
                                 const struct pipe_depth_stencil_alpha_state *d)
{
   struct fp_dsa_state *s = CALLOC_STRUCT(fp_dsa_state);
   (void)pipe;
   if (!s)
      return NULL;
   s->base = *d;
   s->rast.depth_enabled = d->depth_enabled;
   s->rast.depth_writemask = d->depth_enabled && d->depth_writemask;
   s->rast.depth_func = d->depth_enabled ? fp_func(d->depth_func) : RAST_FUNC_ALWAYS;
   for (unsigned i = 0; i < 2; i++) {
      /* Gallium's meaning, which the back end follows: stencil[1].enabled
       * is the two-sided switch; without it the front state and the front
       * reference apply to both faces (st leaves ref_value[1] 0 then). */
      const struct pipe_stencil_state *st = &d->stencil[d->stencil[1].enabled ? i : 0];
      struct rast_stencil_face *f = &s->rast.stencil[i];
      f->enabled = d->stencil[i].enabled;
      f->func = fp_func(st->func);
      f->fail_op = fp_stencil_op(st->fail_op);
      f->zfail_op = fp_stencil_op(st->zfail_op);
      f->zpass_op = fp_stencil_op(st->zpass_op);
      f->valuemask = st->valuemask;
      f->writemask = st->writemask;
   }
   return s;
}

static void fp_bind_dsa_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   draw_flush(fp->draw);
   fp->dsa = cso;
   if (cso) {
      rast_set_depth_stencil(fp->rast, &fp->dsa->rast);
   } else {
      struct rast_depth_stencil_state def;
      memset(&def, 0, sizeof(def));
      def.depth_func = RAST_FUNC_ALWAYS;
      rast_set_depth_stencil(fp->rast, &def);
   }
}

static void fp_set_stencil_ref(struct pipe_context *pipe, const struct pipe_stencil_ref ref)
{
   struct fp_context *fp = fp_context(pipe);
   draw_flush(fp->draw);
   rast_set_stencil_ref(fp->rast, ref.ref_value[0], ref.ref_value[1]);
}

/* ---- rasterizer ---- */

static void *fp_create_rasterizer_state(struct pipe_context *pipe,
                                        const struct pipe_rasterizer_state *r)
{
   struct fp_rasterizer_state *s = CALLOC_STRUCT(fp_rasterizer_state);
   (void)pipe;
   if (!s)
      return NULL;
   s->base = *r;
   s->draw = *r;
   /* The model culls by the determinant's sign (spec section 1); draw
    * culls only when its unfilled-polygon stage needs culled input. */
   if (r->fill_front == PIPE_POLYGON_MODE_FILL && r->fill_back == PIPE_POLYGON_MODE_FILL)
      s->draw.cull_face = PIPE_FACE_NONE;

   s->rast.front_ccw = r->front_ccw;
   s->rast.cull = (enum rast_cull)(s->draw.cull_face == PIPE_FACE_NONE ? r->cull_face
                                                                      : PIPE_FACE_NONE);
   s->rast.scissor = r->scissor;
   s->rast.half_pixel_center = r->half_pixel_center;
   s->rast.bottom_edge_rule = r->bottom_edge_rule;
   s->rast.flatshade = r->flatshade;
   s->rast.flatshade_first = r->flatshade_first;
   s->rast.line_width = r->line_width;
   s->rast.point_size = r->point_size;
   s->rast.point_size_per_vertex = r->point_size_per_vertex;
   s->rast.point_quad_rasterization = r->point_quad_rasterization;
   s->rast.sprite_coord_lower_left = r->sprite_coord_mode == PIPE_SPRITE_COORD_LOWER_LEFT;
   s->rast.point_tri_clip = r->point_tri_clip;
   /* st clears depth_clip_near/far for GL's depth clamp, and draw then
    * stops clipping z; depth_clamp (st: !depth_clip_far) makes the model
    * clamp each fragment's depth to its viewport's range instead. */
   s->rast.depth_clamp = r->depth_clamp;
   /* GL_MULTISAMPLE disabled: a multisampled target drawn at the centres */
   s->rast.single_sample = !r->multisample;
   return s;
}

/* The model's depth ranges: each viewport's n and f, the ends of its z
 * transform (util_viewport_zmin_zmax's, unordered: the model orders
 * them), with the rasterizer's clip_halfz.  Given to the model only when
 * they change: every setter flushes it. */
static void fp_update_depth_ranges(struct fp_context *fp)
{
   STATIC_ASSERT(PIPE_MAX_VIEWPORTS == RAST_MAX_VIEWPORTS);
   const bool halfz = fp->rasterizer && fp->rasterizer->base.clip_halfz;
   struct rast_depth_range r[PIPE_MAX_VIEWPORTS];
   for (unsigned i = 0; i < PIPE_MAX_VIEWPORTS; i++) {
      const struct pipe_viewport_state *vp = &fp->viewports[i];
      r[i].n = halfz ? vp->translate[2] : vp->translate[2] - vp->scale[2];
      r[i].f = vp->translate[2] + vp->scale[2];
   }
   if (memcmp(r, fp->depth_ranges, sizeof(r))) {
      memcpy(fp->depth_ranges, r, sizeof(r));
      rast_set_depth_ranges(fp->rast, 0, PIPE_MAX_VIEWPORTS, r);
   }
}

static void fp_bind_rasterizer_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_rasterizer_state *s = cso;
   /* the shader's sample positions and masks follow GL_MULTISAMPLE */
   if (s && (!fp->rasterizer || fp->rasterizer->base.multisample != s->base.multisample))
      fp->fs_dirty = true;
   fp->rasterizer = s;
   /* draw flushes itself here unless it is the caller (wide points). */
   draw_set_rasterizer_state(fp->draw, s ? &s->draw : NULL, s);
   if (s)
      rast_set_raster_state(fp->rast, &s->rast);
   fp_update_depth_ranges(fp);   /* clip_halfz moves n */
   fp->vl_valid = false;   /* sprite_coord_enable changes the vertex layout */
}

/* ---- samplers and sampler views ---- */

static void *fp_create_sampler_state(struct pipe_context *pipe,
                                     const struct pipe_sampler_state *s)
{
   struct pipe_sampler_state *c = MALLOC_STRUCT(pipe_sampler_state);
   (void)pipe;
   if (c)
      *c = *s;
   return c;
}

static void fp_bind_sampler_states(struct pipe_context *pipe, enum pipe_shader_type shader,
                                   unsigned start, unsigned num, void **samplers)
{
   struct fp_context *fp = fp_context(pipe);
   draw_flush(fp->draw);
   for (unsigned i = 0; i < num && start + i < PIPE_MAX_SAMPLERS; i++)
      fp->samplers[shader][start + i] = samplers ? samplers[i] : NULL;
   fp->tex_epoch++;
   fp->fs_dirty = true;
}

static struct pipe_sampler_view *fp_create_sampler_view(struct pipe_context *pipe,
                                                        struct pipe_resource *texture,
                                                        const struct pipe_sampler_view *templ)
{
   struct fp_sampler_view *v = CALLOC_STRUCT(fp_sampler_view);
   if (!v)
      return NULL;
   v->base = *templ;
   v->base.reference.count = 1;
   v->base.texture = NULL;
   pipe_resource_reference(&v->base.texture, texture);
   v->base.context = pipe;
   fp_init_sampler_view(v);
   return &v->base;
}

static void fp_sampler_view_destroy(struct pipe_context *pipe, struct pipe_sampler_view *view)
{
   (void)pipe;
   pipe_resource_reference(&view->texture, NULL);
   FREE(view);
}

static void fp_set_sampler_views(struct pipe_context *pipe, enum pipe_shader_type shader,
                                 unsigned start, unsigned num, unsigned unbind_trailing,
                                 bool take_ownership, struct pipe_sampler_view **views)
{
   struct fp_context *fp = fp_context(pipe);
   draw_flush(fp->draw);
   for (unsigned i = 0; i < num + unbind_trailing; i++) {
      unsigned slot = start + i;
      struct pipe_sampler_view *v = (views && i < num) ? views[i] : NULL;
      if (slot >= PIPE_MAX_SHADER_SAMPLER_VIEWS)
         break;
      if (take_ownership && v) {
         pipe_sampler_view_reference(&fp->sampler_views[shader][slot], NULL);
         fp->sampler_views[shader][slot] = v;
      } else {
         pipe_sampler_view_reference(&fp->sampler_views[shader][slot], v);
      }
   }
   fp->tex_epoch++;
   fp->fs_dirty = true;
}

/* ---- vertex input ---- */

static void *fp_create_velems(struct pipe_context *pipe, unsigned count,
                              const struct pipe_vertex_element *elems)
{
   struct fp_velems *v = CALLOC_STRUCT(fp_velems);
   (void)pipe;
   if (!v)
      return NULL;
   v->count = MIN2(count, PIPE_MAX_ATTRIBS);
   memcpy(v->elem, elems, v->count * sizeof(elems[0]));
   for (unsigned i = 0; i < v->count; i++) {
      const struct util_format_description *d = util_format_description(elems[i].src_format);
      const int c = d ? util_format_get_first_non_void_channel(elems[i].src_format) : -1;
      v->snorm |= c >= 0 && d->channel[c].type == UTIL_FORMAT_TYPE_SIGNED &&
                  d->channel[c].normalized;
   }
   return v;
}

static void fp_bind_velems(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   fp->velems = cso;
   draw_set_vertex_elements(fp->draw, fp->velems ? fp->velems->count : 0,
                            fp->velems ? fp->velems->elem : NULL);
}

static void fp_set_vertex_buffers(struct pipe_context *pipe, unsigned start, unsigned num,
                                  unsigned unbind_trailing, bool take_ownership,
                                  const struct pipe_vertex_buffer *buffers)
{
   struct fp_context *fp = fp_context(pipe);
   util_set_vertex_buffers_count(fp->vertex_buffer, &fp->num_vertex_buffers, buffers,
                                 start, num, unbind_trailing, take_ownership);
   draw_set_vertex_buffers(fp->draw, start, num, unbind_trailing, buffers);
}

/* ---- viewport, scissor, clip and the rest ---- */

static void fp_set_viewport_states(struct pipe_context *pipe, unsigned start, unsigned num,
                                   const struct pipe_viewport_state *vp)
{
   struct fp_context *fp = fp_context(pipe);
   draw_set_viewport_states(fp->draw, start, num, vp);
   /* The viewports' pixels as llvmpipe rounds them (lp_setup.c's vpwh,
    * whose maximum is inclusive), for the points draw leaves unclipped. */
   struct rast_scissor r[PIPE_MAX_VIEWPORTS];
   num = MIN2(num, PIPE_MAX_VIEWPORTS - MIN2(start, PIPE_MAX_VIEWPORTS));
   for (unsigned i = 0; i < num; i++) {
      const float half_height = fabsf(vp[i].scale[1]);
      const float x0 = vp[i].translate[0] - vp[i].scale[0];
      const float y0 = vp[i].translate[1] - half_height;
      r[i] = (struct rast_scissor){ (int)(x0 + 0.499f), (int)(y0 + 0.499f),
                                    (int)(vp[i].scale[0] * 2.0f + x0 - 0.501f) + 1,
                                    (int)(half_height * 2.0f + y0 - 0.501f) + 1 };
   }
   if (num) {
      rast_set_viewports(fp->rast, start, num, r);
      memcpy(&fp->viewports[start], vp, num * sizeof(*vp));
      fp_update_depth_ranges(fp);
   }
}

static void fp_set_scissor_states(struct pipe_context *pipe, unsigned start, unsigned num,
                                  const struct pipe_scissor_state *sc)
{
   struct fp_context *fp = fp_context(pipe);
   struct rast_scissor r[PIPE_MAX_VIEWPORTS];
   num = MIN2(num, PIPE_MAX_VIEWPORTS - MIN2(start, PIPE_MAX_VIEWPORTS));
   if (!num)
      return;
   draw_flush(fp->draw);
   for (unsigned i = 0; i < num; i++)
      r[i] = (struct rast_scissor){ sc[i].minx, sc[i].miny, sc[i].maxx, sc[i].maxy };
   rast_set_scissors(fp->rast, start, num, r);
}

static void fp_set_clip_state(struct pipe_context *pipe, const struct pipe_clip_state *clip)
{
   struct fp_context *fp = fp_context(pipe);
   draw_set_clip_state(fp->draw, clip);
}

static void fp_set_sample_mask(struct pipe_context *pipe, unsigned mask)
{
   struct fp_context *fp = fp_context(pipe);
   if (mask == fp->sample_mask)
      return;
   draw_flush(fp->draw);
   fp->sample_mask = mask;
   rast_set_sample_mask(fp->rast, mask);
}

/* The model's pattern (rast.h): llvmpipe's standard 4x one. */
static void fp_get_sample_position(struct pipe_context *pipe, unsigned sample_count,
                                   unsigned sample_index, float *out_value)
{
   (void)pipe;
   if (sample_count == RAST_MSAA_SAMPLES && sample_index < RAST_MSAA_SAMPLES) {
      out_value[0] = rast_sample_pos_4x[sample_index][0];
      out_value[1] = rast_sample_pos_4x[sample_index][1];
   } else {
      out_value[0] = out_value[1] = 0.5f;
   }
}

/* Polygon stipple is draw's pstipple stage, which wraps this hook and
 * turns the pattern into a texture and a kill in the fragment shader; the
 * model itself has no stipple. */
static void fp_set_polygon_stipple(struct pipe_context *pipe, const struct pipe_poly_stipple *s)
{
   (void)pipe; (void)s;
}

/* glMinSampleShading (st: the invocations a fragment it asks for): any
 * number above one shades once a sample, four invocations being at least
 * what is asked on the model's 4-sample targets. */
static void fp_set_min_samples(struct pipe_context *pipe, unsigned n)
{
   struct fp_context *fp = fp_context(pipe);
   if ((fp->min_samples > 1) != (n > 1))
      fp->fs_dirty = true;
   fp->min_samples = n;
}

void fp_init_state_functions(struct fp_context *fp)
{
   struct pipe_context *p = &fp->pipe;
   p->create_blend_state = fp_create_blend_state;
   p->bind_blend_state = fp_bind_blend_state;
   p->delete_blend_state = fp_delete_state;
   p->set_blend_color = fp_set_blend_color;
   p->create_depth_stencil_alpha_state = fp_create_dsa_state;
   p->bind_depth_stencil_alpha_state = fp_bind_dsa_state;
   p->delete_depth_stencil_alpha_state = fp_delete_state;
   p->set_stencil_ref = fp_set_stencil_ref;
   p->create_rasterizer_state = fp_create_rasterizer_state;
   p->bind_rasterizer_state = fp_bind_rasterizer_state;
   p->delete_rasterizer_state = fp_delete_state;
   p->create_sampler_state = fp_create_sampler_state;
   p->bind_sampler_states = fp_bind_sampler_states;
   p->delete_sampler_state = fp_delete_state;
   p->create_sampler_view = fp_create_sampler_view;
   p->sampler_view_destroy = fp_sampler_view_destroy;
   p->set_sampler_views = fp_set_sampler_views;
   p->create_vertex_elements_state = fp_create_velems;
   p->bind_vertex_elements_state = fp_bind_velems;
   p->delete_vertex_elements_state = fp_delete_state;
   p->set_vertex_buffers = fp_set_vertex_buffers;
   p->set_viewport_states = fp_set_viewport_states;
   p->set_scissor_states = fp_set_scissor_states;
   p->set_clip_state = fp_set_clip_state;
   p->set_sample_mask = fp_set_sample_mask;
   p->get_sample_position = fp_get_sample_position;
   p->set_polygon_stipple = fp_set_polygon_stipple;
   p->set_min_samples = fp_set_min_samples;
}
