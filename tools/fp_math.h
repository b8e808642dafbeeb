/* The little 4x4 matrix algebra the demo scenes need (column-major, as GL). */
#ifndef FP_MATH_H
#define FP_MATH_H

#include <math.h>
#include <string.h>

#define FP_PI 3.14159265358979f

typedef struct { float m[16]; } fp_mat4;

static inline fp_mat4 fp_mat4_identity(void)
{
   fp_mat4 r;
   memset(&r, 0, sizeof(r));
   r.m[0] = r.m[5] = r.m[10] = r.m[15] = 1.0f;
   return r;
}

static inline fp_mat4 fp_mat4_mul(fp_mat4 a, fp_mat4 b)
{
   fp_mat4 r;
   for (int c = 0; c < 4; c++)
      for (int row = 0; row < 4; row++) {
         float s = 0.0f;
         for (int k = 0; k < 4; k++)
            s += a.m[k * 4 + row] * b.m[c * 4 + k];
         r.m[c * 4 + row] = s;
      }
   return r;
}

static inline fp_mat4 fp_mat4_perspective(float fovy_deg, float aspect, float n, float f)
{
   float t = 1.0f / tanf(fovy_deg * FP_PI / 360.0f);
   fp_mat4 r;
   memset(&r, 0, sizeof(r));
   r.m[0] = t / aspect;
   r.m[5] = t;
   r.m[10] = (f + n) / (n - f);
   r.m[11] = -1.0f;
   r.m[14] = 2.0f * f * n / (n - f);
   return r;
}

static inline fp_mat4 fp_mat4_translate(float x, float y, float z)
{
   fp_mat4 r = fp_mat4_identity();
   r.m[12] = x;
   r.m[13] = y;
   r.m[14] = z;
   return r;
}

/* Rotation about a unit axis (x, y, z) by deg degrees. */
static inline fp_mat4 fp_mat4_rotate(float deg, float x, float y, float z)
{
   float a = deg * FP_PI / 180.0f, c = cosf(a), s = sinf(a), t = 1.0f - c;
   fp_mat4 r = fp_mat4_identity();
   r.m[0] = t * x * x + c;      r.m[4] = t * x * y - s * z;  r.m[8] = t * x * z + s * y;
   r.m[1] = t * x * y + s * z;  r.m[5] = t * y * y + c;      r.m[9] = t * y * z - s * x;
   r.m[2] = t * x * z - s * y;  r.m[6] = t * y * z + s * x;  r.m[10] = t * z * z + c;
   return r;
}

#endif
