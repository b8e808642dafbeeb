/*
 * The fixpipe screen: capabilities honest for what the model draws
 * (GL ES 2.0, desktop GL 2.1 / GLSL 1.20, single sample), formats, fences.
 */
#include <stdio.h>

/* nir.h (for the compiler options type) trips -Wsign-compare and
 * -Wmissing-field-initializers inside Mesa's own code. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include "compiler/nir/nir.h"
#pragma GCC diagnostic pop
#include "util/u_memory.h"
#include "util/u_atomic.h"
#include "util/u_math.h"
#include "util/format/u_format.h"
#include "util/u_screen.h"
#include "util/os_misc.h"
#include "util/os_time.h"
#include "gallivm/lp_bld_init.h"
#include "util/disk_cache.h"
#include "util/mesa-sha1.h"
#include "util/u_cpu_detect.h"
#include <llvm-c/ExecutionEngine.h>
#include "pipe/p_defines.h"
#include "pipe/p_screen.h"
#include "draw/draw_context.h"
#include "frontend/sw_winsys.h"
#include "tgsi/tgsi_exec.h"

#include "fp_public.h"
#include "fp_screen.h"
#include "rast/host/lanes.h"
#include "fp_context.h"
#include "fp_resource.h"

static const char *fp_get_vendor(struct pipe_screen *screen)
{
   (void)screen;
   return "fixpipe";
}

static const char *fp_get_name(struct pipe_screen *screen)
{
   return fp_screen(screen)->name;
}

/* st/mesa compiles to NIR and converts to TGSI for us, as for softpipe:
 * nir_to_tgsi's own defaults (nir_to_tgsi_compiler_options), which it
 * needs (TGSI has no local invocation index: without its lowering every
 * compute shader reading gl_LocalInvocationIndex read zero). */
static const nir_shader_compiler_options fp_compiler_options = {
   .fdot_replicates = true,
   .fuse_ffma32 = true,
   .fuse_ffma64 = true,
   .lower_extract_byte = true,
   .lower_extract_word = true,
   .lower_insert_byte = true,
   .lower_insert_word = true,
   .lower_fdph = true,
   .lower_flrp64 = true,
   .lower_fmod = true,
   .lower_rotate = true,
   .lower_uniforms_to_ubo = true,
   .lower_uadd_sat = true,
   .lower_usub_sat = true,
   .lower_vector_cmp = true,
   .lower_int64_options = nir_lower_imul_2x32_64,
   .max_unroll_iterations = 32,
   .use_interpolated_input_intrinsics = true,
   .lower_cs_local_index_to_id = true,
};

static const void *fp_get_compiler_options(struct pipe_screen *screen,
                                           enum pipe_shader_ir ir,
                                           enum pipe_shader_type shader)
{
   (void)screen; (void)ir; (void)shader;
   return &fp_compiler_options;
}

static int fp_max_levels(const struct fp_screen *s)
{
   return util_logbase2(s->profile->max_target) + 1;
}

