/* Perceptual colour maps for PNG snapshots. */
#ifndef NSPD_IO_COLORMAP_H
#define NSPD_IO_COLORMAP_H

#include "core/fields.h" /* ColormapKind */

#include <stdint.h>

/* RGB of value t in [0, 1] (clamped; NaN maps to grey). Thread-safe: the
 * tables are built once, by whichever call comes first. */
void colormap_rgb(ColormapKind kind, double t, uint8_t rgb[3]);

#endif
