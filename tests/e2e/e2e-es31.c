/*
 * GL ES 3.1 (--case NAME, 64x64 unless --size says):
 *
 *   compute      a compute shader of 64-invocation groups: each reads its
 *                group's 64 words of a storage buffer into shared memory,
 *                waits at a barrier, writes s[63 - i] + s[(i + 1) % 64] back
 *                and counts the odd results in an atomic counter; the
 *                words are then drawn as a texture through the model
 *   shared       shared arrays of vec4, mat3 and a struct in a 13x2x4 work
 *                group, read across the group after a barrier, shared
 *                atomics and every SSBO atomic, against the CPU's results;
 *                the words drawn as above
 *   image        a compute shader writes an RGBA8 image from an r32ui one
 *                (imageLoad, imageStore, imageAtomicAdd), drawn as above
 *   gather       textureGather of a 16x16 random texture (green, then
 *                alpha with a texel offset, then a depth texture with a
 *                comparison, then blue of a 2-D array's layer with an
 *                offset), a band each, through the modeled unit
 *   gather-cube  textureGather on an 8x8 cube map across the corner of
 *                three faces, a view with a swizzle, green then alpha
 *   gather-clamp textureGather(Offset) of 13x7 textures clamped to their
 *                edges, the compiled unit's own case (fp_jit_gather.c):
 *                coordinates across and beyond the texture, on its texel
 *                grid (zero among them), with the extreme offsets, a view
 *                with constant swizzles, lanes out of the register's range
 *                beside lanes within it, and a one-texel-wide texture the
 *                C unit gathers, a band each
 *   gather-ties  as gather-clamp, random coordinates at every distance
 *                from a texel boundary (ties among them, which drivers
 *                decide differently): for the identity of the compiled
 *                and the C unit's gathers, not for comparing drivers
 *   ms-fetch     random flat triangles into a 4-sample texture, then each
 *                pixel shows texelFetch of sample (x + y) % 4
 *   stencil-tex  overlapping triangles counted in a depth/stencil texture,
 *                then sampled as GL_STENCIL_INDEX (usampler2D)
 *   ubo          a uniform block without a layout qualifier (shared:
 *                laid out as the driver chooses, filled by the offsets and
 *                strides it reports) read by dynamic indices in the vertex
 *                shader (per instance) and the fragment shader (per
 *                pixel); every pixel is checked against the CPU's values
 *   image-formats every image format GL ES 3.1 and GL_NV_image_formats
 *                name (the 16-bit normalized ones where GL_EXT_texture_norm16
 *                is exposed): a compute shader loads a 4x4 image of random
 *                texels (no infinities or NaNs) into a storage buffer and
 *                stores it to a second image, a second dispatch loads that
 *                back; the buffers' words are drawn as a texture, a format a
 *                row, and the round trip must give the first load's values
 *   builtins     a fragment shader and a compute shader calling GLSL ES
 *                3.10's built-ins on each pixel's (invocation's) own numbers (ldexp and frexp, the packing functions,
 *                the bit operations, the extended arithmetic), each checked
 *                against an identity it must meet: a pixel is green where
 *                all hold, a colour per failed identity otherwise
 *
 * Self-checks (errors fail the program on any driver): GL ES 3.1 or later,
 * the compute case's words and counter against the CPU's, the image case's
 * atomic sums, and the samples of a pixel a triangle edge crosses differ.
 */
#include "e2e_common.h"

#include <GLES3/gl31.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A program drawn in bands (uniform u_band, whose location it returns),
 * its three samplers on texture units 0, 1, 2; in use. */
static GLint band_program(const char *fs, const char *const samplers[3])
{
   GLuint p = e2e_uv_program_es31(fs);
   glUseProgram(p);
   for (int i = 0; i < 3; i++)
      glUniform1i(glGetUniformLocation(p, samplers[i]), i);
   return glGetUniformLocation(p, "u_band");
}

/* RGBA8 words as a size x size NEAREST texture over the whole target. */
static void show_words(const uint32_t *words, int size)
{
   GLuint tex;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D, tex);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, words);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glUseProgram(e2e_texture_program());
   e2e_draw_rect(-1, -1, 1, 1, 0, 0, 1, 1);
   glDeleteTextures(1, &tex);
}

static void case_compute(int size)
{
   static const char *cs =
      "#version 310 es\n"
      "layout(local_size_x = 64) in;\n"
      "layout(std430, binding = 0) buffer Data { uint v[]; } data;\n"
      "layout(binding = 0, offset = 0) uniform atomic_uint odd;\n"
      "shared uint s[64];\n"
      "void main() {\n"
      "   uint i = gl_LocalInvocationID.x, base = gl_WorkGroupID.x * 64u;\n"
      "   s[i] = data.v[base + i];\n"
      "   barrier();\n"
      "   uint r = s[63u - i] + s[(i + 1u) % 64u];\n"
      "   data.v[base + i] = r;\n"
      "   if ((r & 1u) == 1u) atomicCounterIncrement(odd);\n"
      "}\n";
   const int n = size * size;
   uint32_t *in = malloc((size_t)n * 4), *want = malloc((size_t)n * 4);
   if (!in || !want)
      fp_die("out of memory");
   uint32_t rng = 0xc0de3101u, odd = 0;
   for (int k = 0; k < n; k++)
      in[k] = e2e_rand(&rng);
   for (int k = 0; k < n; k++) {
      const int g = k / 64 * 64, i = k % 64;
      want[k] = in[g + 63 - i] + in[g + (i + 1) % 64];
      odd += want[k] & 1;
   }
   GLuint buf[2];
   glGenBuffers(2, buf);
   glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf[0]);
   glBufferData(GL_SHADER_STORAGE_BUFFER, n * 4, in, GL_DYNAMIC_COPY);
   const uint32_t zero = 0;
   glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, buf[1]);
   glBufferData(GL_ATOMIC_COUNTER_BUFFER, 4, &zero, GL_DYNAMIC_COPY);
   glUseProgram(fp_gl_compute_program(cs));
   glDispatchCompute((GLuint)(n / 64), 1, 1);
   glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT);

   const uint32_t *got = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, n * 4, GL_MAP_READ_BIT);
   int wrong = 0;
   for (int k = 0; got && k < n; k++)
      wrong += got[k] != want[k];
   e2e_check(got && !wrong, "storage buffer words differ from the CPU's");
   if (got)
      memcpy(in, got, (size_t)n * 4);
   glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
   const uint32_t *count = glMapBufferRange(GL_ATOMIC_COUNTER_BUFFER, 0, 4, GL_MAP_READ_BIT);
   printf("stat: wrong_words=%d odd=%u counter=%u\n", wrong, odd, count ? *count : 0);
   e2e_check(count && *count == odd, "the atomic counter is not the number of odd words");
   glUnmapBuffer(GL_ATOMIC_COUNTER_BUFFER);
   for (int k = 0; k < n; k++)
      in[k] |= 0xff000000u;   /* opaque */
   show_words(in, size);
   glDeleteBuffers(2, buf);
   free(in);
   free(want);
}

/* Shared variables of vector, matrix and struct types in a 13x2x4 work
 * group (widths not a multiple of tgsi_exec's four lanes), shared atomics,
 * and every SSBO atomic; each invocation's results against the CPU's. */
