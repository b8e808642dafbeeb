/*
 * The interpolators of Z and colour (FIXPIPE_INTERP, rast_set_interp) on
 * random triangles in both profiles, against the exact plane through the
 * fixed-point vertices (barycentrics in double, exact to far below a
 * register's last bit at these sizes):
 *   - coverage is the scan converter's in every mode: the same pixels,
 *     triangle by triangle, as scanline;
 *   - barycentric (seed 001), covered pixels: |err| <= 1/2 + Σ|A_i|·2^-(W+1)
 *     (each weight rounded once, the sum once);
 *   - vector (seed 002), covered pixels: |err| <= 1/2 + (|ΔA1| + |ΔA2|)·2^-W
 *     (recip(det) rounded once, each of a, b within one unit of 2^-W since
 *     |n_a|, |n_b| <= |det| inside, the sum once);
 *   - the two methods round differently: some pixel must differ;
 *   - RAST_INTERP_MEASURE's mean and largest error are the ones this test
 *     computes, and it measures every covered pixel;
 *   - the counted operations: seed 002 divides once per triangle, seed 001
 *     three times per pixel computed.
 */
#include <math.h>
#include <string.h>
#include "tutil.h"
#include "fixed/fx.h"

#define W_TARGET 256
#define N_TRIS 4000

static struct tctx t;
static int64_t X[3], Y[3];
static double Zr[3], Cr[3][4];
static unsigned mode;
static bool colour_regs;           /* the colour is a register (seed); wide: perspective */
static double worst[3][2], bound[2], sum_err[2];
static uint64_t n_err[2];
static double tot_sum[3][2], tot_n[3][2];      /* the run's, per mode and class */
static uint64_t cov_sum, cov_n;
static int64_t first_z[W_TARGET * W_TARGET];   /* this triangle's Z in the previous mode */
static bool seen[W_TARGET * W_TARGET];
static uint64_t differ, compared;

static void bary(double px, double py, double l[3])
{
   double D = (double)(X[1] - X[0]) * (double)(Y[2] - Y[0]) -
              (double)(X[2] - X[0]) * (double)(Y[1] - Y[0]);
   l[1] = ((px - X[0]) * (double)(Y[2] - Y[0]) - (double)(X[2] - X[0]) * (py - Y[0])) / D;
   l[2] = ((double)(X[1] - X[0]) * (py - Y[0]) - (px - X[0]) * (double)(Y[1] - Y[0])) / D;
   l[0] = 1 - l[1] - l[2];
}

static void hook(struct tctx *tc, const struct rast_quad *q)
{
   const double S = (double)fx_one(tc->prof->xy), H = S / 2;
   for (unsigned i = 0; i < 4; i++) {
      if (!(q->mask & (1u << i)))
         continue;
      const int x = q->x + (int)(i & 1), y = q->y + (int)(i >> 1);
      double l[3];
      bary(x * S + H, y * S + H, l);
      cov_sum += (uint64_t)(y * W_TARGET + x) * 2654435761u;
      cov_n++;
      const double ez = fabs((double)q->z[i] - (l[0] * Zr[0] + l[1] * Zr[1] + l[2] * Zr[2]));
      if (ez > worst[mode][0]) worst[mode][0] = ez;
      sum_err[0] += ez;
      n_err[0]++;
      if (mode != RAST_INTERP_SCANLINE)
         CHECK(ez <= bound[0], "%s: Z at (%d,%d) off by %.3f, bound %.3f",
               rast_interp_name(mode), x, y, ez, bound[0]);
      const size_t p = (size_t)y * W_TARGET + (size_t)x;
      if (mode == RAST_INTERP_BARYCENTRIC) {
         first_z[p] = q->z[i];
         seen[p] = true;
      } else if (mode == RAST_INTERP_VECTOR && seen[p]) {
         differ += first_z[p] != q->z[i];
         compared++;
      }
      for (unsigned c = 0; c < 4 && colour_regs; c++) {
         /* the register, back from the float the shader reads (exact: the
          * float keeps 24 bits of a 21-bit register scaled) */
         const double got = nearbyint((double)q->in[1][c][i] * 255.0 * 4096.0);
         const double ec = fabs(got - (l[0] * Cr[0][c] + l[1] * Cr[1][c] + l[2] * Cr[2][c]));
         if (ec > worst[mode][1]) worst[mode][1] = ec;
         sum_err[1] += ec;
         n_err[1]++;
         if (mode != RAST_INTERP_SCANLINE)
            CHECK(ec <= bound[1] + 1e-3, "%s: colour %u at (%d,%d) off by %.3f, bound %.3f",
                  rast_interp_name(mode), c, x, y, ec, bound[1]);
      }
   }
}