static int fp_get_param(struct pipe_screen *screen, enum pipe_cap param)
{
   struct fp_screen *s = fp_screen(screen);
   switch (param) {
   case PIPE_CAP_NPOT_TEXTURES:
   case PIPE_CAP_MIXED_FRAMEBUFFER_SIZES:
   case PIPE_CAP_MIXED_COLOR_DEPTH_BITS:
   case PIPE_CAP_FRAGMENT_SHADER_TEXTURE_LOD:
   case PIPE_CAP_FRAGMENT_SHADER_DERIVATIVES:
   case PIPE_CAP_OCCLUSION_QUERY:
   case PIPE_CAP_QUERY_TIME_ELAPSED:
   case PIPE_CAP_QUERY_TIMESTAMP:
   case PIPE_CAP_TEXTURE_MIRROR_CLAMP:
   case PIPE_CAP_TEXTURE_MIRROR_CLAMP_TO_EDGE:
   case PIPE_CAP_TEXTURE_SWIZZLE:
   case PIPE_CAP_TEXTURE_SHADOW_MAP:
   case PIPE_CAP_BLEND_EQUATION_SEPARATE:
   case PIPE_CAP_INDEP_BLEND_ENABLE:
   case PIPE_CAP_INDEP_BLEND_FUNC:
   case PIPE_CAP_FS_COORD_ORIGIN_UPPER_LEFT:
   case PIPE_CAP_FS_COORD_PIXEL_CENTER_HALF_INTEGER:
   case PIPE_CAP_FS_COORD_PIXEL_CENTER_INTEGER:
   case PIPE_CAP_PRIMITIVE_RESTART:
   case PIPE_CAP_PRIMITIVE_RESTART_FIXED_INDEX:
   case PIPE_CAP_VS_INSTANCEID:
   case PIPE_CAP_VERTEX_ELEMENT_INSTANCE_DIVISOR:
   case PIPE_CAP_START_INSTANCE:
   case PIPE_CAP_CONDITIONAL_RENDER:
   case PIPE_CAP_CONDITIONAL_RENDER_INVERTED:
   case PIPE_CAP_VERTEX_COLOR_UNCLAMPED:   /* draw module */
   case PIPE_CAP_VERTEX_COLOR_CLAMPED:
   case PIPE_CAP_USER_VERTEX_BUFFERS:
   case PIPE_CAP_TEXTURE_FLOAT_LINEAR:
   case PIPE_CAP_TEXTURE_HALF_FLOAT_LINEAR:
   case PIPE_CAP_TEXTURE_BARRIER:
   case PIPE_CAP_ANISOTROPIC_FILTER:       /* accepted; sampled isotropically */
   case PIPE_CAP_CLIP_HALFZ:               /* draw clips and maps z in [0, w] */
   case PIPE_CAP_STREAM_OUTPUT_PAUSE_RESUME:        /* draw's stream output (fp_so.c) */
   case PIPE_CAP_STREAM_OUTPUT_INTERLEAVE_BUFFERS:
   case PIPE_CAP_TEXTURE_MULTISAMPLE:      /* the model's 4-sample planes, texelFetch */
   case PIPE_CAP_COMPUTE:                  /* tgsi_exec (fp_compute.c) */
   case PIPE_CAP_FRAMEBUFFER_NO_ATTACHMENT:
   case PIPE_CAP_BUFFER_MAP_PERSISTENT_COHERENT:   /* maps are the storage itself */
   case PIPE_CAP_CLEAR_TEXTURE:
   case PIPE_CAP_CULL_DISTANCE:            /* draw's user-cull stage, before the model */
   case PIPE_CAP_POLYGON_OFFSET_CLAMP:     /* draw's offset stage (fp_state_fb.c) */
   case PIPE_CAP_SEAMLESS_CUBE_MAP:        /* the sampler's flag (tex_sampler_desc) */
   case PIPE_CAP_CUBE_MAP_ARRAY:           /* the unit's TEX_TARGET_CUBE_ARRAY */
   case PIPE_CAP_TEXTURE_QUERY_LOD:        /* the unit's LOD (tex_unit_query_lod) */
   case PIPE_CAP_SAMPLER_VIEW_TARGET:      /* views: their own target, format, levels, layers */
   /* GL's depth clamp: draw stops clipping z (depth_clip_near/far) and the
    * model clamps each fragment's depth to its viewport's range
    * (rast_raster_state.depth_clamp). */
   case PIPE_CAP_DEPTH_CLIP_DISABLE:
   /* min/max reduction filtering: the unit's LINEAR levels take the least
    * or greatest tap (tex_sampler_desc.reduction) */
   case PIPE_CAP_SAMPLER_REDUCTION_MINMAX:
   case PIPE_CAP_SAMPLER_REDUCTION_MINMAX_ARB:
   /* an explicit LOD, bias or offset with a shadow 2-D array or cube map:
    * the unit compares at any level it samples */
   case PIPE_CAP_TEXTURE_SHADOW_LOD:
   /* Indirect draws: util_draw_indirect reads the arguments (fp_draw.c),
    * as for GL ES 3.1; st loops over multi-draws. */
   case PIPE_CAP_DRAW_INDIRECT:
   /* copy_image: resource_copy_region copies blocks of one size whatever
    * the formats (util_resource_copy_region), compressed or not. */
   case PIPE_CAP_COPY_BETWEEN_COMPRESSED_AND_PLAIN_FORMATS:
   /* Doubles: shader arithmetic (tgsi_exec, draw's gallivm; compiled
    * fragment shaders with 64-bit operations stay in tgsi_exec), outside
    * the model; a double varying is flat, two 32-bit words the model
    * copies from the provoking vertex. */
   case PIPE_CAP_DOUBLES:
      return 1;
   /* Uniform blocks are read by byte offset (TGSI LOAD in tgsi_exec and
    * draw's gallivm, mesa/patches 0009-0011; NIR's load_ubo in compiled
    * fragment shaders), so st lays out shared and packed blocks as std430,
    * as llvmpipe does, not in std140's vec4 slots.  The default uniforms
    * stay vec4 CONST registers. */
   case PIPE_CAP_LOAD_CONSTBUF:
      return 1;
   /* Robust buffer access: every read a shader or the vertex fetch makes
    * of a buffer reads zero or a value inside it.  draw fetches vertices
    * by each buffer's size (mesa/patches/0020: per-vertex, indexed and
    * instanced, interpreted or compiled), indices by the index buffer's;
    * tgsi_exec and gallivm bound uniform and storage buffer loads.  A
    * software device never loses its state, so the reset query (which a
    * robust context needs) is honest with "no reset" (fp_context.c). */
   case PIPE_CAP_ROBUST_BUFFER_ACCESS_BEHAVIOR:
   case PIPE_CAP_DEVICE_RESET_STATUS_QUERY:
      return 1;
   /* GL ES 3.2's shading language: gpu_shader5 with interpolateAt* through
    * the model, fragment side effects, robust access (docs/driver.md) */
   case PIPE_CAP_ESSL_FEATURE_LEVEL:
      return 320;
   case PIPE_CAP_MAX_TEXTURE_GATHER_COMPONENTS:
      return 4;     /* the unit's bilinear footprint (tex_gather.c) */
   case PIPE_CAP_MIN_TEXTURE_GATHER_OFFSET:
      return -8;
   case PIPE_CAP_MAX_TEXTURE_GATHER_OFFSET:
      return 7;
   case PIPE_CAP_SHADER_BUFFER_OFFSET_ALIGNMENT:
      return 16;
   /* an image store without a format qualifier packs by the view's
    * format (fp_image_store) */
   case PIPE_CAP_IMAGE_STORE_FORMATTED:
      return 1;
   /* st lowers image derefs to image indices for every stage: the
    * fragment stage's NIR reaches nir_to_tgsi in the driver
    * (fp_state_shader.c), which takes only the lowered form */
   case PIPE_CAP_NIR_IMAGES_AS_DEREF:
      return 0;
   /* Texture buffers: texelFetch through the unit's fetch
    * (TEX_TARGET_BUFFER, fp_sampler.c), llvmpipe's limits. */
   case PIPE_CAP_TEXTURE_BUFFER_OBJECTS:
      return 1;
   case PIPE_CAP_TEXTURE_BUFFER_OFFSET_ALIGNMENT:
      return 16;
   case PIPE_CAP_MAX_TEXEL_BUFFER_ELEMENTS_UINT:
      return 134217728;
   case PIPE_CAP_MAX_STREAM_OUTPUT_BUFFERS:
      return PIPE_MAX_SO_BUFFERS;
   case PIPE_CAP_MAX_STREAM_OUTPUT_SEPARATE_COMPONENTS:
   case PIPE_CAP_MAX_STREAM_OUTPUT_INTERLEAVED_COMPONENTS:
      return 16 * 4;
   case PIPE_CAP_ALPHA_TEST:                 /* st lowers it into the shader */
   case PIPE_CAP_SHADER_STENCIL_EXPORT:
   case PIPE_CAP_SHAREABLE_SHADERS:         /* draw's shaders are per context */
   case PIPE_CAP_ACCELERATED:
   case PIPE_CAP_UMA:
   case PIPE_CAP_TEXTURE_TRANSFER_MODES:
      return 0;
   case PIPE_CAP_GLSL_FEATURE_LEVEL:
   case PIPE_CAP_GLSL_FEATURE_LEVEL_COMPATIBILITY:
      /* desktop GL 4.0: ARB_gpu_shader5, its interpolateAt* through the
       * model (docs/msaa.md), doubles outside it (docs/driver.md) */
      return 400;
   case PIPE_CAP_MAX_RENDER_TARGETS:
      return RAST_MAX_CBUFS;
   case PIPE_CAP_FBFETCH:                  /* the back end reads the target first */
      return RAST_MAX_CBUFS;
   case PIPE_CAP_FBFETCH_COHERENT:         /* primitives reach it in order */
      return 1;
   /* Sample shading (ARB_sample_shading; OES_sample_shading and
    * OES_sample_variables with mesa/patches/0015): the model shades once a
    * sample with its interpolators at the sample (docs/msaa.md), every
    * input, so st need not make `sample` variants of a shader for
    * glMinSampleShading: set_min_samples says when. */
   case PIPE_CAP_SAMPLE_SHADING:
   case PIPE_CAP_FORCE_PERSAMPLE_INTERP:
      return 1;
   case PIPE_CAP_MAX_DUAL_SOURCE_RENDER_TARGETS:
      return 1;     /* output 1 is the back end's second source (SRC1 factors) */
   case PIPE_CAP_MAX_TEXTURE_2D_SIZE:
      return s->profile->max_target;
   case PIPE_CAP_MAX_TEXTURE_3D_LEVELS:
      return MIN2(fp_max_levels(s), 9);     /* 256^3 */
   case PIPE_CAP_MAX_TEXTURE_CUBE_LEVELS:
      return fp_max_levels(s);
   case PIPE_CAP_MAX_TEXTURE_ARRAY_LAYERS:
      return 256;
   case PIPE_CAP_MIN_TEXEL_OFFSET:
      return -8;
   case PIPE_CAP_MAX_TEXEL_OFFSET:
      return 7;
   case PIPE_CAP_MAX_VERTEX_ATTRIB_STRIDE:
      return 2048;
   case PIPE_CAP_CONSTANT_BUFFER_OFFSET_ALIGNMENT:
      return 16;
   case PIPE_CAP_MIN_MAP_BUFFER_ALIGNMENT:
      return 64;
   case PIPE_CAP_MAX_VIEWPORTS:         /* gl_ViewportIndex: scissor per primitive */
      return RAST_MAX_VIEWPORTS;
   /* Geometry shaders: draw's, as softpipe's; gl_Layer and
    * gl_ViewportIndex pick each primitive's layer, scissor and viewport in
    * the model (rast_vertex_layout.has_layer, has_viewport_index). */
   case PIPE_CAP_MAX_GEOMETRY_OUTPUT_VERTICES:
   case PIPE_CAP_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS:
      return 1024;
   case PIPE_CAP_MAX_GS_INVOCATIONS:
      return 32;
   /* Vertex streams (ARB_gpu_shader5, ARB_transform_feedback3): draw's
    * geometry stage sorts the primitives by stream, stream output captures
    * each, and only stream 0 reaches the model, as in llvmpipe. */
   case PIPE_CAP_MAX_VERTEX_STREAMS:
      return 4;
   /* Tessellation: draw's, as llvmpipe's (fp_state_tess.c) */
   case PIPE_CAP_MAX_SHADER_PATCH_VARYINGS:
      return 32;
   case PIPE_CAP_ENDIANNESS:
      return PIPE_ENDIAN_NATIVE;
   case PIPE_CAP_MAX_VARYINGS:
      return MIN2(TGSI_EXEC_MAX_INPUT_ATTRIBS, RAST_MAX_VARYINGS) - 2;
   case PIPE_CAP_VENDOR_ID:
   case PIPE_CAP_DEVICE_ID:
      return 0xFFFFFFFF;
   case PIPE_CAP_VIDEO_MEMORY: {
      uint64_t mem;
      if (!os_get_total_physical_memory(&mem))
         return 0;
      return (int)(mem >> 20);
   }
   default:
      return u_pipe_screen_get_param_defaults(screen, param);
   }
}

