/* GL_AMD_performance_monitor by counter name (fp_perfmon.h). */
#include "fp_perfmon.h"
#include "fp_gl.h"

#include <EGL/egl.h>
#include <GLES2/gl2ext.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define FP_PERFMON_MAX 16

struct fp_perfmon {
   GLuint monitor;
   unsigned n;
   GLuint group[FP_PERFMON_MAX], counter[FP_PERFMON_MAX];
   GLenum type[FP_PERFMON_MAX];
   PFNGLGETPERFMONITORGROUPSAMDPROC get_groups;
   PFNGLGETPERFMONITORCOUNTERSAMDPROC get_counters;
   PFNGLGETPERFMONITORCOUNTERSTRINGAMDPROC get_counter_string;
   PFNGLGETPERFMONITORCOUNTERINFOAMDPROC get_counter_info;
   PFNGLGENPERFMONITORSAMDPROC gen;
   PFNGLDELETEPERFMONITORSAMDPROC del;
   PFNGLSELECTPERFMONITORCOUNTERSAMDPROC select;
   PFNGLBEGINPERFMONITORAMDPROC begin;
   PFNGLENDPERFMONITORAMDPROC end;
   PFNGLGETPERFMONITORCOUNTERDATAAMDPROC get_data;
};

/* Finds the counter `name`: its group and index. */
static bool find_counter(struct fp_perfmon *m, const char *name, GLuint *group, GLuint *counter)
{
   GLint ngroups = 0;
   m->get_groups(&ngroups, 0, NULL);
   if (ngroups <= 0)
      return false;
   GLuint *groups = calloc((size_t)ngroups, sizeof(GLuint));
   if (!groups)
      return false;
   m->get_groups(NULL, ngroups, groups);
   bool found = false;
   for (GLint g = 0; g < ngroups && !found; g++) {
      GLint num = 0, max_active = 0;
      m->get_counters(groups[g], &num, &max_active, 0, NULL);
      if (num <= 0)
         continue;
      GLuint *counters = calloc((size_t)num, sizeof(GLuint));
      if (!counters)
         break;
      m->get_counters(groups[g], NULL, NULL, num, counters);
      for (GLint c = 0; c < num && !found; c++) {
         char buf[128];
         GLsizei len = 0;
         m->get_counter_string(groups[g], counters[c], sizeof(buf), &len, buf);
         if (len > 0 && len < (GLsizei)sizeof(buf) && !strcmp(buf, name)) {
            *group = groups[g];
            *counter = counters[c];
            found = true;
         }
      }
      free(counters);
   }
   free(groups);
   return found;
}

struct fp_perfmon *fp_perfmon_open(const char *const *names, unsigned n, const char **why)
{
   const char *ext = (const char *)glGetString(GL_EXTENSIONS);
   if (!ext || !strstr(ext, "GL_AMD_performance_monitor")) {
      *why = "no GL_AMD_performance_monitor";
      return NULL;
   }
   if (n > FP_PERFMON_MAX) {
      *why = "too many counters";
      return NULL;
   }
   struct fp_perfmon *m = calloc(1, sizeof(*m));
   if (!m) {
      *why = "out of memory";
      return NULL;
   }
#define PROC(field, name) m->field = (__typeof__(m->field))eglGetProcAddress(name)
   PROC(get_groups, "glGetPerfMonitorGroupsAMD");
   PROC(get_counters, "glGetPerfMonitorCountersAMD");
   PROC(get_counter_string, "glGetPerfMonitorCounterStringAMD");
   PROC(get_counter_info, "glGetPerfMonitorCounterInfoAMD");
   PROC(gen, "glGenPerfMonitorsAMD");
   PROC(del, "glDeletePerfMonitorsAMD");
   PROC(select, "glSelectPerfMonitorCountersAMD");
   PROC(begin, "glBeginPerfMonitorAMD");
   PROC(end, "glEndPerfMonitorAMD");
   PROC(get_data, "glGetPerfMonitorCounterDataAMD");
#undef PROC
   if (!m->get_groups || !m->get_counters || !m->get_counter_string || !m->get_counter_info ||
       !m->gen || !m->del || !m->select || !m->begin || !m->end || !m->get_data) {
      free(m);
      *why = "GL_AMD_performance_monitor's functions are missing";
      return NULL;
   }
   m->n = n;
   m->gen(1, &m->monitor);
   for (unsigned i = 0; i < n; i++) {
      if (!find_counter(m, names[i], &m->group[i], &m->counter[i])) {
         fp_perfmon_close(m);
         *why = "a counter is missing";
         return NULL;
      }
      m->get_counter_info(m->group[i], m->counter[i], GL_COUNTER_TYPE_AMD, &m->type[i]);
      m->select(m->monitor, GL_TRUE, m->group[i], 1, &m->counter[i]);
   }
   fp_gl_check("selecting performance counters");
   return m;
}

void fp_perfmon_begin(struct fp_perfmon *m)
{
   m->begin(m->monitor);
}

bool fp_perfmon_end(struct fp_perfmon *m, double *values)
{
   m->end(m->monitor);
   glFinish();
   GLuint avail = 0, size = 0;
   m->get_data(m->monitor, GL_PERFMON_RESULT_AVAILABLE_AMD, sizeof(avail), &avail, NULL);
   m->get_data(m->monitor, GL_PERFMON_RESULT_SIZE_AMD, sizeof(size), &size, NULL);
   if (!avail || !size)
      return false;
   GLuint *data = calloc(size / sizeof(GLuint) + 1, sizeof(GLuint));
   if (!data)
      return false;
   GLsizei written = 0;
   m->get_data(m->monitor, GL_PERFMON_RESULT_AMD, (GLsizei)size, data, &written);
   /* records of (group, counter, value): the value 64 bits for
    * GL_UNSIGNED_INT64_AMD, 32 otherwise */
   unsigned found = 0;
   for (GLsizei w = 0; w + 2 < written / (GLsizei)sizeof(GLuint);) {
      GLuint g = data[w], c = data[w + 1];
      w += 2;
      unsigned i = 0;
      while (i < m->n && !(m->group[i] == g && m->counter[i] == c))
         i++;
      GLenum type = i < m->n ? m->type[i] : GL_UNSIGNED_INT;
      if (type == GL_UNSIGNED_INT64_AMD) {
         uint64_t v;
         memcpy(&v, &data[w], sizeof(v));
         w += 2;
         if (i < m->n)
            values[i] = (double)v, found++;
      } else {
         if (type == GL_FLOAT || type == GL_PERCENTAGE_AMD) {
            float f;
            memcpy(&f, &data[w], sizeof(f));
            if (i < m->n)
               values[i] = f, found++;
         } else if (i < m->n) {
            values[i] = data[w], found++;
         }
         w += 1;
      }
   }
   free(data);
   fp_gl_check("reading performance counters");
   return found == m->n;
}

void fp_perfmon_close(struct fp_perfmon *m)
{
   if (!m)
      return;
   m->del(1, &m->monitor);
   free(m);
}
