/*
 * Storage buffers, images and atomic counters in fragment shaders
 * (--case NAME; every case is order-independent, so the image is the same
 * bytes whatever order the fragments run in):
 *
 *   counter    sixteen passes of a rectangle with odd pixel edges (quads
 *              half covered, whose helper invocations must not count), each
 *              fragment adding 1 to an atomic counter, to a storage buffer
 *              word (atomicAdd) and to an r32ui image texel
 *              (imageAtomicAdd); after glMemoryBarrier the three totals
 *              must each be sixteen times the rectangle's pixels (256x256
 *              unless --size says: large enough for the model's threads to
 *              share every pass), and a last pass draws them, a band each
 *   image      a fragment shader stores each fragment's own texel of an
 *              RGBA8 image (imageStore) with every colour channel masked,
 *              behind a depth buffer that rejects the left half: without
 *              early_fragment_tests every fragment must store (the shader
 *              runs before the tests), with them only the right half's;
 *              after glMemoryBarrier a second draw shows each pixel's texel
 *              of both images (imageLoad), the top half the first's
 *   histogram  three overlapping rectangles, each fragment counting its
 *              colour (one of 16, from its position) in a storage buffer
 *              with atomicAdd; the counts are checked against the CPU's
 *              and drawn in the bottom band, a bucket per column band
 *
 * Self-checks (errors fail the program on any driver): GL ES 3.1, the
 * totals, the stored texels and the histogram against the CPU's.
 */
#include "e2e_common.h"

#include <GLES3/gl31.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The program's framebuffer (fp_gl's FBO), bound again after reading
 * through another. */
static GLuint main_fbo;

/* The pixel rectangle [x0, x1) x [y0, y1) of a size x size target, its
 * edges on pixel edges (no pixel centre on an edge), at depth z. */
static void draw_pixels(int x0, int y0, int x1, int y1, float z, int size)
{
   const float l = 2.0f * (float)x0 / (float)size - 1.0f, r = 2.0f * (float)x1 / (float)size - 1.0f;
   const float b = 2.0f * (float)y0 / (float)size - 1.0f, t = 2.0f * (float)y1 / (float)size - 1.0f;
   const float pos[] = { l, b, z, 1, r, b, z, 1, r, t, z, 1, l, b, z, 1, r, t, z, 1, l, t, z, 1 };
   const float uv[12] = { 0 };
   e2e_draw_uv(GL_TRIANGLES, 6, pos, uv, 2);
}

static GLuint make_buffer(GLenum target, GLsizeiptr bytes)
{
   GLuint b;
   glGenBuffers(1, &b);
   glBindBuffer(target, b);
   void *zero = calloc(1, (size_t)bytes);
   if (!zero)
      fp_die("out of memory");
   glBufferData(target, bytes, zero, GL_DYNAMIC_COPY);
   free(zero);
   return b;
}

/* A size x size texture of `format` filled with zeros, bound to `unit`'s
 * image binding. */
static GLuint make_image(GLenum format, int w, int h, GLenum fmt, GLenum type, int cpp, GLuint unit,
                         GLenum access)
{
   GLuint t;
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   glTexStorage2D(GL_TEXTURE_2D, 1, format, w, h);
   void *zero = calloc((size_t)w * (size_t)h, (size_t)cpp);
   if (!zero)
      fp_die("out of memory");
   glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, fmt, type, zero);
   free(zero);
   e2e_tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
   glBindImageTexture(unit, t, 0, GL_FALSE, 0, access, format);
   return t;
}

static uint32_t read_word(GLenum target, GLuint buf, GLintptr offset)
{
   glBindBuffer(target, buf);
   const uint32_t *p = glMapBufferRange(target, offset, 4, GL_MAP_READ_BIT);
   const uint32_t v = p ? *p : 0xffffffffu;
   glUnmapBuffer(target);
   return v;
}