static void case_shared(int size)
{
   static const char *cs =
      "#version 310 es\n"
      "layout(local_size_x = 13, local_size_y = 2, local_size_z = 4) in;\n"
      "struct S { vec2 a; uint b; };\n"
      "shared vec4 sv[104];\n"
      "shared mat3 sm[104];\n"
      "shared S ss[104];\n"
      "shared uint scount;\n"
      "shared int smin;\n"
      "layout(std430, binding = 0) buffer Out { uvec4 o[]; } outp;\n"
      "layout(std430, binding = 1) buffer Atom { uint add, mn, mx, an, orr, xr, xch, pad; int imn, imx; uint cas[]; } at;\n"
      "void main() {\n"
      "   uint i = gl_LocalInvocationIndex;\n"
      "   uint g = gl_WorkGroupID.x;\n"
      "   uint v = i * 2654435761u + g * 40503u;\n"
      "   if (i == 0u) { scount = 0u; smin = 1000000; }\n"
      "   barrier();\n"
      "   sv[i] = vec4(float(i), float(g), float(v & 255u), float(i * g));\n"
      "   sm[i] = mat3(float(i)) + mat3(vec3(1.0, 2.0, 3.0), vec3(float(g)), vec3(float(v & 15u)));\n"
      "   ss[i] = S(vec2(float(i) * 0.5, float(g) + 0.25), v);\n"
      "   atomicAdd(scount, i + 1u);\n"
      "   atomicMin(smin, int(v & 1023u) - 500);\n"
      "   atomicAdd(at.add, v & 255u);\n"
      "   atomicMin(at.mn, v | 1u);\n"
      "   atomicMax(at.mx, v);\n"
      "   atomicAnd(at.an, v | 0x0f0f0f0fu);\n"
      "   atomicOr(at.orr, 1u << (i % 32u));\n"
      "   atomicXor(at.xr, v);\n"
      "   atomicExchange(at.xch, 7u);\n"
      "   /* each its own word: one swap that matches, one that does not */\n"
      "   atomicCompSwap(at.cas[g * 104u + i], g * 104u + i, g * 104u + i + 1000u);\n"
      "   atomicCompSwap(at.cas[g * 104u + i], 7777u, 1u);\n"
      "   atomicMin(at.imn, int(v) >> 8);\n"
      "   atomicMax(at.imx, int(v) >> 8);\n"
      "   barrier();\n"
      "   uint j = 103u - i;\n"
      "   vec4 a = sv[j];\n"
      "   mat3 m = sm[(i + 7u) % 104u];\n"
      "   S t = ss[(i + 13u) % 104u];\n"
      "   outp.o[g * 104u + i] = uvec4(uint(a.x + a.y * 1000.0 + a.z * 7.0 + a.w),\n"
      "                                uint(m[0][0] + m[1][1] * 10.0 + m[2][2] * 100.0 + m[0][1] * 1000.0),\n"
      "                                uint(t.a.x * 4.0 + t.a.y * 4.0) ^ t.b,\n"
      "                                scount + uint(smin + 600));\n"
      "}\n";
   (void)size;
   const unsigned groups = 3, n = 104 * groups;
   uint32_t *want = calloc(n * 4, 4);
   if (!want)
      fp_die("out of memory");
   uint32_t w_add = 0, w_mn = 0xffffffffu, w_mx = 0, w_an = 0xffffffffu, w_or = 0, w_xr = 0;
   int32_t w_imn = 0x7fffffff, w_imx = -0x7fffffff - 1;
   for (unsigned g = 0; g < groups; g++) {
      uint32_t count = 0;
      int32_t smin = 1000000;
      for (unsigned i = 0; i < 104; i++) {
         const uint32_t v = i * 2654435761u + g * 40503u;
         count += i + 1;
         const int32_t m = (int32_t)(v & 1023u) - 500;
         smin = m < smin ? m : smin;
         w_add += v & 255u;
         w_mn = (v | 1u) < w_mn ? (v | 1u) : w_mn;
         w_mx = v > w_mx ? v : w_mx;
         w_an &= v | 0x0f0f0f0fu;
         w_or |= 1u << (i % 32u);
         w_xr ^= v;
         const int32_t s8 = (int32_t)v >> 8;
         w_imn = s8 < w_imn ? s8 : w_imn;
         w_imx = s8 > w_imx ? s8 : w_imx;
      }
      for (unsigned i = 0; i < 104; i++) {
         const unsigned j = 103 - i, k = (i + 7) % 104, t = (i + 13) % 104;
         const uint32_t vj = j * 2654435761u + g * 40503u;
         const uint32_t vk = k * 2654435761u + g * 40503u;
         const uint32_t vt = t * 2654435761u + g * 40503u;
         uint32_t *o = want + 4 * (g * 104 + i);
         o[0] = (uint32_t)((float)j + (float)g * 1000.0f + (float)(vj & 255u) * 7.0f +
                           (float)(j * g));
         /* mat3(k) + mat3(col (1,2,3), col (g,g,g), col (v&15 x3)) */
         const float m00 = (float)k + 1.0f, m11 = (float)k + (float)g,
                     m22 = (float)k + (float)(vk & 15u), m01 = 2.0f;
         o[1] = (uint32_t)(m00 + m11 * 10.0f + m22 * 100.0f + m01 * 1000.0f);
         o[2] = (uint32_t)((float)t * 0.5f * 4.0f + ((float)g + 0.25f) * 4.0f) ^ vt;
         o[3] = count + (uint32_t)(smin + 600);
      }
   }
   GLuint buf[2];
   glGenBuffers(2, buf);
   glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf[0]);
   glBufferData(GL_SHADER_STORAGE_BUFFER, n * 16, NULL, GL_DYNAMIC_COPY);
   /* the ten words, then one per invocation for the swaps, holding its index */
   uint32_t init[10 + 104 * 3] = { 0, 0xffffffffu, 0, 0xffffffffu, 0, 0, 0, 0,
                                   0x7fffffff, 0x80000000u };
   for (unsigned k = 0; k < n; k++)
      init[10 + k] = k;
   glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buf[1]);
   glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(init), init, GL_DYNAMIC_COPY);
   glUseProgram(fp_gl_compute_program(cs));
   glDispatchCompute(groups, 1, 1);
   glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);

   glBindBuffer(GL_SHADER_STORAGE_BUFFER, buf[0]);
   const uint32_t *got = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, n * 16, GL_MAP_READ_BIT);
   int wrong[4] = { 0, 0, 0, 0 };
   for (unsigned k = 0; got && k < n * 4; k++)
      wrong[k % 4] += got[k] != want[k];
   printf("stat: wrong_vec4=%d wrong_mat3=%d wrong_struct=%d wrong_shared_atomics=%d\n",
          wrong[0], wrong[1], wrong[2], wrong[3]);
   e2e_check(got && !wrong[0], "shared vec4 reads differ from the CPU's");
   e2e_check(got && !wrong[1], "shared mat3 reads differ from the CPU's");
   e2e_check(got && !wrong[2], "shared struct reads differ from the CPU's");
   e2e_check(got && !wrong[3], "shared atomics differ from the CPU's");
   /* the words drawn as a texture, their low bytes */
   uint32_t *px = calloc((size_t)size * size, 4);
   if (!px)
      fp_die("out of memory");
   for (unsigned k = 0; got && k < n * 4 && k < (unsigned)(size * size); k++)
      px[k] = got[k] | 0xff000000u;
   glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);

   glBindBuffer(GL_SHADER_STORAGE_BUFFER, buf[1]);
   const uint32_t *a = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, sizeof(init), GL_MAP_READ_BIT);
   const uint32_t want_at[10] = { w_add, w_mn, w_mx, w_an, w_or, w_xr, 7u, 0,
                                  (uint32_t)w_imn, (uint32_t)w_imx };
   int bad_at = 0;
   for (unsigned k = 0; a && k < 10 + n; k++) {
      const uint32_t want_k = k < 10 ? want_at[k] : k - 10 + 1000u;
      if (a[k] != want_k && bad_at < 5)
         printf("ssbo atomic word %u: %#x, want %#x\n", k, a[k], want_k);
      bad_at += a[k] != want_k;
   }
   bad_at += !a;
   printf("stat: wrong_ssbo_atomics=%d\n", bad_at);
   e2e_check(a && !bad_at, "SSBO atomics differ from the CPU's");
   glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
   show_words(px, size);
   glDeleteBuffers(2, buf);
   free(px);
   free(want);
}

