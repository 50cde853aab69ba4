/* Immersed bodies of a case file: a `bodies:` list -> IbmBodySet.
 *
 *   bodies:
 *     - shape: circle            # circle | naca | rectangle | polygon
 *       name: cylinder           # optional; default body<N> (N = position in the list)
 *       center: [2.0, 6.0]       # m
 *       radius: 0.5              # m, > 0
 *       markers: 2048            # optional, >= 8; default 1024
 *       wall: adiabatic          # optional: adiabatic (default) | isothermal
 *       wall_temperature: 300    # K, > 0; required with wall: isothermal, refused otherwise
 *     - shape: naca
 *       digits: "0012"           # 4-digit series MPTT (quotes optional)
 *       chord: 1.0               # m, > 0
 *       leading_edge: [0, 0]     # optional; default [0, 0]
 *       angle_deg: 0             # optional angle of attack, nose up; default 0
 *       markers: 1024            # optional, even, >= 8; default 1024
 *     - shape: rectangle
 *       min: [x, y]              # m
 *       max: [x, y]              # m, above min on both axes
 *       markers_per_side: 64     # optional, >= 1; default 64
 *     - shape: polygon
 *       file: body.csv           # "x, y" per line (commas or blanks; '#' comments; a
 *                                # header line is skipped); relative to the case file
 *       max_spacing: 0.01        # optional: split longer edges, m; default 0 (as given)
 * Markers should be no farther apart than the finest cell near the body.
 * Every body takes `name`, `wall` and `wall_temperature`. */
#ifndef NSPD_CASE_CASE_BODIES_H
#define NSPD_CASE_CASE_BODIES_H

#include "couple/ghost/markers.h"
#include "io/cfg_tree.h"

#include <stdbool.h>

/* Reads map[key] into *set (allocated here). Absent key and !required: an
 * empty set. NSPD_ERR_INPUT with a FILE:LINE:COL message for bad input, or
 * naming the CSV file and its line; on failure *set may be partly filled:
 * free it with ibm_body_set_free. */
int case_read_bodies(CfgNode *map, const char *key, bool required, IbmBodySet *set);

#endif
