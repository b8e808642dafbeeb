/*
 * A video player's GPU upscaler in small: the shape of mpv's polar EWA
 * scaler with debanding, in GL ES 3.1, every texel it reads through
 * textureGatherOffset.
 *
 *   source   a --src x --src RGBA8 "video frame" made on the CPU: smooth
 *            gradients quantized to 6 bits (the bands debanding is for),
 *            discs with hard edges, fine stripes, a little noise; frame f
 *            moves its content by f/3 of a texel
 *   deband   one pass at the source's size: four taps on a ring of random
 *            radius and one of 16 directions (an integer hash of the pixel
 *            and the frame, so every driver draws the same rings) through the bilinear
 *            filter, averaged; where the average is within a threshold of
 *            the texel, it replaces it; then grain of +-1/255
 *   EWA      one pass at the output's size: the 6x6 texels around the
 *            output pixel's position, as nine 2x2 blocks, each gathered per
 *            channel (27 textureGatherOffset calls a pixel), weighed by a
 *            radial (polar) Catmull-Rom kernel of radius 2 over their distance,
 *            normalized, then clamped to the nearest four texels' range
 *            (anti-ringing)
 *
 * Writes -o (the last frame, --size x --size) and prints
 *   stat: frames=N src=S ms_per_frame=T warmup_ms=U
 * with T the mean over the frames after the first W (--warmup W, default
 * 1; glFinish after each), the steady state a player runs in, and U the
 * time of those first W frames: shader compilation, and the frames a
 * driver that tiers its shaders still interprets.  --frames N (default 2),
 * --src S (default --size / 4).  Errors (a GL error, no ES 3.1) fail the
 * program on any driver.
 */
#define _POSIX_C_SOURCE 200809L
#include "e2e_common.h"

#include <GLES3/gl31.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char *fs_deband =
   "#version 310 es\n"
   "precision highp float;\n"
   "precision highp int;\n"
   "uniform highp sampler2D u_src;\n"
   "uniform vec2 u_size;\n"
   "uniform uint u_frame;\n"
   "in vec2 v_uv;\n"
   "out vec4 o_color;\n"
   "uint hash(uint x) {\n"
   "   x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;\n"
   "   return x;\n"
   "}\n"
   "float rand(inout uint h) { h = hash(h); return float(h >> 8) / 16777216.0; }\n"
   "void main() {\n"
   "   uvec2 p = uvec2(gl_FragCoord.xy);\n"
   "   uint h = hash(p.x + p.y * 4099u + u_frame * 16785407u);\n"
   "   vec4 c = texture(u_src, v_uv);\n"
   "   const float range = 4.0, threshold = 10.0 / 255.0;\n"
   "   /* one of 16 directions on the unit circle, by table: the shader\n"
   "    * ALU is not the model's, and sin() and cos() differ between\n"
   "    * tgsi_exec and LLVM, which the model must not see */\n"
   "   const vec2 dir[16] = vec2[16](\n"
   "      vec2(1.0, 0.0), vec2(0.92388, 0.38268), vec2(0.70711, 0.70711), vec2(0.38268, 0.92388),\n"
   "      vec2(0.0, 1.0), vec2(-0.38268, 0.92388), vec2(-0.70711, 0.70711), vec2(-0.92388, 0.38268),\n"
   "      vec2(-1.0, 0.0), vec2(-0.92388, -0.38268), vec2(-0.70711, -0.70711), vec2(-0.38268, -0.92388),\n"
   "      vec2(0.0, -1.0), vec2(0.38268, -0.92388), vec2(0.70711, -0.70711), vec2(0.92388, -0.38268));\n"
   "   float r = range * rand(h);\n"
   "   h = hash(h);\n"
   "   vec2 o = r * dir[h >> 28] / u_size;\n"
   "   vec4 avg = 0.25 * (texture(u_src, v_uv + o) + texture(u_src, v_uv - o)\n"
   "                    + texture(u_src, v_uv + vec2(-o.y, o.x))\n"
   "                    + texture(u_src, v_uv + vec2(o.y, -o.x)));\n"
   "   vec4 d = abs(avg - c);\n"
   "   if (max(max(d.r, d.g), d.b) < threshold) c = avg;\n"
   "   c.rgb += (rand(h) - 0.5) * (2.0 / 255.0);\n"
   "   o_color = vec4(c.rgb, 1.0);\n"
   "}\n";

