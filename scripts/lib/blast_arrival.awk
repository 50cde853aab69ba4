# The free-field blast's probes (cases/iga_cylindrical_blast.yaml: centre,
# r5cm, r7cm, r10cm) from a run's history.csv: each ring probe's arrival
# by the reference's definition (the first time the overpressure exceeds
# 1 % of its peak; ../shared/notes/penalty_calc/radial.py) and by the
# half-rise (50 % of the peak: the middle of a front a mesh smears), its
# peak, and the centre's pressure at 50 and 100 us.
#   awk -f scripts/lib/blast_arrival.awk OUT/history.csv
BEGIN { FS = ","; name[1] = "centre"; name[2] = "r5cm"; name[3] = "r7cm"; name[4] = "r10cm" }
NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
{ t[NR] = $col["time_s"]; for (k = 1; k <= 4; k++) p[k, NR] = $col[name[k] "_p_Pa"]; n = NR }
# cross(k, level): the time probe k's pressure first exceeds level, interpolated
function cross(k, level,    r) {
    for (r = 3; r <= n; r++)
        if (p[k, r] > level)
            return t[r - 1] + (t[r] - t[r - 1]) * (level - p[k, r - 1]) / (p[k, r] - p[k, r - 1])
    return -1
}
function at(k, time,    r) {
    for (r = 3; r <= n; r++)
        if (t[r] >= time)
            return p[k, r - 1] + (p[k, r] - p[k, r - 1]) * (time - t[r - 1]) / (t[r] - t[r - 1])
    return -1
}
END {
    for (k = 2; k <= 4; k++) {
        m = 0
        for (r = 2; r <= n; r++) if (p[k, r] > m) { m = p[k, r]; tm = t[r] }
        printf "%s: arrival (1 %%) %.1f us, half-rise %.1f us, peak %.3f MPa at %.1f us\n", name[k],
            1e6 * cross(k, 1e5 + 0.01 * (m - 1e5)), 1e6 * cross(k, 1e5 + 0.5 * (m - 1e5)), 1e-6 * m, 1e6 * tm
    }
    printf "centre: %.3f MPa at 50 us, %.3f MPa at 100 us\n", 1e-6 * at(1, 5e-5), 1e-6 * at(1, 1e-4)
}
