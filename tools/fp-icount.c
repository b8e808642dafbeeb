/*
 * fp-icount: how many instructions one function executes per call, by
 * single-stepping a program (ptrace).  Under KVM this machine has no
 * hardware counters and its speed drifts by a third from hour to hour;
 * an instruction count is the same on every run, so a change to a hot
 * function can be judged before any timing (docs/datapath.md, "Speed").
 *
 *   fp-icount [--lines FILE] FUNCTION PROGRAM [ARGS...]
 *
 * FUNCTION is a symbol of PROGRAM itself (not of a shared library), as
 * nm -S lists it; the program should make few calls (fp-bench-tex
 * --quads 4000 --runs 1 --case N: a thousand four-quad calls, a few
 * seconds).  Prints the calls, the instructions inside the function's
 * bytes (not those of the functions it calls) and their mean per call.
 * --lines FILE writes "address count" per executed instruction, for
 * addr2line.  x86-64 Linux only.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <getopt.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ptrace.h>
#include <sys/user.h>
#include <sys/wait.h>
#include <unistd.h>

enum { MAX_BYTES = 1 << 16 };     /* a function's bytes: one count each */

/* The symbol's offset and size in the program, from nm -S. */
static int symbol(const char *prog, const char *fn, uint64_t *off, uint64_t *size)
{
   char cmd[4096];
   snprintf(cmd, sizeof(cmd), "nm -S '%s'", prog);
   FILE *p = popen(cmd, "r");
   if (!p)
      return -1;
   char line[1024];
   int found = -1;
   while (fgets(line, sizeof(line), p)) {
      char type, name[512];
      uint64_t a, s;
      if (sscanf(line, "%" SCNx64 " %" SCNx64 " %c %511s", &a, &s, &type, name) == 4 &&
          !strcmp(name, fn) && (type == 't' || type == 'T')) {
         *off = a;
         *size = s;
         found = 0;
      }
   }
   pclose(p);
   return found;
}

/* Where the program's first mapping (its ELF header) lies: a PIE's base. */
static uint64_t load_base(pid_t pid, const char *prog)
{
   char path[64], line[4096];
   snprintf(path, sizeof(path), "/proc/%d/maps", (int)pid);
   FILE *f = fopen(path, "r");
   if (!f)
      return 0;
   const char *base = strrchr(prog, '/') ? strrchr(prog, '/') + 1 : prog;
   uint64_t lo = 0;
   while (fgets(line, sizeof(line), f)) {
      const char *name = strrchr(line, '/');
      if (name && !strncmp(name + 1, base, strlen(base)) && name[1 + strlen(base)] == '\n') {
         lo = strtoull(line, NULL, 16);
         break;
      }
   }
   fclose(f);
   return lo;
}

int main(int argc, char **argv)
{
   static const struct option longopts[] = { { "lines", required_argument, NULL, 'l' },
                                              { NULL, 0, NULL, 0 } };
   const char *lines = NULL;
   int c;
   /* '+': the options end at FUNCTION, the rest are the program's */
   while ((c = getopt_long(argc, argv, "+", longopts, NULL)) == 'l')
      lines = optarg;
   const int a = optind;
   if (c != -1 || argc - a < 2) {
      fprintf(stderr, "usage: fp-icount [--lines FILE] FUNCTION PROGRAM [ARGS...]\n");
      return 2;
   }
   const char *fn = argv[a], *prog = argv[a + 1];
   uint64_t off, size;
   if (symbol(prog, fn, &off, &size) || size == 0 || size > MAX_BYTES) {
      fprintf(stderr, "fp-icount: no function '%s' of at most %d bytes in %s (nm -S)\n", fn,
              MAX_BYTES, prog);
      return 2;
   }
   const pid_t pid = fork();
   if (pid < 0) {
      perror("fp-icount: fork");
      return 1;
   }
   if (pid == 0) {
      ptrace(PTRACE_TRACEME, 0, NULL, NULL);
      execv(prog, &argv[a + 1]);
      perror("fp-icount: exec");
      _exit(127);
   }
   int status;
   waitpid(pid, &status, 0);             /* stopped at the exec */
   if (!WIFSTOPPED(status)) {
      fprintf(stderr, "fp-icount: %s did not start\n", prog);
      return 1;
   }
   const uint64_t start = load_base(pid, prog) + off, end = start + size;
   static uint64_t at[MAX_BYTES];
   uint64_t calls = 0, inside = 0;
   for (;;) {
      if (ptrace(PTRACE_SINGLESTEP, pid, NULL, NULL) != 0) {
         perror("fp-icount: ptrace");
         return 1;
      }
      waitpid(pid, &status, 0);
      if (WIFEXITED(status) || WIFSIGNALED(status))
         break;
      struct user_regs_struct r;
      ptrace(PTRACE_GETREGS, pid, NULL, &r);
      if (r.rip >= start && r.rip < end) {
         inside++;
         calls += r.rip == start;
         at[r.rip - start]++;
      }
   }
   if (WIFSIGNALED(status) || WEXITSTATUS(status) != 0)
      fprintf(stderr, "fp-icount: %s ended with %s %d\n", prog,
              WIFSIGNALED(status) ? "signal" : "status",
              WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
   if (lines) {
      FILE *f = fopen(lines, "w");
      if (!f) {
         fprintf(stderr, "fp-icount: cannot write %s: %s\n", lines, strerror(errno));
         return 1;
      }
      for (uint64_t i = 0; i < size; i++)
         if (at[i])
            fprintf(f, "%" PRIx64 " %" PRIu64 "\n", off + i, at[i]);
      fclose(f);
   }
   printf("%s: %" PRIu64 " calls, %" PRIu64 " instructions, %.1f a call\n", fn, calls, inside,
          calls ? (double)inside / (double)calls : 0.0);
   return 0;
}
