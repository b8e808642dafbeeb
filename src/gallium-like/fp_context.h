#ifndef FP_CONTEXT_H
#define FP_CONTEXT_H

#include "pipe/p_context.h"
#include "pipe/p_state.h"
#include "tgsi/tgsi_scan.h"
#include "draw/draw_vertex.h"
#include "rast/rast.h"
#include "fp_jit.h"

struct draw_context;
struct draw_stage;
struct draw_vertex_shader;
struct draw_tess_ctrl_shader;
struct draw_tess_eval_shader;
struct vbuf_render;
struct tgsi_exec_machine;
struct fp_tgsi_sampler;
struct fp_compute_shader;
struct nir_shader;
struct tgsi_image;
struct tgsi_buffer;

/* The stages with storage buffers and images (fp_context.ssbo, images). */
enum fp_mem_stage { FP_MEM_COMPUTE, FP_MEM_FRAGMENT, FP_MEM_STAGES };

struct fp_blend_state {
   struct pipe_blend_state base;
   struct rast_blend_state rast;
};

struct fp_dsa_state {
   struct pipe_depth_stencil_alpha_state base;
   struct rast_depth_stencil_state rast;
};

struct fp_rasterizer_state {
   struct pipe_rasterizer_state base;
   /* What draw sees: culling is left to the model unless a draw stage
    * (unfilled polygons) must know it first. */
   struct pipe_rasterizer_state draw;
   struct rast_raster_state rast;
};

struct fp_fragment_shader {
   const struct tgsi_token *tokens;
   struct nir_shader *nir;          /* st's NIR, for the compiled path; NULL from TGSI */
   /* What tgsi_exec runs: `tokens`, or with framebuffer fetch a copy that
    * reads the fetched colour of output k from IN[fetch_first + k]
    * (fp_fbfetch.c); fetch_mask: the colour buffers read. */
   const struct tgsi_token *exec_tokens;
   unsigned fetch_first, fetch_mask;
   struct tgsi_shader_info info;
   void *draw_fs;                   /* draw's copy, for wide points etc. */
   bool pixel_center_integer;
   bool color0_to_all;
   bool writes_depth;
   bool may_discard;
   /* stores or atomics to storage buffers and images (atomic counters are
    * storage buffers); early_tests: layout(early_fragment_tests) */
   bool side_effects, early_tests;
   bool reads_fragcoord;          /* gl_FragCoord, an input or a system value */
   /* Sample shading (docs/msaa.md): the SYSTEM_VALUE registers of
    * gl_SampleID, gl_SamplePosition and gl_SampleMaskIn (-1 where not
    * read), the gl_SampleMask output (-1 where not written), and whether
    * the shader runs once a sample whatever glMinSampleShading says (it
    * reads one of those, or has `sample` inputs). */
   int sv_sample_id, sv_sample_pos, sv_sample_mask;
   int sample_mask_output;
   bool per_sample;
   int depth_output;                /* output register, or -1 */
   int color_output[RAST_MAX_CBUFS];
   unsigned num_color_outputs;
   /* Per input component, the samplers whose axis a (s, t, r) it is the
    * coordinate of, read as it is; and the components read any other way
    * (fp_rebase.c). */
   struct fp_coord_use { uint32_t samplers[3]; } coord_use[RAST_MAX_VARYINGS][4];
   uint8_t coord_other[RAST_MAX_VARYINGS];
   /* Per input, the components read as an array layer (fp_rebase.c): the
    * model divides them in binary32 (rast_varying's float_mask). */
   uint8_t layer_read[RAST_MAX_VARYINGS];
   /* Tiered execution: interpreted until hot, then compiled (fp_fs.c). */
   uint64_t quads_interpreted;
   struct fp_jit_variant *jit;
   bool jit_failed;
   bool hot_ahead;                /* a batch about to be drawn makes it hot */
   bool hot_loop;                 /* hot by the rendering loop's rule only */
};

/* A geometry shader: draw runs it in tgsi_exec (mesa/patches 0013), where
 * its texture instructions reach the modeled unit as a vertex shader's
 * do; while one is bound, the vertex shader is the interpreted one too. */
