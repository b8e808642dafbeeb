/*
 * Resources: winsys display targets for what the window system shows or
 * shares, malloc'd linear storage (every level, layer and face) otherwise.
 * Rendering is synchronous, so maps never wait.
 */
#include "util/u_memory.h"
#include "util/u_math.h"
#include "util/u_inlines.h"
#include "util/u_transfer.h"
#include "util/u_surface.h"
#include "util/format/u_format.h"
#include "frontend/sw_winsys.h"

#include "fp_resource.h"
#include "fp_screen.h"

/* Keeps every image addressable by 32-bit offsets in tgsi-sized loops. */
#define FP_MAX_RESOURCE_BYTES (UINT64_C(1) << 31)

static bool fp_linear_layout(struct fp_resource *r, bool allocate)
{
   const struct pipe_resource *pt = &r->base;
   unsigned width = pt->width0, height = pt->height0, depth = pt->depth0;
   uint64_t size = 0;

   for (unsigned level = 0; level <= pt->last_level; level++) {
      unsigned slices = pt->target == PIPE_TEXTURE_3D ? depth
                      : pt->array_size * fp_resource_samples(pt);
      unsigned nblocksy = util_format_get_nblocksy(pt->format, height);
      r->stride[level] = util_format_get_stride(pt->format, width);
      r->level_offset[level] = size;
      r->img_stride[level] = (size_t)r->stride[level] * nblocksy;
      size += (uint64_t)r->img_stride[level] * MAX2(slices, 1);
      if (size > FP_MAX_RESOURCE_BYTES)
         return false;
      width = u_minify(width, 1);
      height = u_minify(height, 1);
      depth = u_minify(depth, 1);
   }
   if (!allocate)
      return true;
   /* Zeroed so that reads of never-written texels are deterministic. */
   r->data = align_malloc(MAX2(size, 1), 64);
   if (r->data)
      memset(r->data, 0, size);
   return r->data != NULL;
}

static bool fp_dt_layout(struct fp_screen *s, struct fp_resource *r,
                         const void *map_front_private)
{
   struct sw_winsys *ws = s->winsys;
   r->dt = ws->displaytarget_create(ws, r->base.bind, r->base.format, r->base.width0,
                                    r->base.height0, 64, map_front_private, &r->stride[0]);
   if (!r->dt)
      return false;
   r->img_stride[0] = (size_t)r->stride[0] *
                      util_format_get_nblocksy(r->base.format, r->base.height0);
   r->level_offset[0] = 0;
   /* The model writes pixels directly: keep the target mapped for its life.
    * No READ/WRITE flags: with them the DRI winsys would copy the window
    * into the buffer at map (X GetImage, BadMatch on an unmapped window) and
    * back at unmap; showing it is flush_frontbuffer's job. */
   r->data = ws->displaytarget_map(ws, r->dt, 0);
   if (!r->data) {
      ws->displaytarget_destroy(ws, r->dt);
      r->dt = NULL;
      return false;
   }
   if (map_front_private) {
      r->front_private = map_front_private;
      simple_mtx_lock(&s->fronts_lock);
      for (unsigned i = 0; i < FP_MAX_FRONTS; i++)
         if (!s->fronts[i]) {
            s->fronts[i] = r;
            break;
         }
      simple_mtx_unlock(&s->fronts_lock);
   }
   return true;
}

void fp_resource_sync_front(struct pipe_resource *pt)
{
   struct fp_resource *r = fp_resource(pt);
   if (!r || !r->front_private || !p_atomic_read(&r->front_stale))
      return;
   /* The DRI winsys reads the window into the buffer when it is mapped
    * for reading (X GetImage: the window is mapped, a buffer was shown in
    * it); mapped again without flags, as the model keeps it. */
   struct sw_winsys *ws = fp_screen(pt->screen)->winsys;
   ws->displaytarget_map(ws, r->dt, PIPE_MAP_READ);
   ws->displaytarget_map(ws, r->dt, 0);
   p_atomic_set(&r->front_stale, false);
}

