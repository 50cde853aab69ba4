/* Wall-clock time for timings and ETAs. */
#ifndef NSPD_CORE_TIMER_H
#define NSPD_CORE_TIMER_H

/* Seconds since an arbitrary fixed point (monotonic clock). */
double nspd_wall_time(void);

#endif