static int fp_get_shader_param(struct pipe_screen *screen, enum pipe_shader_type shader,
                               enum pipe_shader_cap param)
{
   (void)screen;
   switch (param) {
   /* Fragment shaders come as st's NIR: the compiled path takes it as it
    * is (fp_jit_fs.c), and tgsi_exec the TGSI nir_to_tgsi makes of it in
    * the driver, as st would have (fp_state_shader.c).  Tessellation's
    * stages are NIR for draw's LLVM path, the only one that runs them
    * (draw_tess.c reads NIR alone).  The other stages are TGSI for draw and
    * tgsi_exec. */
   case PIPE_SHADER_CAP_PREFERRED_IR:
      return shader == PIPE_SHADER_FRAGMENT || shader == PIPE_SHADER_TESS_CTRL ||
                   shader == PIPE_SHADER_TESS_EVAL
                ? PIPE_SHADER_IR_NIR : PIPE_SHADER_IR_TGSI;
   case PIPE_SHADER_CAP_SUPPORTED_IRS:
      return shader == PIPE_SHADER_FRAGMENT ? (1 << PIPE_SHADER_IR_TGSI) | (1 << PIPE_SHADER_IR_NIR)
             : shader == PIPE_SHADER_TESS_CTRL || shader == PIPE_SHADER_TESS_EVAL
                ? 1 << PIPE_SHADER_IR_NIR
                : 1 << PIPE_SHADER_IR_TGSI;
   default:
      break;
   }
   switch (shader) {
   case PIPE_SHADER_FRAGMENT:
   case PIPE_SHADER_VERTEX:
   case PIPE_SHADER_GEOMETRY:             /* draw, in tgsi_exec (fp_state_shader.c) */
      if (shader == PIPE_SHADER_FRAGMENT && param == PIPE_SHADER_CAP_MAX_INPUTS)
         return RAST_MAX_VARYINGS;
      if (param == PIPE_SHADER_CAP_MAX_TEXTURE_SAMPLERS ||
          param == PIPE_SHADER_CAP_MAX_SAMPLER_VIEWS)
         return 16;
      /* storage buffers and images (atomic counters: st's storage
       * buffers) in fragment shaders, tgsi_exec's numbers as compute's and
       * llvmpipe's (fp_image.c); draw's stages have none */
      if (shader != PIPE_SHADER_FRAGMENT &&
          (param == PIPE_SHADER_CAP_MAX_SHADER_BUFFERS ||
           param == PIPE_SHADER_CAP_MAX_SHADER_IMAGES))
         return 0;
      return shader == PIPE_SHADER_FRAGMENT ? tgsi_exec_get_shader_param(param)
                                            : draw_get_shader_param_no_llvm(shader, param);
   /* draw's LLVM path (gallivm's limits), their texture instructions to
    * the modeled unit's 16 (fp_jit_draw.c) */
   case PIPE_SHADER_TESS_CTRL:
   case PIPE_SHADER_TESS_EVAL:
      if (param == PIPE_SHADER_CAP_MAX_TEXTURE_SAMPLERS ||
          param == PIPE_SHADER_CAP_MAX_SAMPLER_VIEWS)
         return 16;
      if (param == PIPE_SHADER_CAP_MAX_SHADER_BUFFERS ||
          param == PIPE_SHADER_CAP_MAX_SHADER_IMAGES)
         return 0;
      return draw_get_shader_param(shader, param);
   case PIPE_SHADER_COMPUTE:
      if (param == PIPE_SHADER_CAP_MAX_TEXTURE_SAMPLERS ||
          param == PIPE_SHADER_CAP_MAX_SAMPLER_VIEWS)
         return 16;
      return tgsi_exec_get_shader_param(param);
   default:
      return 0;
   }
}