static void case_image(int size)
{
   static const char *cs =
      "#version 310 es\n"
      "#extension GL_OES_shader_image_atomic : require\n"
      "layout(local_size_x = 8, local_size_y = 8) in;\n"
      "layout(r32ui, binding = 0) uniform highp uimage2D src;\n"
      "layout(rgba8, binding = 1) writeonly uniform highp image2D dst;\n"
      "layout(r32ui, binding = 2) uniform highp uimage2D sums;\n"
      "void main() {\n"
      "   ivec2 p = ivec2(gl_GlobalInvocationID.xy);\n"
      "   uint v = imageLoad(src, p).x;\n"
      "   imageAtomicAdd(sums, ivec2(p.x % 4, 0), v & 255u);\n"
      "   imageStore(dst, p, vec4(float(v & 255u), float((v >> 8) & 255u),\n"
      "                           float(p.x * 4), 255.0) / 255.0);\n"
      "}\n";
   const int n = size * size;
   uint32_t *src = malloc((size_t)n * 4);
   if (!src)
      fp_die("out of memory");
   uint32_t rng = 0x1a6e3101u, want[4] = { 0, 0, 0, 0 };
   for (int k = 0; k < n; k++) {
      src[k] = e2e_rand(&rng);
      want[(k % size) % 4] += src[k] & 255;
   }
   GLuint tex[3];
   glGenTextures(3, tex);
   glBindTexture(GL_TEXTURE_2D, tex[0]);
   glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32UI, size, size);
   glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size, size, GL_RED_INTEGER, GL_UNSIGNED_INT, src);
   glBindTexture(GL_TEXTURE_2D, tex[1]);
   glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, size, size);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glBindTexture(GL_TEXTURE_2D, tex[2]);
   glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32UI, 4, 1);
   const uint32_t zero[4] = { 0, 0, 0, 0 };
   glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, zero);
   glBindImageTexture(0, tex[0], 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
   glBindImageTexture(1, tex[1], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
   glBindImageTexture(2, tex[2], 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
   glUseProgram(fp_gl_compute_program(cs));
   glDispatchCompute((GLuint)(size / 8), (GLuint)(size / 8), 1);
   glMemoryBarrier(GL_ALL_BARRIER_BITS);

   /* the sums through a framebuffer read of the r32ui texture */
   GLuint fbo;
   uint32_t got[4 * 4] = { 0 };
   glGenFramebuffers(1, &fbo);
   glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
   glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[2], 0);
   glReadPixels(0, 0, 4, 1, GL_RGBA_INTEGER, GL_UNSIGNED_INT, got);
   glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
   glDeleteFramebuffers(1, &fbo);
   printf("stat: sums=%u,%u,%u,%u\n", got[0], got[4], got[8], got[12]);
   for (int c = 0; c < 4; c++)
      e2e_check(got[4 * c] == want[c], "imageAtomicAdd sums differ from the CPU's");

   glBindTexture(GL_TEXTURE_2D, tex[1]);
   glUseProgram(e2e_texture_program());
   e2e_draw_rect(-1, -1, 1, 1, 0, 0, 1, 1);
   glDeleteTextures(3, tex);
   free(src);
}

static void case_gather(int size)
{
   static const char *fs =
      "#version 310 es\n"
      "precision highp float;\n"
      "uniform highp sampler2D u_tex;\n"
      "uniform highp sampler2DShadow u_depth;\n"
      "uniform highp sampler2DArray u_arr;\n"
      "uniform int u_band;\n"
      "in vec2 v_uv;\n"
      "out vec4 o_color;\n"
      "void main() {\n"
      "   if (u_band == 0) o_color = textureGather(u_tex, v_uv, 1);\n"
      "   else if (u_band == 1) o_color = textureGatherOffset(u_tex, v_uv, ivec2(-3, 2), 3);\n"
      "   else if (u_band == 2) o_color = textureGather(u_depth, v_uv, 0.5);\n"
      "   else o_color = textureGatherOffset(u_arr, vec3(v_uv, 1.3), ivec2(2, -1), 2);\n"
      "}\n";
   enum { W = 16 };
   uint32_t texels[W * W];
   float depth[W * W];
   uint32_t rng = 0x6a7e3101u;
   for (int k = 0; k < W * W; k++) {
      texels[k] = e2e_rand(&rng);
      depth[k] = (float)e2e_rand_range(&rng, 0, 1000) / 1000.0f;
   }
   GLuint tex[3];
   glGenTextures(3, tex);
   /* a 2-D array: its second layer gathered with an offset */
   glActiveTexture(GL_TEXTURE2);
   glBindTexture(GL_TEXTURE_2D_ARRAY, tex[2]);
   glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, W, W, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
   for (int l = 0; l < 3; l++) {
      uint32_t layer[W * W];
      for (int k = 0; k < W * W; k++)
         layer[k] = e2e_rand(&rng);
      glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, l, W, W, 1, GL_RGBA, GL_UNSIGNED_BYTE, layer);
   }
   e2e_tex_params(GL_TEXTURE_2D_ARRAY, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_REPEAT);
   glActiveTexture(GL_TEXTURE1);
   glBindTexture(GL_TEXTURE_2D, tex[1]);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, W, W, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                depth);
   e2e_tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
   glActiveTexture(GL_TEXTURE0);
   glBindTexture(GL_TEXTURE_2D, tex[0]);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, W, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
   e2e_tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_MIRRORED_REPEAT);
   static const char *const units[] = { "u_tex", "u_depth", "u_arr" };
   const GLint band = band_program(fs, units);
   /* bands of a quarter each, edges on the sub-pixel grid (both drivers
    * hold the vertices exactly); coordinates over more than the texture
    * so that the wrap modes act, not on texel boundaries at pixel centres */
   const int edge[5] = { 0, size / 4, size / 2, 3 * size / 4, size };
   for (int b = 0; b < 4; b++) {
      glUniform1i(band, b);
      e2e_draw_rect(-1, e2e_ndc(edge[b] * E2E_SUB, size), 1, e2e_ndc(edge[b + 1] * E2E_SUB, size),
                    -0.31f, -0.27f, 1.43f, 1.38f);
   }
   glDeleteTextures(3, tex);
}