/* Weights of a radial Catmull-Rom kernel of radius 2 over the distance d
 * (polynomials: the same bits compiled and interpreted); its negative lobe
 * rings at edges, which the clamp to the nearest four texels takes out. */
static const char *fs_ewa =
   "#version 310 es\n"
   "precision highp float;\n"
   "precision highp int;\n"
   "uniform highp sampler2D u_src;\n"
   "uniform vec2 u_size;\n"
   "in vec2 v_uv;\n"
   "out vec4 o_color;\n"
   "float weight(float d) {\n"
   "   if (d < 1.0) return (1.5 * d - 2.5) * d * d + 1.0;\n"
   "   if (d < 2.0) return ((-0.5 * d + 2.5) * d - 4.0) * d + 2.0;\n"
   "   return 0.0;\n"
   "}\n"
   "vec2 f;\n"
   "vec3 sum = vec3(0.0), lo = vec3(1.0), hi = vec3(0.0);\n"
   "float wsum = 0.0;\n"
   "/* one 2x2 block, gathered per channel, in gather's order: (0,1), (1,1),\n"
   " * (1,0), (0,0) of the block */\n"
   "void block(vec4 r, vec4 g, vec4 b, vec2 off, bool centre) {\n"
   "   const vec2 at[4] = vec2[4](vec2(0.0, 1.0), vec2(1.0, 1.0), vec2(1.0, 0.0), vec2(0.0, 0.0));\n"
   "   for (int k = 0; k < 4; k++) {\n"
   "      float w = weight(length(off + at[k] - f));\n"
   "      vec3 c = vec3(r[k], g[k], b[k]);\n"
   "      sum += w * c;\n"
   "      wsum += w;\n"
   "      if (centre) { lo = min(lo, c); hi = max(hi, c); }\n"
   "   }\n"
   "}\n"
   "/* the offset of textureGatherOffset is a constant expression in ES 3.1 */\n"
   "#define BLOCK(X, Y) block(textureGatherOffset(u_src, corner, ivec2(X, Y), 0), \\\n"
   "                         textureGatherOffset(u_src, corner, ivec2(X, Y), 1), \\\n"
   "                         textureGatherOffset(u_src, corner, ivec2(X, Y), 2), \\\n"
   "                         vec2(X, Y), X == 0 && Y == 0)\n"
   "void main() {\n"
   "   vec2 pos = v_uv * u_size - 0.5;\n"
   "   vec2 base = floor(pos);\n"
   "   f = pos - base;\n"
   "   /* the corner between texels base and base + 1: each gather there\n"
   "    * returns the 2x2 block from base + offset */\n"
   "   vec2 corner = (base + 1.0) / u_size;\n"
   "   BLOCK(-2, -2); BLOCK(0, -2); BLOCK(2, -2);\n"
   "   BLOCK(-2, 0);  BLOCK(0, 0);  BLOCK(2, 0);\n"
   "   BLOCK(-2, 2);  BLOCK(0, 2);  BLOCK(2, 2);\n"
   "   o_color = vec4(clamp(sum / wsum, lo, hi), 1.0);\n"
   "}\n";

static unsigned char to8(double v)
{
   return (unsigned char)(v <= 0 ? 0 : v >= 1 ? 255 : (int)(v * 255.0 + 0.5));
}

