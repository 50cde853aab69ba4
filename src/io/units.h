/* The unit of an nspd output column or summary key, read from its name:
 * nspd names every dimensional quantity with its unit as a suffix
 * (crack_tip_x_m, crack_speed_m_per_s, energy_J_per_m, ...). */
#ifndef NSPD_IO_UNITS_H
#define NSPD_IO_UNITS_H

#include <stddef.h>

/* The unit ("m/s", "J", "°") or "" for a dimensionless name. */
const char *units_of_key(const char *key);
/* The name without its unit suffix ("crack_speed" for crack_speed_m_per_s),
 * into buf. */
void units_strip(const char *key, char *buf, size_t size);

#endif