struct fp_geometry_shader {
   struct draw_geometry_shader *draw_gs;
   /* compiled (draw's LLVM path), made at its first draw with tessellation,
    * which only draw's LLVM middle end runs (fp_state_tess.c) */
   struct draw_geometry_shader *draw_gs_llvm;
   struct pipe_shader_state state;  /* its own copy of the tokens */
};

/* Tiered like fragment shaders: draw runs it in tgsi_exec until it is hot,
 * then compiled (draw's LLVM path); its texture instructions reach the
 * modeled unit either way (fp_jit_draw.c). */
struct fp_vertex_shader {
   struct draw_vertex_shader *draw_vs;        /* the one bound */
   struct draw_vertex_shader *draw_vs_llvm;   /* once compiled */
   struct pipe_shader_state state;  /* its own copy of the tokens */
   bool llvm_failed;
   uint64_t vertices;
};

/* What one thread of the model shades its quads with (fp_fs.c): the
 * shader's run-time state and the texture unit's glue are written while it
 * shades, so every thread has its own.  Thread 0 is the driver's. */
struct fp_fs_thread {
   struct fp_context *fp;
   struct rast_context *rast;             /* the thread's model context */
   const struct rast_quad *quad;          /* being shaded by tgsi_exec (interpolateAt*) */
   struct tgsi_exec_machine *mach;
   struct fp_tgsi_sampler *sampler;       /* the fragment stage's */
   struct fp_jit_context jit_ctx;
   struct rast_shaded_quad spare;         /* a quad alone: the eight-lane code's other half */
   uint64_t quads_jit, quads_interp;
   uint64_t quads_interp_seen;            /* of quads_interp, counted to the shader */
   /* Threads side by side in one array, each writing its own: a cache
    * line between them, or every shaded quad would pass the line back
    * and forth between the cores. */
   char apart[64];
};

struct fp_velems {
   unsigned count;
   struct pipe_vertex_element elem[PIPE_MAX_ATTRIBS];
   /* an element of a signed normalized format: GL ES 3.0 (2.1.6.1) clamps
    * its most negative value to -1, which draw's compiled fetch (gallivm)
    * does and its interpreted one (translate, util_format's unpack) does
    * not: the 2-bit alpha of GL_INT_2_10_10_10_REV reads -2 there */
   bool snorm;
};

struct fp_sampler_view {
   struct pipe_sampler_view base;
   void *fetch;                     /* util_format_fetch_rgba_func_ptr */
   bool zs;                         /* depth: sampled through unpack_z_float */
   bool stencil;                    /* stencil index, an unsigned integer */
   bool is_unorm, is_snorm;
   bool integer;                  /* pure integer texels, sampled bit for bit */
   unsigned bw, bh, bsize;          /* format block */
};

struct fp_context {
   struct pipe_context pipe;
   const struct fp_options *opts;   /* the screen's: FIXPIPE_* */
   struct rast_context *rast;
   struct draw_context *draw;
   struct vbuf_render *vbuf_render;
   struct draw_stage *vbuf_stage;

   const struct fp_blend_state *blend;
   const struct fp_dsa_state *dsa;
   const struct fp_rasterizer_state *rasterizer;
   struct fp_fragment_shader *fs;
   struct fp_vertex_shader *vs;
   struct fp_geometry_shader *gs;
   /* tessellation (fp_state_tess.c): draw's shaders, and the vertices of a
    * patch */
   struct draw_tess_ctrl_shader *tcs;
   struct draw_tess_eval_shader *tes;
   uint8_t patch_vertices;
   const struct fp_velems *velems;