/* gather-clamp's bands, or (ties) its last band, alone over the target. */
static void case_gather_clamp(int size, bool ties)
{
   static const char *fs =
      "#version 310 es\n"
      "precision highp float;\n"
      "uniform highp sampler2D u_a, u_swz, u_narrow;\n"
      "uniform int u_band;\n"
      "in vec2 v_uv;\n"
      "out vec4 o_color;\n"
      "void main() {\n"
      "   vec2 grid = floor(v_uv * vec2(13.0, 7.0) + 0.5) / vec2(13.0, 7.0);\n"
      "   bool right = gl_FragCoord.x > 40.0;\n"
      "   if (u_band == 0) o_color = textureGatherOffset(u_a, v_uv, ivec2(-8, 7), 0);\n"
      "   else if (u_band == 1) o_color = textureGatherOffset(u_a, grid, ivec2(1, -1), 1);\n"
      "   else if (u_band == 2) o_color = textureGather(u_a, grid, 2)\n"
      "                                 + textureGatherOffset(u_a, grid, ivec2(7, -8), 3);\n"
      "   else if (u_band == 3) o_color = right ? textureGather(u_swz, v_uv, 1)\n"
      "                                         : textureGather(u_swz, v_uv, 2)\n"
      "                                 + textureGather(u_swz, v_uv, 3) * 0.5;\n"
      "   else if (u_band == 4) o_color = textureGather(u_a, v_uv * (right ? 1e30 : 1.0), 0)\n"
      "                                 + textureGather(u_a, v_uv * (right ? 1e-30 : 1.0), 1);\n"
      "   else if (u_band == 5) o_color = textureGather(u_narrow, v_uv, 0);\n"
      "   else {\n"
      "      /* a texel boundary k / size moved by +-2^-e, e random: the\n"
      "       * footprint's decision at every scale of the register */\n"
      "      uvec2 p = uvec2(gl_FragCoord.xy);\n"
      "      uint h = (p.x * 73856093u) ^ (p.y * 19349663u);\n"
      "      h = (h ^ (h >> 13)) * 1274126177u;\n"
      "      vec2 k = vec2(float(h % 23u), float((h >> 5) % 15u)) - vec2(5.0, 4.0);\n"
      "      vec2 e = uintBitsToFloat((uvec2(127u) - uvec2((h >> 9) % 28u, (h >> 14) % 28u)) << 23);\n"
      "      e *= vec2((h & 1u) != 0u ? -1.0 : 1.0, (h & 2u) != 0u ? -1.0 : 1.0);\n"
      "      vec2 c = (k + 0.5 * float((h >> 20) & 1u) + e) / vec2(13.0, 7.0);\n"
      "      o_color = textureGather(u_a, c, 1);\n"
      "   }\n"
      "}\n";
   enum { W = 13, H = 7 };
   uint32_t texels[W * H];
   uint32_t rng = 0x9a7c1a3bu;
   for (int k = 0; k < W * H; k++)
      texels[k] = e2e_rand(&rng);
   GLuint tex[3];
   glGenTextures(3, tex);
   for (int t = 0; t < 3; t++) {
      glActiveTexture(GL_TEXTURE0 + t);
      glBindTexture(GL_TEXTURE_2D, tex[t]);
      if (t == 2)
         glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      else
         glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      e2e_tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
   }
   /* the swizzled view: blue, one, zero, red */
   glActiveTexture(GL_TEXTURE1);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_R, GL_BLUE);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_G, GL_ONE);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_B, GL_ZERO);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_A, GL_RED);
   glActiveTexture(GL_TEXTURE0);
   static const char *const units[] = { "u_a", "u_swz", "u_narrow" };
   const GLint band = band_program(fs, units);
   enum { BANDS = 6 };
   for (int b = ties ? BANDS : 0; b < (ties ? BANDS + 1 : BANDS); b++) {
      glUniform1i(band, b);
      /* edges on the sub-pixel grid; coordinates from below zero to past
       * one, so that both clamps act */
      const int y0 = ties ? 0 : size * b / BANDS, y1 = ties ? size : size * (b + 1) / BANDS;
      e2e_draw_rect(-1, e2e_ndc(y0 * E2E_SUB, size), 1, e2e_ndc(y1 * E2E_SUB, size), -0.37f, -0.29f,
                    1.41f, 1.33f);
   }
   glDeleteTextures(3, tex);
}

/* A triangle with vertices on the sub-pixel grid inside the target. */
static void random_triangle(uint32_t *rng, int size, float pos[12])
{
   for (int k = 0; k < 3; k++) {
      pos[4 * k + 0] = e2e_ndc(e2e_rand_range(rng, 0, size * E2E_SUB), size);
      pos[4 * k + 1] = e2e_ndc(e2e_rand_range(rng, 0, size * E2E_SUB), size);
      pos[4 * k + 2] = 0.0f;
      pos[4 * k + 3] = 1.0f;
   }
}

/* Leaves the texture bound to unit 0 for the pass that reads it. */
/* textureGather on a cube map, its footprints crossing the faces' edges
 * (seamless, as ES 3.0 filters), on a view with a swizzle; the left half
 * gathers green, the right half alpha, which the swizzle takes from red. */
static void case_gather_cube(int size)
{
   static const char *fs =
      "#version 310 es\n"
      "precision highp float;\n"
      "uniform highp samplerCube u_cube;\n"
      "uniform int u_comp;\n"
      "in vec2 v_uv;\n"
      "out vec4 o_color;\n"
      "void main() {\n"
      "   /* directions sweeping across the +x face's corner with +y and +z */\n"
      "   vec3 d = vec3(1.0, v_uv.y * 2.2 - 0.1, v_uv.x * 2.2 - 0.1);\n"
      "   o_color = u_comp == 1 ? textureGather(u_cube, d, 1) : textureGather(u_cube, d, 3);\n"
      "}\n";
   enum { W = 8 };
   uint32_t texels[6][W * W];
   uint32_t rng = 0xc0be3101u;
   for (int f = 0; f < 6; f++)
      for (int k = 0; k < W * W; k++)
         texels[f][k] = e2e_rand(&rng);
   GLuint tex;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
   for (int f = 0; f < 6; f++)
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGBA8, W, W, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, texels[f]);
   glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
   glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
   /* (r, g, b, a) of the view = (b, g, a, r) of the texels */
   glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_SWIZZLE_R, GL_BLUE);
   glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_SWIZZLE_B, GL_ALPHA);
   glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_SWIZZLE_A, GL_RED);
   GLuint p = e2e_uv_program_es31(fs);
   glUseProgram(p);
   glUniform1i(glGetUniformLocation(p, "u_cube"), 0);
   GLint comp = glGetUniformLocation(p, "u_comp");
   const int half = size / 2;
   glUniform1i(comp, 1);
   e2e_draw_rect(-1, -1, e2e_ndc(half * E2E_SUB, size), 1, 0.0f, 0.0f, 0.5f, 1.0f);
   glUniform1i(comp, 3);
   e2e_draw_rect(e2e_ndc(half * E2E_SUB, size), -1, 1, 1, 0.5f, 0.0f, 1.0f, 1.0f);
   glDeleteTextures(1, &tex);
}