/* Frame f of the source: its content moved by f/3 texel to the right. */
static void make_frame(unsigned char *px, int n, int f, uint32_t seed)
{
   uint32_t rng = seed;
   for (int y = 0; y < n; y++) {
      for (int x = 0; x < n; x++) {
         const double u = (x - f / 3.0) / n, v = (double)y / n;
         /* a sky: slow gradients, quantized to 6 bits */
         double r = 0.25 + 0.35 * v, g = 0.35 + 0.25 * u * v, b = 0.55 + 0.3 * (1 - v);
         r = (int)(r * 63) / 63.0;
         g = (int)(g * 63) / 63.0;
         b = (int)(b * 63) / 63.0;
         /* two discs with hard edges */
         const double d0 = (u - 0.3) * (u - 0.3) + (v - 0.35) * (v - 0.35);
         const double d1 = (u - 0.7) * (u - 0.7) + (v - 0.65) * (v - 0.65);
         if (d0 < 0.02) { r = 0.95; g = 0.85; b = 0.2; }
         if (d1 < 0.03) { r = 0.1; g = 0.15; b = 0.12; }
         /* fine stripes in the lower third */
         if (v < 0.3 && ((int)((u + 2) * n) / 2) % 2)
            { r *= 0.6; g *= 0.6; b *= 0.6; }
         const double grain = ((e2e_rand(&rng) & 7) - 3.5) / 255.0;
         unsigned char *p = px + 4 * ((size_t)y * n + x);
         p[0] = to8(r + grain);
         p[1] = to8(g + grain);
         p[2] = to8(b + grain);
         p[3] = 255;
      }
   }
}

static GLuint make_texture(int n, GLenum filter)
{
   GLuint t;
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, n, n);
   e2e_tex_params(GL_TEXTURE_2D, filter, filter, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
   return t;
}

static double now_ms(void)
{
   struct timespec ts;
   clock_gettime(CLOCK_MONOTONIC, &ts);
   return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 128);
   const int frames = atoi(e2e_opt(&a, "frames", "2"));
   const int warmup = atoi(e2e_opt(&a, "warmup", "1"));
   const int n = atoi(e2e_opt(&a, "src", "0")) > 0 ? atoi(e2e_opt(&a, "src", "0")) : a.size / 4;
   if (frames < 1 || n < 4 || warmup < 1 || warmup > frames)
      fp_die("--frames must be at least 1, --warmup from 1 to --frames, --src at least 4");
   struct fp_gl g;
   e2e_begin(&g, &a);
   if (!e2e_check_es31()) {
      e2e_end(&g, &a, NULL);
      return 1;
   }

   unsigned char *px = malloc((size_t)n * n * 4);
   if (!px)
      fp_die("out of memory");
   GLuint src = make_texture(n, GL_LINEAR), debanded = make_texture(n, GL_NEAREST);
   GLuint fbo;
   glGenFramebuffers(1, &fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, fbo);
   glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, debanded, 0);
   e2e_check(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE,
             "the debanding target is not complete");
   const GLuint deband = e2e_uv_program_es31(fs_deband), ewa = e2e_uv_program_es31(fs_ewa);
   glUseProgram(deband);
   glUniform1i(glGetUniformLocation(deband, "u_src"), 0);
   glUniform2f(glGetUniformLocation(deband, "u_size"), (float)n, (float)n);
   glUseProgram(ewa);
   glUniform1i(glGetUniformLocation(ewa, "u_src"), 0);
   glUniform2f(glGetUniformLocation(ewa, "u_size"), (float)n, (float)n);

   const double start = now_ms();
   double t0 = 0;
   for (int f = 0; f < frames; f++) {
      if (f == warmup)
         t0 = now_ms();
      make_frame(px, n, f, 0x5ca1e000u + (uint32_t)f);
      glBindTexture(GL_TEXTURE_2D, src);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n, n, GL_RGBA, GL_UNSIGNED_BYTE, px);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo);
      glViewport(0, 0, n, n);
      glUseProgram(deband);
      glUniform1ui(glGetUniformLocation(deband, "u_frame"), (GLuint)f);
      e2e_draw_rect(-1, -1, 1, 1, 0, 0, 1, 1);
      glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
      glViewport(0, 0, a.size, a.size);
      glBindTexture(GL_TEXTURE_2D, debanded);
      glUseProgram(ewa);
      e2e_draw_rect(-1, -1, 1, 1, 0, 0, 1, 1);
      glFinish();
   }
   const double end = now_ms();
   const double ms = frames > warmup ? (end - t0) / (frames - warmup) : 0;
   printf("stat: frames=%d src=%d ms_per_frame=%.1f warmup_ms=%.1f\n", frames, n, ms,
          (frames > warmup ? t0 : end) - start);
   glDeleteFramebuffers(1, &fbo);
   glDeleteTextures(1, &src);
   glDeleteTextures(1, &debanded);
   free(px);
   glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
   return e2e_finish(&g, &a, NULL);
}