/* A work group of up to 1024 invocations, as softpipe's: tgsi_exec runs
 * them four by four (fp_compute.c). */
static int fp_get_compute_param(struct pipe_screen *screen, enum pipe_shader_ir ir,
                                enum pipe_compute_cap param, void *ret)
{
   uint64_t *v = ret;
   (void)screen; (void)ir;
   switch (param) {
   case PIPE_COMPUTE_CAP_MAX_GRID_SIZE:
      if (v)
         v[0] = v[1] = v[2] = 65535;
      return 3 * sizeof(uint64_t);
   case PIPE_COMPUTE_CAP_MAX_BLOCK_SIZE:
      if (v)
         v[0] = v[1] = v[2] = 1024;
      return 3 * sizeof(uint64_t);
   case PIPE_COMPUTE_CAP_MAX_THREADS_PER_BLOCK:
      if (v)
         v[0] = 1024;
      return sizeof(uint64_t);
   case PIPE_COMPUTE_CAP_MAX_LOCAL_SIZE:
      if (v)
         v[0] = 32768;
      return sizeof(uint64_t);
   default:
      return 0;
   }
}

static float fp_get_paramf(struct pipe_screen *screen, enum pipe_capf param)
{
   (void)screen;
   switch (param) {
   case PIPE_CAPF_MIN_LINE_WIDTH:
   case PIPE_CAPF_MIN_LINE_WIDTH_AA:
   case PIPE_CAPF_MIN_POINT_SIZE:
   case PIPE_CAPF_MIN_POINT_SIZE_AA:
      return 1;
   case PIPE_CAPF_POINT_SIZE_GRANULARITY:
   case PIPE_CAPF_LINE_WIDTH_GRANULARITY:
      return 0.1f;
   case PIPE_CAPF_MAX_LINE_WIDTH:
   case PIPE_CAPF_MAX_LINE_WIDTH_AA:
   case PIPE_CAPF_MAX_POINT_SIZE:
   case PIPE_CAPF_MAX_POINT_SIZE_AA:
      return 255.0f;
   case PIPE_CAPF_MAX_TEXTURE_ANISOTROPY:
      return 16.0f;
   case PIPE_CAPF_MAX_TEXTURE_LOD_BIAS:
      return 16.0f;
   default:
      return 0.0f;
   }
}

