# The blast front at each pressure probe of `nspd radial --probes` (CSV:
# t, then p at each radius): the arrival by the first time the
# overpressure exceeds 1 % of its peak, the half-rise (50 %), and the
# peak, the ambient being the first row's pressure.
#   awk -f scripts/lib/probe_arrival.awk RADIAL.csv
BEGIN { FS = "," }
/^#/ { next }
!header { for (i = 2; i <= NF; i++) name[i] = $i; cols = NF; header = 1; next }
{ n++; t[n] = $1; for (i = 2; i <= cols; i++) p[i, n] = $i }
function cross(i, level,    r) {
    for (r = 2; r <= n; r++)
        if (p[i, r] > level)
            return t[r - 1] + (t[r] - t[r - 1]) * (level - p[i, r - 1]) / (p[i, r] - p[i, r - 1])
    return -1
}
END {
    for (i = 2; i <= cols; i++) {
        m = 0; a = p[i, 1]
        for (r = 1; r <= n; r++) if (p[i, r] > m) { m = p[i, r]; tm = t[r] }
        printf "%s: arrival (1 %%) %.2f us, half-rise %.2f us, peak %.4f MPa at %.2f us\n", name[i],
            1e6 * cross(i, a + 0.01 * (m - a)), 1e6 * cross(i, a + 0.5 * (m - a)), 1e-6 * m, 1e6 * tm
    }
}