void fp_resource_presented(struct fp_screen *s, struct pipe_resource *shown,
                           const void *front_private)
{
   if (!front_private)
      return;
   simple_mtx_lock(&s->fronts_lock);
   for (unsigned i = 0; i < FP_MAX_FRONTS; i++) {
      struct fp_resource *f = s->fronts[i];
      if (f && f->front_private == front_private && &f->base != shown)
         p_atomic_set(&f->front_stale, true);
   }
   simple_mtx_unlock(&s->fronts_lock);
}

static struct pipe_resource *fp_resource_create_front(struct pipe_screen *screen,
                                                      const struct pipe_resource *templat,
                                                      const void *map_front_private)
{
   struct fp_resource *r = CALLOC_STRUCT(fp_resource);
   if (!r)
      return NULL;
   r->base = *templat;
   pipe_reference_init(&r->base.reference, 1);
   r->base.screen = screen;

   bool ok;
   if (r->base.bind & (PIPE_BIND_DISPLAY_TARGET | PIPE_BIND_SCANOUT | PIPE_BIND_SHARED))
      ok = fp_dt_layout(fp_screen(screen), r, map_front_private);
   else
      ok = fp_linear_layout(r, true);
   if (!ok) {
      FREE(r);
      return NULL;
   }
   return &r->base;
}

static struct pipe_resource *fp_resource_create(struct pipe_screen *screen,
                                                const struct pipe_resource *templat)
{
   return fp_resource_create_front(screen, templat, NULL);
}

static bool fp_can_create_resource(struct pipe_screen *screen,
                                   const struct pipe_resource *templat)
{
   struct fp_resource r;
   (void)screen;
   memset(&r, 0, sizeof(r));
   r.base = *templat;
   return fp_linear_layout(&r, false);
}

static void fp_resource_destroy(struct pipe_screen *screen, struct pipe_resource *pt)
{
   struct fp_resource *r = fp_resource(pt);
   struct fp_screen *s = fp_screen(screen);
   struct sw_winsys *ws = s->winsys;
   if (r->front_private) {
      simple_mtx_lock(&s->fronts_lock);
      for (unsigned i = 0; i < FP_MAX_FRONTS; i++)
         if (s->fronts[i] == r)
            s->fronts[i] = NULL;
      simple_mtx_unlock(&s->fronts_lock);
   }
   if (r->dt) {
      ws->displaytarget_unmap(ws, r->dt);
      ws->displaytarget_destroy(ws, r->dt);
   } else if (!r->user_memory) {
      align_free(r->data);
   }
   FREE(r);
}

static struct pipe_resource *fp_resource_from_handle(struct pipe_screen *screen,
                                                     const struct pipe_resource *templat,
                                                     struct winsys_handle *whandle,
                                                     unsigned usage)
{
   struct sw_winsys *ws = fp_screen(screen)->winsys;
   struct fp_resource *r = CALLOC_STRUCT(fp_resource);
   (void)usage;
   if (!r)
      return NULL;
   r->base = *templat;
   pipe_reference_init(&r->base.reference, 1);
   r->base.screen = screen;
   r->dt = ws->displaytarget_from_handle(ws, templat, whandle, &r->stride[0]);
   if (!r->dt)
      goto fail;
   r->img_stride[0] = (size_t)r->stride[0] *
                      util_format_get_nblocksy(templat->format, templat->height0);
   r->data = ws->displaytarget_map(ws, r->dt, 0);
   if (!r->data) {
      ws->displaytarget_destroy(ws, r->dt);
      goto fail;
   }
   return &r->base;
fail:
   FREE(r);
   return NULL;
}

static bool fp_resource_get_handle(struct pipe_screen *screen, struct pipe_context *ctx,
                                   struct pipe_resource *pt, struct winsys_handle *whandle,
                                   unsigned usage)
{
   struct sw_winsys *ws = fp_screen(screen)->winsys;
   struct fp_resource *r = fp_resource(pt);
   (void)ctx; (void)usage;
   if (!r->dt)
      return false;
   return ws->displaytarget_get_handle(ws, r->dt, whandle);
}

