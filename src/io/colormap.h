/* Perceptual colour maps for PNG snapshots. */
#ifndef NSPD_IO_COLORMAP_H
#define NSPD_IO_COLORMAP_H

#include <stdint.h>

typedef enum { COLORMAP_VIRIDIS, COLORMAP_GRAY, COLORMAP_INFERNO } ColormapKind;

/* RGB of value t in [0, 1] (clamped; NaN maps to grey). Thread-safe: the
 * tables are built once, by whichever call comes first. */
void colormap_rgb(ColormapKind kind, double t, uint8_t rgb[3]);

#endif
