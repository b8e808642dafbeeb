/*
 * Compute shaders (GL ES 3.1), run by tgsi_exec as softpipe runs them
 * (sp_compute.c): a work group is a set of machines of four invocations
 * each, run one after the other up to a barrier and then again from it
 * until all end.  Textures are sampled by the modeled unit (the compute
 * stage's fp_tgsi_sampler, LOD 0 as outside the fragment stage); images,
 * shader storage buffers, atomic counters (st lowers them to buffers) and
 * shared memory are memory (fp_image.c).  The fragment stage's storage
 * buffers and images are bound here too (fp_fs.c runs them).  Nothing here
 * is a stage of the modeled rasterizer, so the model's threads are not
 * involved: a dispatch runs on the calling thread, after every draw has
 * reached memory (rast_flush returns with the framebuffer written), and
 * before the next.
 */
#include "util/u_inlines.h"
#include "util/u_memory.h"
#include "tgsi/tgsi_exec.h"
#include "tgsi/tgsi_parse.h"
#include "tgsi/tgsi_scan.h"
#include "draw/draw_context.h"

#include "fp_context.h"
#include "fp_resource.h"

struct fp_compute_shader {
   const struct tgsi_token *tokens;
   struct tgsi_shader_info info;
   unsigned shared_size;                 /* bytes of shared memory */
};

static void *fp_create_compute_state(struct pipe_context *pipe,
                                     const struct pipe_compute_state *templ)
{
   (void)pipe;
   if (templ->ir_type != PIPE_SHADER_IR_TGSI)
      return NULL;   /* the screen asks for TGSI */
   struct fp_compute_shader *cs = CALLOC_STRUCT(fp_compute_shader);
   if (!cs)
      return NULL;
   cs->tokens = tgsi_dup_tokens(templ->prog);
   if (!cs->tokens) {
      FREE(cs);
      return NULL;
   }
   tgsi_scan_shader(cs->tokens, &cs->info);
   cs->shared_size = templ->req_local_mem;
   return cs;
}

static void fp_bind_compute_state(struct pipe_context *pipe, void *cso)
{
   fp_context(pipe)->cs = cso;
}

static void fp_delete_compute_state(struct pipe_context *pipe, void *cso)
{
   struct fp_compute_shader *cs = cso;
   (void)pipe;
   FREE((void *)cs->tokens);
   FREE(cs);
}

static void set_system_value(struct tgsi_exec_machine *m, unsigned semantic, const int v[3])
{
   const int i = m->SysSemanticToIndex[semantic];
   if (i < 0)
      return;
   for (unsigned c = 0; c < 3; c++)
      for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++)
         m->SystemValue[i].xyzw[c].i[p] = v[c];
}

/* The grid: the call's, or three words of the indirect buffer. */
static bool grid_size(const struct pipe_grid_info *info, uint32_t grid[3])
{
   if (!info->indirect) {
      memcpy(grid, info->grid, 3 * sizeof(uint32_t));
      return true;
   }
   const struct pipe_resource *r = info->indirect;
   if (!fp_resource(info->indirect)->data || info->indirect_offset > r->width0 ||
       r->width0 - info->indirect_offset < 3 * sizeof(uint32_t))
      return false;
   memcpy(grid, fp_resource(info->indirect)->data + info->indirect_offset, 3 * sizeof(uint32_t));
   return true;
}

/* One work group: every machine up to its end or the next barrier, again
 * and again until none stopped at a barrier. */
static void run_group(struct tgsi_exec_machine **mach, unsigned n, const int group[3])
{
   for (unsigned i = 0; i < n; i++)
      set_system_value(mach[i], TGSI_SEMANTIC_BLOCK_ID, group);
   bool restart = false;
   do {
      bool barrier = false;
      for (unsigned i = 0; i < n; i++) {
         tgsi_exec_machine_run(mach[i], restart ? mach[i]->pc : 0);
         barrier |= mach[i]->pc != -1;
      }
      restart = barrier;
   } while (restart);
}