static void case_ms_fetch(int size)
{
   GLuint tex, fbo;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, tex);
   glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8, size, size, GL_TRUE);
   glGenFramebuffers(1, &fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, fbo);
   glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, tex, 0);
   e2e_check(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE,
             "the 4-sample texture FBO is not complete");
   GLint samples = 0;
   glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &samples);
   e2e_check(samples == 4, "the texture does not have 4 samples");
   glViewport(0, 0, size, size);
   glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT);
   glUseProgram(e2e_color_program());
   uint32_t rng = 0x3f5e3101u;
   for (int t = 0; t < 20; t++) {
      float pos[12], col[4];
      random_triangle(&rng, size, pos);
      for (int c = 0; c < 3; c++)
         col[c] = (float)e2e_rand_range(&rng, 0, 255) / 255.0f;
      col[3] = 1.0f;
      e2e_draw(GL_TRIANGLES, 3, pos, NULL, col);
   }
   /* a pixel a vertical edge halves: its samples differ */
   const float half[] = { e2e_ndc(0, size), -1, 0, 1, e2e_ndc(E2E_SUB / 2, size), -1, 0, 1,
                          e2e_ndc(0, size), 1, 0, 1, e2e_ndc(E2E_SUB / 2, size), 1, 0, 1 };
   const float red[4] = { 1, 0, 0, 1 };
   e2e_draw(GL_TRIANGLE_STRIP, 4, half, NULL, red);
   glDeleteFramebuffers(1, &fbo);
}

/* Leaves the texture bound to unit 0 for the pass that reads it. */
static void case_stencil_tex(int size)
{
   GLuint tex, fbo;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D, tex);
   glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH24_STENCIL8, size, size);
   glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glGenFramebuffers(1, &fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, fbo);
   glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, tex, 0);
   e2e_check(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE,
             "the depth/stencil texture FBO is not complete");
   glViewport(0, 0, size, size);
   glClearStencil(0);
   glClear(GL_STENCIL_BUFFER_BIT);
   glEnable(GL_STENCIL_TEST);
   glStencilFunc(GL_ALWAYS, 0, 0xff);
   glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
   glUseProgram(e2e_color_program());
   uint32_t rng = 0x57e03101u;
   const float white[4] = { 1, 1, 1, 1 };
   for (int t = 0; t < 12; t++) {
      float pos[12];
      random_triangle(&rng, size, pos);
      e2e_draw(GL_TRIANGLES, 3, pos, NULL, white);
   }
   glDisable(GL_STENCIL_TEST);
   glDeleteFramebuffers(1, &fbo);
}


/* GLSL ES 3.10's built-ins on per-pixel values, each checked in the shader
 * against an identity (an exact one wherever the function is exact): the
 * picture is green on any conformant driver, whatever its interpolation. */
/* GLSL ES 3.10's built-ins, each against an identity it must meet, on the
 * invocation's own numbers (bits, x, uv): `bad` gets a bit per broken one. */
#define BUILTINS_BODY \
   "   uint bad = 0u;\n" \
   "   int e; float m = frexp(x, e);\n" \
   "   if (ldexp(m, e) != x || abs(m) < 0.5 || abs(m) >= 1.0) bad |= 1u;\n" \
   "   vec4 c = vec4(uv, 0.25, 1.0);\n" \
   "   if (any(greaterThan(abs(unpackUnorm4x8(packUnorm4x8(c)) - c), vec4(0.5 / 255.0)))) bad |= 2u;\n" \
   "   vec4 sn = c * 2.0 - 1.0;\n" \
   "   if (any(greaterThan(abs(unpackSnorm4x8(packSnorm4x8(sn)) - sn), vec4(0.5 / 127.0)))) bad |= 2u;\n" \
   "   if (any(greaterThan(abs(unpackUnorm2x16(packUnorm2x16(uv)) - uv), vec2(0.5 / 65535.0)))) bad |= 4u;\n" \
   "   if (any(greaterThan(abs(unpackSnorm2x16(packSnorm2x16(sn.xy)) - sn.xy), vec2(0.5 / 32767.0)))) bad |= 4u;\n" \
   "   if (unpackHalf2x16(packHalf2x16(vec2(0.5, -2.25))) != vec2(0.5, -2.25)) bad |= 8u;\n" \
   "   int lsb = findLSB(bits), msb = findMSB(bits);\n" \
   "   if (bits != 0u && ((bits >> uint(lsb) & 1u) != 1u || (bits & ((1u << uint(lsb)) - 1u)) != 0u ||\n" \
   "                      (bits >> uint(msb)) != 1u)) bad |= 16u;\n" \
   "   uint n = 0u; for (uint v = bits; v != 0u; v &= v - 1u) n++;\n" \
   "   if (uint(bitCount(bits)) != n) bad |= 16u;\n" \
   "   if (bitfieldReverse(bitfieldReverse(bits)) != bits || (bitfieldReverse(bits) >> 31) != (bits & 1u)) bad |= 32u;\n" \
   "   if (bitfieldExtract(bits, 3, 7) != ((bits >> 3) & 127u)) bad |= 32u;\n" \
   "   if (bitfieldExtract(bitfieldInsert(bits, 5u, 9, 3), 9, 3) != 5u) bad |= 32u;\n" \
   "   if (bitfieldExtract(int(bits), 28, 4) != int(bits) >> 28) bad |= 32u;\n" \
   "   uint carry, borrow;\n" \
   "   uint sum = uaddCarry(bits, 0xffff0000u, carry);\n" \
   "   if (sum != bits + 0xffff0000u || carry != (bits >= 0x10000u ? 1u : 0u)) bad |= 64u;\n" \
   "   uint diff = usubBorrow(bits, 0x80000000u, borrow);\n" \
   "   if (diff != bits - 0x80000000u || borrow != (bits < 0x80000000u ? 1u : 0u)) bad |= 64u;\n" \
   "   uint hi, lo; umulExtended(bits, 65537u, hi, lo);\n" \
   "   if (lo != bits * 65537u || hi != (bits >> 16) + ((bits & 0xffffu) + (bits >> 16) >> 16)) bad |= 128u;\n" \
   "   int small = int(bits & 0xffffu) - 32768, ihi, ilo;\n" \
   "   imulExtended(small, -3, ihi, ilo);\n" \
   "   if (ilo != small * -3 || ihi != (ilo < 0 ? -1 : 0)) bad |= 128u;\n" \
   "   if (intBitsToFloat(floatBitsToInt(x)) != x || uintBitsToFloat(floatBitsToUint(x)) != x) bad |= 256u;\n"

static const char *fs_builtins =
   "#version 310 es\n"
   "precision highp float;\n"
   "precision highp int;\n"
   "in vec2 v_uv;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   vec2 uv = v_uv;\n"
   "   uint bits = uint(gl_FragCoord.x) * 2654435761u ^ uint(gl_FragCoord.y) * 40503u;\n"
   "   float x = (uv.x - 0.5) * 1000.0 + 0.375;\n"
   BUILTINS_BODY
   "   o_color = bad == 0u ? vec4(0.0, 1.0, 0.0, 1.0)\n"
   "                       : vec4(float(bad & 15u) / 15.0, 0.0, float(bad >> 4) / 31.0, 1.0);\n"
   "}\n";