static const char counter_fs[] =
   "#version 310 es\n"
   "#extension GL_OES_shader_image_atomic : require\n"
   "precision highp float;\n"
   "layout(binding = 0) uniform atomic_uint u_count;\n"
   "layout(std430, binding = 1) buffer Sum { uint adds; };\n"
   "layout(r32ui, binding = 0) uniform highp uimage2D u_img;\n"
   "in vec2 v_uv;\n"
   "out vec4 o;\n"
   "void main() {\n"
   "   atomicCounterIncrement(u_count);\n"
   "   atomicAdd(adds, 1u);\n"
   "   imageAtomicAdd(u_img, ivec2(0), 1u);\n"
   /* a derivative: the quad's helper invocations run */
   "   o = vec4(0.2, 0.4 + dFdx(v_uv.x), 0.6, 1.0);\n"
   "}\n";

/* The three totals, a band each: their low bytes as red and green (the
 * self-check holds the whole words; llvmpipe 22.3.6 draws the third byte
 * of these words wrong, whether by v >> 16 or through a float). */
static const char totals_fs[] =
   "#version 310 es\n"
   "precision highp float;\n"
   "layout(binding = 0) uniform atomic_uint u_count;\n"
   "layout(std430, binding = 1) readonly buffer Sum { uint adds; };\n"
   "layout(r32ui, binding = 0) readonly uniform highp uimage2D u_img;\n"
   "uniform int u_size;\n"
   "out vec4 o;\n"
   "vec4 bytes(uint v) {\n"
   "   return vec4(float(v & 255u), float((v >> 8) & 255u), 255.0, 255.0) /\n"
   "          255.0;\n"
   "}\n"
   "void main() {\n"
   "   int x = int(gl_FragCoord.x) * 3 / u_size;\n"
   "   uint v = x == 0 ? atomicCounter(u_count) : x == 1 ? adds : imageLoad(u_img, ivec2(0)).x;\n"
   "   o = bytes(v);\n"
   "}\n";

static void counter_case(int size)
{
   const int passes = 16, x0 = 1, y0 = 3, x1 = size - 2, y1 = size - 1;
   const uint32_t want = (uint32_t)(passes * (x1 - x0) * (y1 - y0));
   const GLuint counter = make_buffer(GL_ATOMIC_COUNTER_BUFFER, 4);
   glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, counter);
   const GLuint sum = make_buffer(GL_SHADER_STORAGE_BUFFER, 4);
   glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, sum);
   const GLuint img = make_image(GL_R32UI, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, 4, 0,
                                 GL_READ_WRITE);

   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glUseProgram(e2e_uv_program_es31(counter_fs));
   for (int i = 0; i < passes; i++)
      draw_pixels(x0, y0, x1, y1, 0.0f, size);
   glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                   GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
   const uint32_t got[3] = {
      read_word(GL_ATOMIC_COUNTER_BUFFER, counter, 0),
      read_word(GL_SHADER_STORAGE_BUFFER, sum, 0),
      0,
   };
   /* the image's texel, through a framebuffer (GL ES reads no texture) */
   GLuint fbo, texel[4] = { 0 };
   glGenFramebuffers(1, &fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, fbo);
   glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, img, 0);
   glReadPixels(0, 0, 1, 1, GL_RGBA_INTEGER, GL_UNSIGNED_INT, texel);
   glDeleteFramebuffers(1, &fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, main_fbo);
   uint32_t all[3];
   memcpy(all, got, sizeof(all));
   all[2] = texel[0];
   printf("stat: want=%u,counter=%u,ssbo=%u,image=%u\n", want, all[0], all[1], all[2]);
   e2e_check(all[0] == want, "the atomic counter is not the fragments drawn");
   e2e_check(all[1] == want, "the storage buffer's atomicAdd total is not the fragments drawn");
   e2e_check(all[2] == want, "the imageAtomicAdd total is not the fragments drawn");

   /* the totals as the shaders read them, in the bottom eighth */
   const GLuint p = e2e_uv_program_es31(totals_fs);
   glUseProgram(p);
   glUniform1i(glGetUniformLocation(p, "u_size"), size);
   draw_pixels(0, 0, size, size / 8, 0.0f, size);
   glDeleteTextures(1, &img);
   glDeleteBuffers(1, &counter);
   glDeleteBuffers(1, &sum);
}

static const char store_fs[] =
   "#version 310 es\n"
   "precision highp float;\n"
   "EARLY\n"
   "layout(rgba8, binding = 0) writeonly uniform highp image2D u_img;\n"
   "out vec4 o;\n"
   "void main() {\n"
   "   ivec2 p = ivec2(gl_FragCoord.xy);\n"
   "   imageStore(u_img, p, vec4(vec2(p) / 255.0, 1.0, 1.0));\n"
   "   o = vec4(1.0);\n"
   "}\n";

