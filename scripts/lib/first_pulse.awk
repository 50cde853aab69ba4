# The first pulse of the penalty force on a body (history.csv's
# penalty_force_x_N_per_m): its impulse, from the start until the force
# first turns negative after rising above 100 N/m (the round-off before the
# wave arrives does not end it), in N s per metre of depth. The peak of a
# shock's push sharpens with the mesh (about as 1/h); its impulse converges.
#   awk -f scripts/lib/first_pulse.awk OUT/history.csv
BEGIN { FS = "," }
NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
{
    t = $col["time_s"]; F = $col["penalty_force_x_N_per_m"]
    if (NR > 2 && !done) {
        impulse += 0.5 * (t - tp) * (F + Fp)
        if (F > peak) peak = F
        if (peak > 100 && F < 0) done = 1
    }
    tp = t; Fp = F
}
END { printf "%.4f\n", impulse }