/* The same in a compute shader, 64x64 invocations in 8x8 groups, `bad` to a
 * storage buffer. */
static const char *cs_builtins =
   "#version 310 es\n"
   "precision highp float;\n"
   "precision highp int;\n"
   "layout(local_size_x = 8, local_size_y = 8) in;\n"
   "layout(std430, binding = 0) buffer Bad { uint v[]; } result;\n"
   "void main() {\n"
   "   uvec2 p = gl_GlobalInvocationID.xy;\n"
   "   vec2 uv = (vec2(p) + 0.5) / 64.0;\n"
   "   uint bits = p.x * 2654435761u ^ p.y * 40503u;\n"
   "   float x = (uv.x - 0.5) * 1000.0 + 0.375;\n"
   BUILTINS_BODY
   "   result.v[p.y * 64u + p.x] = bad;\n"
   "}\n";

/* The compute shader's results: the invocations whose identities broke. */
/* case image-formats: a format, its GLSL layout name and kind, its
 * upload format and type, and how to draw random texels of it. */
enum rand_kind { RAND_BYTES, RAND_F32, RAND_F16, RAND_R11G11B10F };
static const struct image_format {
   const char *name;
   char kind;   /* 'f' image2D, 'u' uimage2D, 'i' iimage2D */
   GLenum format, pixel_format, pixel_type;
   int bytes;   /* a texel */
   enum rand_kind rand;
   bool norm16;
} image_formats[] = {
   { "rgba32f", 'f', GL_RGBA32F, GL_RGBA, GL_FLOAT, 16, RAND_F32, false },
   { "rgba16f", 'f', GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, 8, RAND_F16, false },
   { "r32f", 'f', GL_R32F, GL_RED, GL_FLOAT, 4, RAND_F32, false },
   { "rgba8", 'f', GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, RAND_BYTES, false },
   { "rgba8_snorm", 'f', GL_RGBA8_SNORM, GL_RGBA, GL_BYTE, 4, RAND_BYTES, false },
   { "rgba32ui", 'u', GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, 16, RAND_BYTES, false },
   { "rgba16ui", 'u', GL_RGBA16UI, GL_RGBA_INTEGER, GL_UNSIGNED_SHORT, 8, RAND_BYTES, false },
   { "rgba8ui", 'u', GL_RGBA8UI, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, 4, RAND_BYTES, false },
   { "r32ui", 'u', GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, 4, RAND_BYTES, false },
   { "rgba32i", 'i', GL_RGBA32I, GL_RGBA_INTEGER, GL_INT, 16, RAND_BYTES, false },
   { "rgba16i", 'i', GL_RGBA16I, GL_RGBA_INTEGER, GL_SHORT, 8, RAND_BYTES, false },
   { "rgba8i", 'i', GL_RGBA8I, GL_RGBA_INTEGER, GL_BYTE, 4, RAND_BYTES, false },
   { "r32i", 'i', GL_R32I, GL_RED_INTEGER, GL_INT, 4, RAND_BYTES, false },
   /* GL_NV_image_formats */
   { "rg32f", 'f', GL_RG32F, GL_RG, GL_FLOAT, 8, RAND_F32, false },
   { "rg16f", 'f', GL_RG16F, GL_RG, GL_HALF_FLOAT, 4, RAND_F16, false },
   { "r11f_g11f_b10f", 'f', GL_R11F_G11F_B10F, GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV, 4,
     RAND_R11G11B10F, false },
   { "r16f", 'f', GL_R16F, GL_RED, GL_HALF_FLOAT, 2, RAND_F16, false },
   { "rgb10_a2ui", 'u', GL_RGB10_A2UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT_2_10_10_10_REV, 4,
     RAND_BYTES, false },
   { "rg32ui", 'u', GL_RG32UI, GL_RG_INTEGER, GL_UNSIGNED_INT, 8, RAND_BYTES, false },
   { "rg16ui", 'u', GL_RG16UI, GL_RG_INTEGER, GL_UNSIGNED_SHORT, 4, RAND_BYTES, false },
   { "rg8ui", 'u', GL_RG8UI, GL_RG_INTEGER, GL_UNSIGNED_BYTE, 2, RAND_BYTES, false },
   { "r16ui", 'u', GL_R16UI, GL_RED_INTEGER, GL_UNSIGNED_SHORT, 2, RAND_BYTES, false },
   { "r8ui", 'u', GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, 1, RAND_BYTES, false },
   { "rg32i", 'i', GL_RG32I, GL_RG_INTEGER, GL_INT, 8, RAND_BYTES, false },
   { "rg16i", 'i', GL_RG16I, GL_RG_INTEGER, GL_SHORT, 4, RAND_BYTES, false },
   { "rg8i", 'i', GL_RG8I, GL_RG_INTEGER, GL_BYTE, 2, RAND_BYTES, false },
   { "r16i", 'i', GL_R16I, GL_RED_INTEGER, GL_SHORT, 2, RAND_BYTES, false },
   { "r8i", 'i', GL_R8I, GL_RED_INTEGER, GL_BYTE, 1, RAND_BYTES, false },
   { "rgba16", 'f', 0x805B /* GL_RGBA16_EXT */, GL_RGBA, GL_UNSIGNED_SHORT, 8, RAND_BYTES, true },
   { "rgb10_a2", 'f', GL_RGB10_A2, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 4, RAND_BYTES,
     false },
   { "rg16", 'f', 0x822C /* GL_RG16_EXT */, GL_RG, GL_UNSIGNED_SHORT, 4, RAND_BYTES, true },
   { "rg8", 'f', GL_RG8, GL_RG, GL_UNSIGNED_BYTE, 2, RAND_BYTES, false },
   { "r16", 'f', 0x822A /* GL_R16_EXT */, GL_RED, GL_UNSIGNED_SHORT, 2, RAND_BYTES, true },
   { "r8", 'f', GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, RAND_BYTES, false },
   { "rgba16_snorm", 'f', 0x8F9B /* GL_RGBA16_SNORM_EXT */, GL_RGBA, GL_SHORT, 8, RAND_BYTES,
     true },
   { "rg16_snorm", 'f', 0x8F99 /* GL_RG16_SNORM_EXT */, GL_RG, GL_SHORT, 4, RAND_BYTES, true },
   { "rg8_snorm", 'f', GL_RG8_SNORM, GL_RG, GL_BYTE, 2, RAND_BYTES, false },
   { "r16_snorm", 'f', 0x8F98 /* GL_R16_SNORM_EXT */, GL_RED, GL_SHORT, 2, RAND_BYTES, true },
   { "r8_snorm", 'f', GL_R8_SNORM, GL_RED, GL_BYTE, 1, RAND_BYTES, false },
};

/* A texel's random bytes: finite floats only (a NaN's payload is the
 * driver's to keep or not). */
