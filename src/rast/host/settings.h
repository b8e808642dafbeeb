/*
 * One parser for the KEY=VALUE lists of the FIXPIPE_* settings: a
 * precision profile's settings after its name (FIXPIPE_PROFILE), the cycle
 * model's parameters (FIXPIPE_CYCLES) and the vectors' options after their
 * directory (FIXPIPE_VECTORS).  Each list is split and checked for form
 * here, so that every setting refuses a malformed list with the same
 * words; what a key means and which values it takes stay with its unit.
 */
#ifndef RAST_SETTINGS_H
#define RAST_SETTINGS_H

#include <stdbool.h>
#include <stddef.h>

/* The longest list a setting takes, in characters. */
#define RAST_SETTINGS_MAX 255

/* One KEY=VALUE of a list: false to refuse it, with the reason in err. */
typedef bool (*rast_setting_fn)(void *ctx, const char *key, const char *value, char *err,
                                size_t errlen);

/* Calls fn for each KEY=VALUE of the comma-separated list, in order.
 * False, with err set, for a list longer than RAST_SETTINGS_MAX, an empty
 * item, an item without '=' or with an empty key or value, or at fn's
 * first refusal; accepted names the keys for those messages. */
bool rast_settings_each(const char *list, const char *accepted, rast_setting_fn fn, void *ctx,
                        char *err, size_t errlen);

#endif
