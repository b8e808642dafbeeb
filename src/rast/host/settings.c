/*
 * The FIXPIPE_* settings' KEY=VALUE lists (settings.h).
 */
#include <stdio.h>
#include <string.h>

#include "rast/host/settings.h"

bool rast_settings_each(const char *list, const char *accepted, rast_setting_fn fn, void *ctx,
                        char *err, size_t errlen)
{
   char buf[RAST_SETTINGS_MAX + 1];
   const size_t len = strlen(list);
   if (len > RAST_SETTINGS_MAX) {
      snprintf(err, errlen, "longer than %d characters (accepted: %s)", RAST_SETTINGS_MAX,
               accepted);
      return false;
   }
   memcpy(buf, list, len + 1);
   /* Walked by hand rather than by strtok, which would pass over the
    * empty items that a stray comma makes. */
   for (char *item = buf, *next; item; item = next) {
      char *comma = strchr(item, ',');
      next = comma ? comma + 1 : NULL;
      if (comma)
         *comma = '\0';
      char *eq = strchr(item, '=');
      if (!*item) {
         snprintf(err, errlen, "an empty item in '%s' (a list of KEY=VALUE: %s)", list, accepted);
         return false;
      }
      if (!eq || eq == item || !eq[1]) {
         snprintf(err, errlen, "'%s' is not KEY=VALUE (accepted: %s)", item, accepted);
         return false;
      }
      *eq = '\0';
      if (!fn(ctx, item, eq + 1, err, errlen))
         return false;
   }
   return true;
}