static double maxabs3(const double v[3])
{
   double m = 0;
   for (unsigned i = 0; i < 3; i++)
      m += fabs(v[i]);
   return m;
}

static void run(const char *profile)
{
   t_init(&t, profile, W_TARGET, W_TARGET);
   t.hook = hook;
   struct rast_vertex_layout vl;
   memset(&vl, 0, sizeof(vl));
   vl.vertex_size = 2;
   vl.pos_slot = 0;
   vl.num_varyings = 2;
   vl.varying[0] = (struct rast_varying){ .slot = 0, .interp = RAST_INTERP_LINEAR, .usage_mask = 0x1 };   /* unused */
   vl.varying[1] = (struct rast_varying){ .slot = 1, .interp = RAST_INTERP_COLOR, .usage_mask = 0xf };
   rast_set_vertex_layout(t.rc, &vl);
   const bool wide = !strcmp(profile, "wide");
   colour_regs = !wide;
   const double zfull = (double)((INT64_C(1) << t.prof->z_bits) - 1);
   const double W2 = ldexp(1.0, -(int)t.prof->weight.frac_bits);
   memset(worst, 0, sizeof(worst));
   memset(tot_sum, 0, sizeof(tot_sum));
   memset(tot_n, 0, sizeof(tot_n));
   differ = compared = 0;
   uint64_t tris = 0, divs_vec = 0, pix = 0;

   for (unsigned n = 0; n < N_TRIS; n++) {
      float v[3][2][4];
      const double size = n % 4 == 0 ? 250.0 : n % 4 == 1 ? 60.0 : n % 4 == 2 ? 12.0 : 3.0;
      const double cx = 3 + t_rand() * (W_TARGET - 6), cy = 3 + t_rand() * (W_TARGET - 6);
      struct fx_sat s = { 0, 0 };
      for (unsigned k = 0; k < 3; k++) {
         double x = cx + (t_rand() - 0.5) * size, y = cy + (t_rand() - 0.5) * size;
         x = x < 0 ? 0 : x > W_TARGET ? W_TARGET : x;
         y = y < 0 ? 0 : y > W_TARGET ? W_TARGET : y;
         v[k][0][0] = (float)x;
         v[k][0][1] = (float)y;
         v[k][0][2] = (float)t_rand();
         v[k][0][3] = 1.0f;
         for (unsigned c = 0; c < 4; c++)
            v[k][1][c] = (float)t_rand();
         X[k] = fx_from_double(t.prof->xy, v[k][0][0], &s);
         Y[k] = fx_from_double(t.prof->xy, v[k][0][1], &s);
         Zr[k] = (double)fx_from_double(t.prof->z, v[k][0][2] * zfull, &s);
         for (unsigned c = 0; c < 4; c++)
            Cr[k][c] = (double)fx_from_double(t.prof->color, v[k][1][c] * 255.0, &s);
      }
      const double zv[3] = { Zr[0], Zr[1], Zr[2] };
      const double dz[3] = { 0, Zr[1] - Zr[0], Zr[2] - Zr[0] };
      double cb = 0, cv = 0;
      for (unsigned c = 0; c < 4; c++) {
         const double cc[3] = { Cr[0][c], Cr[1][c], Cr[2][c] };
         const double dc[3] = { 0, Cr[1][c] - Cr[0][c], Cr[2][c] - Cr[0][c] };
         cb = fmax(cb, maxabs3(cc));
         cv = fmax(cv, maxabs3(dc));
      }
      uint64_t sum[3] = { 0, 0, 0 }, cnt[3] = { 0, 0, 0 };
      for (mode = 0; mode < 3; mode++) {
         bound[0] = 0.5 + (mode == RAST_INTERP_BARYCENTRIC ? maxabs3(zv) * W2 / 2 : maxabs3(dz) * W2);
         bound[1] = 0.5 + (mode == RAST_INTERP_BARYCENTRIC ? cb * W2 / 2 : cv * W2);
         rast_set_interp(t.rc, mode | RAST_INTERP_MEASURE);
         rast_reset_stats(t.rc);
         sum_err[0] = sum_err[1] = 0;
         n_err[0] = n_err[1] = 0;
         cov_sum = cov_n = 0;
         const double before[2] = { worst[mode][0], worst[mode][1] };
         worst[mode][0] = worst[mode][1] = 0;
         t_begin(&t);
         rast_triangle(t.rc, T_V(v[0]), T_V(v[1]), T_V(v[2]));
         rast_flush(t.rc);
         sum[mode] = cov_sum;
         cnt[mode] = cov_n;
         const struct rast_stats *st = rast_get_stats(t.rc);
         /* the model's own measure is this test's */
         {
            CHECK(st->interp_err_n[0] == n_err[0] && st->interp_err_n[1] == n_err[1],
                  "%s: measured %llu/%llu values, %llu/%llu covered", rast_interp_name(mode),
                  (unsigned long long)st->interp_err_n[0], (unsigned long long)st->interp_err_n[1],
                  (unsigned long long)n_err[0], (unsigned long long)n_err[1]);
            for (unsigned c = 0; c < 2; c++) {
               CHECK(fabs((double)st->interp_err_max[c] / 65536.0 - worst[mode][c]) < 1e-3,
                     "%s: largest error %s %.5f, the model says %.5f", rast_interp_name(mode),
                     c ? "colour" : "Z", worst[mode][c], (double)st->interp_err_max[c] / 65536.0);
               CHECK(fabs((double)st->interp_err_sum[c] / 65536.0 - sum_err[c]) <
                        1e-3 * (double)(n_err[c] + 1),
                     "%s: error sum %s %.3f, the model says %.3f", rast_interp_name(mode),
                     c ? "colour" : "Z", sum_err[c], (double)st->interp_err_sum[c] / 65536.0);
            }
         }
         if (mode == RAST_INTERP_VECTOR) {
            divs_vec += st->interp_div;
            tris += st->triangles;
         }
         if (mode == RAST_INTERP_BARYCENTRIC) {
            CHECK(st->interp_div >= 3 * st->pixels_covered && st->interp_div % 3 == 0,
                  "barycentric: %llu divisions for %llu pixels", (unsigned long long)st->interp_div,
                  (unsigned long long)st->pixels_covered);
            pix += st->pixels_covered;
         }
         for (unsigned c = 0; c < 2; c++) {
            tot_sum[mode][c] += sum_err[c];
            tot_n[mode][c] += (double)n_err[c];
         }
         worst[mode][0] = fmax(worst[mode][0], before[0]);
         worst[mode][1] = fmax(worst[mode][1], before[1]);
      }
      for (unsigned m = 1; m < 3; m++)
         CHECK(sum[m] == sum[0] && cnt[m] == cnt[0],
               "triangle %u: %s covers %llu pixels, scanline %llu", n, rast_interp_name(m),
               (unsigned long long)cnt[m], (unsigned long long)cnt[0]);
      for (size_t p = 0; p < (size_t)W_TARGET * W_TARGET; p++)
         seen[p] = false;
   }
   CHECK(divs_vec == tris && tris > N_TRIS / 2, "vector: %llu divisions for %llu triangles",
         (unsigned long long)divs_vec, (unsigned long long)tris);
   CHECK(compared > 0 && differ > 0, "barycentric and vector agree on all %llu pixels: "
         "nothing tells the methods apart", (unsigned long long)compared);
   printf("%s: %llu pixels; %llu of %llu differ between 001 and 002; error against exact "
          "arithmetic, mean / largest, in the register's last bits:\n", profile,
          (unsigned long long)pix, (unsigned long long)differ, (unsigned long long)compared);
   for (unsigned m = 0; m < 3; m++)
      printf("  %-12s Z %10.3f / %14.3f   colour %10.3f / %12.3f\n", rast_interp_name(m),
             tot_n[m][0] ? tot_sum[m][0] / tot_n[m][0] : 0.0, worst[m][0],
             tot_n[m][1] ? tot_sum[m][1] / tot_n[m][1] : 0.0, worst[m][1]);
   t_fini(&t);
}

int main(void)
{
   t_seed(0x1d0e5eedull);
   run("seed");
   run("wide");
   return t_summary("interp_modes");
}