static void *fp_transfer_map(struct pipe_context *pipe, struct pipe_resource *resource,
                             unsigned level, unsigned usage, const struct pipe_box *box,
                             struct pipe_transfer **transfer)
{
   struct fp_resource *r = fp_resource(resource);
   enum pipe_format format = resource->format;
   struct pipe_transfer *pt = CALLOC_STRUCT(pipe_transfer);
   (void)pipe;
   fp_resource_sync_front(resource);
   if (!pt || !r->data) {
      FREE(pt);
      return NULL;
   }
   pipe_resource_reference(&pt->resource, resource);
   pt->level = level;
   pt->usage = usage;
   pt->box = *box;
   pt->stride = r->stride[level];
   pt->layer_stride = r->img_stride[level];

   size_t offset = r->level_offset[level] + (size_t)box->z * r->img_stride[level];
   offset += (size_t)(box->y / util_format_get_blockheight(format)) * r->stride[level];
   offset += (size_t)(box->x / util_format_get_blockwidth(format)) *
             util_format_get_blocksize(format);
   *transfer = pt;
   return r->data + offset;
}

static void fp_transfer_unmap(struct pipe_context *pipe, struct pipe_transfer *transfer)
{
   (void)pipe;
   pipe_resource_reference(&transfer->resource, NULL);
   FREE(transfer);
}

static struct pipe_surface *fp_create_surface(struct pipe_context *pipe,
                                              struct pipe_resource *pt,
                                              const struct pipe_surface *tmpl)
{
   struct pipe_surface *ps = CALLOC_STRUCT(pipe_surface);
   if (!ps)
      return NULL;
   pipe_reference_init(&ps->reference, 1);
   pipe_resource_reference(&ps->texture, pt);
   ps->context = pipe;
   ps->format = tmpl->format;
   if (pt->target != PIPE_BUFFER) {
      ps->width = u_minify(pt->width0, tmpl->u.tex.level);
      ps->height = u_minify(pt->height0, tmpl->u.tex.level);
      ps->u.tex.level = tmpl->u.tex.level;
      ps->u.tex.first_layer = tmpl->u.tex.first_layer;
      ps->u.tex.last_layer = tmpl->u.tex.last_layer;
   } else {
      ps->width = tmpl->u.buf.last_element - tmpl->u.buf.first_element + 1;
      ps->height = pt->height0;
      ps->u.buf.first_element = tmpl->u.buf.first_element;
      ps->u.buf.last_element = tmpl->u.buf.last_element;
   }
   return ps;
}

static void fp_surface_destroy(struct pipe_context *pipe, struct pipe_surface *surf)
{
   (void)pipe;
   pipe_resource_reference(&surf->texture, NULL);
   FREE(surf);
}

void fp_init_screen_resource_funcs(struct pipe_screen *screen)
{
   screen->resource_create = fp_resource_create;
   screen->resource_create_front = fp_resource_create_front;
   screen->resource_destroy = fp_resource_destroy;
   screen->resource_from_handle = fp_resource_from_handle;
   screen->resource_get_handle = fp_resource_get_handle;
   screen->can_create_resource = fp_can_create_resource;
}

void fp_init_context_resource_funcs(struct pipe_context *pipe)
{
   pipe->buffer_map = fp_transfer_map;
   pipe->buffer_unmap = fp_transfer_unmap;
   pipe->texture_map = fp_transfer_map;
   pipe->texture_unmap = fp_transfer_unmap;
   pipe->transfer_flush_region = u_default_transfer_flush_region;
   pipe->buffer_subdata = u_default_buffer_subdata;
   pipe->texture_subdata = u_default_texture_subdata;
   pipe->clear_buffer = u_default_clear_buffer;
   pipe->create_surface = fp_create_surface;
   pipe->surface_destroy = fp_surface_destroy;
}
