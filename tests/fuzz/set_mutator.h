/* The --set mutator of fuzz_case and fuzz_sim (issue 23): what found the
 * input of issue 23 by hand, as a libFuzzer mutation. It reads the case
 * part of an input (the bytes before a line "#--set"), picks one of its
 * scalar keys by its real path and appends an override that puts an
 * extreme value there: 0, negatives, 1e-300, 1e300, 1e11, a 21-digit
 * integer, NaN, inf or an empty list. */
#ifndef NSPD_TESTS_FUZZ_SET_MUTATOR_H
#define NSPD_TESTS_FUZZ_SET_MUTATOR_H

#include <stddef.h>
#include <stdint.h>

/* The offset of the line "#--set" (at the start or after a newline) that
 * ends an input's case part, or size if there is none. */
size_t fuzz_set_separator(const uint8_t *data, size_t size);

/* Rewrites data[0..size) in place (at most max_size bytes) with one more
 * override, chosen by `seed`; the new size, or 0 when it cannot (a case
 * part that does not parse, no scalar key, 8 overrides already, no
 * room), and then data is unchanged. Deterministic in (data, seed). */
size_t fuzz_set_mutate(uint8_t *data, size_t size, size_t max_size, unsigned seed);

#endif