static const char show_fs[] =
   "#version 310 es\n"
   "precision highp float;\n"
   "layout(rgba8, binding = 0) readonly uniform highp image2D u_late;\n"
   "layout(rgba8, binding = 1) readonly uniform highp image2D u_early;\n"
   "uniform int u_size;\n"
   "out vec4 o;\n"
   "void main() {\n"
   "   ivec2 p = ivec2(gl_FragCoord.xy);\n"
   "   o = p.y >= u_size / 2 ? imageLoad(u_late, p) : imageLoad(u_early, p);\n"
   "}\n";

static GLuint store_program(bool early)
{
   char fs[sizeof(store_fs) + 64];
   const char *at = strstr(store_fs, "EARLY");
   snprintf(fs, sizeof(fs), "%.*s%s%s", (int)(at - store_fs), store_fs,
            early ? "layout(early_fragment_tests) in;" : "", at + 5);
   return e2e_uv_program_es31(fs);
}

static void image_case(int size, unsigned char *img)
{
   const GLuint late = make_image(GL_RGBA8, size, size, GL_RGBA, GL_UNSIGNED_BYTE, 4, 0,
                                  GL_WRITE_ONLY);
   const GLuint early = make_image(GL_RGBA8, size, size, GL_RGBA, GL_UNSIGNED_BYTE, 4, 1,
                                   GL_WRITE_ONLY);
   glClearColor(0, 0, 0, 1);
   glClearDepthf(1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_LESS);
   glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
   /* depth 0.25 on the left half: the stores' fragments at 0.5 fail there */
   glUseProgram(e2e_uv_program_es31("#version 310 es\nprecision highp float;\n"
                                    "out vec4 o;\nvoid main() { o = vec4(0.0); }\n"));
   draw_pixels(0, 0, size / 2, size, -0.5f, size);
   glDepthMask(GL_FALSE);
   /* no colour written, no depth written: only the stores have an effect */
   glBindImageTexture(0, late, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
   glUseProgram(store_program(false));
   draw_pixels(0, 0, size, size, 0.0f, size);
   glBindImageTexture(0, early, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
   glUseProgram(store_program(true));
   draw_pixels(0, 0, size, size, 0.0f, size);
   glDepthMask(GL_TRUE);
   glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
   glDisable(GL_DEPTH_TEST);

   glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
   glBindImageTexture(0, late, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA8);
   glBindImageTexture(1, early, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA8);
   const GLuint p = e2e_uv_program_es31(show_fs);
   glUseProgram(p);
   glUniform1i(glGetUniformLocation(p, "u_size"), size);
   draw_pixels(0, 0, size, size, 0.0f, size);

   glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, img);
   int wrong = 0;
   for (int y = 0; y < size; y++)
      for (int x = 0; x < size; x++) {
         const bool stored = y >= size / 2 || x >= size / 2;
         const unsigned char want[4] = { stored ? (unsigned char)x : 0,
                                         stored ? (unsigned char)y : 0, stored ? 255 : 0,
                                         stored ? 255 : 0 };
         wrong += memcmp(&img[4 * (y * size + x)], want, 4) != 0;
      }
   printf("stat: wrong_texels=%d\n", wrong);
   e2e_check(wrong == 0, "a stored texel differs from what its fragment stored");
   glDeleteTextures(1, &late);
   glDeleteTextures(1, &early);
}

#define BUCKETS 16

static const char hist_fs[] =
   "#version 310 es\n"
   "precision highp float;\n"
   "layout(std430, binding = 0) buffer Hist { uint count[16]; };\n"
   "out vec4 o;\n"
   "void main() {\n"
   "   uvec2 p = uvec2(gl_FragCoord.xy);\n"
   "   uint b = (p.x * 7u + p.y * 3u + p.x * p.y) % 16u;\n"
   "   atomicAdd(count[b], 1u);\n"
   "   o = vec4(float(b & 3u) / 3.0, float(b >> 2) / 3.0, 0.5, 1.0);\n"
   "}\n";

static const char bars_fs[] =
   "#version 310 es\n"
   "precision highp float;\n"
   "layout(std430, binding = 0) readonly buffer Hist { uint count[16]; };\n"
   "uniform int u_size;\n"
   "out vec4 o;\n"
   "void main() {\n"
   "   uint v = count[int(gl_FragCoord.x) * 16 / u_size];\n"
   "   o = vec4(float(v & 255u), float((v >> 8) & 255u), floor(float(v) / 65536.0), 255.0) /\n"
   "       255.0;\n"
   "}\n";

static void histogram_case(int size)
{
   static const int rects[3][4] = { { 0, 8, 40, 64 }, { 13, 8, 64, 50 }, { 5, 21, 58, 33 } };
   uint32_t want[BUCKETS] = { 0 };
   for (int r = 0; r < 3; r++)
      for (int y = rects[r][1] * size / 64; y < rects[r][3] * size / 64; y++)
         for (int x = rects[r][0] * size / 64; x < rects[r][2] * size / 64; x++)
            want[((unsigned)x * 7u + (unsigned)y * 3u + (unsigned)(x * y)) % 16u]++;
   const GLuint hist = make_buffer(GL_SHADER_STORAGE_BUFFER, sizeof(want));
   glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, hist);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glUseProgram(e2e_uv_program_es31(hist_fs));
   for (int r = 0; r < 3; r++)
      draw_pixels(rects[r][0] * size / 64, rects[r][1] * size / 64, rects[r][2] * size / 64,
                  rects[r][3] * size / 64, 0.0f, size);
   glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
   glBindBuffer(GL_SHADER_STORAGE_BUFFER, hist);
   const uint32_t *got = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, sizeof(want),
                                          GL_MAP_READ_BIT);
   int wrong = 0;
   for (int b = 0; b < BUCKETS; b++)
      wrong += !got || got[b] != want[b];
   glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
   printf("stat: wrong_buckets=%d\n", wrong);
   e2e_check(wrong == 0, "a histogram bucket differs from the CPU's count");

   const GLuint p = e2e_uv_program_es31(bars_fs);
   glUseProgram(p);
   glUniform1i(glGetUniformLocation(p, "u_size"), size);
   draw_pixels(0, 0, size, size / 8, 0.0f, size);
   glDeleteBuffers(1, &hist);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   const char *c = NULL;
   for (int i = 1; i + 1 < argc; i++)
      if (!strcmp(argv[i], "--case"))
         c = argv[i + 1];
   e2e_start(&g, &a, argc, argv, c && !strcmp(c, "counter") ? 256 : 64);
   c = e2e_opt(&a, "case", "");
   main_fbo = g.fbo;
   if (!e2e_check_es31())
      return e2e_finish(&g, &a, NULL);
   GLint blocks = 0, images = 0, counters = 0, counter_buffers = 0;
   glGetIntegerv(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS, &blocks);
   glGetIntegerv(GL_MAX_FRAGMENT_IMAGE_UNIFORMS, &images);
   glGetIntegerv(GL_MAX_FRAGMENT_ATOMIC_COUNTERS, &counters);
   glGetIntegerv(GL_MAX_FRAGMENT_ATOMIC_COUNTER_BUFFERS, &counter_buffers);
   fprintf(stderr, "fragment limits: storage blocks %d, images %d, atomic counters %d in %d "
           "buffers\n", blocks, images, counters, counter_buffers);
   e2e_check(blocks >= 2, "fewer than 2 storage blocks in fragment shaders");
   e2e_check(images >= 2, "fewer than 2 images in fragment shaders");
   e2e_check(counters >= 1 && counter_buffers >= 1, "no atomic counters in fragment shaders");
   if (e2e_errors)
      return e2e_finish(&g, &a, NULL);

   if (!strcmp(c, "counter")) {
      counter_case(a.size);
   } else if (!strcmp(c, "image")) {
      unsigned char *img = malloc((size_t)a.size * (size_t)a.size * 4);
      if (!img)
         fp_die("out of memory");
      image_case(a.size, img);
      free(img);
   } else if (!strcmp(c, "histogram")) {
      histogram_case(a.size);
   } else {
      fp_die("--case: counter, image or histogram");
   }
   return e2e_finish(&g, &a, NULL);
}
