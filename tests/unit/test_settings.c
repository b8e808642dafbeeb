/*
 * The FIXPIPE_* settings' KEY=VALUE lists (src/rast/host/settings.h) and
 * the cycle model's parameters read through them (FIXPIPE_CYCLES,
 * docs/cycles.md): a well-formed list reaches its unit pair by pair, in
 * order; a malformed one is refused with the accepted keys named, before
 * any of it takes effect.  The precision profiles' settings, the third
 * list, are test_precision's.
 */
#include <string.h>
#include "tutil.h"
#include "rast/host/settings.h"
#include "rast/instruments/cycles.h"

struct seen {
   char pairs[256];
   int calls;
   const char *refuse; /* a key to refuse */
};

static bool note(void *ctx, const char *key, const char *value, char *err, size_t errlen)
{
   struct seen *s = ctx;
   s->calls++;
   if (s->refuse && !strcmp(key, s->refuse)) {
      snprintf(err, errlen, "%s refused", key);
      return false;
   }
   const size_t n = strlen(s->pairs);
   snprintf(s->pairs + n, sizeof(s->pairs) - n, "[%s|%s]", key, value);
   return true;
}

static void list_ok(const char *list, const char *pairs)
{
   struct seen s = { "", 0, NULL };
   char err[256] = "";
   CHECK(rast_settings_each(list, "a, b", note, &s, err, sizeof(err)), "'%s' refused: %s", list,
         err);
   CHECK(!strcmp(s.pairs, pairs), "'%s' gave %s, not %s", list, s.pairs, pairs);
}

static void list_bad(const char *list, const char *refuse, int calls, const char *must_say)
{
   struct seen s = { "", 0, refuse };
   char err[256] = "";
   CHECK(!rast_settings_each(list, "a, b", note, &s, err, sizeof(err)), "'%s' accepted", list);
   CHECK(strstr(err, must_say) != NULL, "'%s': message '%s' does not say '%s'", list, err,
         must_say);
   CHECK(s.calls == calls, "'%s': %d pairs reached the unit, not %d", list, s.calls, calls);
}

static void lists(void)
{
   list_ok("a=1", "[a|1]");
   list_ok("a=1,b=x=y,a=2", "[a|1][b|x=y][a|2]");
   list_bad("", NULL, 0, "empty item");
   list_bad("a=1,,b=2", NULL, 1, "empty item in 'a=1,,b=2'");
   list_bad("a=1,", NULL, 1, "empty item");
   list_bad(",a=1", NULL, 0, "empty item");
   list_bad("a", NULL, 0, "'a' is not KEY=VALUE (accepted: a, b)");
   list_bad("=1", NULL, 0, "is not KEY=VALUE");
   list_bad("a=", NULL, 0, "is not KEY=VALUE");
   list_bad("a=1,b=2,c=3", "b", 2, "b refused");
   char longer[RAST_SETTINGS_MAX + 2];
   memset(longer, 'a', sizeof(longer) - 1);
   longer[1] = '=';
   longer[sizeof(longer) - 1] = '\0';
   list_bad(longer, NULL, 0, "longer than");
   longer[sizeof(longer) - 2] = '\0';
   struct seen s = { "", 0, NULL };
   char err[64];
   CHECK(rast_settings_each(longer, "a", note, &s, err, sizeof(err)) && s.calls == 1,
         "a list of exactly %d characters is refused", RAST_SETTINGS_MAX);
}

/* field by field: the structure has padding that assignment need not copy */
static bool same_params(const struct rast_cycle_params *a, const struct rast_cycle_params *b)
{
   return a->clock_mhz == b->clock_mhz && a->setup == b->setup && a->cull == b->cull &&
          a->span == b->span && a->pixel == b->pixel && a->cores == b->cores &&
          a->texels == b->texels && a->fragments == b->fragments;
}

static void cycles(void)
{
   struct rast_cycle_params p, d;
   char err[256] = "";
   rast_cycle_params_default(&d);
   CHECK(rast_cycle_params_parse("clock=250,cores=12,texels=8", &p, err, sizeof(err)),
         "cycle parameters refused: %s", err);
   CHECK(p.clock_mhz == 250.0 && p.cores == 12 && p.texels == 8 && p.setup == d.setup &&
            p.fragments == d.fragments,
         "clock=250,cores=12,texels=8 read as clock %g cores %u texels %u", p.clock_mhz, p.cores,
         p.texels);
   char text[256];
   rast_cycle_params_format(&p, text, sizeof(text));
   struct rast_cycle_params q;
   CHECK(rast_cycle_params_parse(text, &q, err, sizeof(err)) && same_params(&p, &q),
         "the formatted parameters '%s' do not read back: %s", text, err);

   static const struct { const char *spec, *must_say; } bad[] = {
      { "clock=0", "clock=0 (accepted: clock=MHZ" },
      { "clock=fast", "clock=fast" },
      { "cores=0", "cores=0 (accepted:" },
      { "cores=5000", "cores=5000" },
      { "setup=-1", "setup=-1" },
      { "span=3x", "span=3x" },
      { "warp=4", "unknown key 'warp' (accepted: clock=MHZ" },
      { "cores=8,,texels=2", "empty item" },
      { "cores", "is not KEY=VALUE (accepted: clock=MHZ" },
   };
   for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
      memset(&p, 0xa5, sizeof(p));
      err[0] = '\0';
      CHECK(!rast_cycle_params_parse(bad[i].spec, &p, err, sizeof(err)), "'%s' accepted",
            bad[i].spec);
      CHECK(strstr(err, bad[i].must_say) != NULL, "'%s': message '%s' does not say '%s'",
            bad[i].spec, err, bad[i].must_say);
      /* a refused list leaves the defaults, none of its pairs */
      CHECK(same_params(&p, &d), "'%s' left parameters other than the defaults",
            bad[i].spec);
   }
}

int main(void)
{
   lists();
   cycles();
   return t_summary("settings");
}