static void image_texel(const struct image_format *f, uint32_t *rng, unsigned char *out)
{
   for (int b = 0; b < f->bytes; b += 4) {
      uint32_t w = e2e_rand(rng);
      switch (f->rand) {
      case RAND_F32: {
         const float x = (float)((int)(w % 2001u) - 1000) / 64.0f;
         memcpy(&w, &x, 4);
         break;
      }
      case RAND_F16:   /* two halves, exponents 0..29 */
         w = (w & 0x83ff83ffu) | ((w >> 10) % 30u) << 10 | ((w >> 20) % 30u) << 26;
         break;
      case RAND_R11G11B10F:   /* exponents 0..30 */
         w = ((w & 0x3fu) | ((w >> 6) % 31u) << 6) |
             ((w >> 11 & 0x3fu) | ((w >> 17) % 31u) << 6) << 11 |
             ((w >> 22 & 0x1fu) | ((w >> 27) % 31u) << 5) << 22;
         break;
      case RAND_BYTES:
         break;
      }
      memcpy(out + b, &w, (size_t)(f->bytes - b < 4 ? f->bytes - b : 4));
   }
}

static void case_image_formats(int size)
{
   if (size < 64)
      fp_die("--case image-formats draws a 64x64 table: --size 64 or more");
   const bool norm16 = e2e_has_extension("GL_EXT_texture_norm16");
   printf("stat: norm16=%d\n", norm16);
   const int nf = (int)(sizeof(image_formats) / sizeof(image_formats[0]));
   uint32_t *words = calloc((size_t)size * size, 4);
   uint32_t rng = 0x1f0a7a11u;
   int tested = 0, differ = 0;
   for (int f = 0; f < nf; f++) {
      const struct image_format *fmt = &image_formats[f];
      if (fmt->norm16 && !norm16)
         continue;
      const char *type = fmt->kind == 'u' ? "uvec4" : fmt->kind == 'i' ? "ivec4" : "vec4";
      const char *img = fmt->kind == 'u' ? "uimage2D" : fmt->kind == 'i' ? "iimage2D" : "image2D";
      char cs[1024];
      snprintf(cs, sizeof(cs),
               "#version 310 es\n"
               "#extension GL_NV_image_formats : enable\n"
               "layout(local_size_x = 4, local_size_y = 4) in;\n"
               "layout(%s, binding = 0) readonly uniform highp %s src;\n"
               "layout(%s, binding = 1) writeonly uniform highp %s dst;\n"
               "layout(std430, binding = 0) buffer Out { highp %s v[16]; };\n"
               "void main() {\n"
               "   ivec2 p = ivec2(gl_LocalInvocationID.xy);\n"
               "   highp %s x = imageLoad(src, p);\n"
               "   v[p.y * 4 + p.x] = x;\n"
               "   imageStore(dst, p, x);\n"
               "}\n", fmt->name, img, fmt->name, img, type, type);
      unsigned char texels[16 * 16];
      for (int t = 0; t < 16; t++)
         image_texel(fmt, &rng, texels + t * fmt->bytes);
      GLuint tex[2], buf[2];
      glGenTextures(2, tex);
      for (int k = 0; k < 2; k++) {
         glBindTexture(GL_TEXTURE_2D, tex[k]);
         glTexStorage2D(GL_TEXTURE_2D, 1, fmt->format, 4, 4);
      }
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glBindTexture(GL_TEXTURE_2D, tex[0]);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, fmt->pixel_format, fmt->pixel_type, texels);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
      glGenBuffers(2, buf);
      const GLuint prog = fp_gl_compute_program(cs);
      glUseProgram(prog);
      for (int pass = 0; pass < 2; pass++) {
         /* pass 0 loads the uploaded image and stores it; pass 1 loads
          * the stored one (and stores it to the first) */
         glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf[pass]);
         glBufferData(GL_SHADER_STORAGE_BUFFER, 256, NULL, GL_DYNAMIC_COPY);
         glBindImageTexture(0, tex[pass], 0, GL_FALSE, 0, GL_READ_ONLY, fmt->format);
         glBindImageTexture(1, tex[1 - pass], 0, GL_FALSE, 0, GL_WRITE_ONLY, fmt->format);
         glDispatchCompute(1, 1, 1);
         glMemoryBarrier(GL_ALL_BARRIER_BITS);
      }
      uint32_t got[2][64];
      for (int pass = 0; pass < 2; pass++) {
         glBindBuffer(GL_SHADER_STORAGE_BUFFER, buf[pass]);
         const void *m = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, 256, GL_MAP_READ_BIT);
         if (m) {
            memcpy(got[pass], m, 256);
            glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
         } else {
            memset(got[pass], 0, 256);
         }
      }
      memcpy(words + (size_t)f * size, got[0], 256);   /* a format a row */
      const bool same = !memcmp(got[0], got[1], 256);
      differ += !same;
      tested++;
      if (!same)
         printf("stat: round_trip_differs=%s\n", fmt->name);
      glDeleteProgram(prog);
      glDeleteBuffers(2, buf);
      glDeleteTextures(2, tex);
   }
   printf("stat: formats=%d round_trips_differing=%d\n", tested, differ);
   e2e_check(tested >= 28, "fewer image formats than GL ES 3.1 with GL_NV_image_formats name");
   e2e_check(differ == 0, "a stored texel loads back as another value");
   show_words(words, size);
   free(words);
}

/* case ubo: int w[67], vec3 v[5], float f[3] in a shared block, both
 * stages reading it; 8x8 cells of 8x8 pixels, one instance a cell. */
static const char *ubo_block =
   "uniform Words { highp int w[67]; highp vec3 v[5]; highp float f[3]; };\n";

static int ubo_w(int i) { return (i * 37 + 11) % 256; }
static int ubo_vz(int j) { return j * 50 + 3; }   /* v[j].z in 255ths */
static int ubo_f(int k) { return k * 100 + 20; }  /* f[k] in 255ths */