   struct pipe_framebuffer_state framebuffer;
   /* The viewports as set, and the depth ranges last given to the model
    * (fp_update_depth_ranges): they follow both these and the
    * rasterizer's clip_halfz. */
   struct pipe_viewport_state viewports[PIPE_MAX_VIEWPORTS];
   struct rast_depth_range depth_ranges[PIPE_MAX_VIEWPORTS];
   struct pipe_vertex_buffer vertex_buffer[PIPE_MAX_ATTRIBS];
   unsigned num_vertex_buffers;
   struct pipe_constant_buffer constants[PIPE_SHADER_TYPES][PIPE_MAX_CONSTANT_BUFFERS];
   struct pipe_sampler_view *sampler_views[PIPE_SHADER_TYPES][PIPE_MAX_SHADER_SAMPLER_VIEWS];
   /* Bumped by every sampler view or sampler state binding: a texture unit
    * bound since then for the same objects is still right (fp_sampler.c). */
   uint64_t tex_epoch;
   const struct pipe_sampler_state *samplers[PIPE_SHADER_TYPES][PIPE_MAX_SAMPLERS];
   unsigned sample_mask;
   unsigned fb_samples;             /* samples a pixel of the bound framebuffer: 1 or 4 */
   unsigned min_samples;            /* set_min_samples: sample shading where above 1 */

   /* The samplers of draw's stages; the fragment stage's is thread 0's. */
   struct fp_tgsi_sampler *tgsi_sampler[PIPE_SHADER_TYPES];
   bool fs_dirty;                  /* shader, constants or samplers changed */
   /* Fragment shading, one of each per thread of the model (FIXPIPE_THREADS). */
   unsigned num_threads;
   struct fp_fs_thread *fs_thread;

   /* Compiled shaders (fp_jit*.c) allowed: not FIXPIPE_DEBUG=nojit. */
   bool jit;
   /* Their LLVM context, made with the first (fp_llvm_context): a process that
    * never compiles a shader never initializes LLVM. */
   LLVMContextRef llvm_context;
   struct {
      uint64_t compiled, failed;
      uint64_t vs_compiled, cache_hits;
      uint64_t vs_failed;         /* gallivm refused: stays in tgsi_exec */
      uint64_t hot_ahead;         /* fragment shaders hot before a batch */
      uint64_t hot_loop;          /* compiled sooner, the process presenting */
      double compile_ms;
   } jit_stats;

   /* The vertex layout last given to draw and to the model. */
   struct vertex_info vinfo;
   struct rast_vertex_layout vl;
   bool vl_valid;
   const struct fp_fragment_shader *vl_fs;   /* the shader vl was built for */

   /* Occlusion queries in flight and conditional rendering. */
   struct pipe_query *render_cond_query;
   bool render_cond_cond;
   enum pipe_render_cond_flag render_cond_mode;
   unsigned active_occlusion_queries;

   /* Transform feedback (fp_so.c): draw's targets, and the primitives
    * written and needed per vertex stream since the context began. */
   struct draw_so_target *so_targets[PIPE_MAX_SO_BUFFERS];
   unsigned num_so_targets;
   uint64_t so_written[PIPE_MAX_VERTEX_STREAMS], so_generated[PIPE_MAX_VERTEX_STREAMS];
   unsigned active_primgen_queries;

   /* Compute (fp_compute.c) and the storage buffers and images of the
    * compute and fragment stages (fp_image.c), indexed by enum
    * fp_mem_stage; the vertex and geometry stages have none.  The
    * fragment stage's interfaces are shared by every thread's machine:
    * they only read the bindings, which change between batches. */
   struct fp_compute_shader *cs;
   struct pipe_shader_buffer ssbo[FP_MEM_STAGES][PIPE_MAX_SHADER_BUFFERS];
   struct pipe_image_view images[FP_MEM_STAGES][PIPE_MAX_SHADER_IMAGES];
   struct tgsi_image *tgsi_image[FP_MEM_STAGES];
   struct tgsi_buffer *tgsi_buffer[FP_MEM_STAGES];
   bool print_stats;
   struct fp_context *stats_next;   /* FIXPIPE_STATS: the contexts alive (fp_context.c) */
   unsigned long stats_every, frames;   /* FIXPIPE_STATS=frames:N; frames presented */
   bool vectors_pending;                /* FIXPIPE_VECTORS: opened at the first draw */
   bool vectors_on;                     /* and written by this context */
   bool events_pending;                 /* FIXPIPE_EVENTS: started at the first draw */
   struct fp_events *events;            /* and recorded by this context (fp_events.c) */
};

static inline struct fp_context *fp_context(struct pipe_context *p)
{
   return (struct fp_context *)p;
}

struct pipe_context *fp_create_context(struct pipe_screen *screen, void *priv,
                                       unsigned flags);