static void fp_launch_grid(struct pipe_context *pipe, const struct pipe_grid_info *info)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_compute_shader *cs = fp->cs;
   uint32_t grid[3];
   if (!cs || !grid_size(info, grid) || !grid[0] || !grid[1] || !grid[2])
      return;
   const unsigned bw = info->block[0], bh = info->block[1], bd = info->block[2];
   const unsigned n = DIV_ROUND_UP(bw, TGSI_QUAD_SIZE) * bh * bd;
   if (!n)
      return;
   struct tgsi_exec_machine **mach = CALLOC(n, sizeof(*mach));
   void *shared = cs->shared_size ? CALLOC(1, cs->shared_size) : NULL;
   bool ok = mach && (shared || !cs->shared_size);

   struct tgsi_sampler *sampler = fp_tgsi_sampler_base(fp->tgsi_sampler[PIPE_SHADER_COMPUTE]);
   const void *constants[PIPE_MAX_CONSTANT_BUFFERS];
   unsigned const_size[PIPE_MAX_CONSTANT_BUFFERS];
   for (unsigned i = 0; i < PIPE_MAX_CONSTANT_BUFFERS; i++) {
      const struct pipe_constant_buffer *c = &fp->constants[PIPE_SHADER_COMPUTE][i];
      constants[i] = c->user_buffer ? (const uint8_t *)c->user_buffer + c->buffer_offset
                     : c->buffer ? fp_resource(c->buffer)->data + c->buffer_offset : NULL;
      const_size[i] = constants[i] ? c->buffer_size : 0;
   }
   const int grid_v[3] = { (int)grid[0], (int)grid[1], (int)grid[2] };
   const int block_v[3] = { (int)bw, (int)bh, (int)bd };
   unsigned k = 0;
   for (unsigned z = 0; z < bd && ok; z++)
      for (unsigned y = 0; y < bh && ok; y++)
         for (unsigned x = 0; x < bw && ok; x += TGSI_QUAD_SIZE) {
            struct tgsi_exec_machine *m = mach[k++] = tgsi_exec_machine_create(PIPE_SHADER_COMPUTE);
            if (!m) {
               ok = false;
               break;
            }
            m->LocalMem = shared;
            m->LocalMemSize = cs->shared_size;
            m->NonHelperMask = (1u << MIN2(TGSI_QUAD_SIZE, bw - x)) - 1;
            tgsi_exec_machine_bind_shader(m, cs->tokens, sampler, fp->tgsi_image[FP_MEM_COMPUTE],
                                          fp->tgsi_buffer[FP_MEM_COMPUTE]);
            tgsi_exec_set_constant_buffers(m, PIPE_MAX_CONSTANT_BUFFERS, constants, const_size);
            set_system_value(m, TGSI_SEMANTIC_GRID_SIZE, grid_v);
            set_system_value(m, TGSI_SEMANTIC_BLOCK_SIZE, block_v);
            const int i = m->SysSemanticToIndex[TGSI_SEMANTIC_THREAD_ID];
            if (i >= 0)
               for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
                  m->SystemValue[i].xyzw[0].i[p] = (int)(x + p);
                  m->SystemValue[i].xyzw[1].i[p] = (int)y;
                  m->SystemValue[i].xyzw[2].i[p] = (int)z;
               }
         }

   if (ok) {
      for (unsigned gz = 0; gz < grid[2]; gz++)
         for (unsigned gy = 0; gy < grid[1]; gy++)
            for (unsigned gx = 0; gx < grid[0]; gx++) {
               const int group[3] = { (int)gx, (int)gy, (int)gz };
               run_group(mach, n, group);
            }
   } else {
      fprintf(stderr, "fixpipe: out of memory for a compute dispatch of %u invocations: "
              "not run\n", bw * bh * bd);
   }

   for (unsigned i = 0; mach && i < n; i++) {
      if (!mach[i])
         continue;
      tgsi_exec_machine_bind_shader(mach[i], NULL, NULL, NULL, NULL);
      tgsi_exec_machine_destroy(mach[i]);
   }
   FREE(mach);
   FREE(shared);
}

/* The stage's bindings (enum fp_mem_stage), or -1 for a stage without
 * storage buffers and images (fp_screen.c). */
static int mem_stage(enum pipe_shader_type shader)
{
   return shader == PIPE_SHADER_COMPUTE ? FP_MEM_COMPUTE
          : shader == PIPE_SHADER_FRAGMENT ? FP_MEM_FRAGMENT : -1;
}

static void fp_set_shader_buffers(struct pipe_context *pipe, enum pipe_shader_type shader,
                                  unsigned start, unsigned count,
                                  const struct pipe_shader_buffer *buffers, unsigned writable)
{
   struct fp_context *fp = fp_context(pipe);
   const int st = mem_stage(shader);
   (void)writable;
   if (st < 0)
      return;
   /* the model's threads read the fragment stage's bindings while they
    * draw: whatever draw still holds is drawn with the old ones */
   if (st == FP_MEM_FRAGMENT)
      draw_flush(fp->draw);
   for (unsigned i = 0; i < count && start + i < PIPE_MAX_SHADER_BUFFERS; i++)
      util_copy_shader_buffer(&fp->ssbo[st][start + i], buffers ? &buffers[i] : NULL);
}

static void fp_set_shader_images(struct pipe_context *pipe, enum pipe_shader_type shader,
                                 unsigned start, unsigned count, unsigned unbind_trailing,
                                 const struct pipe_image_view *images)
{
   struct fp_context *fp = fp_context(pipe);
   const int st = mem_stage(shader);
   if (st < 0)
      return;
   if (st == FP_MEM_FRAGMENT)
      draw_flush(fp->draw);
   for (unsigned i = 0; i < count + unbind_trailing && start + i < PIPE_MAX_SHADER_IMAGES; i++)
      util_copy_image_view(&fp->images[st][start + i], images && i < count ? &images[i] : NULL);
}

void fp_compute_release(struct fp_context *fp)
{
   for (unsigned st = 0; st < FP_MEM_STAGES; st++) {
      for (unsigned i = 0; i < PIPE_MAX_SHADER_BUFFERS; i++)
         pipe_resource_reference(&fp->ssbo[st][i].buffer, NULL);
      for (unsigned i = 0; i < PIPE_MAX_SHADER_IMAGES; i++)
         pipe_resource_reference(&fp->images[st][i].resource, NULL);
      FREE(fp->tgsi_image[st]);
      FREE(fp->tgsi_buffer[st]);
      fp->tgsi_image[st] = NULL;
      fp->tgsi_buffer[st] = NULL;
   }
}

bool fp_init_compute_functions(struct fp_context *fp)
{
   struct pipe_context *p = &fp->pipe;
   p->create_compute_state = fp_create_compute_state;
   p->bind_compute_state = fp_bind_compute_state;
   p->delete_compute_state = fp_delete_compute_state;
   p->launch_grid = fp_launch_grid;
   p->set_shader_buffers = fp_set_shader_buffers;
   p->set_shader_images = fp_set_shader_images;
   bool ok = true;
   for (unsigned st = 0; st < FP_MEM_STAGES; st++) {
      fp->tgsi_image[st] = fp_tgsi_image_create(fp->images[st]);
      fp->tgsi_buffer[st] = fp_tgsi_buffer_create(fp->ssbo[st]);
      ok &= fp->tgsi_image[st] && fp->tgsi_buffer[st];
   }
   return ok;
}