/* Images of compute shaders: plain colour formats util_format packs and
 * unpacks, one sample (fp_image.c). */
static bool fp_image_format(enum pipe_format format, const struct util_format_description *desc)
{
   const struct util_format_pack_description *pack = util_format_pack_description(format);
   const struct util_format_unpack_description *unpack = util_format_unpack_description(format);
   if (desc->layout != UTIL_FORMAT_LAYOUT_PLAIN || desc->colorspace == UTIL_FORMAT_COLORSPACE_ZS ||
       !pack || !unpack || !unpack->unpack_rgba)
      return false;
   if (util_format_is_pure_uint(format))
      return pack->pack_rgba_uint != NULL;
   if (util_format_is_pure_sint(format))
      return pack->pack_rgba_sint != NULL;
   return pack->pack_rgba_float != NULL;
}

static bool fp_is_format_supported(struct pipe_screen *screen, enum pipe_format format,
                                   enum pipe_texture_target target, unsigned sample_count,
                                   unsigned storage_sample_count, unsigned bind)
{
   struct sw_winsys *winsys = fp_screen(screen)->winsys;
   const struct util_format_description *desc = util_format_description(format);

   if (!desc)
      return false;
   /* Multisampled: colour and depth/stencil surfaces and 2-D (array)
    * textures of RAST_MSAA_SAMPLES samples a pixel, drawn by the model
    * (msaa.c), resolved by blits, read by texelFetch (fp_sampler.c). */
   const unsigned samples = MAX2(1, sample_count);
   if (samples != MAX2(1, storage_sample_count))
      return false;
   if (samples != 1) {
      if (samples != RAST_MSAA_SAMPLES ||
          (target != PIPE_TEXTURE_2D && target != PIPE_TEXTURE_RECT &&
           target != PIPE_TEXTURE_2D_ARRAY) ||
          (bind & ~(PIPE_BIND_RENDER_TARGET | PIPE_BIND_DEPTH_STENCIL | PIPE_BIND_SAMPLER_VIEW)))
         return false;
   }

   /* a framebuffer without attachments: its sample counts */
   if (format == PIPE_FORMAT_NONE)
      return !(bind & ~PIPE_BIND_RENDER_TARGET);

   if (bind & (PIPE_BIND_DISPLAY_TARGET | PIPE_BIND_SCANOUT | PIPE_BIND_SHARED)) {
      if (!winsys->is_displaytarget_format_supported(winsys, bind, format))
         return false;
   }
   if ((bind & PIPE_BIND_RENDER_TARGET) && !fp_format_renderable(format))
      return false;
   if ((bind & PIPE_BIND_DEPTH_STENCIL) && !fp_format_depth_supported(format))
      return false;
   if (bind & PIPE_BIND_SAMPLER_VIEW) {
      if (!fp_format_samplable(format))
         return false;
      /* texture buffers: texels of one block each, no depth or stencil
       * (GL's table of buffer texture formats is a subset) */
      if (target == PIPE_BUFFER &&
          (desc->colorspace == UTIL_FORMAT_COLORSPACE_ZS || desc->block.width != 1 ||
           desc->block.height != 1))
         return false;
   }
   if ((bind & PIPE_BIND_SHADER_IMAGE) && !fp_image_format(format, desc))
      return false;
   if (target != PIPE_BUFFER && desc->nr_channels == 3 && desc->is_array &&
       (bind & (PIPE_BIND_RENDER_TARGET | PIPE_BIND_SAMPLER_VIEW)) &&
       !(bind & PIPE_BIND_DISPLAY_TARGET)) {
      /* As softpipe: keep RGB8-like formats for vertex data only, so copies
       * between formats of one size stay possible. */
      return false;
   }
   return true;
}