void fp_init_state_functions(struct fp_context *fp);     /* fp_state.c */
void fp_init_shader_functions(struct fp_context *fp);    /* fp_state_shader.c */
void fp_init_fb_functions(struct fp_context *fp);        /* fp_state_fb.c */
void fp_init_clear_functions(struct fp_context *fp);     /* fp_clear.c */
void fp_init_blit_functions(struct fp_context *fp);      /* fp_blit.c */
void fp_init_query_functions(struct fp_context *fp);     /* fp_query.c */
/* The model's counters as driver queries (fp_query_driver.c). */
void fp_init_screen_query_functions(struct pipe_screen *screen);
bool fp_is_driver_query(unsigned type);
struct fp_counter_query;
struct fp_counter_query *fp_counter_query_create(unsigned type);
void fp_counter_query_begin(struct fp_context *fp, struct fp_counter_query *q);
void fp_counter_query_end(struct fp_context *fp, struct fp_counter_query *q);
void fp_counter_query_result(const struct fp_counter_query *q, union pipe_query_result *result);
/* FIXPIPE_VECTORS (docs/vectors.md): at a context's first draw. */
void fp_vectors_start(struct fp_context *fp);
/* FIXPIPE_EVENTS (fp_events.c, docs/events.md): started at a context's
 * first draw; each draw_vbo's row and maps; a frame's maps written when it
 * is presented; stopped at the context's end. */
void fp_events_start(struct fp_context *fp);
void fp_events_draw_begin(struct fp_context *fp);
void fp_events_draw_end(struct fp_context *fp);
void fp_events_frame(struct fp_context *fp, unsigned long frame);
void fp_events_stop(struct fp_context *fp);
/* FIXPIPE_STATS (fp_instruments.c): the counters on stderr, and the list of
 * live contexts that print theirs at exit. */
void fp_print_stats(const struct fp_context *fp);
void fp_stats_track(struct fp_context *fp, bool live);
/* Every counter of the model, up to date with what it has drawn. */
const struct rast_stats *fp_context_stats(struct fp_context *fp);
void fp_init_draw_functions(struct fp_context *fp);      /* fp_draw.c */
void fp_init_so_functions(struct fp_context *fp);        /* fp_so.c */
/* fp_compute.c: false when out of memory; fp_compute_release at destroy */
bool fp_init_compute_functions(struct fp_context *fp);
void fp_compute_release(struct fp_context *fp);
/* fp_image.c: tgsi_exec's images and storage buffers over these arrays */
struct tgsi_image *fp_tgsi_image_create(const struct pipe_image_view *views);
struct tgsi_buffer *fp_tgsi_buffer_create(const struct pipe_shader_buffer *buffers);
void fp_so_release(struct fp_context *fp);

/* fp_instruments.c: a frame presented (flush_frontbuffer), for FIXPIPE_STATS=frames:N */
void fp_context_frame_presented(struct fp_context *fp);
/* fp_context.c: the LLVM context of compiled fragment shaders, gallivm initialized with the
 * first; NULL if it cannot be made */
LLVMContextRef fp_llvm_context(struct fp_context *fp);

/* fp_state_shader.c: vertex shaders, tiered */
void fp_vs_count(struct fp_context *fp, uint64_t vertices);
/* The compiled copy of a vertex shader, made if need be; false when gallivm
 * refuses it (it stays interpreted). */
bool fp_vs_compile(struct fp_context *fp, struct fp_vertex_shader *vs);
/* Binds the vertex and geometry shaders draw is to run: interpreted or
 * compiled, by what is bound and made. */
void fp_bind_draw_stages(struct fp_context *fp);
/* fp_state_tess.c: tessellation's shaders and state; before a draw, the
 * compiled vertex and geometry shaders it needs (false: it cannot be drawn) */
void fp_init_tess_functions(struct fp_context *fp);
bool fp_tess_validate(struct fp_context *fp);

/* fp_vbuf.c */
struct vbuf_render *fp_create_vbuf_render(struct fp_context *fp);

