/*
 * Which formats the driver renders to and samples from, and the float
 * load/store functions the model's back end calls for render targets
 * without a fast layout.  The integer formats' load and store move the
 * shader's integer outputs bit for bit (util's pack and unpack of pure
 * integer formats take uint32 or int32 values): GL neither blends nor
 * clamps them.  The model's load/store take no format argument,
 * so each renderable format gets its own pair of trampolines.
 */
#include "util/format/u_format.h"
#include "fp_format.h"
#include "fp_screen.h"

#define FP_RT(fmt) \
static void load_##fmt(const uint8_t *src, unsigned n, float (*rgba)[4]) \
{ util_format_unpack_rgba(PIPE_FORMAT_##fmt, rgba, src, n); } \
static void store_##fmt(uint8_t *dst, unsigned n, const float (*rgba)[4]) \
{ util_format_pack_rgba(PIPE_FORMAT_##fmt, dst, rgba, n); }

#define FP_RT_LIST(X) \
   X(R8G8B8A8_UNORM) X(B8G8R8A8_UNORM) X(B8G8R8X8_UNORM) X(R8G8B8X8_UNORM) \
   X(A8R8G8B8_UNORM) X(X8R8G8B8_UNORM) X(A8B8G8R8_UNORM) X(X8B8G8R8_UNORM) \
   X(B5G6R5_UNORM) X(B5G5R5A1_UNORM) X(B5G5R5X1_UNORM) X(B4G4R4A4_UNORM) \
   X(A1B5G5R5_UNORM) X(R5G5B5A1_UNORM) X(A1R5G5B5_UNORM) X(X1B5G5R5_UNORM) X(X1R5G5B5_UNORM) \
   X(B4G4R4X4_UNORM) X(R4G4B4A4_UNORM) X(A4B4G4R4_UNORM) \
   X(R10G10B10A2_UNORM) X(B10G10R10A2_UNORM) X(R10G10B10X2_UNORM) X(B10G10R10X2_UNORM) \
   X(R16_FLOAT) X(R16G16_FLOAT) X(R16G16B16A16_FLOAT) X(R16G16B16X16_FLOAT) \
   X(R32_FLOAT) X(R32G32_FLOAT) X(R32G32B32A32_FLOAT) X(R32G32B32X32_FLOAT) \
   X(R11G11B10_FLOAT) \
   X(R16_UNORM) X(R16G16_UNORM) X(R16G16B16A16_UNORM) \
   X(A8_UNORM) X(L8_UNORM) X(L8A8_UNORM) X(I8_UNORM) X(R8_UNORM) X(R8G8_UNORM) \
   X(A16_UNORM) X(L16_UNORM) X(L16A16_UNORM) X(I16_UNORM) \
   X(A16_FLOAT) X(L16_FLOAT) X(L16A16_FLOAT) X(I16_FLOAT) \
   X(A32_FLOAT) X(L32_FLOAT) X(L32A32_FLOAT) X(I32_FLOAT) \
   X(R8G8B8A8_SRGB) X(B8G8R8A8_SRGB) X(B8G8R8X8_SRGB) X(R8G8B8X8_SRGB) \
   X(A8R8G8B8_SRGB) X(X8R8G8B8_SRGB) X(A8B8G8R8_SRGB) X(X8B8G8R8_SRGB) \
   X(L8_SRGB) X(L8A8_SRGB) X(R8_SRGB) \
   X(R8_UINT) X(R8G8_UINT) X(R8G8B8A8_UINT) X(R8_SINT) X(R8G8_SINT) X(R8G8B8A8_SINT) \
   X(R16_UINT) X(R16G16_UINT) X(R16G16B16A16_UINT) \
   X(R16_SINT) X(R16G16_SINT) X(R16G16B16A16_SINT) \
   X(R32_UINT) X(R32G32_UINT) X(R32G32B32A32_UINT) \
   X(R32_SINT) X(R32G32_SINT) X(R32G32B32A32_SINT) X(R10G10B10A2_UINT) \
   X(R8_SNORM) X(R8G8_SNORM) X(R8G8B8A8_SNORM) X(R16_SNORM) X(R16G16_SNORM) \
   X(R16G16B16A16_SNORM) X(A8_SNORM) X(L8_SNORM) X(L8A8_SNORM) X(I8_SNORM) \
   X(A16_SNORM) X(L16_SNORM) X(L16A16_SNORM) X(I16_SNORM) \
   X(R8G8B8X8_SNORM) X(R8G8B8X8_UINT) X(R8G8B8X8_SINT) X(R16G16B16X16_UNORM) \
   X(R16G16B16X16_SNORM) X(R16G16B16X16_UINT) X(R16G16B16X16_SINT) \
   X(R32G32B32X32_UINT) X(R32G32B32X32_SINT)

FP_RT_LIST(FP_RT)

struct fp_rt_format {
   enum pipe_format format;
   rast_load_func load;
   rast_store_func store;
};

#define FP_RT_ENTRY(fmt) { PIPE_FORMAT_##fmt, load_##fmt, store_##fmt },
static const struct fp_rt_format rt_formats[] = { FP_RT_LIST(FP_RT_ENTRY) };

static const struct fp_rt_format *find_rt(enum pipe_format format)
{
   for (unsigned i = 0; i < sizeof(rt_formats) / sizeof(rt_formats[0]); i++)
      if (rt_formats[i].format == format)
         return &rt_formats[i];
   return NULL;
}

bool fp_format_renderable(enum pipe_format format)
{
   return find_rt(format) != NULL;
}

bool fp_format_color_target(enum pipe_format format, struct rast_color_target *ct)
{
   const struct fp_rt_format *f = find_rt(format);
   if (!f)
      return false;
   ct->cpp = util_format_get_blocksize(format);
   ct->load = f->load;
   ct->store = f->store;
   ct->clamp = util_format_is_unorm(format) || util_format_is_snorm(format);
   ct->snorm = util_format_is_snorm(format);
   switch (format) {
   case PIPE_FORMAT_R8G8B8A8_UNORM: ct->layout = RAST_CL_RGBA8; break;
   case PIPE_FORMAT_B8G8R8A8_UNORM: ct->layout = RAST_CL_BGRA8; break;
   case PIPE_FORMAT_B8G8R8X8_UNORM: ct->layout = RAST_CL_BGRX8; break;
   default: ct->layout = RAST_CL_GENERIC; break;
   }
   return true;
}

enum rast_zs_layout fp_format_zs_layout(enum pipe_format format)
{
   switch (format) {
   case PIPE_FORMAT_Z16_UNORM: return RAST_ZS_Z16;
   case PIPE_FORMAT_Z32_UNORM: return RAST_ZS_Z32;
   case PIPE_FORMAT_Z24_UNORM_S8_UINT: return RAST_ZS_Z24_S8;
   case PIPE_FORMAT_S8_UINT_Z24_UNORM: return RAST_ZS_S8_Z24;
   case PIPE_FORMAT_Z24X8_UNORM: return RAST_ZS_Z24X8;
   case PIPE_FORMAT_X8Z24_UNORM: return RAST_ZS_X8Z24;
   case PIPE_FORMAT_Z32_FLOAT: return RAST_ZS_Z32F;
   case PIPE_FORMAT_Z32_FLOAT_S8X24_UINT: return RAST_ZS_Z32F_S8X24;
   case PIPE_FORMAT_S8_UINT: return RAST_ZS_S8;
   default: return RAST_ZS_NONE;
   }
}

bool fp_format_depth_supported(enum pipe_format format)
{
   return fp_format_zs_layout(format) != RAST_ZS_NONE;
}

/* Sampled through fp_sampler.c: colour formats util_format can fetch (as
 * float, or the integer formats' values bit for bit), and depth formats
 * through unpack_z_float. */
bool fp_format_samplable(enum pipe_format format)
{
   const struct util_format_description *desc = util_format_description(format);
   if (!desc || format == PIPE_FORMAT_NONE)
      return false;
   if (desc->colorspace == UTIL_FORMAT_COLORSPACE_ZS) {
      const struct util_format_unpack_description *u = util_format_unpack_description(format);
      if (util_format_has_depth(desc))
         return u->unpack_z_float != NULL;
      return u->unpack_s_8uint != NULL;   /* stencil texturing: the index as a uint */
   }
   if (desc->colorspace == UTIL_FORMAT_COLORSPACE_YUV ||
       desc->layout == UTIL_FORMAT_LAYOUT_PLANAR2 ||
       desc->layout == UTIL_FORMAT_LAYOUT_PLANAR3)
      return false;
   return util_format_fetch_rgba_func(format) != NULL;
}