static void case_ubo(int size)
{
   char vs_src[1024], fs_src[1024];
   snprintf(vs_src, sizeof(vs_src),
            "#version 300 es\n%s"
            "flat out highp ivec2 v_w;\n"
            "void main() {\n"
            "   int c = gl_InstanceID;\n"
            "   vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);\n"
            "   vec2 cell = vec2(c %% 8, c / 8);\n"
            "   gl_Position = vec4((cell + corner) / 4.0 - 1.0, 0.0, 1.0);\n"
            "   v_w = ivec2(w[(c * 13) %% 67], int(v[c %% 5].z * 255.0 + 0.5));\n"
            "}\n", ubo_block);
   snprintf(fs_src, sizeof(fs_src),
            "#version 300 es\nprecision highp float;\n%s"
            "flat in highp ivec2 v_w;\n"
            "out vec4 o_color;\n"
            "void main() {\n"
            "   ivec2 p = ivec2(gl_FragCoord.xy) * 64 / %d;\n"
            "   int i = (p.x + 7 * p.y) %% 67;\n"
            "   o_color = vec4(float(w[i]) / 255.0, float(v_w.x) / 255.0,\n"
            "                  float(v_w.y) / 255.0, f[i %% 3]);\n"
            "}\n", ubo_block, size);
   static const char *const attr[] = { NULL };
   GLuint p = fp_gl_program(vs_src, fs_src, attr);
   glUseProgram(p);

   /* the block as this driver lays it out */
   static const char *const names[3] = { "w[0]", "v[0]", "f[0]" };
   GLuint idx[3];
   GLint off[3], stride[3], bytes = 0;
   glGetUniformIndices(p, 3, names, idx);
   glGetActiveUniformsiv(p, 3, idx, GL_UNIFORM_OFFSET, off);
   glGetActiveUniformsiv(p, 3, idx, GL_UNIFORM_ARRAY_STRIDE, stride);
   const GLuint block = glGetUniformBlockIndex(p, "Words");
   glGetActiveUniformBlockiv(p, block, GL_UNIFORM_BLOCK_DATA_SIZE, &bytes);
   printf("stat: strides=%d,%d,%d size=%d\n", stride[0], stride[1], stride[2], bytes);
   e2e_check(bytes > 0 && bytes <= 4096, "the block's size");
   unsigned char data[4096] = { 0 };
   for (int i = 0; i < 67; i++) {
      const int32_t x = ubo_w(i);
      memcpy(data + off[0] + i * stride[0], &x, 4);
   }
   for (int j = 0; j < 5; j++) {
      const float x[3] = { (float)j, (float)-j, (float)ubo_vz(j) / 255.0f };
      memcpy(data + off[1] + j * stride[1], x, sizeof(x));
   }
   for (int k = 0; k < 3; k++) {
      const float x = (float)ubo_f(k) / 255.0f;
      memcpy(data + off[2] + k * stride[2], &x, 4);
   }
   GLuint buf;
   glGenBuffers(1, &buf);
   glBindBuffer(GL_UNIFORM_BUFFER, buf);
   glBufferData(GL_UNIFORM_BUFFER, bytes, data, GL_STATIC_DRAW);
   glUniformBlockBinding(p, block, 1);
   glBindBufferBase(GL_UNIFORM_BUFFER, 1, buf);
   glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, 64);

   unsigned char *px = malloc((size_t)size * size * 4);
   glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, px);
   int wrong = 0;
   for (int y = 0; y < size; y++) {
      for (int x = 0; x < size; x++) {
         const int qx = x * 64 / size, qy = y * 64 / size;
         const int i = (qx + 7 * qy) % 67, c = x * 8 / size + 8 * (y * 8 / size);
         const int want[4] = { ubo_w(i), ubo_w(c * 13 % 67), ubo_vz(c % 5), ubo_f(i % 3) };
         const unsigned char *q = px + ((size_t)y * size + x) * 4;
         for (int ch = 0; ch < 4; ch++)
            wrong += q[ch] != want[ch];
      }
   }
   free(px);
   printf("stat: wrong_channels=%d\n", wrong);
   e2e_check(wrong == 0, "a value read from the uniform block is wrong");
   glDeleteBuffers(1, &buf);
}

static int builtins_compute(void)
{
   GLuint buf;
   glGenBuffers(1, &buf);
   glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf);
   glBufferData(GL_SHADER_STORAGE_BUFFER, 64 * 64 * 4, NULL, GL_DYNAMIC_COPY);
   glUseProgram(fp_gl_compute_program(cs_builtins));
   glDispatchCompute(8, 8, 1);
   glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
   const uint32_t *got = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, 64 * 64 * 4, GL_MAP_READ_BIT);
   int broken = got ? 0 : 64 * 64;
   for (int k = 0; got && k < 64 * 64; k++)
      broken += got[k] != 0;
   glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
   glDeleteBuffers(1, &buf);
   return broken;
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   if (!e2e_check_es31()) {
      /* nothing more to try */
   } else if (!strcmp(c, "compute")) {
      case_compute(a.size);
   } else if (!strcmp(c, "shared")) {
      case_shared(a.size);
   } else if (!strcmp(c, "image")) {
      case_image(a.size);
   } else if (!strcmp(c, "gather")) {
      case_gather(a.size);
   } else if (!strcmp(c, "gather-cube")) {
      case_gather_cube(a.size);
   } else if (!strcmp(c, "gather-clamp") || !strcmp(c, "gather-ties")) {
      case_gather_clamp(a.size, !strcmp(c, "gather-ties"));
   } else if (!strcmp(c, "image-formats")) {
      case_image_formats(a.size);
      glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
   } else if (!strcmp(c, "ubo")) {
      glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
      glViewport(0, 0, a.size, a.size);
      case_ubo(a.size);
   } else if (!strcmp(c, "builtins")) {
      glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
      glViewport(0, 0, a.size, a.size);
      glUseProgram(e2e_uv_program_es31(fs_builtins));
      e2e_draw_rect(-1, -1, 1, 1, 0, 0, 1, 1);
      /* the corner pixels: green where every identity held */
      unsigned char px[4];
      glReadPixels(a.size / 2, a.size / 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
      printf("stat: pixel=%u,%u,%u\n", px[0], px[1], px[2]);
      e2e_check(px[0] == 0 && px[1] == 255 && px[2] == 0, "a built-in broke its identity");
      const int broken = builtins_compute();
      printf("stat: compute_broken=%d\n", broken);
      e2e_check(broken == 0, "a built-in broke its identity in the compute shader");
   } else if (!strcmp(c, "ms-fetch") || !strcmp(c, "stencil-tex")) {
      const bool ms = !strcmp(c, "ms-fetch");
      static const char *fs_ms =
         "#version 310 es\n"
         "precision highp float;\n"
         "uniform highp sampler2DMS u_ms;\n"
         "in vec2 v_uv;\n"
         "out vec4 o_color;\n"
         "void main() {\n"
         "   ivec2 p = ivec2(gl_FragCoord.xy);\n"
         "   o_color = texelFetch(u_ms, p, (p.x + p.y) % 4);\n"
         "}\n";
      static const char *fs_st =
         "#version 310 es\n"
         "precision highp float;\n"
         "uniform highp usampler2D u_stencil;\n"
         "in vec2 v_uv;\n"
         "out vec4 o_color;\n"
         "void main() {\n"
         "   uint s = texelFetch(u_stencil, ivec2(gl_FragCoord.xy), 0).x;\n"
         "   o_color = vec4(float(s * 40u % 256u) / 255.0, float(s) / 8.0, 0.0, 1.0);\n"
         "}\n";
      if (ms)
         case_ms_fetch(a.size);
      else
         case_stencil_tex(a.size);
      glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
      glViewport(0, 0, a.size, a.size);
      glUseProgram(e2e_uv_program_es31(ms ? fs_ms : fs_st));
      e2e_draw_rect(-1, -1, 1, 1, 0, 0, 1, 1);
      if (ms) {
         /* pixel (0, y) is half covered by the red strip: sample 0 (x 0.375)
          * is red, sample 1 (0.875) is not */
         unsigned char px[2][4];
         glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[0]);   /* sample 0 */
         glReadPixels(0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[1]);   /* sample 1 */
         printf("stat: s0=%u,%u,%u s1=%u,%u,%u\n", px[0][0], px[0][1], px[0][2], px[1][0],
                px[1][1], px[1][2]);
         e2e_check(px[0][0] == 255 && px[0][1] == 0 && px[0][2] == 0,
                   "sample 0 of the edge pixel is not red");
         e2e_check(!(px[1][0] == 255 && px[1][1] == 0 && px[1][2] == 0),
                   "sample 1 of the edge pixel is red");
      }
   } else {
      fp_die("--case: compute, shared, image, gather, gather-cube, gather-clamp, gather-ties, "
             "image-formats, ubo, builtins, ms-fetch or stencil-tex");
   }
   glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);   /* the one read back */
   return e2e_finish(&g, &a, NULL);
}