/* fp_fs.c: bind the current fragment shader to tgsi_exec and the model. */
void fp_fs_validate(struct fp_context *fp);
/* fp_fs.c: after the model drew a batch: the interpreted quads counted to
 * the shader (it compiles once hot, at the same quad whatever the threads). */
void fp_fs_batch_done(struct fp_context *fp);
/* fp_fs.c: before a batch is drawn: whether the bound shader is interpreted
 * and may be compiled, and then, with the quads the batch's triangles
 * cover, whether it is hot already (compiled before the batch). */
bool fp_fs_batch_may_compile(const struct fp_context *fp);
void fp_fs_batch_ahead(struct fp_context *fp, double quads);

/* fp_sampler.c */
/* Its range and LOD counts go to rc, the model context of the thread it
 * samples on. */
struct fp_tgsi_sampler *fp_tgsi_sampler_create(struct fp_context *fp,
                                               enum pipe_shader_type stage,
                                               struct rast_context *rc);
void fp_tgsi_sampler_destroy(struct fp_tgsi_sampler *s);
struct tgsi_sampler *fp_tgsi_sampler_base(struct fp_tgsi_sampler *s);
/* A run of the fragment shader begins (a quad interpreted, or a call of
 * compiled code): what the sampler remembers of the last run goes. */
void fp_tgsi_sampler_begin(struct fp_tgsi_sampler *s);
/* `max` quads (2 or 4) whose operands compiled code laid out as
 * tgsi_exec's get_samples would have (fp_jit_sample.c), `quads` of them
 * real; control is an enum tgsi_sampler_control. */
struct tex_quad;
void fp_tgsi_sample_quads(struct tgsi_sampler *s, uint32_t sview_index, uint32_t sampler_index,
                          uint32_t control, uint32_t quads, uint32_t max,
                          const struct tex_quad *q, float rgba[][4][4]);
/* Gathers of channel `comp` with the offsets (s, t) on `max` quads laid out
 * so by compiled code, `quads` of them real. */
void fp_tgsi_gather_quads(struct tgsi_sampler *s, uint32_t sview_index, uint32_t sampler_index,
                          uint32_t comp, int32_t offset_s, int32_t offset_t, uint32_t quads,
                          uint32_t max, const struct tex_quad *q, float rgba[][4][4]);
/* What it counted so far, into rc's counters (not while rc's thread draws). */
void fp_tgsi_sampler_flush_stats(struct fp_tgsi_sampler *s, struct rast_context *rc);
/* What compiled gathers read and count (fp_jit_context): the sampler's
 * table of units' registers, its context's binding epoch, its counter. */
struct fp_jit_gather;
void fp_tgsi_sampler_jit_gathers(struct tgsi_sampler *s, const struct fp_jit_gather **gathers,
                                 const uint64_t **epoch, uint64_t **gathered);
/* The registers of the (texture, sampler) pairs compiled gathers read,
 * filled where the binding epoch has changed. */
void fp_tgsi_sampler_jit_prepare(struct fp_tgsi_sampler *s, const uint8_t (*units)[2],
                                 unsigned n);
void fp_init_sampler_view(struct fp_sampler_view *view);

/* fp_query.c: false when conditional rendering says skip. */
bool fp_check_render_cond(struct fp_context *fp);

/* fp_rebase.c: the shader's reads of its inputs, once; and which
 * components of input `input` the model may rebase with the samplers now
 * bound (rast_varying's rebase_mask and rebase_even). */
void fp_rebase_scan(struct fp_fragment_shader *fs);
/* fp_fbfetch.c: exec_tokens and fetch_mask of a shader; false when the
 * shader cannot be run. */
bool fp_fbfetch_prepare(struct fp_fragment_shader *fs);
/* Drops what tgsi_to_nir cannot read (the advanced-blend property) from
 * fs->tokens, before anything else looks at them; false: out of memory. */
bool fp_fbfetch_strip(struct fp_fragment_shader *fs);
void fp_fbfetch_release(struct fp_fragment_shader *fs);
/* fp_vbuf.c: the vertex layout's rebase masks after a sampler change. */
void fp_vbuf_update_rebase(struct fp_context *fp);
void fp_rebase_modes(const struct fp_context *fp, unsigned input, uint8_t *mask, uint8_t *even);

#endif