/* Mesa's on-disk shader cache for compiled fragment shaders, keyed like
 * llvmpipe's: this driver binary, LLVM's, and the CPU the code is for.
 * MESA_SHADER_CACHE_DISABLE turns it off as for every Mesa driver.
 * Opened at the first compilation (fp_screen_disk_cache): most short
 * programs never compile a shader, and opening it starts a thread. */
static void fp_disk_cache_create(const void *data)
{
   struct fp_screen *s = (struct fp_screen *)data;
   struct mesa_sha1 ctx;
   unsigned char sha1[20];
   char id[20 * 2 + 1];
   _mesa_sha1_init(&ctx);
   if (!disk_cache_get_function_identifier(fp_disk_cache_create, &ctx) ||
       !disk_cache_get_function_identifier(LLVMLinkInMCJIT, &ctx))
      return;
   const struct util_cpu_caps_t *caps = util_get_cpu_caps();
   _mesa_sha1_update(&ctx, caps, 5 * sizeof(uint32_t));   /* as llvmpipe: the ISA flags */
   _mesa_sha1_final(&ctx, sha1);
   disk_cache_format_hex_id(id, sha1, 20 * 2);
   s->disk_cache = disk_cache_create("fixpipe", id, 0);
}

struct disk_cache *fp_screen_disk_cache(struct fp_screen *s)
{
   util_call_once_data(&s->disk_cache_once, fp_disk_cache_create, s);
   return s->disk_cache;
}

static void fp_destroy_screen(struct pipe_screen *screen)
{
   struct fp_screen *s = fp_screen(screen);
   disk_cache_destroy(s->disk_cache);
   simple_mtx_destroy(&s->fronts_lock);
   if (s->winsys->destroy)
      s->winsys->destroy(s->winsys);
   FREE(s);
}

static void fp_flush_frontbuffer(struct pipe_screen *screen, struct pipe_context *pipe,
                                 struct pipe_resource *resource, unsigned level,
                                 unsigned layer, void *context_private,
                                 struct pipe_box *sub_box)
{
   struct fp_screen *s = fp_screen(screen);
   struct fp_resource *r = fp_resource(resource);
   (void)level; (void)layer;
   p_atomic_inc(&s->frames_presented);
   if (pipe)
      fp_context_frame_presented(fp_context(pipe));
   if (r->dt) {
      s->winsys->displaytarget_display(s->winsys, r->dt, context_private, sub_box);
      fp_resource_presented(s, resource, context_private);
   }
}

/* Rendering is synchronous: every fence is signalled when it is made. */
static void fp_fence_reference(struct pipe_screen *screen, struct pipe_fence_handle **ptr,
                               struct pipe_fence_handle *fence)
{
   (void)screen;
   *ptr = fence;
}

static bool fp_fence_finish(struct pipe_screen *screen, struct pipe_context *ctx,
                            struct pipe_fence_handle *fence, uint64_t timeout)
{
   (void)screen; (void)ctx; (void)fence; (void)timeout;
   return true;
}

static uint64_t fp_get_timestamp(struct pipe_screen *screen)
{
   (void)screen;
   return os_time_get_nano();
}

struct pipe_screen *fixpipe_create_screen(struct sw_winsys *winsys)
{
   struct fp_screen *s = CALLOC_STRUCT(fp_screen);
   if (!s)
      return NULL;

   s->winsys = winsys;
   s->disk_cache_once = (util_once_flag)UTIL_ONCE_FLAG_INIT;
   simple_mtx_init(&s->fronts_lock, mtx_plain);
   s->opts = fp_options_from_env();
   s->profile = s->opts->profile;
   if (!s->profile) {
      FREE(s);
      return NULL;
   }
   /* the lanes' instruction set, process-wide like the CPU it is for */
   if ((s->opts->debug & FP_DEBUG_NOAVX512) && rast_lanes() == &rast_lanes_avx512)
      rast_lanes_set(&rast_lanes_avx2);
   snprintf(s->name, sizeof(s->name), "fixpipe (%s)", s->profile->name);

   s->base.destroy = fp_destroy_screen;
   s->base.get_name = fp_get_name;
   s->base.get_vendor = fp_get_vendor;
   s->base.get_device_vendor = fp_get_vendor;
   s->base.get_param = fp_get_param;
   s->base.get_shader_param = fp_get_shader_param;
   s->base.get_paramf = fp_get_paramf;
   s->base.get_compute_param = fp_get_compute_param;
   s->base.get_timestamp = fp_get_timestamp;
   fp_init_screen_query_functions(&s->base);
   s->base.is_format_supported = fp_is_format_supported;
   s->base.context_create = fp_create_context;
   s->base.flush_frontbuffer = fp_flush_frontbuffer;
   s->base.get_compiler_options = fp_get_compiler_options;
   s->base.fence_reference = fp_fence_reference;
   s->base.fence_finish = fp_fence_finish;

   fp_init_screen_resource_funcs(&s->base);
   return &s->base;
}
